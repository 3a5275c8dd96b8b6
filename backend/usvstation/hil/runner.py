"""Run the firmware in QEMU with its HIL bridge and serve its radio (`usv-station hil`).

QEMU's USART1 and USART2 connect to two Unix sockets this process listens on (so nothing
races QEMU for a port): USART2 goes to the HilBridge, USART1 is relayed to the station's
side, a TCP port on 127.0.0.1 (one client at a time; a new one replaces the old, as a
restarted station would) or a new pseudo-terminal. Bytes of the boat nobody listens to are
dropped, as a radio's. The run ends when `stop` is set, QEMU exits or its HIL link closes;
QEMU is then ended by its pid (and dies with this process if it is killed)."""

from __future__ import annotations

import asyncio
import contextlib
import ctypes
import os
import signal
import tempfile
from collections.abc import Awaitable, Callable
from dataclasses import dataclass, replace
from pathlib import Path

from usvstation.hil.bridge import HilBridge
from usvstation.hil.provision import Provision
from usvstation.hil.qemu import QemuCommand
from usvstation.link.transport import FdStream, PtyPair

CONNECT_TIMEOUT_S = 30.0  # QEMU connecting its two UARTs (a loaded machine)
CLIENT_BACKLOG = 1 << 16  # bytes waiting for a slow TCP client before the boat's are dropped
PR_SET_PDEATHSIG = 1


class HilError(RuntimeError):
    """QEMU did not start or the port cannot be served (one line for the operator)."""


@dataclass(frozen=True)
class HilRun:
    image: Path
    provision: Provision
    port: int | None = None  # TCP port on 127.0.0.1 (0: any free); None: a new pty
    monitor: Path | None = None  # the QEMU monitor on this Unix socket


async def run_hil(run: HilRun, bridge: HilBridge, *, unix_time: Callable[[], float],
                  announce: Callable[[str], None], log: Callable[[str], None],
                  stop: asyncio.Event) -> str:
    """Serve until stopped or QEMU ends; returns why the run ended."""
    with tempfile.TemporaryDirectory(prefix="usv-hil-") as tmp:
        work = Path(tmp)
        provision = run.provision  # without a page image file of its own: one for this run
        if not provision.nv_path:
            provision = replace(provision, nv_path=str(work / "nv.bin"))
        config = work / "provision.bin"
        config.write_bytes(provision.to_bytes())
        nv = Path(provision.nv_path)
        qemu = QemuCommand(run.image, config, work / "radio.sock", work / "hil.sock", nv,
                           run.monitor)
        links: dict[str, asyncio.Future] = {
            k: asyncio.get_running_loop().create_future() for k in ("radio", "hil")}
        servers = [await asyncio.start_unix_server(_accept_once(links[k]), path=str(p))
                   for k, p in (("radio", qemu.radio_socket), ("hil", qemu.hil_socket))]
        side = await _StationSide.open(run.port)  # a port in use fails before QEMU starts
        try:
            return await _run_qemu(qemu, links, side, bridge, unix_time, announce, log, stop)
        finally:
            await side.close()
            for s in servers:
                s.close()


async def _run_qemu(qemu: QemuCommand, links: dict[str, asyncio.Future], side: _StationSide,
                    bridge: HilBridge, unix_time: Callable[[], float],
                    announce: Callable[[str], None], log: Callable[[str], None],
                    stop: asyncio.Event) -> str:
    proc = await asyncio.create_subprocess_exec(
        *qemu.argv(), stdin=asyncio.subprocess.DEVNULL,
        stdout=asyncio.subprocess.PIPE, stderr=asyncio.subprocess.STDOUT,
        preexec_fn=_die_with_parent)
    try:
        qemu_out = asyncio.create_task(_lines(proc.stdout, lambda s: log(f"qemu: {s}")))
        await _connected(links, proc)
        radio_r, side.to_boat = links["radio"].result()
        hil_r, hil_w = links["hil"].result()
        announce(side.where)
        tasks = {
            asyncio.create_task(_bridge(hil_r, hil_w, bridge, unix_time)): "HIL link closed",
            asyncio.create_task(side.from_boat(radio_r)): "radio link closed",
            asyncio.create_task(proc.wait()): "QEMU exited",
            asyncio.create_task(stop.wait()): "stopped",
        }
        try:
            done, _ = await asyncio.wait(tasks, return_when=asyncio.FIRST_COMPLETED)
            return tasks[next(iter(done))]
        finally:
            for t in tasks:
                t.cancel()
            qemu_out.cancel()
    finally:
        await _end(proc)


def _accept_once(slot: asyncio.Future) -> Callable[..., Awaitable[None]]:
    async def accept(reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        if slot.done():
            writer.close()
        else:
            slot.set_result((reader, writer))

    return accept


async def _connected(links: dict[str, asyncio.Future], proc: asyncio.subprocess.Process) -> None:
    """Wait for QEMU to connect both UARTs; HilError if it exits or takes too long."""
    exited = asyncio.ensure_future(proc.wait())
    pending = set(links.values())
    try:
        async with asyncio.timeout(CONNECT_TIMEOUT_S):
            while pending and not exited.done():
                done, _ = await asyncio.wait(pending | {exited},
                                             return_when=asyncio.FIRST_COMPLETED)
                pending -= done
    except TimeoutError:
        raise HilError(f"QEMU did not connect the boat's UARTs in {CONNECT_TIMEOUT_S:g} s") \
            from None
    finally:
        exited.cancel()
    if pending:
        raise HilError(f"QEMU exited with status {proc.returncode} before the boat's UARTs "
                       "connected (its output is above)")


async def _bridge(reader: asyncio.StreamReader, writer: asyncio.StreamWriter, bridge: HilBridge,
                  unix_time: Callable[[], float]) -> None:
    while data := await reader.read(4096):
        out = bridge.receive(data, unix_time())
        if out:
            writer.write(out)


async def _lines(stream: asyncio.StreamReader | None, log: Callable[[str], None]) -> None:
    if stream is None:
        return
    while line := await stream.readline():
        log(line.decode(errors="replace").rstrip())


async def _end(proc: asyncio.subprocess.Process) -> None:
    if proc.returncode is None:
        with contextlib.suppress(ProcessLookupError):
            proc.terminate()
        try:
            await asyncio.wait_for(proc.wait(), 10.0)
        except TimeoutError:
            with contextlib.suppress(ProcessLookupError):
                proc.kill()
            await proc.wait()


def _die_with_parent() -> None:
    """In the QEMU child before exec: SIGTERM when this process dies (Linux)."""
    with contextlib.suppress(OSError, AttributeError):
        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGTERM)


class _StationSide:
    """The station's end of the radio: a TCP port on 127.0.0.1 or a new pty."""

    def __init__(self) -> None:
        self.to_boat: asyncio.StreamWriter | None = None  # QEMU's USART1, once connected
        self.where = ""
        self.server: asyncio.Server | None = None
        self.client: asyncio.StreamWriter | None = None
        self.pty: PtyPair | None = None
        self._pty_stream: FdStream | None = None
        self._pty_task: asyncio.Task | None = None

    @classmethod
    async def open(cls, port: int | None) -> _StationSide:
        side = cls()
        if port is None:
            side.pty = PtyPair()
            stream = side.pty.master_stream()
            side._pty_stream = stream
            side._pty_task = asyncio.create_task(side._pump_pty(stream))
            side.where = side.pty.slave_path
            return side
        try:
            side.server = await asyncio.start_server(side._on_client, "127.0.0.1", port)
        except OSError as exc:
            why = os.strerror(exc.errno) if exc.errno else str(exc)
            raise HilError(f"cannot listen on 127.0.0.1:{port}: {why}") from None
        bound = side.server.sockets[0].getsockname()[1]
        side.where = f"127.0.0.1:{bound}"
        return side

    async def _on_client(self, reader: asyncio.StreamReader,
                         writer: asyncio.StreamWriter) -> None:
        old, self.client = self.client, writer
        if old is not None:
            old.close()
        try:
            while data := await reader.read(4096):
                await self._to_boat(data)
        except (ConnectionError, OSError):
            pass
        finally:
            if self.client is writer:
                self.client = None
            writer.close()

    async def _pump_pty(self, stream: FdStream) -> None:
        while data := await stream.read():
            await self._to_boat(data)

    async def _to_boat(self, data: bytes) -> None:
        if self.to_boat is not None:  # before QEMU connected: into the air
            self.to_boat.write(data)
            await self.to_boat.drain()

    async def from_boat(self, reader: asyncio.StreamReader) -> None:
        """The boat's bytes to whoever listens (dropped when nobody does or cannot keep up)."""
        while data := await reader.read(4096):
            if self._pty_stream is not None:
                await self._pty_stream.write(data)
            elif self.client is not None and not self.client.is_closing() and \
                    self.client.transport.get_write_buffer_size() < CLIENT_BACKLOG:
                self.client.write(data)

    async def close(self) -> None:
        if self._pty_task is not None:
            self._pty_task.cancel()
        if self._pty_stream is not None:
            await self._pty_stream.close()
        if self.client is not None:
            self.client.close()
        if self.server is not None:
            self.server.close()
        if self.pty is not None:
            self.pty.close()
