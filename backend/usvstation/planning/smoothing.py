"""B-spline smoothing of a planned path (the beta-spline curves of paper 000 Figs. 14 and 17).

The waypoints (x, y, t) are the control polygon of a clamped B-spline: the
curve starts at the start, ends at the goal tangent to the last segment (so
a recovery still arrives along the ramp axis), stays inside the convex hull
of neighbouring waypoints, and its time t(u) is monotone because the control
times increase. The smoothed trajectory is then itself checked against the
moving inflated obstacles with the exact segment test of eq. 9 on a dense
polyline; if a cubic curve cuts a corner into an obstacle, a quadratic
(closer to the polygon) is tried before giving up.
"""

from __future__ import annotations

import numpy as np
from scipy.interpolate import BSpline

from usvstation.planning.xyt import ObstacleField

SAMPLES_PER_SEGMENT = 12


def clamped_bspline(control: np.ndarray, degree: int) -> BSpline:
    """Clamped uniform B-spline over u in [0, 1] with the given control points (n, d)."""
    n = control.shape[0]
    k = min(degree, n - 1)
    inner = np.linspace(0.0, 1.0, n - k + 1)[1:-1]
    knots = np.concatenate([np.zeros(k + 1), inner, np.ones(k + 1)])
    return BSpline(knots, control, k)


def smooth_path(x: np.ndarray, y: np.ndarray, t: np.ndarray, field: ObstacleField) -> dict:
    """Smoothed trajectory samples and whether they stay clear of inflated obstacles."""
    control = np.column_stack([x, y, t])
    result: dict = {}
    for degree in (3, 2):
        curve = clamped_bspline(control, degree)
        u = np.linspace(0.0, 1.0, SAMPLES_PER_SEGMENT * (len(x) - 1) + 1)
        pts = curve(u)
        vel = curve.derivative()(u)
        free, clearance = _check(pts, field)
        dt_du = np.maximum(vel[:, 2], 1e-12)
        speed = np.hypot(vel[:, 0], vel[:, 1]) / dt_du
        heading = np.degrees(np.arctan2(vel[:, 1], vel[:, 0])) % 360.0
        result = {
            "degree": int(curve.k),
            "collision_free": bool(free),
            "min_clearance_m": None if clearance is None else round(clearance, 6),
            "points": [
                {"x": round(a, 6), "y": round(b, 6), "t": round(c, 6), "speed": round(s, 6),
                 "heading_deg": round(h, 6)}
                for a, b, c, s, h in np.column_stack([pts, speed, heading]).tolist()
            ],
        }
        if free:
            break
    return result


def _check(pts: np.ndarray, field: ObstacleField) -> tuple[bool, float | None]:
    if field.count == 0:
        return True, None
    x, y, t = pts[:, 0], pts[:, 1], pts[:, 2]
    hits = field.hits(x[:-1], y[:-1], t[:-1], x[1:], y[1:], t[1:])
    return (not bool(hits.any())), field.clearance(x, y, t)
