"""The clock: simulated time jumps to the next timer, stands still while work handed to a
thread runs (inline, at once), and orders events by their simulated instants alone."""

from __future__ import annotations

import asyncio
import threading

import pytest
from hypothesis import given
from hypothesis import strategies as st

from usvstation.clock import ManualClock, SimClock, run_simulated, utc_iso


@given(st.lists(st.lists(st.floats(0.001, 50.0), min_size=1, max_size=8), min_size=1,
                max_size=6))
def test_tasks_wake_in_the_order_of_their_simulated_instants(plans):
    """Each task sleeps its list of delays; every wake-up happens exactly at the sum of the
    delays so far, and the wake-ups come in time order, whatever the machine does."""

    async def main(clock: SimClock) -> tuple[list, float]:
        woke: list[tuple[float, float]] = []

        async def task(delays: list[float]) -> None:
            due = 0.0
            for d in delays:
                await clock.sleep(d)
                due += d
                woke.append((clock.now(), due))

        await asyncio.gather(*(task(p) for p in plans))
        return woke, clock.now()

    woke, end = run_simulated(main)
    assert [t for t, _ in woke] == sorted(t for t, _ in woke)
    for t, due in woke:
        assert t == pytest.approx(due, abs=1e-9 * max(1.0, due))
    assert end == pytest.approx(max(sum(p) for p in plans), rel=1e-9)


def test_time_stands_still_while_work_handed_to_a_thread_runs():
    started = threading.Event()

    async def main(clock: SimClock) -> tuple[float, float, int]:
        ticks = 0

        async def ticker() -> None:
            nonlocal ticks
            while True:
                await clock.sleep(0.01)
                ticks += 1

        task = asyncio.get_running_loop().create_task(ticker())
        await clock.sleep(0.1)
        before, ticks_before = clock.now(), ticks

        def work() -> None:
            started.set()
            threading.Event().wait(0.2)  # 0.2 s of real work

        await asyncio.to_thread(work)
        assert await asyncio.to_thread(lambda: 7) == 7
        with pytest.raises(ZeroDivisionError):
            await asyncio.to_thread(lambda: 1 / 0)
        after = clock.now()
        task.cancel()
        return before, after, ticks - ticks_before

    before, after, ticks = run_simulated(main)
    assert started.is_set() and after == before and ticks == 0


def test_timeouts_run_on_simulated_time():
    async def main(clock: SimClock) -> float:
        with pytest.raises(TimeoutError):
            await asyncio.wait_for(asyncio.Event().wait(), 3600.0)
        return clock.now()

    assert run_simulated(main) == pytest.approx(3600.0)


def test_unix_time_counts_from_the_epoch():
    async def main(clock: SimClock) -> str:
        await clock.sleep(90.5)
        return utc_iso(clock.unix())

    assert run_simulated(main) == "2026-01-01T00:01:30.500Z"


def test_manual_clock_moves_only_when_told():
    clock = ManualClock(10.0)
    assert clock.now() == 10.0
    clock.advance(2.5)
    clock.set(20.0)
    assert clock.now() == 20.0 and clock.unix() == clock.epoch + 20.0
    with pytest.raises(ValueError, match="does not go back"):
        clock.set(5.0)
