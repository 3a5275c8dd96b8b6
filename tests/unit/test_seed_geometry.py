"""Shared geometry of the seed planners: turn limit, speed profile, timed checks."""

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from usvstation.planning.seeds.common import (
    World,
    limit_turns,
    path_metrics,
    speed_profile,
    turns_deg,
)
from usvstation.planning.seeds.rrt import bspline_path
from usvstation.planning.xyt import closest_approach
from usvstation.scenario import parse_scenario

coord = st.floats(-200.0, 200.0, allow_nan=False)
polyline = st.lists(st.tuples(coord, coord), min_size=2, max_size=12).map(
    lambda p: np.array(p, float)).filter(
    lambda p: np.all(np.hypot(*np.diff(p, axis=0).T) > 0.5))


@given(polyline, st.floats(30.0, 170.0))
@settings(max_examples=200, deadline=None)
def test_limit_turns_keeps_ends_and_meets_the_limit(pts, limit):
    out = limit_turns(pts, limit, cut=5.0)
    assert np.allclose(out[0], pts[0]) and np.allclose(out[-1], pts[-1])
    tr = turns_deg(out)
    assert tr.size == 0 or tr.max() <= limit


def _scenario(speed0, vmin, vmax, accel):
    return parse_scenario({
        "name": "s", "kind": "transit", "start": {"x": 0.0, "y": 0.0, "speed": speed0},
        "goal": {"x": 100.0, "y": 0.0},
        "vessel": {"speed_min": vmin, "speed_max": vmax, "accel_max": accel}})


@given(polyline, st.floats(0.0, 4.0), st.floats(0.3, 3.0), st.floats(0.05, 2.0),
       st.floats(0.1, 4.0))
@settings(max_examples=200, deadline=None)
def test_speed_profile_respects_limits(pts, v0, cruise, accel, vspan):
    sc = _scenario(v0, 0.2, 0.2 + vspan, accel)
    t, v = speed_profile(pts, sc, min(max(cruise, 0.2), 0.2 + vspan))
    assert t[0] == 0.0 and np.all(np.diff(t) > 0)
    assert np.all(v >= 0.2 - 1e-12) and np.all(v <= 0.2 + vspan + 1e-12)
    dv_dt = np.abs(np.diff(v)) / np.diff(t)
    assert np.all(dv_dt <= accel * (1 + 1e-9))


@given(st.floats(-30, 30), st.floats(-30, 30), st.floats(-2, 2), st.floats(-2, 2),
       st.floats(0.5, 10))
@settings(max_examples=300, deadline=None)
def test_timed_segment_check_agrees_with_closest_approach(cx, cy, vx, vy, r):
    w = World(np.array([cx]), np.array([cy]), np.array([vx]), np.array([vy]),
              np.array([r]), np.array([r]))
    p0, p1 = np.array([[-20.0, 0.0]]), np.array([[20.0, 5.0]])
    hit = w.segments_hit(p0, 0.0, p1, 20.0)[0]
    d = float(closest_approach(-20.0, 0.0, 0.0, 20.0, 5.0, 20.0, cx, cy, vx, vy))
    if abs(d - r) > 1e-6:
        assert hit == (d < r)


def test_bspline_never_shorter_than_the_polyline():
    rng = np.random.default_rng(0)
    for _ in range(20):
        pts = np.cumsum(rng.normal(0.0, 10.0, size=(8, 2)), axis=0)
        spline = bspline_path(pts, 0.5)
        assert path_metrics(spline)["length_m"] >= path_metrics(pts)["length_m"] - 1e-6
        assert np.allclose(spline[0], pts[0]) and np.allclose(spline[-1], pts[-1])


def test_swept_corridor_covers_the_track():
    """With a band that admits any meeting time, the corridor is the whole track."""
    w = World(np.array([0.0]), np.array([0.0]), np.array([1.0]), np.array([0.0]),
              np.array([2.0]), np.array([3.0]))
    s = w.swept_window(np.array([0.0, 0.0]), 1.0, 10.0, slow=1e9, fast=1e9)
    assert not s.moving.any()
    for t in np.linspace(0.0, 10.0, 41):
        assert not s.points_free(np.array([[t, 0.0]]), 0.0)[0]
    assert s.points_free(np.array([[13.5, 0.0]]), 0.0)[0]
    assert math.isclose(float(s.cx.max()), 10.0)
