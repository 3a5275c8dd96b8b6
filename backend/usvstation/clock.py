"""One clock for the whole station (shared/DESIGN.md principle 7, docs/design.md "Clock").

Every service, the boat link, the world, the monitor, the simulated boat and the simulated
sea read the time from the `Clock` they are given, and wait through it; nothing below the
entry points reads the wall clock or sleeps directly (a ruff rule enforces it).

- `RealClock`: the wall clock (`usv-station serve`, `sim`, `hil`).
- `SimClock` on a `VirtualTimeLoop`: simulated time. The loop is an ordinary asyncio
  selector loop whose `time()` is virtual: when no callback is ready and nothing runs in a
  thread, it jumps straight to its next timer instead of waiting. A whole recovery then
  runs as fast as the CPU allows, and the same every time: its order of events depends
  only on the timers, never on how busy the machine is. Work handed to a thread
  (`asyncio.to_thread`, `run_in_executor`) runs inline instead, at once: the virtual time
  does not move and nothing else runs meanwhile (a real thread would finish at a moment
  the machine's load decides, and so reorder what happens at one simulated instant).
  Real sockets or pipes are not watched for in simulated time: simulated parts talk over
  in-memory streams (`link.transport.MemoryPipe`).
- `ManualClock`: a clock a test or a stepped bench advances by hand.
- `Stopwatch`, `pause`: real time for what benchmarks measure and their load generators.

`run_simulated(main)` runs a coroutine function on a fresh virtual loop, like
`asyncio.run`.
"""

from __future__ import annotations

import asyncio
import datetime as dt
import selectors
import time
from collections.abc import Awaitable, Callable, Coroutine
from concurrent.futures import Executor
from typing import Any, Protocol, TypeVar

T = TypeVar("T")

SIM_EPOCH = 1_767_225_600.0  # 2026-01-01T00:00:00Z: the default unix time of simulated t = 0
IDLE_POLL_S = 0.05  # real time a virtual loop with no timer waits for real I/O


class Clock(Protocol):
    """What every part of the station reads the time from."""

    def now(self) -> float:
        """Monotonic seconds (differences only)."""
        ...

    def unix(self) -> float:
        """Seconds since the Unix epoch (timestamps, MAVLink signing)."""
        ...

    async def sleep(self, seconds: float) -> None:
        """Wait `seconds` of this clock's time (asyncio, on the running loop)."""
        ...


def utc_iso(unix: float) -> str:
    """`unix` as an ISO-8601 UTC timestamp with milliseconds, e.g. 2026-01-01T00:00:00.000Z."""
    stamp = dt.datetime.fromtimestamp(unix, dt.UTC)
    return stamp.strftime("%Y-%m-%dT%H:%M:%S.") + f"{stamp.microsecond // 1000:03d}Z"


class RealClock:
    """The wall clock."""

    def now(self) -> float:
        return time.monotonic()

    def unix(self) -> float:
        return time.time()

    async def sleep(self, seconds: float) -> None:
        await asyncio.sleep(seconds)

    def __repr__(self) -> str:
        return "RealClock()"


REAL_CLOCK = RealClock()


class Stopwatch:
    """Elapsed wall time and this process's CPU time since it was made: for the figures
    benchmarks and campaigns report, never for what decides an outcome."""

    def __init__(self) -> None:
        self.t0, self.c0 = time.perf_counter(), time.process_time()

    def elapsed(self) -> float:
        return time.perf_counter() - self.t0

    def cpu(self) -> float:
        return time.process_time() - self.c0


def pause(seconds: float) -> None:
    """Block this thread for `seconds` of real time (benchmark load generators only)."""
    time.sleep(seconds)


class ManualClock:
    """A clock that moves only when told to (`advance`, `set`): for stepped simulations and
    unit tests that drive a sans-IO part with explicit times. `sleep` advances it."""

    def __init__(self, start: float = 0.0, epoch: float = SIM_EPOCH) -> None:
        self.t = float(start)
        self.epoch = epoch

    def now(self) -> float:
        return self.t

    def unix(self) -> float:
        return self.epoch + self.t

    def advance(self, seconds: float) -> float:
        if seconds < 0:
            raise ValueError(f"a clock does not go back ({seconds} s)")
        self.t += seconds
        return self.t

    def set(self, t: float) -> None:
        self.advance(t - self.t)

    async def sleep(self, seconds: float) -> None:
        self.advance(max(seconds, 0.0))
        await asyncio.sleep(0)


class _VirtualSelector(selectors.BaseSelector):
    """The loop's selector: polls the real one without waiting, and where the loop would
    wait for its next timer, moves the virtual clock there instead."""

    def __init__(self, loop: VirtualTimeLoop, real: selectors.BaseSelector) -> None:
        self._loop, self._real = loop, real

    def register(self, fileobj, events, data=None):  # type: ignore[no-untyped-def]
        return self._real.register(fileobj, events, data)

    def unregister(self, fileobj):  # type: ignore[no-untyped-def]
        return self._real.unregister(fileobj)

    def modify(self, fileobj, events, data=None):  # type: ignore[no-untyped-def]
        return self._real.modify(fileobj, events, data)

    def get_key(self, fileobj):  # type: ignore[no-untyped-def]
        return self._real.get_key(fileobj)

    def get_map(self):  # type: ignore[no-untyped-def]
        return self._real.get_map()

    def close(self) -> None:
        self._real.close()

    def select(self, timeout: float | None = None):  # type: ignore[no-untyped-def]
        events = self._real.select(0)
        if events or timeout == 0:
            return events
        if timeout is None:  # nothing scheduled: only real I/O (or another thread) can wake us
            return self._real.select(IDLE_POLL_S)
        self._loop.advance(timeout)
        return []


class VirtualTimeLoop(asyncio.SelectorEventLoop):
    """An asyncio loop on simulated time (see the module's docstring)."""

    def __init__(self, start: float = 0.0) -> None:
        self._virtual_time = float(start)
        super().__init__(selectors.DefaultSelector())
        self._selector = _VirtualSelector(self, self._selector)

    def time(self) -> float:
        return self._virtual_time

    def advance(self, seconds: float) -> None:
        """Move the virtual clock forward (the loop does this itself while idle)."""
        if seconds > 0:
            self._virtual_time += seconds

    def run_in_executor(self, executor: Executor | None, func: Callable[..., T],
                        *args: Any) -> asyncio.Future[T]:
        """`func(*args)` at once, on this thread: the result is the same whatever the machine
        is doing (see the module's docstring)."""
        fut: asyncio.Future[T] = self.create_future()
        try:
            fut.set_result(func(*args))
        except Exception as exc:  # handed to the awaiting coroutine, as a thread's would be
            fut.set_exception(exc)
        return fut


class SimClock:
    """Simulated time: the running virtual loop's time; `unix()` counts from `epoch`."""

    def __init__(self, loop: VirtualTimeLoop, epoch: float = SIM_EPOCH) -> None:
        self.loop, self.epoch = loop, epoch

    def now(self) -> float:
        return self.loop.time()

    def unix(self) -> float:
        return self.epoch + self.loop.time()

    async def sleep(self, seconds: float) -> None:
        await asyncio.sleep(seconds)

    def __repr__(self) -> str:
        return f"SimClock(t={self.loop.time():.3f})"


def run_simulated(main: Callable[[SimClock], Coroutine[Any, Any, T]], *,
                  epoch: float = SIM_EPOCH) -> T:
    """Run `main(clock)` to completion on a new virtual-time loop (like `asyncio.run`)."""
    loop_box: list[VirtualTimeLoop] = []

    def factory() -> VirtualTimeLoop:
        loop_box.append(VirtualTimeLoop())
        return loop_box[0]

    with asyncio.Runner(loop_factory=factory) as runner:
        return runner.run(_with_clock(main, loop_box, epoch))


async def _with_clock(main: Callable[[SimClock], Awaitable[T]], loop_box: list[VirtualTimeLoop],
                      epoch: float) -> T:
    return await main(SimClock(loop_box[0], epoch))
