"""`/api/runs`, `/api/telemetry` and its export: stored runs and telemetry."""

from __future__ import annotations

import asyncio
import datetime as dt
import json
from collections.abc import AsyncIterator
from typing import Annotated, Any, Literal

from fastapi import (
    APIRouter,
    HTTPException,
    Query,
    Request,
)
from fastapi.responses import Response, StreamingResponse

from usvstation.api.deps import Read, StationDep
from usvstation.api.models import (
    RunRow,
    StoredTelemetryRow,
)
from usvstation.runtime import release_memory
from usvstation.services.export import FORMATS, export_chunks, planned_route

TELEMETRY_PAGE_MAX = 100_000
TELEMETRY_CHUNK = 1_000  # rows read and encoded at once


def _utc(value: dt.datetime | None) -> str | None:
    """Datetime query parameter to the stored ISO form (UTC, milliseconds, Z)."""
    if value is None:
        return None
    if value.tzinfo is None:
        value = value.replace(tzinfo=dt.UTC)
    return value.astimezone(dt.UTC).strftime("%Y-%m-%dT%H:%M:%S.%f")[:-3] + "Z"


async def _in_thread(chunks: Any) -> AsyncIterator[str]:
    """Iterate a blocking generator in a worker thread, chunk by chunk."""
    done = object()
    while (piece := await asyncio.to_thread(next, chunks, done)) is not done:
        yield piece


_dumps = json.JSONEncoder(separators=(",", ":"), allow_nan=False).encode


def _encoder(request: Request) -> asyncio.Semaphore:
    """The app's one telemetry page encoder (made on first use, on the app's loop)."""
    state = request.app.state
    if getattr(state, "telemetry_encoder", None) is None:
        state.telemetry_encoder = asyncio.Semaphore(1)
    return state.telemetry_encoder


router = APIRouter()


@router.get("/api/runs", tags=["telemetry"], dependencies=Read)
async def list_runs(station: StationDep) -> list[RunRow]:
    return await asyncio.to_thread(station.store.runs)


@router.get("/api/telemetry", tags=["telemetry"], dependencies=Read,
         response_model=list[StoredTelemetryRow],
         responses={200: {"headers": {"X-Next-After": {
             "description": "present when the page is full: pass it as `after` for the "
             "next page", "schema": {"type": "integer"}}}}})
async def telemetry(
    station: StationDep,
    request: Request,
    run: Annotated[int | None, Query(ge=1, le=2**63 - 1)] = None,
    since: dt.datetime | None = None,
    until: dt.datetime | None = None,
    after: Annotated[int, Query(ge=0, le=2**63 - 1,
                                description="cursor: rows with a larger id")] = 0,
    limit: Annotated[int, Query(ge=1, le=TELEMETRY_PAGE_MAX)] = TELEMETRY_PAGE_MAX,
) -> Response:
    """Telemetry rows in id order, one page of at most 100,000 rows, streamed: read and
    encoded off the event loop `TELEMETRY_CHUNK` rows at a time, each sent before the next
    is read (a slow client holds one chunk, not the page); one chunk is encoded at a time
    whatever the number of clients (the encoder holds the GIL, which the event loop and
    the boat link's thread need too)."""
    store, lo, hi = station.store, _utc(since), _utc(until)
    encoder = _encoder(request)
    count, end = await asyncio.to_thread(store.telemetry_page, run, lo, hi, limit, after)

    def chunk(cursor: int, first: bool) -> tuple[bytes, int | None]:
        """The page's next rows above `cursor` as JSON array items; the next cursor."""
        rows = [r for r in store.telemetry(run, lo, hi, TELEMETRY_CHUNK, cursor)
                if end is not None and r["id"] <= end]
        if not rows:
            return b"", None
        # row by row, in a Python loop: the GIL changes hands between rows (one dumps of
        # the whole chunk would hold it for tens of ms, the link's heartbeat waiting)
        text = ",".join([_dumps(r) for r in rows])
        last = rows[-1]["id"]
        return (b"" if first else b",") + text.encode(), None if last == end else last

    async def body() -> AsyncIterator[bytes]:
        yield b"["
        cursor: int | None = after if end is not None else None
        first = True
        try:
            while cursor is not None:
                async with encoder:
                    piece, cursor = await asyncio.to_thread(chunk, cursor, first)
                if piece:
                    yield piece
                    first = False
        finally:
            if count >= TELEMETRY_CHUNK:  # a large page: its memory back to the system
                await asyncio.to_thread(release_memory)
        yield b"]"

    headers = {"X-Next-After": str(end)} if count == limit and end is not None else None
    return StreamingResponse(body(), media_type="application/json", headers=headers)


@router.get("/api/telemetry/export", tags=["telemetry"], dependencies=Read)
async def export(station: StationDep, run: Annotated[int | None, Query(ge=1, le=2**63 - 1)] = None,
    format: Literal["csv", "gpx", "geojson", "jsonl"] = "csv",
) -> StreamingResponse:
    run_row = await asyncio.to_thread(station.store.run, run) if run is not None else None
    if run is not None and run_row is None:
        raise HTTPException(404, detail=f"no run {run}")
    plan_job = station.plans.get(run_row["plan_id"]) if run_row and run_row["plan_id"] else None
    media, ext = FORMATS[format]
    chunks = export_chunks(format, station.store.iter_telemetry(run), run_row,
                           planned_route(plan_job))
    name = f"run-{run}" if run is not None else "telemetry"
    return StreamingResponse(
        _in_thread(chunks), media_type=media,
        headers={"Content-Disposition": f'attachment; filename="{name}.{ext}"'},
    )
