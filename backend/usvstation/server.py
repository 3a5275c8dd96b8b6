"""Run the station under uvicorn (`usv-station serve`).

The boat link comes first: with an external boat (`--link URL`) `serve` opens it on its own
thread before it even imports the web app, so a restarted station reaches a boat that is
running a mission before the boat's 3 s failsafe (docs/link.md). The heavy imports follow.
"""

from __future__ import annotations

import asyncio
import collections
import contextlib
import gc
import logging
import os
import resource
import socket
import sqlite3
import sys
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

import uvicorn
from uvicorn.protocols.http.httptools_impl import HttpToolsProtocol

from usvstation.config import Settings

if TYPE_CHECKING:
    from usvstation.services.boat_link import OpenedLink

SHUTDOWN_GRACE_S = 3  # SIGTERM: connections get this long, then telemetry is flushed
# asyncio accepts up to `backlog` connections in one loop callback: a burst of 1000 held
# the loop 120-160 ms at 4096. 128 bounds one callback (the kernel queues the rest).
ACCEPT_BATCH = 128
WS_PING_S = 10.0  # websocket ping interval and timeout
WS_MAX_MESSAGE = 1 << 20
SWITCH_INTERVAL_S = 0.001


class StartError(Exception):
    """The station cannot start; the message is one line for stderr (exit 2)."""


class HeaderTimeoutProtocol(HttpToolsProtocol):
    """uvicorn's HTTP protocol, closing a connection whose request headers are not complete
    within `header_timeout_s` of its opening or of the request's first byte (half-open and
    slow-header connections, also on a kept-alive connection's later requests), and at once
    a connection beyond `max_per_client` open ones from the same address: a flood of
    half-open connections from one client never fills the server's `--max-connections`
    (which would answer 503 to everybody, the operator's own kept-alive console included)."""

    header_timeout_s = 10.0
    max_per_client = 256

    def connection_made(self, transport: asyncio.Transport) -> None:  # type: ignore[override]
        super().connection_made(transport)
        self._header_timer: asyncio.TimerHandle | None = None
        self._peer = self.client[0] if self.client else None
        if self._peer is not None:
            counts = _open_per_client(self.server_state)
            counts[self._peer] += 1
            if counts[self._peer] > self.max_per_client:
                transport.abort()  # nothing read, nothing answered
                return
        self._header_timer = self.loop.call_later(self.header_timeout_s, self._header_timeout)

    def on_message_begin(self) -> None:
        super().on_message_begin()
        if self._header_timer is None:
            self._header_timer = self.loop.call_later(self.header_timeout_s,
                                                      self._header_timeout)

    def on_headers_complete(self) -> None:
        self._cancel_header_timer()
        super().on_headers_complete()

    def _cancel_header_timer(self) -> None:
        if self._header_timer is not None:
            self._header_timer.cancel()
            self._header_timer = None

    def _header_timeout(self) -> None:
        self._header_timer = None
        upgraded = self.transport.get_protocol() is not self  # now a websocket
        if not upgraded and not self.transport.is_closing():
            self.transport.close()

    def handle_websocket_upgrade(self) -> None:
        """A websocket leaves this protocol without `connection_lost` (and counts against
        --max-ws-clients from then on)."""
        self._cancel_header_timer()
        self._release_peer()
        super().handle_websocket_upgrade()

    def connection_lost(self, exc: Exception | None) -> None:
        self._cancel_header_timer()
        self._release_peer()
        super().connection_lost(exc)

    def _release_peer(self) -> None:
        if self._peer is not None:
            counts = _open_per_client(self.server_state)
            counts[self._peer] -= 1
            if counts[self._peer] <= 0:
                del counts[self._peer]
            self._peer = None


def _open_per_client(state: object) -> collections.Counter[str]:
    """Open connections by client address, kept on uvicorn's per-server state."""
    counts = getattr(state, "usv_open_per_client", None)
    if counts is None:
        counts = collections.Counter()
        state.usv_open_per_client = counts  # type: ignore[attr-defined]
    return counts


def preflight(settings: Settings) -> None:
    """StartError for what would fail later: the data dir, the serial device."""
    data = settings.data_dir
    try:
        data.mkdir(parents=True, exist_ok=True)
        probe = data / f".write-probe-{os.getpid()}"
        with probe.open("wb") as f:
            f.write(b"x" * 4096)
            f.flush()
            os.fsync(f.fileno())
        probe.unlink()
    except OSError as exc:
        raise StartError(f"data dir {data}: {exc.strerror or exc}") from None
    link = settings.link
    if link != "sim" and "://" not in link and not Path(link).exists():
        raise StartError(f"serial device {link} not found (--link)")


def raise_fd_limit() -> None:
    """Allow as many open connections as the hard limit lets (1024 is a common default)."""
    with contextlib.suppress(ValueError, OSError):
        soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
        want = 65536 if hard == resource.RLIM_INFINITY else min(hard, 65536)
        if soft < want:
            resource.setrlimit(resource.RLIMIT_NOFILE, (want, hard))


def show_station_log() -> None:
    """The station's own log lines (logger `usvstation`: info and above) on stderr, one line
    each, beside uvicorn's."""
    logger = logging.getLogger("usvstation")
    if not any(getattr(h, "usv_station", False) for h in logger.handlers):
        handler = logging.StreamHandler()
        handler.setFormatter(logging.Formatter("%(message)s"))
        handler.usv_station = True  # type: ignore[attr-defined]
        logger.addHandler(handler)
        logger.setLevel(logging.INFO)


def _one_line(exc: BaseException) -> str:
    text = str(exc).strip().splitlines()
    return f"{type(exc).__name__}: {text[0]}" if text else type(exc).__name__


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
    """Start the station and block until SIGINT or SIGTERM; returns the exit code.

    Every start-up failure raises StartError (one line; the CLI exits 2)."""
    preflight(settings)
    # threads hand the GIL over after 1 ms instead of 5: the boat link's thread waits less
    # behind a request's Python work (C calls that hold it longer are kept short elsewhere)
    sys.setswitchinterval(SWITCH_INTERVAL_S)
    opened = open_link_first(settings)
    if opened is not None:
        announce(f"usv-station: boat link open on {opened.device} (before the web app)")
    try:
        return _serve(settings, announce, opened)
    finally:
        if opened is not None:
            close_opened(opened)


def open_link_first(settings: Settings) -> OpenedLink | None:
    """An external boat's link, open on its own thread before the web app is even imported
    (None with the embedded simulated boat, which starts with the station)."""
    if settings.link == "sim":
        return None
    from usvstation.config import resolve_link_key
    from usvstation.services.boat_link import open_link_thread

    return open_link_thread(settings, resolve_link_key(settings), settings.link)


def close_opened(opened: OpenedLink) -> None:
    """Close a link `open_link_first` opened (a no-op once the station closed it)."""
    loop = opened.host.loop
    if loop is None or loop.is_closed() or not loop.is_running():
        return
    with contextlib.suppress(Exception):
        opened.host.call_blocking(opened.link.close, timeout=5.0)
    with contextlib.suppress(RuntimeError):
        loop.call_soon_threadsafe(loop.stop)


def _serve(settings: Settings, announce: Callable[[str], None],
           opened: OpenedLink | None) -> int:
    from usvstation.api.app import create_app
    from usvstation.api.console import default_frontend_dir, frontend_problem
    from usvstation.api.guard import install_log_redaction
    from usvstation.station import Station

    try:
        station = Station(settings, link=opened)
    except (OSError, sqlite3.Error) as exc:
        raise StartError(f"data dir {settings.data_dir}: {_one_line(exc)}") from None
    try:
        sock = bind(settings.host, settings.port)
    except OSError as exc:
        raise StartError(f"cannot listen on {settings.host}:{settings.port}: "
                         f"{exc.strerror}") from None
    raise_fd_limit()
    install_log_redaction()
    show_station_log()
    settings = settings.model_copy(update={"port": sock.getsockname()[1]})
    app = create_app(station)
    HeaderTimeoutProtocol.header_timeout_s = settings.header_timeout_s
    HeaderTimeoutProtocol.max_per_client = settings.max_client_connections
    config = uvicorn.Config(app, log_level="info", lifespan="on",
                            timeout_graceful_shutdown=SHUTDOWN_GRACE_S,
                            timeout_keep_alive=settings.keep_alive_s,
                            limit_concurrency=settings.max_connections, backlog=ACCEPT_BATCH,
                            http=HeaderTimeoutProtocol, ws_ping_interval=WS_PING_S,
                            ws_ping_timeout=WS_PING_S, ws_max_size=WS_MAX_MESSAGE)
    server = uvicorn.Server(config)
    link = "simulated boat (pty)" if settings.link == "sim" else settings.link
    announce(f"usv-station: data in {settings.data_dir.resolve()}, boat link: {link}")
    problem = frontend_problem(settings.frontend_dir or default_frontend_dir())
    if problem is not None:
        announce(f"usv-station: warning: {problem}")
    failed: list[str] = []

    async def run() -> None:
        try:
            await station.start()  # here, not in the lifespan: a failure is one line
        except Exception as exc:
            failed.append(_one_line(exc))
            with contextlib.suppress(Exception):
                await station.stop()
            return
        task = asyncio.create_task(server.serve(sockets=[sock]))
        while not server.started and not task.done():
            await asyncio.sleep(0.05)
        if server.started:
            # Everything start-up built lives as long as the station: out of the collector's
            # sight, a full collection no longer walks it (it held the loop ~100 ms). No
            # gc.collect() first: that walk would itself hold the loop ~70 ms.
            gc.freeze()
            announce(f"usv-station: 3D view http://127.0.0.1:{station.view.port}/ "
                     f"(loopback only; browsers use {console_url(settings, '')}3d/)")
            announce(f"usv-station: console {console_url(settings, station.token)}")
        await task

    asyncio.run(run())
    if failed:
        raise StartError(f"cannot start: {failed[0]}")
    return 0 if server.started else 1


def _host(settings: Settings) -> str:
    host = "127.0.0.1" if settings.host in ("0.0.0.0", "::", "") else settings.host
    return f"[{host}]" if ":" in host else host
