"""`BoatLink`: the station's asyncio service around the sans-IO StationProtocol.

    async with BoatLink("/dev/ttyUSB0", baud=57600) as link:
        await link.wait_link_up(5)
        result = await link.upload_mission(mission, progress_cb=print)
        outcome = await link.command("start", mission_id=mission.mission_id,
                                     mission_crc=mission.crc)
        async for event in link.events():   # TelemetryReceived, BoatReport, LinkDown, ...
            ...

It reconnects on its own: when the port closes or cannot be opened it retries every
`reconnect_s`, and the link comes up again with the paired boat's next HEARTBEAT.
"""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import AsyncIterator, Awaitable, Callable

from usvstation.clock import REAL_CLOCK, Clock
from usvstation.link.mission import Mission
from usvstation.link.protocol import (
    CommandOutcome,
    LinkConfig,
    LinkDown,
    LinkEvent,
    LinkUp,
    MissionState,
    ReadbackResult,
    StationProtocol,
    Telemetry,
    TelemetryReceived,
    UploadProgress,
    UploadResult,
)
from usvstation.link.transport import ByteStream, open_stream

StreamFactory = Callable[[], Awaitable[ByteStream]]


class LinkError(RuntimeError):
    """The request cannot be sent: link down or an upload/readback in progress."""


class BoatLink:
    """Station side of the boat link on the event loop; one instance per boat."""

    def __init__(self, url: str | None = None, *, baud: int = 57600,
                 stream_factory: StreamFactory | None = None,
                 config: LinkConfig | None = None, reconnect_s: float = 1.0,
                 key: bytes | None = None, session: int | None = None,
                 clock: Clock = REAL_CLOCK) -> None:
        if url is None and stream_factory is None:
            raise ValueError("BoatLink needs a url or a stream_factory")
        self.url = url
        self.clock = clock
        self._factory = stream_factory or (lambda: open_stream(url, baud))
        self.protocol = StationProtocol(config or LinkConfig(baud=baud), self._now(), key=key,
                                        unix_time=clock.unix(), session=session)
        self.reconnect_s = reconnect_s
        self.stream: ByteStream | None = None
        self._task: asyncio.Task | None = None
        self._write_lock = asyncio.Lock()
        self._subscribers: list[asyncio.Queue[LinkEvent]] = []
        self._callbacks: list[Callable[[LinkEvent], None]] = []
        self._uploads: dict[int, tuple[asyncio.Future, Callable | None]] = {}
        self._commands: dict[int, asyncio.Future] = {}
        self._readbacks: dict[int, asyncio.Future] = {}
        self._link_event = asyncio.Event()
        self.last_error = ""

    def _now(self) -> float:
        return self.clock.now()

    # ---- lifecycle
    async def start(self) -> None:
        if self._task is None:
            self._task = asyncio.get_running_loop().create_task(self._run())

    async def close(self) -> None:
        if self._task is not None:
            self._task.cancel()
            with contextlib.suppress(asyncio.CancelledError):
                await self._task
            self._task = None
        await self._close_stream("closed by the station")

    async def __aenter__(self) -> BoatLink:
        await self.start()
        return self

    async def __aexit__(self, *exc: object) -> None:
        await self.close()

    async def disconnect(self) -> None:
        """Close the port now (it is reopened after reconnect_s), e.g. to free the device."""
        await self._close_stream("port closed by the station")

    # ---- state
    @property
    def link_up(self) -> bool:
        return self.protocol.link_up

    @property
    def report(self) -> MissionState | None:
        """The boat's last USV_MISSION_STATE."""
        return self.protocol.report

    @property
    def telemetry(self) -> Telemetry | None:
        return self.protocol.telemetry

    @property
    def signed(self) -> bool:
        return self.protocol.codec.signed

    async def wait_link_up(self, timeout: float | None = None) -> bool:
        """True once the link is up; False after `timeout` seconds."""
        with contextlib.suppress(TimeoutError):
            await asyncio.wait_for(self._link_event.wait(), timeout)
        return self.link_up

    # ---- events
    def events(self, maxsize: int = 1000) -> AsyncIterator[LinkEvent]:
        """Every event (TelemetryReceived, BoatReport, BoatRebooted, LinkUp, LinkDown,
        StatusTextReceived, UploadProgress, UploadResult, ReadbackResult, CommandOutcome).
        A slow consumer loses its oldest events, never blocks the link."""
        queue: asyncio.Queue[LinkEvent] = asyncio.Queue(maxsize)
        self._subscribers.append(queue)

        async def gen() -> AsyncIterator[LinkEvent]:
            try:
                while True:
                    yield await queue.get()
            finally:
                self._subscribers.remove(queue)

        return gen()

    async def telemetry_stream(self) -> AsyncIterator[Telemetry]:
        async for ev in self.events():
            if isinstance(ev, TelemetryReceived):
                yield ev.telemetry

    def add_listener(self, callback: Callable[[LinkEvent], None]) -> None:
        """Call `callback(event)` on the event loop for every event."""
        self._callbacks.append(callback)

    def _dispatch(self, events: list[LinkEvent]) -> None:
        for ev in events:
            if isinstance(ev, LinkUp):
                self._link_event.set()
            elif isinstance(ev, LinkDown):
                self._link_event.clear()
            if isinstance(ev, UploadProgress | UploadResult):
                fut, cb = self._uploads.get(ev.mission_id, (None, None))
                if cb is not None and isinstance(ev, UploadProgress):
                    cb(ev)
                if fut is not None and isinstance(ev, UploadResult):
                    self._uploads.pop(ev.mission_id, None)
                    if not fut.done():
                        fut.set_result(ev)
            elif isinstance(ev, CommandOutcome):
                fut = self._commands.pop(ev.seq, None)
                if fut is not None and not fut.done():
                    fut.set_result(ev)
            elif isinstance(ev, ReadbackResult):
                fut = self._readbacks.pop(ev.mission_id, None)
                if fut is not None and not fut.done():
                    fut.set_result(ev)
            for cb in self._callbacks:
                cb(ev)
            for q in self._subscribers:
                if q.full():
                    q.get_nowait()
                q.put_nowait(ev)

    # ---- requests
    async def upload_mission(self, mission: Mission,
                             progress_cb: Callable[[UploadProgress], None] | None = None,
                             swap_at_ms: int = 0) -> UploadResult:
        """Upload a mission; returns when the boat acknowledged END (ok=True: activated, or
        the hot swap at boat uptime `swap_at_ms` scheduled) or the upload failed (ok=False
        with the reason; the boat never activates a partial mission)."""
        fut = asyncio.get_running_loop().create_future()
        try:
            self.protocol.start_upload(mission, self._now(), swap_at_ms)
        except RuntimeError as exc:
            raise LinkError(str(exc)) from None
        self._uploads[mission.mission_id] = (fut, progress_cb)
        await self._flush()
        return await fut

    async def read_mission(self, mission_id: int, count: int) -> ReadbackResult:
        """Read the boat's copy of a mission back, item by item."""
        fut = asyncio.get_running_loop().create_future()
        try:
            self.protocol.start_readback(mission_id, count, self._now())
        except RuntimeError as exc:
            raise LinkError(str(exc)) from None
        self._readbacks[mission_id] = fut
        await self._flush()
        return await fut

    async def command(self, name: str, mission_id: int = 0, mission_crc: int = 0
                      ) -> CommandOutcome:
        """Send start/hold/resume/abort; returns the boat's answer or, after the bounded
        retries, an outcome with result None (never waits for ever)."""
        fut = asyncio.get_running_loop().create_future()
        try:
            seq = self.protocol.send_command(name.lower(), self._now(), mission_id, mission_crc)
        except RuntimeError as exc:
            raise LinkError(str(exc)) from None
        self._commands[seq] = fut
        await self._flush()
        return await fut

    def boat_uptime_ms(self) -> int | None:
        return self.protocol.boat_uptime_ms(self._now())

    # ---- I/O loop
    async def _flush(self) -> None:
        data = self.protocol.data_to_send()
        if not data or self.stream is None:
            return
        async with self._write_lock:
            try:
                await self.stream.write(data)
            except (ConnectionError, OSError) as exc:
                await self._close_stream(f"write failed: {exc}")

    async def _close_stream(self, reason: str) -> None:
        stream, self.stream = self.stream, None
        if stream is not None:
            with contextlib.suppress(Exception):
                await stream.close()
            self._dispatch(self.protocol.connection_lost(reason, self._now()))

    async def _run(self) -> None:
        while True:
            try:
                self.stream = await self._factory()
            except (OSError, ConnectionError) as exc:
                self.last_error = f"cannot open {self.url}: {exc}"
                await self.clock.sleep(self.reconnect_s)
                continue
            reader = asyncio.get_running_loop().create_task(self._read_loop(self.stream))
            try:
                await self._timer_loop(reader)
            finally:
                reader.cancel()
                with contextlib.suppress(asyncio.CancelledError, Exception):
                    await reader
            await self._close_stream("port closed")
            await self.clock.sleep(self.reconnect_s)

    async def _read_loop(self, stream: ByteStream) -> None:
        while True:
            try:
                data = await stream.read()
            except (ConnectionError, OSError) as exc:
                self.last_error = str(exc)
                return
            if not data:
                return
            self._dispatch(self.protocol.receive_data(data, self._now()))
            await self._flush()

    async def _timer_loop(self, reader: asyncio.Task) -> None:
        while not reader.done() and self.stream is not None:
            self._dispatch(self.protocol.poll(self._now()))
            await self._flush()
            # requests flush their own bytes at once; this loop only serves timers
            await self.clock.sleep(min(max(self.protocol.next_deadline() - self._now(), 0.001),
                                    0.02))
