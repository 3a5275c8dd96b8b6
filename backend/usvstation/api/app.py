"""The station's HTTP app (shared/DESIGN.md "HTTP API", stable paths): middleware, one router
per resource (health, scenario_routes, plans, missions, telemetry, live, world, alerts,
charts, planners; request and response models in models.py), the docs, the 3D view and
the console."""

from __future__ import annotations

import re
import sqlite3
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager

from fastapi import FastAPI, Request
from fastapi.middleware.cors import CORSMiddleware
from fastapi.responses import JSONResponse

from usvstation import __version__
from usvstation.api import health, live, missions, plans, scenario_routes, telemetry
from usvstation.api.alerts import router as alerts_router
from usvstation.api.charts import router as charts_router
from usvstation.api.console import default_frontend_dir, mount_console, mount_docs
from usvstation.api.deps import Read
from usvstation.api.guard import Guard, GuardConfig
from usvstation.api.planners import planners_router
from usvstation.api.view3d import mount_view3d, view3d_clients
from usvstation.api.world import router as world_router
from usvstation.services.errors import (
    Conflict,
    LinkUnavailable,
    NoAnswer,
    NotFound,
    QueueFull,
    StationError,
)
from usvstation.station import Station

RETRY_AFTER_S = 5  # what a 429 asks the client to wait
# The HTTP status of each domain error the services raise (the first kind that matches).
HTTP_STATUS: tuple[tuple[type[StationError], int], ...] = (
    (NotFound, 404), (Conflict, 409), (QueueFull, 429), (LinkUnavailable, 503),
    (NoAnswer, 504), (StationError, 409),
)


class BodyRoutes:
    """Which (method, path) reach a route that reads a request body: the guard refuses a
    body anywhere else without reading it. Read from the app's OpenAPI document (every
    route with a body declares its `requestBody` there) at the first request that
    announces a body, after every router is included."""

    def __init__(self, app: FastAPI) -> None:
        self.app = app
        self._table: list[tuple[str, re.Pattern[str]]] | None = None

    def takes_body(self, method: str, path: str) -> bool:
        if self._table is None:
            self._table = [(verb.upper(), _path_pattern(template))
                           for template, ops in self.app.openapi()["paths"].items()
                           for verb, op in ops.items() if "requestBody" in op]
        return any(method == verb and pattern.fullmatch(path) for verb, pattern in self._table)


def _path_pattern(template: str) -> re.Pattern[str]:
    """An OpenAPI path template (`/api/plans/{plan_id}`) as a regular expression."""
    parts = re.split(r"(\{[^}]+\})", template)
    return re.compile("".join("[^/]+" if p.startswith("{") else re.escape(p) for p in parts))


def create_app(station: Station) -> FastAPI:
    """The FastAPI app bound to a station; the station starts and stops with the app."""

    @asynccontextmanager
    async def lifespan(_: FastAPI) -> AsyncIterator[None]:
        await station.start()
        body_routes.takes_body("GET", "/")  # the route table before the first request
        try:
            yield
        finally:
            await station.stop()

    app = FastAPI(title="USV recovery shore station", version=__version__, lifespan=lifespan,
                  description="IGA recovery planning, mission upload and telemetry (paper 000).",
                  docs_url=None, redoc_url=None)
    body_routes = BodyRoutes(app)
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
        cors_origins=frozenset(settings.cors_origins),
        max_ws_clients=settings.max_ws_clients,
        ws_clients=lambda: len(station.hub.subscribers) + view3d_clients(app),
        takes_body=body_routes.takes_body))

    @app.exception_handler(StationError)
    async def refused(_: Request, exc: StationError) -> JSONResponse:
        """A request a service refuses: the status of its kind (HTTP_STATUS) and the reason."""
        status = next(code for kind, code in HTTP_STATUS if isinstance(exc, kind))
        headers = {"Retry-After": str(RETRY_AFTER_S)} if status == 429 else None
        return JSONResponse({"detail": str(exc)}, status_code=status, headers=headers)

    @app.exception_handler(sqlite3.OperationalError)
    async def database_busy(_: Request, exc: sqlite3.OperationalError) -> JSONResponse:
        """The database refused (locked by another process, disk full): 503, never 500."""
        return JSONResponse({"detail": f"the station's database refused: {exc}; try again"},
                            status_code=503, headers={"Retry-After": str(RETRY_AFTER_S)})

    for router in (health.router, scenario_routes.router, plans.router, missions.router,
                   telemetry.router, live.router, world_router, alerts_router, charts_router):
        app.include_router(router)
    frontend = station.settings.frontend_dir or default_frontend_dir()
    app.include_router(planners_router(dependencies=Read))
    mount_docs(app, frontend)
    mount_view3d(app, lambda: station.view.port, lambda: station.view.secret)
    mount_console(app, frontend)
    return app
