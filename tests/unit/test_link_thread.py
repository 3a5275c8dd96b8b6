"""Where the boat link runs (link/station.py LinkHost): its own thread and loop in `serve`
(LinkThread), the caller's loop in simulated time (SameLoop); the heartbeat gap the link
measures (PeakMeter, BoatLink.heartbeat_gap) in simulated time over an in-memory pipe."""

from __future__ import annotations

import asyncio
import threading

import pytest

from usvstation.clock import run_simulated
from usvstation.link.protocol import LinkConfig
from usvstation.link.station import BoatLink, LinkThread, PeakMeter, SameLoop
from usvstation.link.transport import MemoryPipe


def test_a_link_thread_runs_requests_on_its_own_loop_and_hands_events_back_in_order():
    seen: list[tuple[str, int]] = []

    async def main() -> None:
        host = LinkThread("test-link")
        await host.start()
        try:
            owner = threading.get_ident()

            async def where() -> int:
                return threading.get_ident()

            link_thread = await host.call(where)
            assert link_thread != owner and host.loop is not None

            deliver = host.to_owner(lambda tag, n: seen.append((tag, n)))

            async def burst() -> None:  # on the link's loop: events in a row
                for i in range(500):
                    deliver("event", i)

            await host.call(burst)

            async def fail() -> None:
                raise ValueError("the link's own error")

            with pytest.raises(ValueError, match="the link's own error"):
                await host.call(fail)
            done = asyncio.Event()
            host.post(lambda: deliver("last", -1))
            host.post(lambda: host.to_owner(done.set)())
            await asyncio.wait_for(done.wait(), 30)
        finally:
            await host.stop()
        assert host.loop is not None and host.loop.is_closed()

    asyncio.run(main())
    assert seen == [("event", i) for i in range(500)] + [("last", -1)]


def test_events_before_the_owner_runs_wait_for_it():
    got: list[int] = []
    host = LinkThread()
    host.start_now()
    forward = host.to_owner(got.append)
    host.call_blocking(_emit(forward, 3), timeout=30)

    async def main() -> None:
        done = asyncio.Event()
        host.adopt_owner()
        host.post(host.to_owner(done.set))
        await asyncio.wait_for(done.wait(), 30)
        await host.stop()

    asyncio.run(main())
    assert got == [0, 1, 2]


def _emit(forward, n):
    async def run() -> None:
        for i in range(n):
            forward(i)

    return run


def test_same_loop_is_direct():
    host = SameLoop()
    out: list[int] = []
    host.to_owner(out.append)(1)
    host.post(out.append, 2)

    async def two() -> int:
        return 3

    out.append(asyncio.run(host.call(two)))
    assert out == [1, 2, 3]


def test_peak_meter_keeps_the_worst_of_the_window_and_ever():
    m = PeakMeter(window_s=60.0)
    for t, v in [(0.0, 0.25), (1.0, 0.9), (2.0, 0.25), (3.0, 0.3)]:
        m.record(t, v)
    assert m.worst_since(3.0) == 0.9 and m.worst_ever == 0.9 and m.count == 4
    m.record(62.0, 0.26)  # the 0.9 is more than a minute old
    assert m.worst_since(62.0) == 0.3
    assert m.worst_since(200.0) == 0.0 and m.worst_ever == 0.9


def test_the_link_measures_its_heartbeat_intervals():
    async def main(clock) -> tuple[int, float]:
        pipe = MemoryPipe()

        async def station_end():
            return pipe.station

        link = BoatLink(stream_factory=station_end, config=LinkConfig(), clock=clock,
                        key=bytes(32), session=7)
        await link.start()
        heard = bytearray()

        async def boat_side() -> None:  # nobody answers: the station still beats
            while True:
                heard.extend(await pipe.boat.read())

        listener = asyncio.get_running_loop().create_task(boat_side())
        await clock.sleep(10.0)
        await link.close()
        listener.cancel()
        assert heard  # heartbeats went out
        assert list(link.late_heartbeats) == []  # none over 375 ms on a loop nothing holds
        return link.heartbeat_gap.count, link.heartbeat_gap.worst_ever

    count, worst = run_simulated(main)
    assert count >= 35  # 4 a second for 10 s, the first one opens the count
    assert worst == pytest.approx(0.25, abs=0.03)
