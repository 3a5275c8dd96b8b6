"""The station's HTTP API (shared/DESIGN.md "HTTP API", stable paths) and live websocket."""

from __future__ import annotations

import asyncio
import contextlib
import datetime as dt
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from typing import Annotated, Any, Literal

from fastapi import (
    Depends,
    FastAPI,
    HTTPException,
    Query,
    Request,
    WebSocket,
    WebSocketDisconnect,
)
from fastapi.middleware.cors import CORSMiddleware
from fastapi.responses import JSONResponse, StreamingResponse
from pydantic import BaseModel, ConfigDict, Field

from usvstation import __version__
from usvstation.api.auth import require_token
from usvstation.api.console import default_frontend_dir, mount_console
from usvstation.api.planners import PlannerName, planners_router
from usvstation.scenario import Scenario
from usvstation.services.boat import BoatError
from usvstation.services.export import FORMATS, export_chunks, planned_route
from usvstation.station import Station

Auth = [Depends(require_token)]


class PlanRequest(BaseModel):
    """Plan a scenario (default: the working scenario) with a planner and seed."""

    model_config = ConfigDict(extra="forbid")
    scenario: Scenario | None = None
    planner: PlannerName = "iga"
    seed: int | None = Field(None, ge=0, le=2**31 - 1)


class Accepted(BaseModel):
    id: str
    status: str


class MissionRequest(BaseModel):
    """Upload a finished plan to the boat."""

    model_config = ConfigDict(extra="forbid")
    plan_id: str = Field(min_length=1, max_length=64)


class CommandRequest(BaseModel):
    """A boat command; START needs a verified mission, ABORT stops the propellers."""

    model_config = ConfigDict(extra="forbid")
    command: Literal["start", "hold", "resume", "abort"]


def _utc(value: dt.datetime | None) -> str | None:
    """Datetime query parameter to the stored ISO form (UTC, milliseconds, Z)."""
    if value is None:
        return None
    if value.tzinfo is None:
        value = value.replace(tzinfo=dt.UTC)
    return value.astimezone(dt.UTC).strftime("%Y-%m-%dT%H:%M:%S.%f")[:-3] + "Z"


def create_app(station: Station) -> FastAPI:
    """The FastAPI app bound to a station; the station starts and stops with the app."""

    @asynccontextmanager
    async def lifespan(_: FastAPI) -> AsyncIterator[None]:
        await station.start()
        try:
            yield
        finally:
            await station.stop()

    app = FastAPI(title="USV recovery shore station", version=__version__, lifespan=lifespan,
                  description="IGA recovery planning, mission upload and telemetry (paper 000).")
    app.state.token = station.token
    app.state.station = station
    if station.settings.cors_origins:
        app.add_middleware(CORSMiddleware, allow_origins=station.settings.cors_origins,
                           allow_methods=["*"], allow_headers=["*"])

    @app.exception_handler(BoatError)
    async def boat_refused(_: Request, exc: BoatError) -> JSONResponse:
        """A request the boat service refuses: its status (404, 409, 503, 504) and reason."""
        return JSONResponse({"detail": str(exc)}, status_code=exc.status)

    @app.get("/api/health", tags=["station"])
    async def health() -> dict[str, Any]:
        return {"version": __version__, **station.health()}

    @app.get("/api/scenario", tags=["scenario"])
    async def get_scenario() -> Scenario:
        return await station.working_scenario()

    @app.put("/api/scenario", tags=["scenario"], dependencies=Auth)
    async def put_scenario(scenario: Scenario) -> Scenario:
        await station.set_working_scenario(scenario)
        return scenario

    @app.post("/api/plans", status_code=202, tags=["plans"], dependencies=Auth)
    async def post_plan(req: PlanRequest | None = None) -> Accepted:
        req = req or PlanRequest()
        scenario = req.scenario or await station.working_scenario()
        job = await station.plans.submit(scenario, req.planner, req.seed)
        return Accepted(id=job["id"], status=job["status"])

    @app.get("/api/plans", tags=["plans"])
    async def list_plans() -> list[dict[str, Any]]:
        return [station.plans.summary(j) for j in station.plans.jobs.values()]

    @app.get("/api/plans/{plan_id}", tags=["plans"])
    async def get_plan(plan_id: str) -> dict[str, Any]:
        job = station.plans.get(plan_id)
        if job is None:
            raise HTTPException(404, detail=f"no plan {plan_id!r}")
        return {k: job[k] for k in ("id", "status", "plan", "error", "created_at", "planner",
                                    "seed", "scenario")}

    @app.post("/api/missions", status_code=202, tags=["boat"], dependencies=Auth,
              responses={409: {"description": "plan not done, no origin, or a mission running"},
                         503: {"description": "the boat link is down"}})
    async def post_mission(req: MissionRequest) -> dict[str, Any]:
        return await station.boat.create_mission(req.plan_id)

    @app.get("/api/missions", tags=["boat"])
    async def list_missions() -> list[dict[str, Any]]:
        return [station.boat.get_mission(k) for k in station.boat.missions]

    @app.get("/api/missions/{mission_id}", tags=["boat"])
    async def get_mission(mission_id: str) -> dict[str, Any]:
        mission = station.boat.get_mission(mission_id)
        if mission is None:
            raise HTTPException(404, detail=f"no mission {mission_id!r}")
        return mission

    @app.post("/api/boat/command", tags=["boat"], dependencies=Auth,
              responses={409: {"description": "no verified mission, or the boat refused"},
                         503: {"description": "the boat link is down"},
                         504: {"description": "the boat did not acknowledge in time"}})
    async def boat_command(req: CommandRequest) -> dict[str, Any]:
        return await station.boat.command(req.command)

    @app.get("/api/boat", tags=["boat"])
    async def boat() -> dict[str, Any]:
        return station.boat.snapshot()

    @app.get("/api/runs", tags=["telemetry"])
    async def list_runs() -> list[dict[str, Any]]:
        return await asyncio.to_thread(station.store.runs)

    @app.get("/api/telemetry", tags=["telemetry"])
    async def telemetry(
        run: Annotated[int | None, Query(ge=1, le=2**63 - 1)] = None,
        since: dt.datetime | None = None,
        until: dt.datetime | None = None,
        limit: Annotated[int, Query(ge=1, le=1_000_000)] = 100_000,
    ) -> list[dict[str, Any]]:
        return await asyncio.to_thread(station.store.telemetry, run, _utc(since), _utc(until),
                                       limit)

    @app.get("/api/telemetry/export", tags=["telemetry"])
    async def export(
        run: Annotated[int | None, Query(ge=1, le=2**63 - 1)] = None,
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

    @app.websocket("/ws/live")
    async def live(ws: WebSocket) -> None:
        await ws.accept()
        sub = station.hub.subscribe()
        try:
            await ws.send_json({"type": "hello",
                                "data": {"version": __version__, **station.boat.snapshot()}})
            sender = asyncio.create_task(_pump(ws, sub))
            receiver = asyncio.create_task(_drain(ws))
            _, pending = await asyncio.wait({sender, receiver},
                                               return_when=asyncio.FIRST_COMPLETED)
            for task in pending:
                task.cancel()
        except WebSocketDisconnect:
            pass
        finally:
            station.hub.unsubscribe(sub)

    app.include_router(planners_router())
    mount_console(app, station.settings.frontend_dir or default_frontend_dir())
    return app


async def _pump(ws: WebSocket, sub: Any) -> None:
    while (text := await sub.next()) is not None:
        await ws.send_text(text)
    with contextlib.suppress(RuntimeError):
        await ws.close(code=1013, reason="too slow: live updates dropped")


async def _drain(ws: WebSocket) -> None:
    with contextlib.suppress(WebSocketDisconnect):
        while True:
            await ws.receive_text()


async def _in_thread(chunks: Any) -> AsyncIterator[str]:
    """Iterate a blocking generator in a worker thread, chunk by chunk."""
    done = object()
    while (piece := await asyncio.to_thread(next, chunks, done)) is not done:
        yield piece
