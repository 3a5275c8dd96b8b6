"""A timed polyline against moving circles, in compiled loops (numba, issue 27).

Finishing a plan checks its smoothed path and measures its clearances against
every obstacle: (samples x obstacles) pairs, 180 x 1000 on a dense field, which
NumPy holds as a dozen temporaries of that size. These kernels walk the pairs
once, each expression in the NumPy reference's order, skipping the pairs that a box test
shows cannot meet (or cannot be nearer than the least clearance found so far) by more than
`kernel.SLACK`, so their results are the reference's bit for bit
(tests/unit/test_plan_kernel_geom.py; `swept_clearances` to within rounding, its
reference using CPython's math.hypot, which rounds differently from libm's):

- `polyline_hits`: per segment, does it enter an open circle (eq. 9,
  `ObstacleField.hits(...).any(axis=0)`);
- `field_clearance`: least distance from the polyline to a circle's edge
  (`ObstacleField.clearance`, closest approach of two linear motions);
- `hull_clearance`: the same in the validator's form (`validate.clearance_matrix(...)
  .min()`, the hull's half length added to the radii);
- `swept_clearances`: the validator's clearance of each segment to each moving
  obstacle shifted in time by up to +-m (`validate.closest_distance`, a
  parallelogram's distance to the origin).

Without numba the callers use the references.
"""

from __future__ import annotations

import math

import numpy as np

from usvstation.planning.kernel import AVAILABLE, SLACK, njit


def _polyline_hits(x: np.ndarray, y: np.ndarray, t: np.ndarray, centre: np.ndarray,
                   velocity: np.ndarray, r: np.ndarray) -> np.ndarray:  # pragma: no cover
    """(S,) True where segment s of the polyline (x, y, t) enters an open moving circle."""
    out = np.zeros(x.shape[0] - 1, np.bool_)
    for s in range(x.shape[0] - 1):
        for m in range(r.shape[0]):
            cx, cy, vx, vy = centre[m, 0], centre[m, 1], velocity[m, 0], velocity[m, 1]
            if _box_gap(x[s], y[s], t[s], x[s + 1], y[s + 1], t[s + 1], cx, cy, vx,
                        vy) > r[m] + SLACK:  # cannot meet: skipped (kernel.eq12_batch)
                continue
            ex0, ey0 = x[s] - (cx + vx * t[s]), y[s] - (cy + vy * t[s])
            ex1, ey1 = x[s + 1] - (cx + vx * t[s + 1]), y[s + 1] - (cy + vy * t[s + 1])
            r2 = r[m] * r[m]
            c0 = ex0 * ex0 + ey0 * ey0 - r2
            c1 = ex1 * ex1 + ey1 * ey1 - r2
            ddx, ddy = ex1 - ex0, ey1 - ey0
            a = ddx * ddx + ddy * ddy
            b = c1 - c0 - a
            if c0 < 0.0 or c1 < 0.0 or (b < 0.0 and b > -2.0 * a and b * b > 4.0 * a * c0):
                out[s] = True
                break
    return out


def _box_gap(x0: float, y0: float, t0: float, x1: float, y1: float, t1: float, cx: float,
             cy: float, vx: float, vy: float) -> float:  # pragma: no cover
    """A lower bound of the distance between the boat on segment (x0, y0, t0) -> (x1, y1,
    t1) and a centre moving from (cx, cy) at (vx, vy): the gap between the segment's box
    and the box the centre sweeps over [t0, t1] (the larger of the x and y gaps)."""
    gx = max(cx + min(vx * t0, vx * t1) - max(x0, x1), min(x0, x1) - cx - max(vx * t0, vx * t1))
    gy = max(cy + min(vy * t0, vy * t1) - max(y0, y1), min(y0, y1) - cy - max(vy * t0, vy * t1))
    return max(gx, gy, 0.0)


def _closest(ex: float, ey: float, dx: float, dy: float) -> float:  # pragma: no cover
    """|e + s d| at the s in [0, 1] closest to the origin (`xyt.closest_approach`)."""
    dd = dx * dx + dy * dy
    s = -(ex * dx + ey * dy) / dd if dd > 0.0 else 0.0
    s = min(max(s, 0.0), 1.0)
    return math.hypot(ex + s * dx, ey + s * dy)


def _field_clearance(x: np.ndarray, y: np.ndarray, t: np.ndarray, centre: np.ndarray,
                     velocity: np.ndarray, radius: np.ndarray) -> float:  # pragma: no cover
    """min over segments and circles of closest approach - radius (`ObstacleField.clearance`:
    e = (x0 - cx) - vx t0)."""
    best = math.inf
    for s in range(x.shape[0] - 1):
        dt = t[s + 1] - t[s]
        for m in range(radius.shape[0]):
            cx, cy, vx, vy = centre[m, 0], centre[m, 1], velocity[m, 0], velocity[m, 1]
            if _box_gap(x[s], y[s], t[s], x[s + 1], y[s + 1], t[s + 1], cx, cy, vx,
                        vy) - radius[m] > best + SLACK:  # cannot be nearer than the best
                continue
            ex, ey = x[s] - cx - vx * t[s], y[s] - cy - vy * t[s]
            dx, dy = (x[s + 1] - x[s]) - vx * dt, (y[s + 1] - y[s]) - vy * dt
            best = min(best, _closest(ex, ey, dx, dy) - radius[m])
    return best


def _hull_clearance(x: np.ndarray, y: np.ndarray, t: np.ndarray, centre: np.ndarray,
                    velocity: np.ndarray, r: np.ndarray) -> float:  # pragma: no cover
    """min over segments and circles of closest approach - r (`validate.clearance_matrix`:
    e = x0 - (cx + vx t0), r the radius plus half the hull)."""
    best = math.inf
    for s in range(x.shape[0] - 1):
        t0, t1 = t[s], t[s + 1]
        for m in range(r.shape[0]):
            ox, oy, vx, vy = centre[m, 0], centre[m, 1], velocity[m, 0], velocity[m, 1]
            if _box_gap(x[s], y[s], t0, x[s + 1], y[s + 1], t1, ox, oy, vx,
                        vy) - r[m] > best + SLACK:  # cannot be nearer than the best
                continue
            r0x, r0y = x[s] - (ox + vx * t0), y[s] - (oy + vy * t0)
            drx = (x[s + 1] - x[s]) - vx * (t1 - t0)
            dry = (y[s + 1] - y[s]) - vy * (t1 - t0)
            best = min(best, _closest(r0x, r0y, drx, dry) - r[m])
    return best


def _point_segment(ax: float, ay: float, bx: float, by: float) -> float:  # pragma: no cover
    """Distance from the origin to segment a-b (`validate._point_segment` at p = 0)."""
    dx, dy = bx - ax, by - ay
    dd = dx * dx + dy * dy
    s = 0.0 if dd == 0.0 else min(1.0, max(0.0, ((0.0 - ax) * dx + (0.0 - ay) * dy) / dd))
    return math.hypot(ax + s * dx - 0.0, ay + s * dy - 0.0)


def _swept_clearances(x: np.ndarray, y: np.ndarray, t: np.ndarray, centre: np.ndarray,
                      velocity: np.ndarray, margin: np.ndarray) -> np.ndarray:  # pragma: no cover
    """(S, M) least distance between the boat on each segment and each centre shifted in time
    by any d in [-margin, margin] (`validate.closest_distance`)."""
    n_seg, n_obs = x.shape[0] - 1, centre.shape[0]
    out = np.empty((n_seg, n_obs))
    cx = np.empty(4)
    cy = np.empty(4)
    for s in range(n_seg):
        dt = t[s + 1] - t[s]
        for m in range(n_obs):
            ox, oy, ovx, ovy = centre[m, 0], centre[m, 1], velocity[m, 0], velocity[m, 1]
            r0x = x[s] - (ox + ovx * t[s])
            r0y = y[s] - (oy + ovy * t[s])
            drx = (x[s + 1] - x[s]) - ovx * dt
            dry = (y[s + 1] - y[s]) - ovy * dt
            if margin[m] <= 0.0 or (ovx == 0.0 and ovy == 0.0):
                out[s, m] = _point_segment(r0x, r0y, r0x + drx, r0y + dry)
                continue
            qx, qy = -ovx * margin[m], -ovy * margin[m]
            cx[0], cy[0] = r0x - qx, r0y - qy
            cx[1], cy[1] = r0x + drx - qx, r0y + dry - qy
            cx[2], cy[2] = r0x + drx + qx, r0y + dry + qy
            cx[3], cy[3] = r0x + qx, r0y + qy
            positive = negative = True
            for k in range(4):
                ax, ay, bx, by = cx[k], cy[k], cx[(k + 1) % 4], cy[(k + 1) % 4]
                side = (bx - ax) * (0.0 - ay) - (by - ay) * (0.0 - ax)
                positive = positive and side > 0.0
                negative = negative and side < 0.0
            if positive or negative:
                out[s, m] = 0.0
                continue
            best = _point_segment(cx[0], cy[0], cx[1], cy[1])
            for k in range(1, 4):
                best = min(best, _point_segment(cx[k], cy[k], cx[(k + 1) % 4], cy[(k + 1) % 4]))
            out[s, m] = best
    return out


if AVAILABLE:
    _jit = njit(cache=True, nogil=True, error_model="numpy")
    _closest, _point_segment, _box_gap = _jit(_closest), _jit(_point_segment), _jit(_box_gap)
    polyline_hits, field_clearance, hull_clearance, swept_clearances = (
        _jit(f) for f in (_polyline_hits, _field_clearance, _hull_clearance,
                          _swept_clearances))
else:  # pragma: no cover - numba is a dependency; the callers then use NumPy
    polyline_hits = field_clearance = hull_clearance = swept_clearances = None
