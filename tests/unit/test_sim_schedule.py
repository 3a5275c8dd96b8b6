"""The simulated boat's TELEMETRY keeps a fixed schedule in boat time, however late it runs."""

from __future__ import annotations

import itertools
import random

import pytest
from link_harness import Harness

from usvstation.link.protocol import TelemetryReceived
from usvstation.sim.boat import BoatConfig


def _boat_times_ms(h: Harness) -> list[int]:
    return [e.telemetry.time_ms for e in h.of(TelemetryReceived)]


@pytest.mark.parametrize(("hz", "sim_speed"), [(5.0, 1.0), (10.0, 1.0), (5.0, 4.0)])
def test_telemetry_on_a_fixed_boat_time_grid_under_jitter(hz, sim_speed):
    h = Harness(boat_cfg=BoatConfig(telemetry_hz=hz, sim_speed=sim_speed))
    h.connect()
    rng = random.Random(3)
    end = h.t + 20.0 / sim_speed
    while h.t < end:  # late, irregular updates: 1 ms to 0.45 s apart
        h.step(rng.uniform(0.001, 0.45))
    times = _boat_times_ms(h)
    assert len(times) > 50
    period_ms = round(1000 / hz)
    assert {b - a for a, b in itertools.pairwise(times)} == {period_ms}
    assert all(t % period_ms == 0 for t in times)


def test_a_long_stall_skips_frames_but_keeps_the_grid():
    h = Harness(boat_cfg=BoatConfig(telemetry_hz=5.0, failsafe_timeout_s=100.0))
    h.connect()
    h.step(5.0)  # the process was stopped for 5 s
    h.run(2.0, dt=0.05)
    times = _boat_times_ms(h)
    assert all(t % 200 == 0 for t in times)
    gaps = [b - a for a, b in itertools.pairwise(times)]
    assert max(gaps) <= 5200 and gaps[-5:] == [200] * 5
