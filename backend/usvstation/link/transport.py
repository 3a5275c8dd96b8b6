"""Byte transports for usv-link: serial ports and pyserial URLs (pyserial-asyncio), UDP
(`udp://HOST:PORT` to a vehicle, `udpin://HOST:PORT` to listen for one), a
pseudo-terminal pair, an in-memory pipe (simulated time) and a fault-injecting,
line-rate-pacing wrapper.

All of them are `ByteStream`s: `await read()` returns the next bytes (b"" once closed),
`await write(data)` queues bytes, `await close()`.
"""

from __future__ import annotations

import asyncio
import contextlib
import os
import tty
from typing import Protocol

import numpy as np

from usvstation.clock import REAL_CLOCK, Clock
from usvstation.link.wire import split_frames


class ByteStream(Protocol):
    async def read(self) -> bytes: ...

    async def write(self, data: bytes) -> None: ...

    async def close(self) -> None: ...


class SerialStream:
    """A serial device (/dev/ttyUSB0, /dev/pts/N) or pyserial URL (socket://host:port)."""

    def __init__(self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        self._reader, self._writer = reader, writer

    @classmethod
    async def open(cls, url: str, baud: int = 57600) -> SerialStream:
        import serial_asyncio

        reader, writer = await serial_asyncio.open_serial_connection(url=url, baudrate=baud)
        return cls(reader, writer)

    async def read(self) -> bytes:
        try:
            return await self._reader.read(4096)
        except (OSError, ConnectionError) as exc:  # pyserial raises SerialException(OSError)
            raise ConnectionError(str(exc)) from exc

    async def write(self, data: bytes) -> None:
        if self._writer.is_closing():
            raise ConnectionError("the port is closed")
        self._writer.write(data)
        await self._writer.drain()

    async def close(self) -> None:
        self._writer.close()
        with contextlib.suppress(Exception):
            await self._writer.wait_closed()


class PtyPair:
    """A pseudo-terminal pair in raw mode: `master_fd` for the boat side, `slave_path` is a
    serial device the station opens like a real port. The slave stays open here so the
    station can close and reopen it (reconnect) without destroying the pair."""

    def __init__(self) -> None:
        self.master_fd, self._slave_fd = os.openpty()
        tty.setraw(self._slave_fd)
        tty.setraw(self.master_fd)
        os.set_blocking(self.master_fd, False)
        self.slave_path = os.ttyname(self._slave_fd)

    def master_stream(self, max_backlog: int = 4096) -> FdStream:
        return FdStream(self.master_fd, max_backlog=max_backlog, owns_fd=False)

    def close(self) -> None:
        for fd in (self.master_fd, self._slave_fd):
            with contextlib.suppress(OSError):
                os.close(fd)


class FdStream:
    """A non-blocking file descriptor (a pty master) on the event loop.

    Like a radio, it never blocks the writer: when the far side does not read and more
    than `max_backlog` bytes wait, the oldest are dropped (counted in `dropped`)."""

    def __init__(self, fd: int, *, max_backlog: int = 4096, owns_fd: bool = True) -> None:
        self.fd = fd
        self.max_backlog = max_backlog
        self.owns_fd = owns_fd
        self.dropped = 0
        self._loop = asyncio.get_running_loop()
        self._rx: asyncio.Queue[bytes] = asyncio.Queue()
        self._tx = bytearray()
        self._closed = False
        os.set_blocking(fd, False)
        self._loop.add_reader(fd, self._on_readable)

    def _on_readable(self) -> None:
        try:
            data = os.read(self.fd, 65536)
        except BlockingIOError:
            return
        except OSError:  # EIO: no process has the slave open; poll again shortly
            self._loop.remove_reader(self.fd)
            self._loop.call_later(0.05, self._rearm)
            return
        if data:
            self._rx.put_nowait(data)

    def _rearm(self) -> None:
        if not self._closed:
            self._loop.add_reader(self.fd, self._on_readable)

    async def read(self) -> bytes:
        if self._closed:
            return b""
        data = await self._rx.get()
        return data

    async def write(self, data: bytes) -> None:
        if self._closed:
            raise ConnectionError("closed")
        self._tx += data
        if len(self._tx) > self.max_backlog:
            cut = len(self._tx) - self.max_backlog
            self.dropped += cut
            del self._tx[:cut]
        self._flush()

    def _flush(self) -> None:
        while self._tx:
            try:
                n = os.write(self.fd, self._tx)
            except BlockingIOError:
                n = 0
            except OSError:
                self.dropped += len(self._tx)
                self._tx.clear()
                return
            if n == 0:
                self._loop.call_later(0.005, self._flush)
                return
            del self._tx[:n]

    async def close(self) -> None:
        if self._closed:
            return
        self._closed = True
        self._loop.remove_reader(self.fd)
        self._rx.put_nowait(b"")
        if self.owns_fd:
            with contextlib.suppress(OSError):
                os.close(self.fd)


class PipeEnd:
    """One end of a `MemoryPipe`."""

    def __init__(self, rx: asyncio.Queue[bytes], tx: asyncio.Queue[bytes]) -> None:
        self._rx, self._tx = rx, tx
        self.closed = False

    async def read(self) -> bytes:
        if self.closed:
            return b""
        return await self._rx.get()

    async def write(self, data: bytes) -> None:
        if self.closed:
            raise ConnectionError("closed")
        if data:
            self._tx.put_nowait(bytes(data))

    async def close(self) -> None:
        if not self.closed:
            self.closed = True
            self._rx.put_nowait(b"")  # wakes our own reader
            self._tx.put_nowait(b"")  # the far end reads end-of-stream


class MemoryPipe:
    """Two ByteStreams joined back to back in memory: what the station writes on `station`
    the boat reads on `boat`, and back. Nothing waits on a file descriptor, so both sides
    run on a virtual-time loop (clock.py); wrap an end in FaultInjectingStream for airtime,
    loss and radio silence."""

    def __init__(self) -> None:
        to_boat: asyncio.Queue[bytes] = asyncio.Queue()
        to_station: asyncio.Queue[bytes] = asyncio.Queue()
        self.station = PipeEnd(to_station, to_boat)
        self.boat = PipeEnd(to_boat, to_station)


class FaultInjectingStream:
    """Wraps a ByteStream's writes like a radio link: drops whole MAVLink 2 frames with
    probability `loss`, flips each bit with probability `ber`, and paces the bytes at `baud`
    (10 bits a byte, as 8N1) through a transmit queue, so bandwidth and queueing are real.

    `enabled = False` is the radio switched off: everything written is lost. Counters:
    frames_sent, frames_dropped, bits_flipped, bytes_on_wire."""

    def __init__(self, inner: ByteStream, *, loss: float = 0.0, ber: float = 0.0,
                 baud: int | None = None, seed: int = 0, clock: Clock = REAL_CLOCK) -> None:
        if not 0 <= loss <= 1 or not 0 <= ber < 1:
            raise ValueError(f"loss must be in [0, 1] and ber in [0, 1), got {loss}, {ber}")
        self.inner, self.clock = inner, clock
        self.loss, self.ber, self.baud = loss, ber, baud
        self.enabled = True
        self.rng = np.random.default_rng(seed)
        self.frames_sent = self.frames_dropped = self.bits_flipped = self.bytes_on_wire = 0
        self._queue: asyncio.Queue[bytes] = asyncio.Queue()
        self._pump = asyncio.get_running_loop().create_task(self._send_paced())
        self._line_free_at = 0.0

    async def read(self) -> bytes:
        return await self.inner.read()

    async def write(self, data: bytes) -> None:
        if not self.enabled:
            return
        out = bytearray()
        for frame in split_frames(data):
            if self.loss and self.rng.random() < self.loss:
                self.frames_dropped += 1
                continue
            self.frames_sent += 1
            out += frame
        if self.ber and out:
            flips = self.rng.binomial(len(out) * 8, self.ber)
            for pos in self.rng.integers(0, len(out) * 8, flips):
                out[pos // 8] ^= 1 << (pos % 8)
            self.bits_flipped += int(flips)
        if out:
            self._queue.put_nowait(bytes(out))

    async def _send_paced(self) -> None:
        chunk = 16
        while True:
            data = await self._queue.get()
            for i in range(0, len(data), chunk):
                piece = data[i : i + chunk]
                if self.baud:
                    now = self.clock.now()
                    start = max(now, self._line_free_at)
                    self._line_free_at = start + len(piece) * 10 / self.baud
                    if start > now:
                        await self.clock.sleep(start - now)
                try:
                    await self.inner.write(piece)
                except ConnectionError:
                    break
                self.bytes_on_wire += len(piece)

    async def close(self) -> None:
        self._pump.cancel()
        with contextlib.suppress(asyncio.CancelledError):
            await self._pump
        await self.inner.close()


class UdpStream:
    """MAVLink over UDP, one datagram per write. `udp://HOST:PORT`: send to the vehicle at
    HOST:PORT from an ephemeral port (MAVSDK's `udpin://`, a companion's router);
    `udpin://HOST:PORT`: listen there and answer whoever sent last (ArduPilot SITL's and
    most autopilots' `udpout` to a ground station, port 14550 by convention)."""

    def __init__(self) -> None:
        self._rx: asyncio.Queue[bytes] = asyncio.Queue()
        self._transport: asyncio.DatagramTransport | None = None
        self.peer: tuple[str, int] | None = None
        self.closed = False

    @classmethod
    async def open(cls, url: str) -> UdpStream:
        scheme, _, rest = url.partition("://")
        host, _, port = rest.rpartition(":")
        if scheme not in ("udp", "udpin") or not host or not port.isdigit():
            raise ValueError(f"{url!r}: expected udp://HOST:PORT or udpin://HOST:PORT")
        self = cls()
        loop = asyncio.get_running_loop()
        protocol = _Datagrams(self)
        if scheme == "udp":
            self.peer = (host, int(port))
            transport, _ = await loop.create_datagram_endpoint(lambda: protocol,
                                                               remote_addr=self.peer)
        else:
            transport, _ = await loop.create_datagram_endpoint(lambda: protocol,
                                                               local_addr=(host, int(port)))
        self._transport = transport
        return self

    async def read(self) -> bytes:
        if self.closed:
            return b""
        return await self._rx.get()

    async def write(self, data: bytes) -> None:
        if self.closed or self._transport is None:
            raise ConnectionError("closed")
        if self.peer is None:
            return  # listening, and nobody has spoken yet
        for frame in split_frames(data):  # one frame a datagram, as MAVLink routers send
            if self._transport.get_extra_info("peername") is not None:
                self._transport.sendto(frame)
            else:
                self._transport.sendto(frame, self.peer)

    async def close(self) -> None:
        if not self.closed:
            self.closed = True
            if self._transport is not None:
                self._transport.close()
            self._rx.put_nowait(b"")


class _Datagrams(asyncio.DatagramProtocol):
    def __init__(self, stream: UdpStream) -> None:
        self.stream = stream

    def datagram_received(self, data: bytes, addr: tuple[str, int]) -> None:
        if data:
            self.stream.peer = self.stream.peer if self.stream._transport is not None and \
                self.stream._transport.get_extra_info("peername") is not None else addr
            self.stream._rx.put_nowait(data)

    def error_received(self, exc: Exception) -> None:
        pass  # ICMP port unreachable while the vehicle is not up yet: it comes back


async def open_stream(url: str, baud: int = 57600) -> ByteStream:
    """Open a serial device, a pyserial URL (socket://host:port: TCP) or a UDP URL
    (udp://HOST:PORT, udpin://HOST:PORT) as a ByteStream."""
    if url.startswith(("udp://", "udpin://")):
        return await UdpStream.open(url)
    return await SerialStream.open(url, baud)
