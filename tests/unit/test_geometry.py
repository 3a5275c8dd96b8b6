"""The one geometry: angles, cross-track sign, eq. 7 inflation, timed-path position, link units."""

import math

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

from usvstation.geometry import (
    CDEG,
    CM,
    E7,
    MS,
    angle_diff,
    cross_track_error,
    inflated_radius,
    position_at,
    wrap_180,
    wrap_angle,
    wrap_deg,
)

rad = st.floats(-1e4, 1e4, allow_nan=False)
deg = st.floats(-1e6, 1e6, allow_nan=False)
coord = st.floats(-1e3, 1e3, allow_nan=False)


# --- angles -----------------------------------------------------------------------------------
@given(rad)
def test_wrap_angle_is_in_range_idempotent_and_keeps_the_direction(a) -> None:
    w = wrap_angle(a)
    assert -math.pi <= w < math.pi
    assert wrap_angle(w) == w
    assert (math.cos(w), math.sin(w)) == pytest.approx((math.cos(a), math.sin(a)), abs=1e-9)


@given(st.lists(rad, min_size=1, max_size=20))
def test_wrap_angle_on_an_array_is_element_wise(angles) -> None:
    assert wrap_angle(np.array(angles)).tolist() == [wrap_angle(a) for a in angles]


def test_wrap_angle_on_the_seam() -> None:
    assert wrap_angle(math.pi) == -math.pi
    assert wrap_angle(-math.pi) == -math.pi
    assert wrap_angle(3 * math.pi / 2) == pytest.approx(-math.pi / 2)


@given(deg)
def test_wrap_deg_and_wrap_180_are_in_range_and_idempotent(a) -> None:
    w, r = wrap_deg(a), wrap_180(a)
    assert 0.0 <= w < 360.0 and wrap_deg(w) == w
    assert -180.0 < r <= 180.0 and wrap_180(r) == r
    assert math.cos(math.radians(w)) == pytest.approx(math.cos(math.radians(a)), abs=1e-6)
    assert math.cos(math.radians(r)) == pytest.approx(math.cos(math.radians(a)), abs=1e-6)


def test_degree_wraps_exact_values() -> None:
    assert wrap_deg([-90.0, 360.0, 725.0]).tolist() == [270.0, 0.0, 5.0]
    assert wrap_180([-180.0, 180.0, 190.0, -190.0]).tolist() == [180.0, 180.0, -170.0, 170.0]
    assert wrap_180(-180.0) == 180.0


@given(rad, rad)
def test_angle_diff_is_antisymmetric_and_the_smallest_turn(a, b) -> None:
    d = angle_diff(a, b)
    assume(abs(abs(d) - math.pi) > 1e-6)
    assert angle_diff(b, a) == pytest.approx(-d, abs=1e-9)
    assert -math.pi <= d < math.pi
    assert (math.cos(b + d), math.sin(b + d)) == pytest.approx((math.cos(a), math.sin(a)),
                                                               abs=1e-6)


def test_angle_diff_across_the_seam() -> None:
    assert angle_diff(math.radians(179), math.radians(-179)) == pytest.approx(math.radians(-2))
    assert angle_diff(np.radians([179, -179]), np.radians([-179, 179])) == pytest.approx(
        np.radians([-2, 2]))


# --- cross-track ------------------------------------------------------------------------------
def test_cross_track_is_positive_left_of_the_direction_of_travel() -> None:
    assert cross_track_error(5, 2, 0, 0, 10, 0) == 2.0  # east-going leg, boat north: left
    assert cross_track_error(5, -2, 0, 0, 10, 0) == -2.0
    assert cross_track_error(5, 2, 10, 0, 0, 0) == -2.0  # the same point, leg reversed
    assert cross_track_error(-3, 4, 0, 0, 0, 10) == 3.0  # north-going leg, boat west: left
    assert cross_track_error(3, 4, 0, 0, 0, 10) == -3.0


def test_cross_track_of_a_degenerate_leg_is_the_distance() -> None:
    assert cross_track_error(3, 4, 1, 1, 1, 1) == pytest.approx(math.hypot(2, 3))


@given(coord, coord, coord, coord, coord, coord)
def test_cross_track_is_the_signed_distance_to_the_line(px, py, ax, ay, bx, by) -> None:
    length = math.hypot(bx - ax, by - ay)
    assume(length > 1e-3)
    e = cross_track_error(px, py, ax, ay, bx, by)
    assert cross_track_error(px, py, bx, by, ax, ay) == pytest.approx(-e, abs=1e-9)
    # the foot of the perpendicular, moved back by e along the left normal, is on the line
    nx, ny = -(by - ay) / length, (bx - ax) / length
    qx, qy = px - e * nx, py - e * ny
    assert (qx - ax) * nx + (qy - ay) * ny == pytest.approx(0.0, abs=1e-6)
    assert cross_track_error(px, py, ax, ay, ax + 3 * (bx - ax), ay + 3 * (by - ay)) \
        == pytest.approx(e, abs=1e-6)


# --- eq. 7 ------------------------------------------------------------------------------------
def test_inflation_is_eq7_on_the_paper_numbers() -> None:
    # R_c "usually taken as 1 m" (paper 000 after eq. 7), D_USV the 1.2 m default hull
    assert inflated_radius(3.0, 1.2, 1.0) == pytest.approx(5.2)
    assert inflated_radius(np.array([0.0, 2.0]), 1.2, 1.0).tolist() == pytest.approx([2.2, 4.2])


@given(st.floats(0, 1e3), st.floats(0.1, 200), st.floats(0, 1e3))
def test_inflation_grows_by_hull_and_compensation(r, hull, r_c) -> None:
    assert inflated_radius(r, hull, r_c) == pytest.approx(r + hull + r_c)
    assert inflated_radius(np.array([r]), hull, r_c)[0] == inflated_radius(r, hull, r_c)


# --- timed path -------------------------------------------------------------------------------
@st.composite
def timed_paths(draw):
    n = draw(st.integers(1, 8))
    gaps = draw(st.lists(st.floats(0.1, 100.0), min_size=n - 1, max_size=n - 1))
    t = np.concatenate([[draw(st.floats(0.0, 100.0))], np.zeros(n - 1)])
    t[1:] = t[0] + np.cumsum(gaps)
    xs = np.array(draw(st.lists(coord, min_size=n, max_size=n)))
    ys = np.array(draw(st.lists(coord, min_size=n, max_size=n)))
    return t, xs, ys


@given(timed_paths())
def test_position_at_waypoint_times_is_the_waypoint(path) -> None:
    t, xs, ys = path
    for i in range(len(t)):
        assert position_at(t, xs, ys, float(t[i])) == pytest.approx((xs[i], ys[i]), abs=1e-9)
    assert position_at(t, xs, ys, float(t[0]) - 5.0) == (xs[0], ys[0])
    assert position_at(t, xs, ys, float(t[-1]) + 5.0) == (xs[-1], ys[-1])


@given(timed_paths(), st.floats(0.0, 1.0))
def test_position_is_continuous_and_linear_in_time(path, f) -> None:
    t, xs, ys = path
    assume(len(t) >= 2)
    speed = float(np.max(np.hypot(np.diff(xs), np.diff(ys)) / np.diff(t)))
    tq = np.linspace(t[0] - 1.0, t[-1] + 1.0, 400)
    x, y = position_at(t, xs, ys, tq)
    step = np.hypot(np.diff(x), np.diff(y))
    assert np.all(step <= speed * (tq[1] - tq[0]) + 1e-6)
    tm = float(t[0] + f * (t[1] - t[0]))
    assert position_at(t, xs, ys, tm) == pytest.approx(
        (xs[0] + f * (xs[1] - xs[0]), ys[0] + f * (ys[1] - ys[0])), abs=1e-6)


def test_position_at_on_a_hand_made_plan() -> None:
    t, xs, ys = [0.0, 20.0, 30.0], [80.0, 40.0, 0.0], [10.0, 0.0, 0.0]
    assert position_at(t, xs, ys, 10.0) == pytest.approx((60.0, 5.0))
    assert position_at(t, xs, ys, 25.0) == pytest.approx((20.0, 0.0))
    x, y = position_at(t, xs, ys, np.array([-1.0, 99.0]))
    assert x.tolist() == [80.0, 0.0] and y.tolist() == [10.0, 0.0]


# --- link units -------------------------------------------------------------------------------
@given(st.floats(-90.0, 90.0))
def test_degrees_e7_round_trip(a) -> None:
    n = E7.to_wire(a)
    assert isinstance(n, int) and abs(E7.from_wire(n) - a) <= 0.5e-7 + 1e-12
    assert E7.to_wire(E7.from_wire(n)) == n


@given(st.lists(st.integers(-1_800_000_000, 1_800_000_000), min_size=1, max_size=10))
def test_e7_arrays_round_trip_exactly(ns) -> None:
    assert E7.to_wire(E7.from_wire(np.array(ns))).tolist() == ns
    assert E7.from_wire(np.array(ns)).tolist() == [E7.from_wire(n) for n in ns]


@given(st.integers(0, 35999))
def test_centidegrees_round_trip(c) -> None:
    assert CDEG.to_wire(CDEG.from_wire(c)) == c


@given(deg)
def test_centidegrees_are_a_compass_angle(a) -> None:
    c = CDEG.to_wire(a)
    assert 0 <= c < 36000
    assert abs(wrap_180(CDEG.from_wire(c) - a)) <= 0.005 + 1e-6


@given(st.integers(0, 0xFFFF), st.integers(0, 0xFFFFFFFF))
def test_speed_and_time_round_trip(cms, ms) -> None:
    assert CM.to_wire(CM.from_wire(cms)) == cms
    assert MS.to_wire(MS.from_wire(ms)) == ms
    assert MS.to_wire(np.array([MS.from_wire(ms)])).tolist() == [ms]


def test_units_on_hand_made_values() -> None:
    assert (E7.to_wire(47.3977419), E7.from_wire(473977419)) == (473977419, 47.3977419)
    assert (CDEG.to_wire(-0.5), CDEG.to_wire(359.996), CDEG.from_wire(9000)) == (35950, 0, 90.0)
    assert (CM.to_wire(1.234), CM.from_wire(250), MS.to_wire(1.5), MS.from_wire(2500)) == \
        (123, 2.5, 1500, 2.5)
