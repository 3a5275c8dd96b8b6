"""Eq. 9: a path segment against a moving circle, exactly, within the segment's time window."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from usvstation.planning.xyt import (
    ObstacleField,
    closest_approach,
    eq9_coefficients,
    eq9_roots,
    segments_hit_circles,
)


def hit(p0, t0, p1, t1, c, v, r):
    """One segment against one circle; positions as (x, y)."""
    return bool(segments_hit_circles(p0[0], p0[1], t0, p1[0], p1[1], t1, c[0], c[1], v[0], v[1], r))


def test_crossing_a_static_circle_hits():
    # boat along y = 0 from x = -10 to 10 in 10 s through a circle of radius 2 at the origin
    assert hit((-10, 0), 0, (10, 0), 10, (0, 0), (0, 0), 2.0)


def test_passing_beside_a_static_circle_misses():
    assert not hit((-10, 3), 0, (10, 3), 10, (0, 0), (0, 0), 2.0)


def test_tangent_is_not_a_hit():
    # closest distance exactly equals the radius
    assert not hit((-10, 2), 0, (10, 2), 10, (0, 0), (0, 0), 2.0)
    assert hit((-10, 1.999), 0, (10, 1.999), 10, (0, 0), (0, 0), 2.0)


def test_crossing_obstacle_hand_computed_roots():
    # boat (0,0)->(10,0) at 1 m/s; obstacle from (5,-5) northwards at 1 m/s, r = 1.
    # relative position d(tau) = (-5 + tau, 5 - tau): |d|^2 = 2 (5 - tau)^2 -> closest 0 at tau = 5
    a, b, c = eq9_coefficients(0.0, 0.0, 0.0, 10.0, 0.0, 10.0, 5.0, -5.0, 0.0, 1.0, 1.0)
    assert (a, b, c) == pytest.approx((2.0, -20.0, 49.0))
    tau1, tau2 = eq9_roots(a, b, c)
    assert tau1 == pytest.approx(5 - 1 / math.sqrt(2))
    assert tau2 == pytest.approx(5 + 1 / math.sqrt(2))
    assert hit((0, 0), 0, (10, 0), 10, (5, -5), (0, 1), 1.0)


def test_relative_motion_sign_matters():
    # the same obstacle moving southwards never meets the boat (the paper's printed "+V t"
    # sign would make it collide)
    assert not hit((0, 0), 0, (10, 0), 10, (5, -5), (0, -1), 1.0)


def test_collision_outside_the_time_window_is_ignored():
    # the crossing obstacle arrives at the boat's track at t = 5 s, but this segment ends at 4 s
    assert not hit((0, 0), 0, (4, 0), 4, (5, -5), (0, 1), 1.0)
    # and a later segment that starts after the encounter is also clear
    assert not hit((7, 0), 7, (10, 0), 10, (5, -5), (0, 1), 1.0)


def test_segment_window_uses_absolute_time():
    # obstacle from (5, -10) northwards at 1 m/s reaches (5, 0) at t = 10 s
    # a segment over t in [5, 15] has the boat at (5, 0) at t = 10 s: contact
    assert hit((0, 0), 5, (10, 0), 15, (5, -10), (0, 1), 1.0)
    # the same track over t in [0, 10] passes (5, 0) at t = 5 s, closest 3.54 m: clear
    assert not hit((0, 0), 0, (10, 0), 10, (5, -10), (0, 1), 1.0)


def test_parallel_motion_keeps_distance():
    # obstacle moving alongside at the boat's velocity, 3 m away: never closer than 3 m
    assert not hit((0, 0), 0, (10, 0), 10, (0, 3), (1, 0), 2.5)
    assert hit((0, 0), 0, (10, 0), 10, (0, 2), (1, 0), 2.5)


def test_overtaking_a_slower_obstacle():
    # obstacle 6 m ahead at 0.5 m/s, boat at 1 m/s: gap closes at 0.5 m/s, contact (r = 2)
    # when the gap is 2 m, after 8 s
    assert hit((0, 0), 0, (10, 0), 10, (6, 0), (0.5, 0), 2.0)
    assert not hit((0, 0), 0, (7.9, 0), 7.9, (6, 0), (0.5, 0), 2.0)


def test_obstacle_starting_inside_hits():
    assert hit((0, 0), 0, (10, 0), 10, (0.5, 0.5), (0, 0), 2.0)


def test_ending_inside_hits():
    assert hit((-10, 0), 0, (0, 0), 10, (0.5, 0), (0, 0), 1.0)


def test_field_hits_shape_and_values():
    field = ObstacleField(
        centre=np.array([[0.0, 0.0], [50.0, 0.0]]), velocity=np.zeros((2, 2)),
        radius=np.array([1.0, 1.0]), inflated=np.array([2.0, 2.0]),
    )
    x0, y0, t0 = np.array([-10.0, -10.0, 40.0]), np.array([0.0, 5.0, 0.0]), np.zeros(3)
    x1, y1, t1 = np.array([10.0, 10.0, 60.0]), np.array([0.0, 5.0, 0.0]), np.full(3, 20.0)
    hits = field.hits(x0, y0, t0, x1, y1, t1)
    assert hits.shape == (2, 3)
    assert hits.tolist() == [[True, False, False], [False, False, True]]
    assert field.hits(x0, y0, t0, x1, y1, t1, inflated=False)[0, 0]


coord = st.floats(-50, 50, allow_nan=False)
vel = st.floats(-3, 3, allow_nan=False)


@settings(max_examples=400, deadline=None)
@given(coord, coord, coord, coord, st.floats(0.1, 30), st.floats(0, 30),
       coord, coord, vel, vel, st.floats(0.2, 10))
def test_hit_test_agrees_with_the_roots_and_closest_approach(
    x0, y0, x1, y1, dt, t0, cx, cy, vx, vy, r
):
    """Three routes to the same answer: the root window, the closest approach, the hit test."""
    t1 = t0 + dt
    got = hit((x0, y0), t0, (x1, y1), t1, (cx, cy), (vx, vy), r)
    d = float(closest_approach(x0, y0, t0, x1, y1, t1, cx, cy, vx, vy))
    if abs(d - r) > 1e-6 * max(1.0, r):  # away from tangency the answers must agree exactly
        assert got == (d < r)
    a, b, c = eq9_coefficients(x0, y0, t0, x1, y1, t1, cx, cy, vx, vy, r)
    if c < -1e-9:
        assert got  # starts inside
    elif a > 1e-9:
        tau1, tau2 = eq9_roots(a, b, c)
        if not math.isnan(tau1) and min(tau2, dt) - max(tau1, 0.0) > 1e-6:
            assert got  # the roots' open interval overlaps the window


@settings(max_examples=200, deadline=None)
@given(coord, coord, coord, coord, st.floats(0.1, 30), coord, coord, vel, vel)
def test_closest_approach_matches_dense_sampling(x0, y0, x1, y1, dt, cx, cy, vx, vy):
    s = np.linspace(0.0, 1.0, 2001)
    px, py = x0 + (x1 - x0) * s, y0 + (y1 - y0) * s
    ox, oy = cx + vx * dt * s, cy + vy * dt * s
    sampled = np.min(np.hypot(px - ox, py - oy))
    exact = float(closest_approach(x0, y0, 0.0, x1, y1, dt, cx, cy, vx, vy))
    assert exact <= sampled + 1e-9
    assert sampled - exact <= 0.1  # the sampling step bounds the gap
