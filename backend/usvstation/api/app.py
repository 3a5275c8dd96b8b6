"""The station's HTTP API (shared/DESIGN.md "HTTP API", stable paths) and live websocket."""

from __future__ import annotations

import asyncio
import contextlib
import datetime as dt
import json
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
from fastapi.responses import JSONResponse, Response, StreamingResponse
from pydantic import BaseModel, ConfigDict, Field

from usvstation import __version__
from usvstation.api.alerts import router as alerts_router
from usvstation.api.auth import require_operator, require_viewer
from usvstation.api.charts import router as charts_router
from usvstation.api.console import default_frontend_dir, mount_console, mount_docs
from usvstation.api.guard import Guard, GuardConfig
from usvstation.api.planners import PlannerName, planners_router
from usvstation.api.view3d import mount_view3d
from usvstation.api.world import router as world_router
from usvstation.scenario import Scenario
from usvstation.services.boat import BoatError
from usvstation.services.export import FORMATS, export_chunks, planned_route
from usvstation.services.plans import (
    PlanNotCancellable,
    PlanQueueFull,
    outdated_by,
    scenario_from_boat,
)
from usvstation.station import Station

Auth = [Depends(require_operator)]  # changes and commands
Read = [Depends(require_viewer)]  # reading: the viewer token or the operator's
TELEMETRY_PAGE_MAX = 100_000
PLAN_RETRY_AFTER_S = 5


class TelemetryRow(BaseModel):
    """One stored telemetry frame (`id` orders the rows and is the paging cursor)."""

    id: int
    run: int | None
    time: str
    boat_time: float | None
    lat: float | None
    lon: float | None
    x: float | None
    y: float | None
    heading_deg: float | None
    course_deg: float | None
    speed: float | None
    ramp_heading_deg: float | None
    yaw_rate_dps: float | None
    fix_type: int | None
    satellites: int | None
    hdop: float | None
    thrust_left: float | None
    thrust_right: float | None
    battery_v: float | None
    waypoint_index: int | None
    cross_track_m: float | None
    state: str | None


class WriterHealth(BaseModel):
    received: int
    committed: int
    queued: int
    dropped: int
    retries: int
    error: str | None


class PlansHealth(BaseModel):
    queued: int
    running: int
    workers: int
    workers_alive: int
    worker_pids: list[int]
    workers_replaced: int
    queue_max: int
    timeout_s: float


class LoopLag(BaseModel):
    worst_last_minute: float = Field(description="ms, worst event-loop lag of the last minute")
    worst_since_start: float = Field(description="ms")


class Health(BaseModel):
    """Station health; no boat data (open without a token)."""

    version: str
    status: Literal["ok", "degraded"]
    reasons: list[str]
    telemetry_writer: WriterHealth
    plans: PlansHealth
    websocket_clients: int
    link_up: bool
    loop_lag_ms: LoopLag
    viser_port: int | None


class PlanSummary(BaseModel):
    id: str
    status: Literal["queued", "running", "done", "failed", "cancelled"]
    created_at: str
    planner: str
    seed: int | None
    error: str | None
    scenario: str
    fitness: float | None


class PlanJob(BaseModel):
    id: str
    status: Literal["queued", "running", "done", "failed", "cancelled"]
    plan: dict[str, Any] | None = Field(description="the plan (shared/DESIGN.md 'Plan output')")
    error: str | None
    created_at: str
    planner: str
    seed: int | None
    scenario: dict[str, Any]


class RunRow(BaseModel):
    id: int
    mission_id: str | None
    plan_id: str | None
    started_at: str
    ended_at: str | None
    state: str
    points: int


class PlanRequest(BaseModel):
    """Plan a scenario (default: the working scenario) with a planner and seed."""

    model_config = ConfigDict(extra="forbid")
    scenario: Scenario | None = None
    planner: PlannerName = "iga"
    seed: int | None = Field(None, ge=0, le=2**31 - 1)
    from_boat: bool = Field(
        False, description="plan from the boat's latest telemetry (position, heading, speed), "
        "obstacles propagated to that instant of the running mission",
    )


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
    mission_id: str | None = Field(None, min_length=1, max_length=64,
                                   description="START: the mission to start (required)")


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
                  description="IGA recovery planning, mission upload and telemetry (paper 000).",
                  docs_url=None, redoc_url=None)
    app.state.token = station.token
    app.state.tokens = station.tokens
    app.state.station = station
    settings = station.settings
    if settings.cors_origins:
        app.add_middleware(CORSMiddleware, allow_origins=settings.cors_origins,
                           allow_methods=["*"], allow_headers=["*"])
    app.add_middleware(Guard, config=GuardConfig(
        tokens=station.tokens, max_body_bytes=settings.max_body_bytes,
        bound_host=settings.host, allowed_hosts=frozenset(h.lower() for h in
                                                          settings.allowed_hosts),
        allowed_origins=frozenset(settings.allowed_origins),
        max_ws_clients=settings.max_ws_clients,
        ws_clients=lambda: len(station.hub.subscribers)))

    @app.exception_handler(BoatError)
    async def boat_refused(_: Request, exc: BoatError) -> JSONResponse:
        """A request the boat service refuses: its status (404, 409, 503, 504) and reason."""
        return JSONResponse({"detail": str(exc)}, status_code=exc.status)

    @app.get("/api/health", tags=["station"], response_model=Health)
    async def health() -> dict[str, Any]:
        return {"version": __version__, **station.health(), "viser_port": station.view.port}

    @app.get("/api/scenario", tags=["scenario"], dependencies=Read)
    async def get_scenario() -> Scenario:
        return await station.working_scenario()

    @app.put("/api/scenario", tags=["scenario"], dependencies=Auth)
    async def put_scenario(scenario: Scenario) -> Scenario:
        await station.set_working_scenario(scenario)
        return scenario

    @app.post("/api/plans", status_code=202, tags=["plans"], dependencies=Auth,
              responses={429: {"description": "the plan queue is full (Retry-After)"}})
    async def post_plan(req: PlanRequest | None = None) -> Accepted:
        req = req or PlanRequest()
        scenario = req.scenario or await station.working_scenario()
        if req.from_boat:
            try:
                handler = station.boat.handler
                scenario = scenario_from_boat(scenario, handler and handler.telemetry,
                                              handler and handler.run_t0)
            except ValueError as exc:
                raise HTTPException(409, detail=str(exc)) from None
        try:
            job = await station.plans.submit(scenario, req.planner, req.seed)
        except PlanQueueFull as exc:
            raise HTTPException(429, detail=str(exc),
                                headers={"Retry-After": str(PLAN_RETRY_AFTER_S)}) from None
        return Accepted(id=job["id"], status=job["status"])

    @app.get("/api/plans", tags=["plans"], dependencies=Read, response_model=list[PlanSummary])
    async def list_plans() -> list[dict[str, Any]]:
        return [station.plans.summary(j) for j in station.plans.jobs.values()]

    @app.delete("/api/plans/{plan_id}", tags=["plans"], dependencies=Auth,
                response_model=PlanSummary,
                responses={404: {"description": "no such plan"},
                           409: {"description": "the plan already ended"}})
    async def cancel_plan(plan_id: str) -> dict[str, Any]:
        """Cancel a queued or running plan: it ends `cancelled`, its worker is replaced."""
        try:
            job = await station.plans.cancel(plan_id)
        except PlanNotCancellable as exc:
            raise HTTPException(409, detail=str(exc)) from None
        if job is None:
            raise HTTPException(404, detail=f"no plan {plan_id!r}")
        return station.plans.summary(job)

    @app.get("/api/plans/{plan_id}", tags=["plans"], dependencies=Read, response_model=PlanJob)
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
        job = station.plans.get(req.plan_id)
        if job is not None:  # a plan of the working scenario, which changed since: refused
            changed = outdated_by(job["scenario"], await station.working_scenario())
            if changed:
                raise HTTPException(409, detail=(
                    f"plan {req.plan_id} was made for scenario {job['scenario']['name']!r} as it "
                    f"was before it changed ({', '.join(changed)}): plan again"))
        return await station.boat.create_mission(req.plan_id)

    @app.get("/api/missions", tags=["boat"], dependencies=Read)
    async def list_missions() -> list[dict[str, Any]]:
        return [station.boat.get_mission(k) for k in station.boat.missions]

    @app.get("/api/missions/{mission_id}", tags=["boat"], dependencies=Read)
    async def get_mission(mission_id: str) -> dict[str, Any]:
        mission = station.boat.get_mission(mission_id)
        if mission is None:
            raise HTTPException(404, detail=f"no mission {mission_id!r}")
        return mission

    @app.get("/api/missions/{mission_id}/verify", tags=["boat"], dependencies=Read,
             responses={404: {"description": "no such mission"},
                        409: {"description": "the boat does not hold it"},
                        503: {"description": "the boat link is down"},
                        504: {"description": "the boat did not answer the readback"}})
    async def verify_mission(mission_id: str) -> dict[str, Any]:
        """Read the boat's copy back and compare it item by item."""
        return await station.boat.verify(mission_id)

    @app.post("/api/boat/command", tags=["boat"], dependencies=Auth,
              responses={409: {"description": "no verified mission, or the boat refused"},
                         503: {"description": "the boat link is down"},
                         504: {"description": "the boat did not acknowledge in time"}})
    async def boat_command(req: CommandRequest) -> dict[str, Any]:
        return await station.boat.command(req.command, req.mission_id)

    @app.get("/api/boat", tags=["boat"], dependencies=Read)
    async def boat() -> dict[str, Any]:
        return station.boat.snapshot()

    @app.get("/api/runs", tags=["telemetry"], dependencies=Read, response_model=list[RunRow])
    async def list_runs() -> list[dict[str, Any]]:
        return await asyncio.to_thread(station.store.runs)

    @app.get("/api/telemetry", tags=["telemetry"], dependencies=Read,
             response_model=list[TelemetryRow],
             responses={200: {"headers": {"X-Next-After": {
                 "description": "present when the page is full: pass it as `after` for the "
                 "next page", "schema": {"type": "integer"}}}}})
    async def telemetry(
        run: Annotated[int | None, Query(ge=1, le=2**63 - 1)] = None,
        since: dt.datetime | None = None,
        until: dt.datetime | None = None,
        after: Annotated[int, Query(ge=0, le=2**63 - 1,
                                    description="cursor: rows with a larger id")] = 0,
        limit: Annotated[int, Query(ge=1, le=TELEMETRY_PAGE_MAX)] = TELEMETRY_PAGE_MAX,
    ) -> Response:
        """Telemetry rows in id order, one page of at most 100,000 rows (read and encoded off
        the event loop)."""
        def page() -> tuple[bytes, int | None]:
            rows = station.store.telemetry(run, _utc(since), _utc(until), limit, after)
            body = json.dumps(rows, separators=(",", ":"), allow_nan=False).encode()
            return body, rows[-1]["id"] if len(rows) == limit else None

        body, next_after = await asyncio.to_thread(page)
        headers = {"X-Next-After": str(next_after)} if next_after is not None else None
        return Response(body, media_type="application/json", headers=headers)

    @app.get("/api/telemetry/export", tags=["telemetry"], dependencies=Read)
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
            _, pending = await asyncio.wait({sender, receiver},
                                               return_when=asyncio.FIRST_COMPLETED)
            for task in pending:
                task.cancel()
        except WebSocketDisconnect:
            pass
        finally:
            station.hub.unsubscribe(sub)

    app.include_router(world_router)
    app.include_router(alerts_router)
    app.include_router(charts_router)
    frontend = station.settings.frontend_dir or default_frontend_dir()
    app.include_router(planners_router(dependencies=Read))
    mount_docs(app, frontend)
    mount_view3d(app, lambda: station.view.port)
    mount_console(app, frontend)
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
