"""The 3D view (viser) behind the station's own door: `/3d/` proxies viser's HTTP and websocket.

viser always binds 127.0.0.1; browsers reach it only through these routes,
which `api.guard.Guard` has already checked (token, Host, Origin).
"""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import Callable

import httpx
from fastapi import FastAPI, Request, WebSocket
from fastapi.responses import RedirectResponse, Response
from starlette.websockets import WebSocketDisconnect

HOP_HEADERS = {"connection", "keep-alive", "transfer-encoding", "content-encoding",
               "content-length", "upgrade"}


def mount_view3d(app: FastAPI, viser_port: Callable[[], int | None]) -> None:
    """Routes `/3d`, `/3d/...` (HTTP GET) and the websocket `/3d/...` to 127.0.0.1:viser_port."""

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
        async with httpx.AsyncClient(timeout=30) as client:
            try:
                r = await client.get(url, params=request.query_params)
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
        from websockets.asyncio.client import connect
        from websockets.exceptions import ConnectionClosed

        port = viser_port()
        if port is None:
            await ws.close(code=1013)
            return
        offered = [p.strip() for p in ws.headers.get("sec-websocket-protocol", "").split(",")
                   if p.strip()]
        try:
            upstream = await connect(f"ws://127.0.0.1:{port}/{path}", max_size=None,
                                     subprotocols=offered or None, open_timeout=10,
                                     compression=None)
        except (OSError, TimeoutError, ConnectionClosed, Exception):
            await ws.close(code=1011)
            return
        async with upstream:
            await ws.accept(subprotocol=upstream.subprotocol)

            async def down() -> None:
                async for message in upstream:
                    if isinstance(message, bytes):
                        await ws.send_bytes(message)
                    else:
                        await ws.send_text(message)

            async def up() -> None:
                while True:
                    message = await ws.receive()
                    if message["type"] == "websocket.disconnect":
                        return
                    if message.get("bytes") is not None:
                        await upstream.send(message["bytes"])
                    elif message.get("text") is not None:
                        await upstream.send(message["text"])

            tasks = [asyncio.create_task(down()), asyncio.create_task(up())]
            try:
                await asyncio.wait(tasks, return_when=asyncio.FIRST_COMPLETED)
            finally:
                for t in tasks:
                    t.cancel()
                for t in tasks:
                    with contextlib.suppress(asyncio.CancelledError, WebSocketDisconnect,
                                             ConnectionClosed, RuntimeError, Exception):
                        await t
        with contextlib.suppress(RuntimeError):
            await ws.close()
