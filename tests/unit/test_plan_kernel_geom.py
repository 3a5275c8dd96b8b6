"""The compiled polyline-against-circles kernels (planning/kernel_geom.py) equal their NumPy
and Python references bit for bit; the smoothed path is repaired before it is dropped."""

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from usvstation.planning import kernel_geom
from usvstation.planning.smoothing import clamped_bspline, smooth_path
from usvstation.planning.validate import clearance_matrix, closest_distance
from usvstation.planning.xyt import ObstacleField
from usvstation.scenario import parse_scenario

pytestmark = pytest.mark.skipif(not kernel_geom.AVAILABLE, reason="numba is not installed")


def _field(rng: np.random.Generator, m: int, spread: float) -> ObstacleField:
    centre = rng.uniform(-spread, spread, size=(m, 2))
    velocity = np.where(rng.random((m, 1)) < 0.5, 0.0, rng.normal(0.0, 1.0, size=(m, 2)))
    radius = rng.uniform(0.3, 6.0, size=m)
    return ObstacleField(centre, velocity, radius, radius + rng.uniform(0.0, 3.0, size=m))


def _polyline(rng: np.random.Generator, n: int, spread: float):
    x, y = rng.uniform(-spread, spread, size=(2, n))
    t = np.cumsum(rng.uniform(0.0, 5.0, size=n))  # a repeated time now and then: dt = 0
    t[rng.random(n) < 0.1] = t[0]
    return x, y, np.sort(t)


@settings(max_examples=80, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(2, 40), m=st.integers(1, 30),
       spread=st.sampled_from([5.0, 30.0, 300.0]))
def test_polyline_kernels_equal_the_numpy_references(seed, n, m, spread):
    rng = np.random.default_rng(seed)
    f = _field(rng, m, spread)
    x, y, t = _polyline(rng, n, spread)
    want_hits = f.hits(x[:-1], y[:-1], t[:-1], x[1:], y[1:], t[1:]).any(axis=0)
    got = kernel_geom.polyline_hits(x, y, t, f.centre, f.velocity, f.inflated)
    np.testing.assert_array_equal(got, want_hits)
    assert kernel_geom.field_clearance(x, y, t, f.centre, f.velocity, f.radius) == \
        f.clearance(x, y, t)


@settings(max_examples=60, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(2, 20), m=st.integers(1, 12),
       margin=st.sampled_from([0.0, 3.0, 10.0]))
def test_validator_kernels_equal_the_validator(seed, n, m, margin):
    rng = np.random.default_rng(seed)
    x, y, t = _polyline(rng, n, 60.0)
    f = _field(rng, m, 60.0)
    plan = {"waypoints": [{"x": float(a), "y": float(b), "t": float(c)}
                          for a, b, c in zip(x, y, t, strict=True)]}
    sc = parse_scenario({
        "name": "k", "start": {"x": 900.0, "y": 900.0}, "goal": {"x": -900.0, "y": 900.0},
        "kind": "transit",  # start and goal away from the circles: only these matter here
        "obstacles": [{"x": float(c[0]), "y": float(c[1]), "radius": float(r),
                       "vx": float(v[0]), "vy": float(v[1])}
                      for c, v, r in zip(f.centre, f.velocity, f.radius, strict=True)]})
    obs = sc.obstacles
    centre = np.array([[o.x, o.y] for o in obs])
    velocity = np.array([[o.vx, o.vy] for o in obs])
    r = np.array([o.radius for o in obs]) + sc.vessel.length / 2.0
    assert kernel_geom.hull_clearance(x, y, t, centre, velocity, r) == \
        float(clearance_matrix(plan, sc).min())
    margins = np.full(len(obs), margin)
    got = kernel_geom.swept_clearances(x, y, t, centre, velocity, margins)
    wps = plan["waypoints"]
    want = [[closest_distance(wps[i], wps[i + 1], o.x, o.y, o.vx, o.vy, margin) for o in obs]
            for i in range(len(wps) - 1)]
    # within rounding: the reference's math.hypot is CPython's, the kernel's libm's
    np.testing.assert_allclose(got, np.array(want), rtol=1e-15, atol=1e-12)


def test_a_smoothed_path_that_cuts_a_corner_is_repaired_not_dropped():
    """A right-angle turn round a buoy just inside the corner (1.7 m off both legs, 1.2 m
    in radius): the cubic and quadratic curves both cut the corner into it, the repaired
    cubic hugs the corner and stays clear, from the start to the goal, time increasing."""
    x, y = np.array([0.0, 10, 20, 20, 20]), np.array([0.0, 0, 0, 10, 20])
    t = np.array([0.0, 5, 10, 15, 20])
    r = np.array([1.2])
    field = ObstacleField(np.array([[18.3, 1.7]]), np.zeros((1, 2)), r, r)
    for degree in (3, 2):  # the unrepaired curves hit it
        pts = clamped_bspline(np.column_stack([x, y, t]), degree)(np.linspace(0, 1, 400))
        assert (np.hypot(pts[:, 0] - 18.3, pts[:, 1] - 1.7) < 1.2).any()
    out = smooth_path(x, y, t, field)
    assert out["collision_free"] and out["degree"] == 3 and out["repaired"] > 0
    pts = out["points"]
    assert (pts[0]["x"], pts[0]["y"], pts[-1]["x"], pts[-1]["y"]) == (0.0, 0.0, 20.0, 20.0)
    assert all(b["t"] > a["t"] for a, b in itertools.pairwise(pts))
    assert min(np.hypot(p["x"] - 18.3, p["y"] - 1.7) for p in pts) > 1.2


def test_a_path_with_no_clear_curve_is_dropped_after_the_repair():
    """An obstacle on the polygon itself: no curve near it is clear; the repair gives up."""
    x, y = np.array([0.0, 10, 20, 20, 20]), np.array([0.0, 0, 0, 10, 20])
    t = np.array([0.0, 5, 10, 15, 20])
    r = np.array([1.0])
    field = ObstacleField(np.array([[8.0, 0.0]]), np.zeros((1, 2)), r, r)
    assert not smooth_path(x, y, t, field)["collision_free"]
