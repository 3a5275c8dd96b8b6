"""Start a real station (uvicorn on 127.0.0.1, ephemeral port) inside the test process."""

from __future__ import annotations

import asyncio
import socket
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager

import uvicorn

from usvstation.api.app import create_app
from usvstation.config import Settings
from usvstation.station import Station

TOKEN = "test-token-0123456789"


@contextmanager
def running_station(settings: Settings, timeout: float = 60.0) -> Iterator[tuple[str, Station]]:
    station = Station(settings)
    app = create_app(station)
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    server = uvicorn.Server(uvicorn.Config(app, log_level="warning", lifespan="on"))
    thread = threading.Thread(target=lambda: asyncio.run(server.serve(sockets=[sock])),
                              daemon=True)
    thread.start()
    deadline = time.monotonic() + timeout
    while not server.started:
        if not thread.is_alive() or time.monotonic() > deadline:
            raise RuntimeError("the station did not start")
        time.sleep(0.02)
    try:
        yield f"http://127.0.0.1:{port}", station
    finally:
        server.should_exit = True
        thread.join(15)
        sock.close()
