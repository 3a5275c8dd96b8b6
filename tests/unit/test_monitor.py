"""Plan monitor: progress, slip, cross-track, predicted clearance, DCPA/TCPA, encounter
classes on hand-made cases, and alert hysteresis."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

from usvstation.world.monitor import (
    REPEAT_S,
    AlertTracker,
    Assessment,
    BoatState,
    MonitorConfig,
    TargetAssessment,
    TargetState,
    assess,
    dcpa_tcpa,
    encounter,
    level_of,
)

# straight in along the ramp axis, 100 m in 100 s
PLAN = np.array([[100.0, 0.0, 0.0], [50.0, 0.0, 50.0], [0.0, 0.0, 100.0]])
L = 1.2


def boat(x: float, y: float, elapsed: float, vx: float = -1.0, vy: float = 0.0) -> BoatState:
    return BoatState(x, y, vx, vy, elapsed)


def test_on_schedule_on_track() -> None:
    a = assess(PLAN, boat(50.0, 0.0, 50.0), [], L)
    assert (a.plan_time_s, a.slip_s, a.cross_track_m) == pytest.approx((50.0, 0.0, 0.0))
    assert a.path[-1] == pytest.approx((0.0, 0.0, 50.0))


def test_behind_schedule_and_off_track() -> None:
    a = assess(PLAN, boat(60.0, 3.0, 50.0), [], L)
    assert (a.plan_time_s, a.slip_s, a.cross_track_m) == pytest.approx((40.0, 10.0, 3.0))
    # the predicted path starts at the boat and rejoins the plan after rejoin_s (10 s)
    assert a.path[0] == pytest.approx((60.0, 3.0, 0.0))
    k = int(np.searchsorted(a.path[:, 2], 10.0))
    assert a.path[k] == pytest.approx((50.0, 0.0, 10.0))
    assert a.path[-1, 2] == pytest.approx(60.0)  # the rest of the plan, slip kept


def test_static_target_on_the_path() -> None:
    t = TargetState("manual:0", 30.0, 0.0, 0.0, 0.0, 2.0)
    (ta,) = assess(PLAN, boat(50.0, 0.0, 50.0), [t], L).targets
    assert ta.min_clearance_m == pytest.approx(-2.0 - L / 2)
    assert ta.t_min_s == pytest.approx(20.0, abs=0.5)
    assert (ta.dcpa_m, ta.tcpa_s) == pytest.approx((0.0, 20.0))


def test_crossing_target_meets_the_boat_and_one_that_passes_behind() -> None:
    hit = TargetState("ais:1", 30.0, -20.0, 0.0, 1.0, 3.0)  # at (30, 0) in 20 s, as the boat
    late = TargetState("ais:2", 30.0, -40.0, 0.0, 1.0, 3.0)  # 20 m short when the boat passes
    a = assess(PLAN, boat(50.0, 0.0, 50.0), [hit, late], L)
    h, lt = a.targets
    assert h.min_clearance_m == pytest.approx(-3.0 - L / 2, abs=1e-9)
    assert h.t_min_s == pytest.approx(20.0)
    # closest approach of the late one: minimise |(30-20+s... )| numerically
    s = np.arange(0, 50.5, 0.5)
    d = np.hypot((50 - s) - 30.0, -(-40.0 + s)) - 3.0 - L / 2
    assert lt.min_clearance_m == pytest.approx(d.min())
    assert a.min_clearance_m == h.min_clearance_m


def test_targets_move_with_their_relative_velocity_only() -> None:
    same = TargetState("ais:3", 45.0, 0.0, -1.0, 0.0, 1.0)  # 5 m ahead, same velocity
    (ta,) = assess(PLAN, boat(50.0, 0.0, 50.0), [same], L).targets
    assert ta.min_clearance_m == pytest.approx(5.0 - 1.0 - L / 2)
    assert ta.tcpa_s == 0.0 and ta.dcpa_m == pytest.approx(5.0)


# DCPA/TCPA and classes: own at (0, 0) heading north (90 in a counter-clockwise frame with
# x east, y north) at 2 m/s; the test vectors of shared/notes/seeds-digest.md section 2.3.
def v(speed: float, compass_deg: float) -> tuple[float, float]:
    c = np.radians(compass_deg)
    return float(speed * np.sin(c)), float(speed * np.cos(c))


@pytest.mark.parametrize(("p", "tgt", "own_speed", "dcpa", "tcpa", "cls"), [
    ((8, 40), v(2.0, 180), 2.0, 8.00, 10.00, "head-on"),
    ((20, 20), v(2.0, 270), 2.0, 0.00, 10.00, "crossing-give-way"),
    ((21.2, 0), v(3.0, 315), 2.0, 1.21, 9.96, "crossing-give-way"),
    ((-20, 20), v(2.0, 90), 2.0, 0.00, 10.00, "crossing-stand-on"),
    ((3, 15), v(1.0, 0), 2.0, 3.00, 15.00, "overtaking-give-way"),
    ((2, -20), v(3.5, 0), 2.0, 2.00, 13.33, "overtaking-stand-on"),
    ((10, -30), v(2.0, 180), 2.0, 10.00, -7.50, "none"),  # astern, opening
])
def test_dcpa_tcpa_and_encounter(p, tgt, own_speed, dcpa, tcpa, cls) -> None:
    own = v(own_speed, 0)
    d, t = dcpa_tcpa(p, (tgt[0] - own[0], tgt[1] - own[1]))
    assert (d, t) == pytest.approx((dcpa, tcpa), abs=0.01)
    assert encounter(p, own, tgt) == cls


def test_encounter_of_a_stopped_boat_uses_its_heading() -> None:
    assert encounter((10, 10), (0.0, 0.0), (0.0, -1.0)) == "none"
    assert encounter((10, 10), (0.0, 0.0), (0.0, -1.0), own_heading_deg=90.0) == \
        "crossing-give-way"


@given(st.floats(-500, 500), st.floats(-500, 500), st.floats(-10, 10), st.floats(-10, 10))
def test_dcpa_is_the_minimum_distance(px: float, py: float, wx: float, wy: float) -> None:
    assume(np.hypot(wx, wy) > 1e-3)  # below 1e-6 m/s the target counts as keeping station
    d, t = dcpa_tcpa((px, py), (wx, wy))
    ts = np.linspace(min(t, 0) - 10, max(t, 0) + 10, 2001)
    dist = np.hypot(px + wx * ts, py + wy * ts)
    assert d <= dist.min() + 1e-6
    assert np.hypot(px + wx * t, py + wy * t) == pytest.approx(d, abs=1e-6)


# --- hysteresis -----------------------------------------------------------------------------
def test_level_of_enters_at_threshold_and_leaves_past_the_band() -> None:
    th = (1.0, 2.0, 3.0)
    seq = [0.0, 3.0, 2.9, 2.6, 2.4, 1.6, 1.4, 0.6, 0.4]
    levels, cur = [], -1
    for value in seq:
        cur = level_of(value, th, cur, 0.5)
        levels.append(cur)
    assert levels == [-1, 2, 2, 2, 1, 1, 0, 0, -1]


def clearance(value: float, tid: str = "ais:9", tcpa: float = -1.0) -> Assessment:
    return Assessment(0.0, 0.0, 0.0, np.zeros((1, 3)),
                      [TargetAssessment(tid, value, 5.0, 50.0, tcpa, "none")])


def test_clearance_wobbling_at_the_threshold_is_one_alert_announced_once() -> None:
    # advisory below 2 x 1.6 m, caution below the plan's margin 1.6 m, warning below 1.0 m,
    # alarm at contact; every change of level is an event of the same condition
    tracker = AlertTracker(MonitorConfig(clearance_margin_m=1.6, clearance_warning_m=1.0,
                                         clearance_hysteresis_m=0.5))
    changes = []
    for t, value in enumerate((10.0, 3.0, 1.5, 0.9, 1.1, 0.9, 1.4, 0.9, 1.6, 0.9)):
        changes += [(e.level, e.announce) for e in tracker.update(clearance(value), float(t))
                    if e.kind == "clearance"]
    assert changes == [("advisory", True), ("caution", True), ("warning", True),
                       # 1.6 m clears the band (1.0 + 0.5): down to caution, and the warning
                       # again 1 s later is not announced again (within REPEAT_S)
                       ("caution", False), ("warning", False)]
    assert tracker.levels == {("clearance", "ais:9"): 2}
    # 30 s after the last announcement the same warning asks for attention again
    tracker.update(clearance(1.6), 40.0)
    (again,) = [e for e in tracker.update(clearance(0.9), 41.0) if e.kind == "clearance"]
    assert (again.level, again.announce) == ("warning", True)


def test_a_condition_ends_when_it_clears_and_when_its_target_is_gone() -> None:
    tracker = AlertTracker()
    tracker.update(clearance(1.2), 0.0)
    (end,) = [e for e in tracker.update(clearance(5.0), 1.0) if e.kind == "clearance"]
    assert (end.level, end.target_id, end.announce) == (None, "ais:9", False)
    tracker.update(clearance(1.2), 2.0)
    empty = Assessment(0.0, 0.0, 0.0, np.zeros((1, 3)), [])
    (gone,) = [e for e in tracker.update(empty, 3.0) if e.target_id == "ais:9"]
    assert (gone.level, gone.message) == (None, "ais:9: no longer tracked")
    assert tracker.levels == {}


@given(st.lists(st.floats(-5.0, 10.0), min_size=1, max_size=60))
def test_one_announcement_per_level_within_the_repeat_time(values: list[float]) -> None:
    """Whatever the clearance does within REPEAT_S, each level is announced at most once."""
    tracker = AlertTracker()
    announced = [e.level for i, v in enumerate(values)
                 for e in tracker.update(clearance(v), i * REPEAT_S / 100) if e.announce]
    assert len(announced) == len(set(announced))


def test_alert_messages_name_the_target_and_contact() -> None:
    (e,) = [e for e in AlertTracker().update(clearance(-0.4)) if e.kind == "clearance"]
    assert e.level == "alarm" and e.target_id == "ais:9"
    assert e.message == "ais:9: predicted clearance contact in 5 s (plan margin 1.6 m)"
    now = TargetAssessment("ais:9", 2.4, 0.0, 50.0, -1.0, "none")
    (e,) = [e for e in AlertTracker().update(Assessment(0.0, 0.0, 0.0, np.zeros((1, 3)), [now]))
            if e.kind == "clearance"]
    assert e.message == "ais:9: predicted clearance 2.4 m now (plan margin 1.6 m)"


def test_slip_and_cross_track_levels() -> None:
    tracker = AlertTracker(MonitorConfig(time_margin_s=4.0))
    a = Assessment(0.0, 4.2, 6.0, np.zeros((1, 3)), [])
    got = {(e.kind, e.level) for e in tracker.update(a)}
    assert got == {("slip", "warning"), ("cross_track", "caution")}
    assert tracker.update(a) == []


def test_collision_course_only_for_a_new_moving_target() -> None:
    t_plan_clear = TargetAssessment("ais:5", 10.0, 5.0, 0.5, 20.0, "crossing-give-way")
    t_plan_hits = TargetAssessment("ais:6", 1.2, 5.0, 0.5, 20.0, "crossing-give-way")
    t_known = TargetAssessment("manual:0", 1.2, 5.0, 0.5, 20.0, "head-on", known=True)
    t_buoy = TargetAssessment("arpa:1", 1.2, 5.0, 0.5, 20.0, "head-on", moving=False)
    a = Assessment(0.0, 0.0, 0.0, np.zeros((1, 3)), [t_plan_clear, t_plan_hits, t_known,
                                                      t_buoy])
    got = {(e.kind, e.target_id, e.level) for e in AlertTracker().update(a)}
    assert ("collision_course", "ais:5", "caution") in got
    assert ("collision_course", "ais:6", "warning") in got
    # the plan's own obstacles and targets still over ground: their predicted clearance only
    assert {e for e in got if e[0] == "collision_course"} == {
        ("collision_course", "ais:5", "caution"), ("collision_course", "ais:6", "warning")}
    assert ("clearance", "manual:0", "caution") in got and ("clearance", "arpa:1", "caution") \
        in got
