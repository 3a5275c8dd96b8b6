"""LOS geometry, AV-LOS speed law, sliding curve, schedules, compensation and angle wrapping."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

from usvstation.dynamics import Environment, VesselState, WaveField, otter
from usvstation.geometry import angle_diff, cross_track_error, wrap_angle
from usvstation.guidance.compensation import CompensatedAVLOS, DisturbancePredictor
from usvstation.guidance.geometry import circle_segment_intersections, project_on_segment
from usvstation.guidance.los import (
    AVLOSGuidance,
    LookaheadTracker,
    LOSGuidance,
    avlos_speed,
    limit_correction,
)
from usvstation.guidance.sliding_curve import SlidingCurveGuidance
from usvstation.guidance.trajectory import Schedule, Trajectory

coord = st.floats(-100.0, 100.0, allow_nan=False)
angle = st.floats(-50.0, 50.0, allow_nan=False)
PAPER = Trajectory.from_xyt([(0, 0, 0), (0, 20, 8), (30, 20, 14), (30, 0, 22)])


def pose(x: float, y: float, psi: float = 0.0) -> VesselState:
    return VesselState(x, y, psi)


# ------------------------------------------------------------------ angles


@given(angle)
def test_wrap_angle_lands_in_range_and_keeps_the_direction(a) -> None:
    w = wrap_angle(a)
    assert -math.pi <= w < math.pi
    assert math.cos(w) == pytest.approx(math.cos(a), abs=1e-9)
    assert math.sin(w) == pytest.approx(math.sin(a), abs=1e-9)
    assert wrap_angle(np.array([a]))[0] == pytest.approx(w)


@given(angle, angle)
def test_angle_diff_is_the_smallest_signed_turn(a, b) -> None:
    d = angle_diff(a, b)
    assert abs(d) <= math.pi
    assert math.cos(b + d) == pytest.approx(math.cos(a), abs=1e-9)
    assert math.sin(b + d) == pytest.approx(math.sin(a), abs=1e-9)


def test_angle_diff_across_the_seam() -> None:
    assert angle_diff(math.radians(179), math.radians(-179)) == pytest.approx(math.radians(-2))
    assert angle_diff(math.radians(-179), math.radians(179)) == pytest.approx(math.radians(2))
    assert wrap_angle(math.pi) == pytest.approx(-math.pi)


# ------------------------------------------------------------------ geometry


@given(coord, coord, st.floats(0.1, 50.0), coord, coord, coord, coord)
def test_circle_segment_intersections_lie_on_both(cx, cy, r, ax, ay, bx, by) -> None:
    assume(math.hypot(bx - ax, by - ay) > 1e-3)
    for s in circle_segment_intersections(cx, cy, r, ax, ay, bx, by):
        assert 0.0 <= s <= 1.0 + 1e-9
        px, py = ax + s * (bx - ax), ay + s * (by - ay)
        assert math.hypot(px - cx, py - cy) == pytest.approx(r, rel=1e-6, abs=1e-6)


@given(coord, coord, st.floats(0.1, 50.0), coord, coord, coord, coord)
def test_circle_segment_intersection_count_matches_the_geometry(cx, cy, r, ax, ay, bx, by) -> None:
    assume(math.hypot(bx - ax, by - ay) > 1e-3)
    hits = circle_segment_intersections(cx, cy, r, ax, ay, bx, by)
    da, db = math.hypot(ax - cx, ay - cy), math.hypot(bx - cx, by - cy)
    s = project_on_segment(cx, cy, ax, ay, bx, by)
    nearest = math.hypot(ax + s * (bx - ax) - cx, ay + s * (by - ay) - cy)
    margin = 1e-6 * max(1.0, r)
    inside_a, inside_b = da < r - margin, db < r - margin
    outside_a, outside_b = da > r + margin, db > r + margin
    if (inside_a and outside_b) or (inside_b and outside_a):
        assert len(hits) == 1  # one end inside, the other outside: exactly one crossing
    elif da > r + margin and db > r + margin and nearest < r - margin:
        assert len(hits) == 2  # both ends outside, the segment cuts through
    elif nearest > r + margin or max(da, db) < r - margin:
        assert hits == []  # misses, or lies wholly inside


def test_an_end_a_hair_inside_the_circle_is_inside() -> None:
    """Hypothesis found it: both ends inside, one by 6e-8 m, so no crossing (the test used
    to call that end outside)."""
    assert circle_segment_intersections(0.0, 5.960464477539063e-08, 1.0, 0.0, 0.0, 0.0, 1.0) == []


def test_circle_segment_exact_cases() -> None:
    assert circle_segment_intersections(0, 0, 3, -5, 0, 5, 0) == pytest.approx([0.2, 0.8])
    assert circle_segment_intersections(0, 3, 3, -5, 0, 5, 0) == pytest.approx([0.5])  # tangent
    assert circle_segment_intersections(0, 5, 3, -5, 0, 5, 0) == []
    assert circle_segment_intersections(0, 0, 3, 1, 1, 1, 1) == []  # degenerate segment


@given(coord, coord, coord, coord, coord, coord)
def test_projection_is_the_nearest_point_of_the_segment(px, py, ax, ay, bx, by) -> None:
    s = project_on_segment(px, py, ax, ay, bx, by)
    d = math.hypot(ax + s * (bx - ax) - px, ay + s * (by - ay) - py)
    for q in np.linspace(0.0, 1.0, 21):
        assert d <= math.hypot(ax + q * (bx - ax) - px, ay + q * (by - ay) - py) + 1e-7


def test_cross_track_error_is_positive_to_the_left() -> None:
    assert cross_track_error(5, 2, 0, 0, 10, 0) == pytest.approx(2.0)
    assert cross_track_error(5, -2, 0, 0, 10, 0) == pytest.approx(-2.0)


# ------------------------------------------------------------------ LOS look-ahead (Fig. 9)


def test_lookahead_on_a_straight_leg_is_r_ahead_of_the_projection() -> None:
    tracker = LookaheadTracker(PAPER, 3.0)
    la = tracker.find(1.0, 5.0)  # 1 m right of the first leg (x = 0)
    assert la.on_circle and la.segment == 0
    assert (la.x, la.y) == pytest.approx((0.0, 5.0 + math.sqrt(8.0)))
    assert la.distance == pytest.approx(3.0)


def test_lookahead_hands_over_at_the_end_of_a_segment() -> None:
    tracker = LookaheadTracker(PAPER, 3.0)
    assert tracker.find(0.0, 16.0).segment == 0  # P2 still 4 m away
    la = tracker.find(0.0, 18.0)  # P2 inside the circle: the next leg is searched
    assert la.segment == 1 and tracker.segment == 1
    assert (la.x, la.y) == pytest.approx((math.sqrt(9.0 - 4.0), 20.0))
    # S_K is out of the team: going back near the first leg does not return to it.
    assert tracker.find(0.0, 10.0).segment == 1


def test_lookahead_past_the_last_waypoint_is_the_end() -> None:
    tracker = LookaheadTracker(PAPER, 3.0)
    tracker.segment = 2
    la = tracker.find(30.0, 1.0)
    assert (la.segment, la.fraction) == (2, 1.0)
    assert (la.x, la.y) == pytest.approx((30.0, 0.0))


def test_boat_far_off_the_path_steers_r_ahead_of_the_nearest_point() -> None:
    guidance = LOSGuidance(PAPER, 3.0, speed_max=8.0)
    cmd = guidance.update(pose(10.0, 5.0), 2.0)  # 10 m right of the first leg
    assert cmd.target == pytest.approx((0.0, 8.0))  # closes at an angle, never circles
    assert cmd.heading == pytest.approx(math.atan2(3.0, -10.0))  # at the path, slightly ahead
    assert guidance.tracker.find(10.0, 5.0).on_circle is False


def test_classic_los_uses_the_isochronous_target_speed() -> None:
    guidance = LOSGuidance(PAPER, 3.0, speed_max=8.0)
    assert guidance.update(pose(0.0, 4.0), 1.0).speed == pytest.approx(2.5)
    assert guidance.update(pose(0.0, 4.0), 10.0).speed == pytest.approx(5.0)  # whatever the place
    assert guidance.update(pose(0.0, 4.0), 30.0).speed == pytest.approx(2.5)  # late: keeps going
    with pytest.raises(ValueError, match="look-ahead radius must be > 0"):
        LOSGuidance(PAPER, 0.0)


# ------------------------------------------------------------------ AV-LOS speed law (eq. 13)


def test_avlos_speed_law() -> None:
    assert avlos_speed(3.0, 1.2, 8.0) == pytest.approx(2.5)  # on schedule: R / dT
    assert avlos_speed(3.0, 0.6, 8.0) == pytest.approx(5.0)  # late: faster
    assert avlos_speed(3.0, 2.4, 8.0) == pytest.approx(1.25)  # early: slower
    assert avlos_speed(3.0, 0.1, 8.0) == 8.0  # saturates at speed_max
    assert avlos_speed(3.0, -1.0, 8.0) == 8.0  # look-ahead point already overdue
    assert avlos_speed(3.0, 100.0, 8.0, speed_min=0.5) == 0.5


def test_avlos_on_the_trajectory_commands_the_planned_speed_and_reacts_to_timing() -> None:
    guidance = AVLOSGuidance(PAPER, 3.0, speed_max=8.0)
    on_time = guidance.update(pose(0.0, 5.0), 2.0)  # desired position at t = 2 is (0, 5)
    assert on_time.speed == pytest.approx(2.5)
    assert on_time.heading == pytest.approx(math.pi / 2)
    assert on_time.target_time == pytest.approx(3.2)
    late = AVLOSGuidance(PAPER, 3.0, speed_max=8.0).update(pose(0.0, 5.0), 2.8)
    early = AVLOSGuidance(PAPER, 3.0, speed_max=8.0).update(pose(0.0, 5.0), 1.2)
    assert late.speed > on_time.speed > early.speed


@given(st.floats(0.5, 5.0), st.floats(0.1, 5.0), st.floats(0.2, 4.0), st.floats(0.5, 3.0))
def test_limit_correction_keeps_direction_and_bounds_it(distance, dt, v_sched, accel) -> None:
    raw = avlos_speed(distance, dt, 50.0)
    limited = limit_correction(raw, v_sched, distance, dt, accel)
    ahead = (dt - distance / v_sched) * v_sched
    assert abs(limited - v_sched) <= math.sqrt(2 * accel * abs(ahead)) + 1e-9
    assert abs(limited - v_sched) <= abs(raw - v_sched) + 1e-9
    assert (limited - v_sched) * (raw - v_sched) >= 0.0


def test_feasible_schedule_ramps_speed_changes_within_the_acceleration() -> None:
    exact, smooth = Schedule.exact(PAPER), Schedule.feasible(PAPER, 1.5)
    slopes = np.diff(np.diff(smooth.arcs) / np.diff(smooth.times)) / np.diff(smooth.times)[1:]
    assert np.max(np.abs(slopes)) <= 1.5 * (1 + 1e-6)
    for arc in (10.0, 35.0, 60.0):  # far from the speed changes it is the plan
        assert smooth.time_at_arc(arc) == pytest.approx(exact.time_at_arc(arc), abs=1e-6)
    # The end is not braked for: the boat carries on at the last speed.
    assert smooth.time_at_arc(PAPER.length) == pytest.approx(22.0, abs=0.02)
    assert smooth.speed_at_time(21.0) == pytest.approx(2.5)


# ------------------------------------------------------------------ trajectories


def test_trajectory_interpolates_linearly_in_time() -> None:
    assert PAPER.position_at(4.0) == pytest.approx([0.0, 10.0])
    assert PAPER.position_at(11.0) == pytest.approx([15.0, 20.0])
    assert PAPER.position_at(-1.0) == pytest.approx([0.0, 0.0])  # held at the ends
    assert PAPER.position_at(99.0) == pytest.approx([30.0, 0.0])
    assert PAPER.velocity_at(10.0) == pytest.approx((5.0, 0.0))
    assert PAPER.length == pytest.approx(70.0)
    assert PAPER.arrival_heading == pytest.approx(-math.pi / 2)


def test_trajectory_refuses_times_that_do_not_increase() -> None:
    message = r"waypoint 2 at t = 4 s is not after waypoint 1 at t = 5 s"
    with pytest.raises(ValueError, match=message):
        Trajectory.from_xyt([(0, 0, 0), (1, 0, 5), (2, 0, 4)])
    with pytest.raises(ValueError, match="at least 2 waypoints"):
        Trajectory.from_xyt([(0, 0, 0)])


def test_extension_continues_along_the_arrival_heading_at_the_last_speed() -> None:
    ext = PAPER.extended(10.0)
    assert ext.points[-1] == pytest.approx([30.0, -10.0])
    assert ext.times[-1] == pytest.approx(26.0)
    tail = PAPER.replace_tail(5.0, (31.0, 5.0))
    # Only the last 5 m change: P (5 m before the end) is kept at its time.
    assert tail.points[:-2] == pytest.approx(np.array([[0, 0], [0, 20], [30, 20], [30, 5]]))
    assert tail.times[-3] == pytest.approx(20.0)
    assert tail.points[-2] == pytest.approx([31.0, 5.0])
    assert tail.times[-2] == pytest.approx(20.0 + 2.0 * 1.0 / (1.0 + math.hypot(1.0, 5.0)))


def test_trajectory_from_a_plan() -> None:
    plan = {"waypoints": [{"x": 10.0, "y": 0.0, "t": 0.0}, {"x": 0.0, "y": 0.0, "t": 5.0}]}
    assert Trajectory.from_plan(plan).speed_at(1.0) == pytest.approx(2.0)
    with pytest.raises(ValueError, match="plan waypoints need x, y and t"):
        Trajectory.from_plan({"waypoints": [{"x": 1.0}]})


# ------------------------------------------------------------------ sliding curve (paper 002)


def test_sliding_curve_target_slides_delta_ahead_of_the_projection() -> None:
    guidance = SlidingCurveGuidance(PAPER, delta=3.0, speed_max=8.0)
    cmd = guidance.update(pose(2.0, 5.0), 2.0)
    assert cmd.target == pytest.approx((0.0, 8.0))
    assert cmd.heading == pytest.approx(math.atan2(3.0, -2.0))
    behind = SlidingCurveGuidance(PAPER, delta=3.0).update(pose(1.0, -4.0), 0.0)
    assert behind.target == pytest.approx((0.0, 3.0))  # drawn to W_i, not past it


def test_sliding_curve_target_carries_round_a_corner_and_switches_legs() -> None:
    guidance = SlidingCurveGuidance(PAPER, delta=3.0, speed_max=8.0)
    assert guidance.update(pose(0.0, 19.0), 7.6).target == pytest.approx((2.0, 20.0))
    guidance.update(pose(0.5, 20.2), 8.0)
    assert guidance.leg == 1


# ------------------------------------------------------------------ compensation (sec. 3.1)


def test_compensation_without_disturbance_changes_nothing() -> None:
    pred = DisturbancePredictor(otter(), Environment())
    psi, surge = pred.compensate(0.0, 2.0, 0.0)
    assert psi == pytest.approx(math.pi / 2)
    assert surge == pytest.approx(2.0)


def test_compensation_heads_into_a_cross_current() -> None:
    env = Environment.with_current(0.3, math.pi / 2)  # flows to +y
    pred = DisturbancePredictor(otter(), env)
    psi, surge = pred.compensate(-3.0, 0.0, math.pi)  # make good 3 m/s towards -x
    assert math.degrees(angle_diff(psi, math.pi)) == pytest.approx(math.degrees(math.atan(0.1)))
    # The surge command is over ground; through the water the boat runs it minus the current's
    # share along the heading, and water velocity plus current is the wanted ground velocity.
    hx, hy = math.cos(psi), math.sin(psi)
    water = surge - (env.current[0] * hx + env.current[1] * hy)
    ground = (water * hx + env.current[0], water * hy + env.current[1])
    assert ground == pytest.approx((-3.0, 0.0), abs=1e-9)


def test_compensation_adds_the_wave_sway_drift() -> None:
    waves = WaveField.from_sea_state(3, math.radians(135.0))
    pred = DisturbancePredictor(otter(), Environment.with_current(0.3, math.pi / 2, waves=waves))
    current_only = DisturbancePredictor(otter(), Environment.with_current(0.3, math.pi / 2))
    assert abs(pred.crab_angle(math.pi, 3.0)) > abs(current_only.crab_angle(math.pi, 3.0))


def test_compensated_approach_comes_in_from_up_current_to_the_goal() -> None:
    traj = Trajectory.from_xyt([(60.0, 0.0, 0.0), (0.0, 0.0, 20.0)])
    env = Environment.with_current(0.3, math.pi / 2)
    g = CompensatedAVLOS(traj, DisturbancePredictor(otter(), env), 8.0, speed_max=3.0)
    assert g.approach_segment is None  # decided near the end, with the drift known then
    g.update(VesselState(25.0, 0.0, math.pi, 3.0), 12.0)
    assert g.bend_decided
    assert g.trajectory.points[-3] == pytest.approx([12.0, 0.0])  # the last 12 m only
    via = g.trajectory.points[-2]
    assert via[0] == pytest.approx(8.0, abs=0.2)
    assert via[1] < -0.1  # up-current
    assert g.trajectory.points[-1] == pytest.approx([0.0, 0.0])
    assert math.degrees(abs(g.approach_crab)) == pytest.approx(1.5)  # 0.3 x the 5 deg tolerance
    near = g.update(VesselState(3.0, -0.3, math.pi, 3.0), 19.0)
    assert abs(math.degrees(angle_diff(near.heading, math.pi))) <= 4.5 + 1e-9
    calm = CompensatedAVLOS(traj, DisturbancePredictor(otter(), Environment()), 8.0)
    calm.update(VesselState(25.0, 0.0, math.pi, 3.0), 12.0)
    assert calm.bend_decided and calm.approach_segment is None  # nothing to bend for
    refused = CompensatedAVLOS(traj, DisturbancePredictor(otter(), env), 8.0,
                               path_check=lambda bent: False)
    refused.update(VesselState(25.0, 0.0, math.pi, 3.0), 12.0)
    assert refused.bend_rejected and len(refused.trajectory.points) == 2  # plan kept
