"""HOLD that adapts, an observer that keeps estimating through turns, a biased compass
(issue 24). The simulated boat (`DynamicVehicle`) steers on RTK-class sensors; the judge
reads its truth."""

from __future__ import annotations

import math

import pytest

from usvstation.bench.tracking import hold_through_change
from usvstation.dynamics import Environment
from usvstation.sim.dynamic import OVER_CAPACITY, DynamicVehicle


def _hold_through(speed: float, turn_deg: float, over_s: float, *, through_slack: bool,
                  seconds: float = 180.0) -> tuple[float, float | None]:
    """(largest true distance from the hold point, seconds to the first over-capacity
    notice or None): bench tracking's `hold_through_change`."""
    row = hold_through_change(speed, turn_deg, over_s, through_slack, hold=seconds)
    return row["radius_m"], row["over_capacity_after_s"]


@pytest.mark.parametrize(("turn", "slack"), [(90.0, False), (180.0, True)])
def test_hold_stays_within_2_m_as_a_1_mps_current_turns_or_reverses(turn, slack):
    """1 m/s turning 90 deg, or reversing through slack water, over 20 s: within 2 m for
    180 s, and no over-capacity notice (it can hold)."""
    worst, notice = _hold_through(1.0, turn, 20.0, through_slack=slack)
    assert worst <= 2.0
    assert notice is None


def test_hold_through_a_current_step():
    """0.5 m/s across, stepping to 0.8 m/s at 45 deg within a second: back within 2 m and
    the step costs at most a couple of metres."""
    v = DynamicVehicle(40.0, 0.0, -math.pi / 2, env=Environment.with_current(0.5, math.pi / 2),
                       sensors="rtk", seed=4)
    v.hold()
    while v.truth.t < 60.0:
        v.step(0.2)
    v.env = Environment.with_current(0.8, math.pi / 4)
    distances = []
    while v.truth.t < 240.0:
        v.step(0.2)
        distances.append(math.hypot(v.truth.x - 40.0, v.truth.y))
    assert max(distances) <= 2.0
    assert max(distances[-300:]) <= 0.5  # the last minute: back on the point


def test_a_current_turning_beyond_what_hold_can_ride_out_is_reported_within_10_s():
    """2.4 m/s (78 % of top speed) turning 90 deg in 10 s: the boat is still turning to
    meet it when it is already drifting; it says so within 10 s."""
    worst, notice = _hold_through(2.4, 90.0, 10.0, through_slack=False, seconds=60.0)
    assert notice is not None and notice <= 10.0
    assert worst > 2.0


def test_the_notice_is_the_boats_statustext_and_clears_when_it_holds_again():
    v = DynamicVehicle(40.0, 0.0, -math.pi / 2, env=Environment.with_current(3.5, math.pi / 2))
    v.hold()
    for _ in range(100):
        v.step(0.2)
    assert v.notice == OVER_CAPACITY
    v.env = Environment.with_current(0.3, math.pi / 2)
    v.keeper.hold_at(v.measurement.x, v.measurement.y)  # a new HOLD where it drifted to
    for _ in range(300):
        v.step(0.2)
    assert v.notice is None


def test_the_observer_keeps_estimating_through_a_turn():
    """A 90 deg turn at 2 m/s in a 0.5 m/s cross current: the estimate stays within 0.15 m/s
    of the current all through the turn (it models the turn's slip instead of freezing)."""
    from usvstation.sim.vehicle import Waypoint

    env = Environment.with_current(0.5, math.pi / 2)
    v = DynamicVehicle(0.0, 0.0, 0.0, speed=2.0, env=env, sensors="rtk", seed=2)
    wps = [Waypoint(0.0, 0.0, 0.0, 2.0, 0.0), Waypoint(60.0, 0.0, 30.0, 2.0, math.pi / 2),
           Waypoint(60.0, 60.0, 60.0, 2.0, math.pi / 2)]
    v.set_mission(wps)
    v.start()
    errors, turning = [], []
    while v.truth.t < 55.0:
        v.step(0.2)
        ex, ey = v.observer.estimate
        if v.truth.t > 15.0:
            errors.append(math.hypot(ex, ey - 0.5))
            turning.append(abs(v.truth.yaw_rate) > math.radians(5.0))
    assert any(turning)  # it did turn
    assert max(e for e, turn in zip(errors, turning, strict=True) if turn) < 0.15
    assert max(errors) < 0.15


def test_a_compass_that_reads_3_deg_high_still_arrives():
    """Plans of the arrival bench (a seed it reports), 3 deg of compass bias: the boat learns
    the bias through its turns and arrives within 0.3 m and 5 deg of the truth."""
    from usvstation.bench.arrival import FAMILIES, fly, plans

    family = FAMILIES["bench"].__class__("compass_bias_3", "compass reads 3 deg high",
                                         compass_bias_deg=3.0)
    for name, seed, scenario, plan in plans((21,), ("case1", "case2")):
        out = fly(plan, scenario, family, "approach", "rtk-moving-base", seed=seed)
        assert out.kind == "arrived", (name, out)
        assert out.offset <= 0.3 and out.heading <= 5.0
