"""Eq. 12 of a batch of decoded paths in one compiled call (numba, issue 27).

At the public cases' sizes (60-120 paths of 6-16 waypoints) the NumPy
evaluator (`fitness.Evaluator.fitness_numpy`, the tested reference) spends
most of its time in the fixed cost of about 40 NumPy calls per batch. This
kernel does the same arithmetic path by path in one call: the hard gates
(acceleration, speed, turn, first turn, speed through the water), the
collision test of eq. 9 over the evaluator's precomputed (segment,
obstacle) pairs, stopping at a path's first hit and skipping the pairs whose
circle, swept over the segment's time window, cannot reach the segment's box
(by more than `SLACK`), the four terms and eq. 12.
Every expression is written in the reference's order, so the values agree
bit for bit (tests/unit/test_plan_kernel.py checks it on random inputs); the
transcendental functions whose NumPy versions are vectorised differently from
libm (arctan2, sin, cos) stay in NumPy: the headings and the first-turn flags
come in as arrays.

Compiled with `cache=True` (planning/warm.py loads or compiles every kernel of the
planner once per process; `bench planner` reports the cold start); without numba
the evaluator falls back to the NumPy reference.
"""

from __future__ import annotations

import math

import numpy as np

try:
    from numba import njit
except ImportError:  # pragma: no cover - numba is a dependency; NumPy is the fallback
    njit = None

AVAILABLE = njit is not None
_EPS = 1e-9
# m: a pair is skipped only when its swept circle stays this much further than its radius
# from the segment's box, far beyond eq. 9's rounding (1e-7 m at 20 km), so that the skip
# never changes a verdict
SLACK = 1e-6


def _eq12_batch(x: np.ndarray, y: np.ndarray, v: np.ndarray, t: np.ndarray,
                seg_len: np.ndarray, heading: np.ndarray, first_bad: np.ndarray,
                pair_seg: np.ndarray, pair_obs: np.ndarray, limits: np.ndarray,
                weights: np.ndarray) -> np.ndarray:  # pragma: no cover - compiled
    """Fitness (eq. 12) of paths given as (N, P) arrays of waypoints (one path per column),
    their (N - 1, P) segment lengths and headings and (P,) first-turn violations.

    limits = (accel_max, speed_min, speed_max, turn_max, current x, current y,
    distance); weights = (a, b, c, d, A, normalised).
    pair_obs rows: (cx, cy, vx, vy, inflated radius) of pair k's obstacle, pair_seg[k]
    its segment.
    """
    n, p = x.shape
    accel, vmin, vmax, turn_max, cx, cy, dist = (
        limits[0], limits[1], limits[2], limits[3], limits[4], limits[5], limits[6])
    wa, wb, wc, wd, scale, normalised = (weights[0], weights[1], weights[2], weights[3],
                                         weights[4], weights[5])
    current = cx != 0.0 or cy != 0.0
    c2 = cx * cx + cy * cy
    lo2 = (vmin * (1 - 1e-6)) ** 2
    hi2 = (vmax * (1 + 1e-6)) ** 2
    acc_lim = 2.0 * accel * (1.0 + _EPS)
    out = np.zeros(p)
    for j in range(p):
        ok = not first_bad[j]
        for i in range(n):
            vi = v[i, j]
            if vi < vmin - _EPS or vi > vmax + _EPS:
                ok = False
        for i in range(n - 1):
            dx = x[i + 1, j] - x[i, j]
            dy = y[i + 1, j] - y[i, j]
            length = seg_len[i, j]
            v0, v1 = v[i, j], v[i + 1, j]
            if abs(v1 * v1 - v0 * v0) > acc_lim * (length + _EPS) or length <= _EPS:
                ok = False
            if current:
                along = (dx * cx + dy * cy) / max(length, _EPS)
                w0 = v0 * (v0 - 2.0 * along) + c2
                w1 = v1 * (v1 - 2.0 * along) + c2
                if (w0 < lo2 or w0 > hi2 or v0 <= along or w1 < lo2 or w1 > hi2
                        or v1 <= along):
                    ok = False
        turn_sum = 0.0
        for i in range(n - 2):
            d = heading[i + 1, j] - heading[i, j]
            turn = abs((d + math.pi) % (2.0 * math.pi) - math.pi)
            turn_sum = turn if i == 0 else turn_sum + turn
            if turn > turn_max + _EPS:
                ok = False
        if not ok:
            continue
        for k in range(pair_seg.shape[0]):
            s0 = pair_seg[k]
            s1 = s0 + 1
            ox, oy, ovx, ovy, r = (pair_obs[k, 0], pair_obs[k, 1], pair_obs[k, 2],
                                   pair_obs[k, 3], pair_obs[k, 4])
            t0, t1 = t[s0, j], t[s1, j]
            # skip a pair whose circle, swept over the segment's time window, stays further
            # than r + SLACK from the segment's box in x or in y: it cannot meet it
            sx0, sx1, sy0, sy1 = ovx * t0, ovx * t1, ovy * t0, ovy * t1
            reach = r + SLACK
            if (ox + min(sx0, sx1) - reach > max(x[s0, j], x[s1, j])
                    or ox + max(sx0, sx1) + reach < min(x[s0, j], x[s1, j])
                    or oy + min(sy0, sy1) - reach > max(y[s0, j], y[s1, j])
                    or oy + max(sy0, sy1) + reach < min(y[s0, j], y[s1, j])):
                continue
            ex0 = x[s0, j] - (ox + ovx * t0)
            ey0 = y[s0, j] - (oy + ovy * t0)
            ex1 = x[s1, j] - (ox + ovx * t1)
            ey1 = y[s1, j] - (oy + ovy * t1)
            r2 = r * r
            q0 = ex0 * ex0 + ey0 * ey0 - r2
            q1 = ex1 * ex1 + ey1 * ey1 - r2
            ddx, ddy = ex1 - ex0, ey1 - ey0
            a = ddx * ddx + ddy * ddy
            b = q1 - q0 - a
            if q0 < 0.0 or q1 < 0.0 or (b < 0.0 and b > -2.0 * a and b * b > 4.0 * a * q0):
                ok = False
                break
        if not ok:
            continue
        len_sum = seg_len[0, j]
        for i in range(1, n - 1):
            len_sum += seg_len[i, j]
        mal = abs(y[0, j])
        for i in range(1, n):
            mal += abs(y[i, j])
        fit_mal = mal / n
        fit_d = len_sum / dist
        fit_ang = (turn_sum if n > 2 else 0.0) / math.pi
        if normalised:
            t_term = t[n - 1, j] * vmax / dist
            mal_term = fit_mal / dist
        else:
            t_term = t[n - 1, j] / (n - 1)
            mal_term = fit_mal
        denom = wa * fit_d + wb * t_term
        denom += wc * fit_ang
        denom += wd * mal_term
        out[j] = scale / denom
    return out


eq12_batch = njit(cache=True, nogil=True)(_eq12_batch) if AVAILABLE else None
