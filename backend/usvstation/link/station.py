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

Where it runs is the caller's choice, through a `LinkHost`: `SameLoop` (the caller's own
loop: simulated time, tests) or `LinkThread` (a thread of its own with its own event loop:
`usv-station serve`, so nothing the web API does can delay a heartbeat). Either way the
services reach it through `LinkHost.call` (a request, run on the link's loop) and
`LinkHost.to_owner` (the link's events, handed back to the caller's loop in order).
`BoatLink.heartbeat_gap` is the link's own measure of how late it was: the worst interval
between two HEARTBEATs written to the port.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
import os
import threading
from collections import deque
from collections.abc import AsyncIterator, Awaitable, Callable, Coroutine
from typing import Any, Protocol, TypeVar

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
T = TypeVar("T")
log = logging.getLogger("usvstation.link")
GAP_WINDOW_S = 60.0  # "worst of the last minute"
LATE_FACTOR = 1.5  # a heartbeat interval over 1.5 periods (375 ms) is late: kept to be shown
LATE_KEPT = 20


class PeakMeter:
    """The largest value recorded in the last `window_s` and since the start; safe to read
    from any thread (one lock around a short deque of decreasing values)."""

    def __init__(self, window_s: float = GAP_WINDOW_S) -> None:
        self.window_s = window_s
        self.worst_ever = 0.0
        self.count = 0
        self._samples: deque[tuple[float, float]] = deque()  # (time, value), values decrease
        self._lock = threading.Lock()

    def record(self, now: float, value: float) -> None:
        with self._lock:
            self.count += 1
            self.worst_ever = max(self.worst_ever, value)
            samples = self._samples
            while samples and samples[0][0] < now - self.window_s:
                samples.popleft()
            while samples and samples[-1][1] <= value:
                samples.pop()
            samples.append((now, value))

    def worst_since(self, now: float) -> float:
        """The largest value recorded after `now - window_s` (0 when none)."""
        with self._lock:
            cutoff = now - self.window_s
            return next((v for t, v in self._samples if t >= cutoff), 0.0)


class LinkHost(Protocol):
    """Where a BoatLink runs, as its owner (the boat service, on its own loop) sees it."""

    async def start(self) -> None:
        """Ready to run the link (called on the owner's loop)."""
        ...

    async def stop(self) -> None:
        """Let the link's loop go (after the link closed)."""
        ...

    async def call(self, make: Callable[[], Coroutine[Any, Any, T]]) -> T:
        """Run the coroutine `make()` on the link's loop; its result on the owner's."""
        ...

    def post(self, fn: Callable[..., object], *args: object) -> None:
        """Call `fn(*args)` on the link's loop, soon (fire and forget)."""
        ...

    def to_owner(self, callback: Callable[..., object]) -> Callable[..., None]:
        """A function the link calls on its loop that calls `callback` on the owner's loop
        with the same arguments, in the order the link called it."""
        ...


class SameLoop:
    """The link on its owner's loop: everything is a direct call (simulated time, tests:
    one loop, one order of events)."""

    async def start(self) -> None:
        return None

    async def stop(self) -> None:
        return None

    async def call(self, make: Callable[[], Coroutine[Any, Any, T]]) -> T:
        return await make()

    def post(self, fn: Callable[..., object], *args: object) -> None:
        fn(*args)

    def to_owner(self, callback: Callable[..., object]) -> Callable[..., None]:
        def direct(*args: object) -> None:
            callback(*args)

        return direct


OUTBOX_MAX = 100_000  # events waiting for a stalled owner loop (then the oldest are dropped)


class LinkThread:
    """The link on a thread of its own with its own event loop (`usv-station serve`): the
    owner's loop may stall (a request body, a query, a fan-out) and the link still keeps
    its heartbeat schedule. Requests cross with `run_coroutine_threadsafe`; events come
    back through one outbox, drained on the owner's loop in the order they were put."""

    def __init__(self, name: str = "boat-link") -> None:
        self.name = name
        self.loop: asyncio.AbstractEventLoop | None = None
        self.dropped = 0  # events lost because the owner's loop did not drain the outbox
        self.nice: int | None = None  # the thread's nice value, when it could raise it
        self._owner: asyncio.AbstractEventLoop | None = None
        self._thread: threading.Thread | None = None
        self._outbox: deque[tuple[Callable[..., object], tuple[object, ...]]] = deque()
        self._lock = threading.Lock()
        self._drain_scheduled = False

    async def start(self) -> None:
        self.start_now()
        self.adopt_owner()

    def start_now(self) -> None:
        """Start the thread and its loop (from the owner's loop or before it runs)."""
        if self._thread is not None:
            return
        ready = threading.Event()

        def run() -> None:
            self.nice = _raise_priority()
            loop = asyncio.new_event_loop()
            asyncio.set_event_loop(loop)
            self.loop = loop
            ready.set()
            try:
                loop.run_forever()
            finally:
                for task in asyncio.all_tasks(loop):
                    task.cancel()
                with contextlib.suppress(Exception):
                    loop.run_until_complete(asyncio.gather(*asyncio.all_tasks(loop),
                                                           return_exceptions=True))
                loop.close()

        self._thread = threading.Thread(target=run, name=self.name, daemon=True)
        self._thread.start()
        ready.wait()

    def adopt_owner(self) -> None:
        """The running loop is the owner's: events go there, those that waited first."""
        self._owner = asyncio.get_running_loop()
        with self._lock:
            if not self._outbox or self._drain_scheduled:
                return
            self._drain_scheduled = True
        self._owner.call_soon(self._drain)

    async def stop(self) -> None:
        loop, thread = self.loop, self._thread
        if loop is None or thread is None:
            return
        with contextlib.suppress(RuntimeError):
            loop.call_soon_threadsafe(loop.stop)
        await asyncio.to_thread(thread.join, 10.0)
        self._thread = None

    async def call(self, make: Callable[[], Coroutine[Any, Any, T]]) -> T:
        assert self.loop is not None, "start() first"
        self._owner = self._owner or asyncio.get_running_loop()
        done = asyncio.run_coroutine_threadsafe(make(), self.loop)
        return await asyncio.wrap_future(done)

    def call_blocking(self, make: Callable[[], Coroutine[Any, Any, T]],
                      timeout: float | None = None) -> T:
        """`call` from a thread that runs no loop (start-up, before the owner's loop)."""
        assert self.loop is not None, "start() first"
        return asyncio.run_coroutine_threadsafe(make(), self.loop).result(timeout)

    def post(self, fn: Callable[..., object], *args: object) -> None:
        assert self.loop is not None, "start() first"
        with contextlib.suppress(RuntimeError):  # the loop already closed: nothing to do
            self.loop.call_soon_threadsafe(fn, *args)

    def to_owner(self, callback: Callable[..., object]) -> Callable[..., None]:
        def forward(*args: object) -> None:
            with self._lock:
                if len(self._outbox) >= OUTBOX_MAX:
                    self._outbox.popleft()
                    self.dropped += 1
                self._outbox.append((callback, args))
                if self._drain_scheduled or self._owner is None:
                    return
                self._drain_scheduled = True
            with contextlib.suppress(RuntimeError):  # the owner's loop closed
                self._owner.call_soon_threadsafe(self._drain)

        return forward

    def _drain(self) -> None:
        with self._lock:
            items = list(self._outbox)
            self._outbox.clear()
            self._drain_scheduled = False
        for callback, args in items:
            try:
                callback(*args)
            except Exception:  # one listener's fault never loses the others' events
                log.exception("link event handler failed")


LINK_NICE = -5  # the link's thread asks the OS for this priority (when it may: root,
# CAP_SYS_NICE or RLIMIT_NICE); the rest of the station keeps the default 0


def _raise_priority() -> int | None:
    """Raise this thread's scheduling priority (Linux: a thread's own nice value) so a busy
    machine delays the heartbeat less; the nice value obtained, None when not allowed."""
    if not hasattr(os, "setpriority") or not hasattr(threading, "get_native_id"):
        return None
    tid = threading.get_native_id()
    try:
        os.setpriority(os.PRIO_PROCESS, tid, LINK_NICE)
        return os.getpriority(os.PRIO_PROCESS, tid)
    except OSError:
        return None


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
        # the worst interval between two HEARTBEATs written to the port (while it is open)
        self.heartbeat_gap = PeakMeter()
        # the latest late ones (over LATE_FACTOR periods): (unix time written, interval s)
        self.late_heartbeats: deque[tuple[float, float]] = deque(maxlen=LATE_KEPT)
        self._heartbeat_mark = self.protocol.monitor.next_heartbeat
        self._heartbeat_written_at: float | None = None

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
        mark = self.protocol.monitor.next_heartbeat  # moves on when a HEARTBEAT is queued
        async with self._write_lock:
            try:
                await self.stream.write(data)
            except (ConnectionError, OSError) as exc:
                await self._close_stream(f"write failed: {exc}")
                return
        if mark != self._heartbeat_mark:
            self._heartbeat_mark = mark
            now = self._now()
            if self._heartbeat_written_at is not None:
                gap = now - self._heartbeat_written_at
                self.heartbeat_gap.record(now, gap)
                if gap > LATE_FACTOR * self.protocol.config.heartbeat_period_s:
                    self.late_heartbeats.append((self.clock.unix(), gap))
            self._heartbeat_written_at = now

    async def _close_stream(self, reason: str) -> None:
        stream, self.stream = self.stream, None
        self._heartbeat_written_at = None  # a closed port is no late heartbeat
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
