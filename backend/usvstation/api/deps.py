"""Dependencies of the API's routes: the station the app is bound to, and the two roles."""

from __future__ import annotations

from typing import Annotated, TypeVar

from fastapi import Depends, HTTPException
from starlette.requests import HTTPConnection

from usvstation.api.auth import require_operator, require_viewer
from usvstation.station import Station


async def _station(conn: HTTPConnection) -> Station:
    return conn.app.state.station


StationDep = Annotated[Station, Depends(_station)]
Auth = [Depends(require_operator)]  # changes and commands
Read = [Depends(require_viewer)]  # reading: the viewer token or the operator's
T = TypeVar("T")


def found(value: T | None, what: str) -> T:
    """`value`, or a 404 "no {what}" when there is none."""
    if value is None:
        raise HTTPException(404, detail=f"no {what}")
    return value
