"""Line sources for ship inputs: UDP (the usual ship network), TCP clients and serial ports.

`parse_source` validates a `--nmea` URL; `run_source` reads lines from it until cancelled,
handing each to a callback with the bytes of one sentence. A TCP or serial source that
fails is reopened after a pause; nothing a source sends can stop the station.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
from collections.abc import Callable
from dataclasses import dataclass
from typing import Literal
from urllib.parse import parse_qs, urlsplit

from usvstation.clock import REAL_CLOCK, Clock

log = logging.getLogger(__name__)

NMEA_BAUD = 4800  # NMEA 0183; AIS transponders use 38400: serial:///dev/ttyUSB0?baud=38400
RETRY_S = 2.0
MAX_LINE = 1024  # NMEA lines are at most 82 characters; longer junk is cut


@dataclass(frozen=True)
class Source:
    kind: Literal["udp", "tcp", "serial"]
    host: str = ""
    port: int = 0
    device: str = ""
    baud: int = NMEA_BAUD

    def __str__(self) -> str:
        if self.kind == "serial":
            return f"serial://{self.device}?baud={self.baud}"
        return f"{self.kind}://{self.host}:{self.port}"


def parse_source(url: str) -> Source:
    """`udp://HOST:PORT`, `tcp://HOST:PORT`, `serial:///dev/ttyX?baud=N`, or a device path."""
    if url.startswith("/") or url.startswith("serial:"):
        parts = urlsplit(url) if url.startswith("serial:") else None
        device = parts.path if parts else url
        query = parse_qs(parts.query) if parts else {}
        try:
            baud = int(query.get("baud", [NMEA_BAUD])[0])
        except ValueError:
            raise ValueError(f"bad baud rate in {url!r}") from None
        if not device or baud <= 0:
            raise ValueError(f"expected serial:///dev/DEVICE?baud=N, got {url!r}")
        return Source("serial", device=device, baud=baud)
    parts = urlsplit(url)
    if parts.scheme not in ("udp", "tcp"):
        raise ValueError(f"expected udp://HOST:PORT, tcp://HOST:PORT or a serial device, "
                         f"got {url!r}")
    try:
        port = parts.port
    except ValueError:
        port = None
    if not parts.hostname or port is None:
        raise ValueError(f"{url!r} needs a host and a port")
    return Source(parts.scheme, host=parts.hostname, port=port)  # type: ignore[arg-type]


class _Lines:
    """Splits a byte stream into lines."""

    def __init__(self, on_line: Callable[[bytes], None]) -> None:
        self.on_line, self.buf = on_line, b""

    def feed(self, data: bytes) -> None:
        self.buf += data
        *lines, self.buf = self.buf.split(b"\n")
        if len(self.buf) > MAX_LINE:
            lines.append(self.buf)
            self.buf = b""
        for line in lines:
            if line.strip():
                self.on_line(line.strip()[:MAX_LINE])


class _Datagrams(asyncio.DatagramProtocol):
    def __init__(self, on_line: Callable[[bytes], None]) -> None:
        self.on_line = on_line

    def datagram_received(self, data: bytes, addr: object) -> None:
        for line in data.splitlines():
            if line.strip():
                self.on_line(line.strip()[:MAX_LINE])


async def open_udp(source: Source, on_line: Callable[[bytes], None]
                   ) -> tuple[asyncio.DatagramTransport, int]:
    """Listen for datagrams; returns the transport and the bound port (for port 0)."""
    loop = asyncio.get_running_loop()
    transport, _ = await loop.create_datagram_endpoint(
        lambda: _Datagrams(on_line), local_addr=(source.host, source.port))
    return transport, transport.get_extra_info("sockname")[1]  # type: ignore[return-value]


async def run_stream_source(source: Source, on_line: Callable[[bytes], None],
                            on_state: Callable[[str], None] = lambda _: None,
                            clock: Clock = REAL_CLOCK) -> None:
    """Read a TCP or serial source until cancelled, reopening it when it fails."""
    while True:
        lines = _Lines(on_line)
        try:
            if source.kind == "tcp":
                reader, writer = await asyncio.open_connection(source.host, source.port)
            else:
                import serial_asyncio

                reader, writer = await serial_asyncio.open_serial_connection(
                    url=source.device, baudrate=source.baud)
            on_state("open")
            try:
                while data := await reader.read(4096):
                    lines.feed(data)
            finally:
                writer.close()
                with contextlib.suppress(Exception):
                    await writer.wait_closed()
            on_state("closed")
        except (OSError, ConnectionError) as exc:
            on_state(f"error: {exc}")
            log.warning("nmea %s: %s", source, exc)
        await clock.sleep(RETRY_S)
