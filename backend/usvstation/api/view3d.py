"""The 3D view (viser) behind the station's own door: `/3d/` proxies viser's HTTP and websocket.

viser binds 127.0.0.1 and answers only requests carrying this start's secret
(viz/view.py `PROXY_SECRET_HEADER`), which only these routes send; browsers reach it through
them, after `api.guard.Guard` checked the token, Host and Origin. Each `/3d` websocket counts
against `--max-ws-clients` with the live ones (`view3d_clients`). A viewer's scene is read
only: what its browser sends (GUI changes: a layer, the time slider) never reaches viser, so
no other client sees it. A client that goes away is one line in the log.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
from collections.abc import Callable

import httpx
from fastapi import FastAPI, Request, WebSocket
from fastapi.responses import RedirectResponse, Response
from starlette.websockets import WebSocketDisconnect

from usvstation.api.auth import Role, token_from_headers
from usvstation.viz.view import PROXY_SECRET_HEADER

HOP_HEADERS = {"connection", "keep-alive", "transfer-encoding", "content-encoding",
               "content-length", "upgrade"}
log = logging.getLogger("usvstation.view3d")


def view3d_clients(app: FastAPI) -> int:
    """Open `/3d` websockets (they count against the live client limit)."""
    return getattr(app.state, "view3d_clients", 0)


def mount_view3d(app: FastAPI, viser_port: Callable[[], int | None],
                 secret: Callable[[], str]) -> None:
    """Routes `/3d`, `/3d/...` (HTTP GET) and the websocket `/3d/...` to 127.0.0.1:viser_port,
    with the proxy's `secret`."""
    app.state.view3d_clients = 0

    @app.get("/3d", include_in_schema=False)
    async def view3d_root() -> RedirectResponse:
        return RedirectResponse("/3d/", status_code=307)

    @app.get("/3d/{path:path}", include_in_schema=False)
    async def view3d_http(path: str, request: Request) -> Response:
        port = viser_port()
        if port is None:
            return Response("the 3D view is not running\n", status_code=503,
                            media_type="text/plain")
        url = f"http://127.0.0.1:{port}/{path}"
        async with httpx.AsyncClient(timeout=30, headers={PROXY_SECRET_HEADER: secret()}) as c:
            try:
                r = await c.get(url, params=request.query_params)
            except httpx.HTTPError as exc:
                return Response(f"the 3D view does not answer: {exc}\n", status_code=502,
                                media_type="text/plain")
        headers = {k: v for k, v in r.headers.items() if k.lower() not in HOP_HEADERS}
        return Response(r.content, status_code=r.status_code, headers=headers)

    @app.websocket("/3d")
    async def view3d_ws_root(ws: WebSocket) -> None:
        await view3d_ws(ws, "")  # viser's client drops the trailing slash of its page URL

    @app.websocket("/3d/{path:path}")
    async def view3d_ws(ws: WebSocket, path: str) -> None:
        port = viser_port()
        if port is None:
            await ws.close(code=1013)
            return
        read_only = ws.app.state.tokens.role(token_from_headers(ws.headers)) is not Role.OPERATOR
        app.state.view3d_clients += 1
        try:
            reason = await _proxy(ws, f"ws://127.0.0.1:{port}/{path}", secret(), read_only)
        finally:
            app.state.view3d_clients -= 1
        log.info("usv-station: 3D view client %s gone: %s", _peer(ws), reason)


async def _proxy(ws: WebSocket, url: str, secret: str, read_only: bool) -> str:
    """Join the browser's websocket to viser's until either side ends; why it ended."""
    from websockets.asyncio.client import connect
    from websockets.exceptions import ConnectionClosed, InvalidHandshake

    offered = [p.strip() for p in ws.headers.get("sec-websocket-protocol", "").split(",")
               if p.strip()]
    try:
        upstream = await connect(url, max_size=None, subprotocols=offered or None,
                                 open_timeout=10, compression=None,
                                 additional_headers={PROXY_SECRET_HEADER: secret})
    except (OSError, TimeoutError, InvalidHandshake) as exc:
        with contextlib.suppress(RuntimeError):
            await ws.close(code=1011)
        return f"the 3D view's server refused: {exc}"
    async with upstream:
        await ws.accept(subprotocol=upstream.subprotocol)

        async def down() -> str:
            async for message in upstream:
                if isinstance(message, bytes):
                    await ws.send_bytes(message)
                else:
                    await ws.send_text(message)
            return "the 3D view's server closed"

        async def up() -> str:
            while True:
                message = await ws.receive()
                if message["type"] == "websocket.disconnect":
                    return f"closed by the browser ({message.get('code', 1000)})"
                if read_only:
                    continue  # a viewer's GUI changes stay in its own browser
                if message.get("bytes") is not None:
                    await upstream.send(message["bytes"])
                elif message.get("text") is not None:
                    await upstream.send(message["text"])

        tasks = [asyncio.create_task(down()), asyncio.create_task(up())]
        reason = "cancelled"
        try:
            done, _ = await asyncio.wait(tasks, return_when=asyncio.FIRST_COMPLETED)
            finished = done.pop()
            exc = finished.exception()
            reason = finished.result() if exc is None else _why(exc)
        finally:
            for t in tasks:
                t.cancel()
            for t in tasks:
                with contextlib.suppress(asyncio.CancelledError, WebSocketDisconnect,
                                         ConnectionClosed, RuntimeError, OSError):
                    await t
    with contextlib.suppress(RuntimeError, WebSocketDisconnect, OSError):
        await ws.close()
    return reason


def _why(exc: BaseException) -> str:
    """One line for how a proxied connection broke (no traceback: a dropped browser is
    ordinary)."""
    text = str(exc).strip().splitlines()
    return f"{type(exc).__name__}: {text[0]}" if text else type(exc).__name__


def _peer(ws: WebSocket) -> str:
    client = ws.client
    return f"{client.host}:{client.port}" if client is not None else "?"
