"""The exact validator's geometry (issue 12), against dense sampling: timing-margin distance and
the planner's circle chains that stand for a swept moving obstacle."""

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from usvstation.planning.problem import sweep_moving
from usvstation.planning.validate import closest_distance

coord = st.floats(-50, 50, allow_nan=False)
vel = st.floats(-8, 8, allow_nan=False)


@settings(max_examples=150, deadline=None)
@given(x0=coord, y0=coord, x1=coord, y1=coord, t0=st.floats(0, 20), dt=st.floats(0.5, 20),
       ox=coord, oy=coord, vx=vel, vy=vel, margin=st.floats(0, 5))
def test_margin_distance_is_the_least_over_time_and_shift(x0, y0, x1, y1, t0, dt, ox, oy, vx, vy,
                                                           margin):
    a = {"x": x0, "y": y0, "t": t0}
    b = {"x": x1, "y": y1, "t": t0 + dt}
    exact = closest_distance(a, b, ox, oy, vx, vy, margin)
    s = np.linspace(0.0, 1.0, 201)[:, None]
    d = np.linspace(-margin, margin, 41)[None, :]
    px, py, t = x0 + s * (x1 - x0), y0 + s * (y1 - y0), t0 + s * dt
    sampled = np.hypot(px - (ox + vx * (t + d)), py - (oy + vy * (t + d))).min()
    # sampling never goes below the exact least distance, and finds it to within its grid
    step = math.hypot(x1 - x0, y1 - y0) / 200 + math.hypot(vx, vy) * (dt / 200 + margin / 20)
    assert exact <= sampled + 1e-9
    assert sampled - exact <= step + 1e-6


@settings(max_examples=100, deadline=None)
@given(vx=vel, vy=vel, r=st.floats(0.5, 10), margin=st.floats(0.1, 5),
       u=st.floats(-1, 1), w=st.floats(-1, 1))
def test_circle_chain_covers_the_swept_capsule(vx, vy, r, margin, u, w):
    centre, velocity = np.array([[3.0, -2.0]]), np.array([[vx, vy]])
    c, _v, _r, infl, src = sweep_moving(centre, velocity, np.array([r]), np.array([r]), margin)
    assert set(src.tolist()) == {0}
    # a point of the capsule: on the swept track at shift u * margin, within r of it
    shift = u * margin
    ang = w * math.pi
    p = centre[0] + velocity[0] * shift + 0.999 * r * np.array([math.cos(ang), math.sin(ang)])
    assert np.any(np.hypot(c[:, 0] - p[0], c[:, 1] - p[1]) <= infl + 1e-9)
