"""Run the station under uvicorn (`usv-station serve`)."""

from __future__ import annotations

import asyncio
import socket
from collections.abc import Callable

import uvicorn

from usvstation.api.app import create_app
from usvstation.api.console import default_frontend_dir, frontend_problem
from usvstation.config import Settings
from usvstation.station import Station

SHUTDOWN_GRACE_S = 3  # SIGTERM: connections get this long, then telemetry is flushed


def console_url(settings: Settings, token: str) -> str:
    query = f"/?token={token}" if token else "/"
    return f"http://{_host(settings)}:{settings.port}{query}"


def bind(host: str, port: int) -> socket.socket:
    """The listening socket (port 0: any free port), bound before the station starts.

    Created as IPPROTO_TCP so that asyncio sets TCP_NODELAY on every accepted
    connection (it checks the protocol number); with protocol 0 each keep-alive
    response waited ~40 ms for the client's delayed ACK.
    """
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    sock = socket.socket(family, socket.SOCK_STREAM, socket.IPPROTO_TCP)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    sock.bind((host, port))
    return sock


def serve(settings: Settings, announce: Callable[[str], None] = print) -> int:
    """Start the station and block until SIGINT or SIGTERM; returns the exit code."""
    station = Station(settings)
    try:
        sock = bind(settings.host, settings.port)
    except OSError as exc:
        announce(f"usv-station: cannot listen on {settings.host}:{settings.port}: {exc.strerror}")
        return 1
    settings = settings.model_copy(update={"port": sock.getsockname()[1]})
    app = create_app(station)
    config = uvicorn.Config(app, log_level="info", lifespan="on",
                            timeout_graceful_shutdown=SHUTDOWN_GRACE_S)
    server = uvicorn.Server(config)
    link = "simulated boat (pty)" if settings.link == "sim" else settings.link
    announce(f"usv-station: data in {settings.data_dir.resolve()}, boat link: {link}")
    problem = frontend_problem(settings.frontend_dir or default_frontend_dir())
    if problem is not None:
        announce(f"usv-station: warning: {problem}")

    async def run() -> None:
        task = asyncio.create_task(server.serve(sockets=[sock]))
        while not server.started and not task.done():
            await asyncio.sleep(0.05)
        if server.started:
            announce(f"usv-station: 3D view http://{_host(settings)}:{station.view.port}/")
            announce(f"usv-station: console {console_url(settings, station.token)}")
        await task

    asyncio.run(run())
    return 0 if server.started else 1


def _host(settings: Settings) -> str:
    host = "127.0.0.1" if settings.host in ("0.0.0.0", "::", "") else settings.host
    return f"[{host}]" if ":" in host else host
