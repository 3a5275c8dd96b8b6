"""Run the station under uvicorn (`usv-station serve`)."""

from __future__ import annotations

from collections.abc import Callable

import uvicorn

from usvstation.api.app import create_app
from usvstation.config import Settings
from usvstation.station import Station

SHUTDOWN_GRACE_S = 3  # SIGTERM: connections get this long, then telemetry is flushed


def console_url(settings: Settings, token: str) -> str:
    host = "127.0.0.1" if settings.host in ("0.0.0.0", "::", "") else settings.host
    host = f"[{host}]" if ":" in host else host
    query = f"/?token={token}" if token else "/"
    return f"http://{host}:{settings.port}{query}"


def serve(settings: Settings, announce: Callable[[str], None] = print) -> int:
    """Start the station and block until SIGINT or SIGTERM; returns the exit code."""
    station = Station(settings)
    app = create_app(station)
    config = uvicorn.Config(app, host=settings.host, port=settings.port, log_level="info",
                            timeout_graceful_shutdown=SHUTDOWN_GRACE_S, lifespan="on")
    server = uvicorn.Server(config)
    link = "simulated boat (pty)" if settings.link == "sim" else settings.link
    announce(f"usv-station: data in {settings.data_dir.resolve()}, boat link: {link}")
    announce(f"usv-station: console {console_url(settings, station.token)}")
    server.run()
    return 0 if server.started else 1
