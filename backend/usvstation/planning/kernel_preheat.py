"""One preheating draw in compiled calls (numba, issue 27): Algorithm 1 lines 5-15.

A draw proposes `candidates` points for every pending individual of a
waypoint block and keeps one admissible point per individual
(`preheat._Grower._draw`, the NumPy reference). Its NumPy form costs about
60 NumPy calls, most of their time fixed overhead at the public cases'
sizes. Here the arithmetic runs element by element in four kernels, each
expression in the reference's order, so the kept points, speeds, times and
blocked counts are the reference's bit for bit
(tests/unit/test_plan_kernel_preheat.py). Between the kernels the caller
draws the random numbers with NumPy's generator (in the reference's order and
shapes) and applies the transcendental functions (arctan2 of the aim, tan of
the drawn bearing, arctan2 of the segments) with NumPy, whose vectorised
versions differ from libm in the last bit:

    aim_args   -> np.arctan2 -> slopes -> np.tan -> place_y -> np.arctan2 -> finish

`finish` tests each candidate segment against the obstacles of its block
(eq. 9), pruned exactly as the reference prunes them (by the draw's x-y-t box
when the draw is large, then by each individual's box from 16 obstacles on),
counts the hits per obstacle for the failure report, and places the chosen
candidate in the walk's state and levels.
"""

from __future__ import annotations

import math

import numpy as np

from usvstation.planning.kernel import AVAILABLE, njit
from usvstation.planning.xyt import PRUNE_ELEMENTS

_EPS = 1e-9
_PAIR_MIN_OBSTACLES = 16  # as preheat._PAIR_MIN_OBSTACLES


def _np_min(a: float, b: float) -> float:  # pragma: no cover - compiled
    """np.minimum of two floats: NaN if either is NaN."""
    if a != a or b != b:
        return math.nan
    return a if a <= b else b


def _np_max(a: float, b: float) -> float:  # pragma: no cover - compiled
    """np.maximum of two floats: NaN if either is NaN."""
    if a != a or b != b:
        return math.nan
    return a if a >= b else b


def _py_min(a: float, b: float) -> float:  # pragma: no cover - compiled
    """Python's min(a, b): b only if b < a."""
    return b if b < a else a


def _py_max(a: float, b: float) -> float:  # pragma: no cover - compiled
    """Python's max(a, b): b only if b > a."""
    return b if b > a else a


def _aim_args(state: np.ndarray, idx: np.ndarray, toward_goal: bool, gx: float, gy: float,
              run_in: float, x_res: float) -> tuple:  # pragma: no cover - compiled
    """(ay - py, px - ax) of each pending walk (`_Grower._aim`): the arguments of the aim
    bearing's arctan2. `toward_goal`: aim at the goal (a transit, or the last block)."""
    n = idx.shape[0]
    num = np.empty(n)
    den = np.empty(n)
    for i in range(n):
        w = idx[i]
        px, py, join_x, aim_y = state[0, w], state[1, w], state[5, w], state[6, w]
        if toward_goal:
            ax, ay = gx, gy
        elif px > join_x + x_res:
            ax, ay = join_x, aim_y
        else:
            ax, ay = run_in, gy
        num[i] = ay - py
        den[i] = px - ax
    return num, den


def _slopes(state: np.ndarray, idx: np.ndarray, offset: np.ndarray, aim: np.ndarray,
            wide: bool, any_bearing: bool, turn_max: float, max_slope: float,
            spread: float) -> np.ndarray:  # pragma: no cover - compiled
    """The drawn bearing of every candidate (against -x), clipped into the turn window:
    uniform over the window when `wide`, else the aim (`aim`, per walk) plus `spread`
    times the offset. `any_bearing`: the first leg of a boat free to point anywhere."""
    n, c = offset.shape
    out = np.empty((n, c))
    for i in range(n):
        slope0 = state[4, idx[i]]
        if any_bearing:
            lo, hi = -max_slope, max_slope
        else:
            lo = _np_max(slope0 - turn_max, -max_slope)
            hi = _np_min(slope0 + turn_max, max_slope)
        for j in range(c):
            if wide:
                slope = lo + (hi - lo) * (offset[i, j] + 1.0) / 2.0
            else:
                slope = aim[i] + spread * offset[i, j]
            out[i, j] = _np_min(_np_max(slope, lo), hi)
    return out


def _place_y(state: np.ndarray, idx: np.ndarray, xl: np.ndarray, tan_slope: np.ndarray,
             x_min: float, x_base: int, x_res: float, cone: bool, cone_m: np.ndarray,
             y_res: float, y_lo: float, y_count: int, gx: float,
             gy: float) -> tuple:  # pragma: no cover - compiled
    """Candidate points on the y grid (the arrival cone's in the last block when `cone`):
    x, y, y level, the segment from the walk (dx = px - x, dy) and the goal leg's
    arctan2 arguments (gy - y, x - gx)."""
    n, c = xl.shape
    x = np.empty((n, c))
    y = np.empty((n, c))
    yl = np.empty((n, c), np.int64)
    dx = np.empty((n, c))
    dy = np.empty((n, c))
    gnum = np.empty((n, c))
    gden = np.empty((n, c))
    for i in range(n):
        w = idx[i]
        px, py = state[0, w], state[1, w]
        for j in range(c):
            xx = x_min + (x_base + xl[i, j]) * x_res
            ddx = px - xx
            yy = py + ddx * tan_slope[i, j]
            if cone:
                m = cone_m[xl[i, j]]
                cell = _np_min(_np_max(np.rint(yy / y_res), -m), m)
                yy, level = cell * y_res, np.int64(cell + m)
            else:
                cell = _np_max(np.rint((yy - y_lo) / y_res), 0)
                level = np.int64(_np_min(cell, y_count - 1))
                yy = y_lo + level * y_res
            x[i, j], y[i, j], yl[i, j], dx[i, j], dy[i, j] = xx, yy, level, ddx, yy - py
            gnum[i, j], gden[i, j] = gy - yy, xx - gx
    return x, y, yl, dx, dy, gnum, gden


def _speed_level(pv: float, pt: float, seg: float, ux: float, uy: float, u: float,
                 limits: np.ndarray) -> tuple:  # pragma: no cover - compiled
    """`_Grower._speed` of one candidate: (level, speed, time, admissible).

    limits = (2 accel_max, v_min^2, v_max^2, current x, current y, v_lo, v_res, levels).
    """
    reach, pv2 = limits[0] * seg, pv * pv
    vlo = math.sqrt(_np_max(pv2 - reach, limits[1]))
    vhi = math.sqrt(_np_min(pv2 + reach, limits[2]))
    cx, cy = limits[3], limits[4]
    if cx != 0.0 or cy != 0.0:
        along, across = ux * cx + uy * cy, ux * cy - uy * cx
        c2 = across * across
        vhi = _np_min(vhi, along + math.sqrt(_np_max(limits[2] - c2, 0.0)))
        if c2 >= limits[2]:
            vhi = -1.0
        vlo = _np_max(vlo, along + math.sqrt(_np_max(limits[1] - c2, 0.0)) + 1e-6)
    v_lo, v_res = limits[5], limits[6]
    jlo = max(np.int64(np.ceil((vlo - v_lo) / v_res - 1e-9)), 0)
    jhi = min(np.int64(np.floor((vhi - v_lo) / v_res + 1e-9)), np.int64(limits[7]) - 1)
    level = jhi if u >= 1.0 else min(jlo + np.int64(u * (jhi - jlo + 1)), jhi)
    v = v_lo + level * v_res
    return level, v, pt + 2.0 * seg / (pv + v), jlo <= jhi


def _water_bad(dx: float, dy: float, v0: float, v1: float, length: float,
               water: np.ndarray) -> bool:  # pragma: no cover - compiled
    """`fitness.water_speed_bad` of one segment; water = (cx, cy, |c|^2, lo^2, hi^2)."""
    along = (dx * water[0] + dy * water[1]) / _np_max(length, _EPS)
    c2, lo2, hi2 = water[2], water[3], water[4]
    w0, w1 = v0 * (v0 - 2.0 * along) + c2, v1 * (v1 - 2.0 * along) + c2
    return (w0 < lo2 or w0 > hi2 or v0 <= along or w1 < lo2 or w1 > hi2
            or v1 <= along)


def _hit(px: float, py: float, pt: float, x: float, y: float, t: float, cx: float, cy: float,
         vx: float, vy: float, r: float) -> bool:  # pragma: no cover - compiled
    """Eq. 9 in normalised time (`xyt.hits_from_relative`) for one segment and circle."""
    ex0, ey0 = px - (cx + vx * pt), py - (cy + vy * pt)
    ex1, ey1 = x - (cx + vx * t), y - (cy + vy * t)
    r2 = r * r
    c0 = ex0 * ex0 + ey0 * ey0 - r2
    c1 = ex1 * ex1 + ey1 * ey1 - r2
    ddx, ddy = ex1 - ex0, ey1 - ey0
    a = ddx * ddx + ddy * ddy
    b = c1 - c0 - a
    return c0 < 0.0 or c1 < 0.0 or (b < 0.0 and b > -2.0 * a and b * b > 4.0 * a * c0)


def _box_reaches(o: int, obs: np.ndarray, xlo: float, xhi: float, ylo: float, yhi: float,
                 tlo: float, thi: float) -> bool:  # pragma: no cover - compiled
    """Obstacle o's circle, swept over [tlo, thi], reaches the box (`preheat._near_box`)."""
    cx, cy, vx, vy, r = obs[o, 0], obs[o, 1], obs[o, 2], obs[o, 3], obs[o, 4]
    sx0, sx1, sy0, sy1 = vx * tlo, vx * thi, vy * tlo, vy * thi
    return (cx + _np_max(sx0, sx1) + r >= xlo and cx + _np_min(sx0, sx1) - r <= xhi
            and cy + _np_max(sy0, sy1) + r >= ylo and cy + _np_min(sy0, sy1) - r <= yhi)


def _free(x0: np.ndarray, y0: np.ndarray, t0: np.ndarray, x1: np.ndarray, y1: np.ndarray,
          t1: np.ndarray, obs: np.ndarray, index: np.ndarray, hits: np.ndarray,
          free: np.ndarray) -> None:  # pragma: no cover - compiled
    """`preheat._Grower._free` of (n, C) candidate segments (x0, y0, t0) -> (x1, y1, t1)
    against the block's obstacles `obs` rows (cx, cy, vx, vy, R_l), report rows `index`:
    free[i, j] is cleared on a hit and hits[index[o]] counts them, the obstacles pruned as
    the reference prunes them (exact: pruning never drops a hit)."""
    n, c = x0.shape
    m = obs.shape[0]
    for i in range(n):
        for j in range(c):
            free[i, j] = True
    if m == 0:
        return
    keep = np.arange(m)
    if m * n * c > PRUNE_ELEMENTS:  # the draw's box
        xlo = ylo = tlo = math.inf
        xhi = yhi = thi = -math.inf
        a0, a1, b0, b1 = math.inf, math.inf, -math.inf, -math.inf
        c0, c1, d0, d1 = math.inf, math.inf, -math.inf, -math.inf
        for i in range(n):
            for j in range(c):
                a0, a1 = _np_min(a0, x0[i, j]), _np_min(a1, x1[i, j])
                b0, b1 = _np_max(b0, x0[i, j]), _np_max(b1, x1[i, j])
                c0, c1 = _np_min(c0, y0[i, j]), _np_min(c1, y1[i, j])
                d0, d1 = _np_max(d0, y0[i, j]), _np_max(d1, y1[i, j])
                tlo, thi = _np_min(tlo, t0[i, j]), _np_max(thi, t1[i, j])
        xlo, xhi, ylo, yhi = _py_min(a0, a1), _py_max(b0, b1), _py_min(c0, c1), _py_max(d0, d1)
        near = 0
        for o in range(m):
            if _box_reaches(o, obs, xlo, xhi, ylo, yhi, tlo, thi):
                keep[near] = o
                near += 1
        keep = keep[:near]
        if near == 0:
            return
    paired = keep.shape[0] >= _PAIR_MIN_OBSTACLES
    for i in range(n):
        if paired:  # the individual's own box
            xlo = ylo = tlo = math.inf
            xhi = yhi = thi = -math.inf
            a0, a1, b0, b1 = math.inf, math.inf, -math.inf, -math.inf
            c0, c1, d0, d1 = math.inf, math.inf, -math.inf, -math.inf
            for j in range(c):
                a0, a1 = _np_min(a0, x0[i, j]), _np_min(a1, x1[i, j])
                b0, b1 = _np_max(b0, x0[i, j]), _np_max(b1, x1[i, j])
                c0, c1 = _np_min(c0, y0[i, j]), _np_min(c1, y1[i, j])
                d0, d1 = _np_max(d0, y0[i, j]), _np_max(d1, y1[i, j])
                tlo, thi = _np_min(tlo, t0[i, j]), _np_max(thi, t1[i, j])
            xlo, xhi = _np_min(a0, a1), _np_max(b0, b1)
            ylo, yhi = _np_min(c0, c1), _np_max(d0, d1)
        for o in keep:
            if paired and not _box_reaches(o, obs, xlo, xhi, ylo, yhi, tlo, thi):
                continue
            for j in range(c):
                if _hit(x0[i, j], y0[i, j], t0[i, j], x1[i, j], y1[i, j], t1[i, j],
                        obs[o, 0], obs[o, 1], obs[o, 2], obs[o, 3], obs[o, 4]):
                    free[i, j] = False
                    hits[index[o]] += 1


def _finish(state: np.ndarray, idx: np.ndarray, greedy: np.ndarray, levels: np.ndarray,
            k: int, last: bool, xl: np.ndarray, x: np.ndarray, y: np.ndarray, yl: np.ndarray,
            dx: np.ndarray, dy: np.ndarray, slope: np.ndarray, goal_slope: np.ndarray,
            offset: np.ndarray, u_speed: np.ndarray, u_goal: np.ndarray, key_rand: np.ndarray,
            turn_first: bool, turn_max: float, goal: np.ndarray, limits: np.ndarray,
            water: np.ndarray, obs: np.ndarray, index: np.ndarray, obs_goal: np.ndarray,
            index_goal: np.ndarray, hits: np.ndarray) -> np.ndarray:  # pragma: no cover
    """The rest of `_Grower._draw`: speeds reachable within accel_max, the turn, water-speed
    and collision gates (and the goal leg's in the last block), the choice (the admissible
    candidate of least key: |offset| for a greedy walk, else a random key) written into
    `levels` and `state`. Returns placed (n,)."""
    n, c = x.shape
    current = limits[3] != 0.0 or limits[4] != 0.0
    gx, gy = goal[0], goal[1]
    good = np.empty((n, c), np.bool_)
    vl = np.empty((n, c), np.int64)
    v = np.empty((n, c))
    t = np.empty((n, c))
    x0 = np.empty((n, c))
    y0 = np.empty((n, c))
    t0 = np.empty((n, c))
    for i in range(n):
        w = idx[i]
        px, py, pt, pv, slope0 = state[0, w], state[1, w], state[2, w], state[3, w], state[4, w]
        for j in range(c):
            seg = math.hypot(dx[i, j], dy[i, j])
            level, vv, tt, ok = _speed_level(pv, pt, seg, -dx[i, j] / seg, dy[i, j] / seg,
                                             u_speed[i, j], limits)
            if turn_first:
                ok = ok and abs(slope[i, j] - slope0) <= turn_max + _EPS
            if current:
                ok = ok and not _water_bad(x[i, j] - px, dy[i, j], pv, vv, seg, water)
            good[i, j], vl[i, j], v[i, j], t[i, j] = ok, level, vv, tt
            x0[i, j], y0[i, j], t0[i, j] = px, py, pt
    free = np.empty((n, c), np.bool_)
    _free(x0, y0, t0, x, y, t, obs, index, hits, free)
    gvl = np.zeros((n, c), np.int64)
    if last:
        gxs = np.full((n, c), gx)
        gys = np.full((n, c), gy)
        gt = np.empty((n, c))
        for i in range(n):
            for j in range(c):
                ok = good[i, j] and free[i, j]
                ok = ok and abs(goal_slope[i, j] - slope[i, j]) <= turn_max + _EPS
                gdx, gdy = gx - x[i, j], gy - y[i, j]
                gseg = math.hypot(x[i, j] - gx, y[i, j] - gy)
                level, gv, gtt, gok = _speed_level(v[i, j], t[i, j], gseg, gdx / gseg,
                                                   gdy / gseg, u_goal[i, j], limits)
                if current:
                    gok = gok and not _water_bad(gdx, gdy, v[i, j], gv, gseg, water)
                good[i, j], gvl[i, j], gt[i, j] = ok and gok, level, gtt
        _free(x, y, t, gxs, gys, gt, obs_goal, index_goal, hits, free)
    placed = np.zeros(n, np.bool_)
    for i in range(n):
        w = idx[i]
        col = -1
        best = math.inf
        for j in range(c):
            if good[i, j] and free[i, j]:
                key = abs(offset[i, j]) if greedy[w] else key_rand[i, j]
                if col < 0 or key < best:
                    col, best = j, key
        if col < 0:
            continue
        placed[i] = True
        levels[w, 3 * k] = xl[i, col]
        levels[w, 3 * k + 1] = yl[i, col]
        levels[w, 3 * k + 2] = vl[i, col]
        if last:
            levels[w, levels.shape[1] - 1] = gvl[i, col]
        state[0, w], state[1, w], state[2, w] = x[i, col], y[i, col], t[i, col]
        state[3, w], state[4, w] = v[i, col], slope[i, col]
    return placed


_jit = njit(cache=True, nogil=True, error_model="numpy") if AVAILABLE else None
if _jit is not None:
    _np_min, _np_max, _py_min, _py_max = (_jit(f) for f in (_np_min, _np_max, _py_min, _py_max))
    _speed_level, _water_bad, _hit, _box_reaches = (
        _jit(f) for f in (_speed_level, _water_bad, _hit, _box_reaches))
    _free = _jit(_free)
    aim_args, slopes, place_y, finish = (
        _jit(f) for f in (_aim_args, _slopes, _place_y, _finish))
else:  # pragma: no cover - numba is a dependency; preheating then runs the NumPy reference
    aim_args = slopes = place_y = finish = None
