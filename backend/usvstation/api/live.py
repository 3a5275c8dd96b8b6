"""`/ws/live`: the live websocket (events from the station's hub)."""

from __future__ import annotations

import asyncio
import contextlib
from typing import Any

from fastapi import (
    APIRouter,
    WebSocket,
    WebSocketDisconnect,
)

from usvstation import __version__
from usvstation.api.deps import StationDep


async def _pump(ws: WebSocket, sub: Any) -> None:
    while (text := await sub.next()) is not None:
        await ws.send_text(text)
    with contextlib.suppress(RuntimeError):
        await ws.close(code=1013, reason="too slow: live updates dropped")


async def _drain(ws: WebSocket) -> None:
    with contextlib.suppress(WebSocketDisconnect):
        while True:
            await ws.receive_text()


router = APIRouter()


@router.websocket("/ws/live")
async def live(station: StationDep, ws: WebSocket) -> None:
    """Token, Origin and client limit are checked by `Guard` before this runs."""
    await ws.accept()
    sub = station.hub.subscribe()
    try:
        h = station.health()
        await ws.send_json({"type": "hello",
                            "data": {"version": __version__, **station.boat.snapshot(),
                                     "health": {"status": h["status"],
                                                "reasons": h["reasons"]}}})
        sender = asyncio.create_task(_pump(ws, sub))
        receiver = asyncio.create_task(_drain(ws))
        done, pending = await asyncio.wait({sender, receiver},
                                              return_when=asyncio.FIRST_COMPLETED)
        for task in pending:
            task.cancel()
        # every task's end collected: a send to a client that has just gone ends the sender
        # with WebSocketDisconnect (or starlette's RuntimeError after a close), an ordinary
        # end, not "Task exception was never retrieved" with a traceback in the log
        for task in (*done, *pending):
            with contextlib.suppress(asyncio.CancelledError, WebSocketDisconnect, RuntimeError):
                await task
    except WebSocketDisconnect:
        pass
    finally:
        station.hub.unsubscribe(sub)
