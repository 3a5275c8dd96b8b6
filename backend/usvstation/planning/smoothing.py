"""B-spline smoothing of a planned path (the beta-spline curves of paper 000 Figs. 14 and 17).

The waypoints (x, y, t) are the control polygon of a clamped B-spline: the
curve starts at the start, ends at the goal tangent to the last segment (so
a recovery still arrives along the ramp axis), stays inside the convex hull
of neighbouring waypoints, and its time t(u) is monotone because the control
times increase. The smoothed trajectory is then itself checked against the
moving inflated obstacles with the exact segment test of eq. 9 on a dense
polyline; if a cubic curve cuts a corner into an obstacle, a quadratic
(closer to the polygon) is tried, then the cubic curve is repaired with more
control points on the polygon where it hits, before giving up (issue 27).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from usvstation.planning import kernel_geom
from usvstation.planning.xyt import ObstacleField

if TYPE_CHECKING:
    from scipy.interpolate import BSpline

SAMPLES_PER_SEGMENT = 12


def clamped_bspline(control: np.ndarray, degree: int) -> BSpline:
    """Clamped uniform B-spline over u in [0, 1] with the given control points (n, d)."""
    n = control.shape[0]
    k = min(degree, n - 1)
    inner = np.linspace(0.0, 1.0, n - k + 1)[1:-1]
    knots = np.concatenate([np.zeros(k + 1), inner, np.ones(k + 1)])
    from scipy.interpolate import BSpline  # here: serve starts without scipy

    return BSpline(knots, control, k)


def smooth_path(x: np.ndarray, y: np.ndarray, t: np.ndarray, field: ObstacleField) -> dict:
    """Smoothed trajectory samples and whether they stay clear of inflated obstacles.

    The cubic curve, else the quadratic one; where both cut a corner into an obstacle the
    cubic curve is repaired before it is given up (`repair`): control points are added
    on the polygon next to the samples that hit, which pulls the curve towards the
    waypoints' polygon there, itself clear. `repaired` counts the points added.
    """
    control = np.column_stack([x, y, t])
    result: dict = {}
    for degree in (3, 2):
        result, _ = _sample(control, degree, field)
        if result["collision_free"]:
            return result
    return repair(control, 3, field) or result


REPAIR_ROUNDS = 8  # rounds of added control points before the smoothed path is dropped


def repair(control: np.ndarray, degree: int, field: ObstacleField) -> dict | None:
    """The curve of `control` made clear by adding control points: in each round the
    midpoint of every polygon segment that shapes a colliding sample's knot span (x, y
    and t halfway: the polygon, linear in time, is unchanged). A clamped B-spline lies
    in the convex hull of each degree + 1 consecutive control points, so the curve
    closes in on the polygon where points are added. None when `REPAIR_ROUNDS` do not
    clear it."""
    ctrl = control
    for _ in range(REPAIR_ROUNDS):
        result, bad = _sample(ctrl, degree, field)
        if result["collision_free"]:
            result["repaired"] = ctrl.shape[0] - control.shape[0]
            return result
        ctrl = _refine(ctrl, degree, bad)
    result, _ = _sample(ctrl, degree, field)
    if result["collision_free"]:
        result["repaired"] = ctrl.shape[0] - control.shape[0]
        return result
    return None


def _refine(ctrl: np.ndarray, degree: int, bad_u: np.ndarray) -> np.ndarray:
    """`ctrl` with the midpoints of the polygon segments that shape the knot spans holding
    the parameters `bad_u`."""
    n = ctrl.shape[0]
    k = min(degree, n - 1)
    spans = np.minimum((bad_u * (n - k)).astype(np.int64), n - k - 1)  # uniform inner knots
    segments = np.unique((spans[:, None] + np.arange(k)[None, :]).ravel())
    mids = 0.5 * (ctrl[segments] + ctrl[segments + 1])
    return np.insert(ctrl, segments + 1, mids, axis=0)


def _sample(control: np.ndarray, degree: int, field: ObstacleField,
            ) -> tuple[dict, np.ndarray]:
    """The curve's samples as the plan's `smoothed` entry, and the parameters of the
    samples that begin a colliding sample segment."""
    curve = clamped_bspline(control, degree)
    u = np.linspace(0.0, 1.0, SAMPLES_PER_SEGMENT * (control.shape[0] - 1) + 1)
    pts = curve(u)
    vel = curve.derivative()(u)
    hits, clearance = _check(pts, field)
    dt_du = np.maximum(vel[:, 2], 1e-12)
    speed = np.hypot(vel[:, 0], vel[:, 1]) / dt_du
    heading = np.degrees(np.arctan2(vel[:, 1], vel[:, 0])) % 360.0
    result = {
        "degree": int(curve.k),
        "collision_free": not bool(hits.any()),
        "min_clearance_m": None if clearance is None else round(clearance, 6),
        "points": [
            {"x": round(a, 6), "y": round(b, 6), "t": round(c, 6), "speed": round(s, 6),
             "heading_deg": round(h, 6)}
            for a, b, c, s, h in np.column_stack([pts, speed, heading]).tolist()
        ],
    }
    return result, u[:-1][hits]


def _check(pts: np.ndarray, field: ObstacleField) -> tuple[np.ndarray, float | None]:
    """Per sample segment: does it enter an inflated obstacle (eq. 9); and the least
    distance from the samples to an obstacle's edge (None without obstacles)."""
    if field.count == 0:
        return np.zeros(pts.shape[0] - 1, dtype=bool), None
    x, y, t = (np.ascontiguousarray(pts[:, i]) for i in range(3))
    if kernel_geom.AVAILABLE:
        c, w = np.ascontiguousarray(field.centre), np.ascontiguousarray(field.velocity)
        return (kernel_geom.polyline_hits(x, y, t, c, w, np.ascontiguousarray(field.inflated)),
                kernel_geom.field_clearance(x, y, t, c, w, np.ascontiguousarray(field.radius)))
    hits = field.hits(x[:-1], y[:-1], t[:-1], x[1:], y[1:], t[1:]).any(axis=0)
    return hits, field.clearance(x, y, t)
