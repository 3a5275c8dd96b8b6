"""Preheating: collision-free population initialisation (paper 000 Algorithm 1, lines 2-18).

Every individual is grown waypoint by waypoint from the start towards the
goal; a new point is kept only if the segment that reaches it is free of
every obstacle (eq. 9) and respects the turn and acceleration limits,
otherwise it is drawn again, at most `preheat_retries` times (the paper's
N_max "to prevent program crashes"); an individual that stays blocked is
restarted from the start, at most `preheat_restarts` times.

The loop runs over waypoints and retries, never over individuals: each
draw proposes `candidates` points for every pending individual at once and
keeps one admissible point per individual.

Candidates head for an aim point within a random bearing spread of +-55
degrees, narrowed over the last waypoints so the path can still turn onto
the goal; a second draw for a blocked waypoint spreads over every bearing
the turn limit admits (up to 80 degrees off the x step). A transit aims at
the goal. A recovery aims at a point on the ramp axis that each individual
draws between the run-in and the start, and
follows the axis from there (a fifth of the individuals aim at a random y
until that point instead, for wide detours round long walls): the
population holds paths that join the axis early (small malposition,
Fit_mal) and late (short, Fit_d). Half of the
individuals keep the admissible candidate closest to the aim (near-straight
paths that detour only where they must), the other half a random admissible
one (wide detours on either side). Three quarters of the candidate speeds
are the fastest the acceleration limit allows, the rest uniform in the
reachable range.

Only obstacles that can reach a waypoint block's x-range are tested there:
moving ones always, static ones when their inflated circle overlaps it; of
those, a large draw tests the ones that reach its box in x-y-t, and with 16
or more, each individual's candidates only against the ones that reach its
own box (exact: the same points are kept as by the all-pairs test). Every eq. 9
pass holds at most `KERNEL_ELEMENTS` elements.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from usvstation.geometry import angle_diff
from usvstation.planning import kernel_preheat
from usvstation.planning.encoding import GeneLayout
from usvstation.planning.fitness import water_speed_bad
from usvstation.planning.problem import Problem
from usvstation.planning.xyt import PRUNE_ELEMENTS, Num, hits_from_relative
from usvstation.scenario.options import IGAOptions

_MAX_SLOPE = math.radians(80.0)  # steepest segment against the x step
_SPREAD = math.radians(55.0)  # bearing spread of candidates around the aim
_EPS = 1e-9
_PAIR_MIN_OBSTACLES = 16  # from this many obstacles on, candidates are paired per individual
KERNEL_ELEMENTS = 1 << 18  # elements per eq. 9 pass: 2 MB a temporary


@dataclass
class PreheatReport:
    """Where preheating got stuck; feeds the "no feasible plan" reason."""

    requested: int = 0
    produced: int = 0
    blocked_at: dict[int, int] = field(default_factory=dict)  # waypoint index -> count
    obstacle_hits: np.ndarray | None = None  # per obstacle, rejected candidates

    def merge(self, other: PreheatReport) -> None:
        self.requested += other.requested
        self.produced += other.produced
        for k, n in other.blocked_at.items():
            self.blocked_at[k] = self.blocked_at.get(k, 0) + n
        if other.obstacle_hits is not None:
            self.obstacle_hits = (
                other.obstacle_hits.copy() if self.obstacle_hits is None
                else self.obstacle_hits + other.obstacle_hits
            )


@dataclass(frozen=True)
class _Obstacles:
    """A subset of the obstacles shaped (m, 1, 1) for broadcasting against (n, C) candidates."""

    index: np.ndarray
    cx: np.ndarray
    cy: np.ndarray
    vx: np.ndarray
    vy: np.ndarray
    r: np.ndarray

    def relative(self, x: Num, y: Num, t: Num) -> tuple[np.ndarray, np.ndarray]:
        return x - (self.cx + self.vx * t), y - (self.cy + self.vy * t)


@dataclass
class _Walk:
    """Per-individual state of the walk towards the goal.

    `state` (7, count) holds one row per quantity, so that a draw gathers the state of
    its individuals in one call: x, y, t, v of the last waypoint placed; the bearing of
    the last segment against -x (rad, nan before the first); where a recovery aims to
    join the ramp axis; the y it aims for until then (the axis, or a wide detour).
    """

    state: np.ndarray  # rows: x, y, t, v, slope, join_x, aim_y
    greedy: np.ndarray  # keeps the admissible candidate closest to the aim

    PLACED = 5  # the first rows (x, y, t, v, slope), which every placed waypoint updates


class _Grower:
    """Grows batches of individuals for one layout (the context of Algorithm 1's loop)."""

    def __init__(self, layout: GeneLayout, problem: Problem, opts: IGAOptions,
                 rng: np.random.Generator, report: PreheatReport,
                 compiled: bool | None = None) -> None:
        self.layout, self.problem, self.opts, self.rng = layout, problem, opts, rng
        self.report = report
        if report.obstacle_hits is None:
            report.obstacle_hits = np.zeros(problem.obstacles.count, dtype=np.int64)
        self.compiled = kernel_preheat.AVAILABLE if compiled is None else compiled
        if not self.compiled:
            self.near = [self._near_block(k) for k in range(layout.n_mid + 1)]
        else:
            self.near_rows = self._near_rows()
            cx, cy = problem.current
            self.speed_limits = np.array([
                2.0 * problem.accel_max, problem.speed_min**2, problem.speed_max**2, cx, cy,
                layout.v_lo, layout.v_res, layout.v_count], dtype=np.float64)
            self.water = np.array([cx, cy, cx * cx + cy * cy,
                                   (problem.speed_min * (1 - 1e-6)) ** 2,
                                   (problem.speed_max * (1 + 1e-6)) ** 2])
            self.goal = np.asarray(layout.goal, dtype=np.float64)
            self.no_aim = np.zeros(4 * 2 * opts.population)  # enough for any draw
        self.v2min, self.v2max = problem.speed_min**2, problem.speed_max**2
        last = layout.n_mid - 1
        self.run_in = float(layout.x_of(layout.x_count[last] // 2, last))
        # a boat under way: its course binds the first leg (slope is measured against -x)
        self.start_slope = np.nan
        if problem.start_course is not None:
            self.start_slope = angle_diff(math.pi, problem.start_course)

    def _near_rows(self) -> list[tuple[np.ndarray, np.ndarray]]:
        """`_near_block` of every block as the compiled draw takes it: the rows (cx, cy, vx,
        vy, R_l) of the obstacles near block k and their indices, all blocks at once."""
        lay, f = self.layout, self.problem.obstacles
        blocks = np.arange(lay.n_mid)
        tops = np.concatenate([[float(lay.start[0])], lay.x_of(lay.x_count, blocks)])
        bottoms = np.concatenate([lay.x_of(0, blocks), [float(lay.goal[0])]])
        reach = f.inflated + lay.x_res
        near = ((f.centre[None, :, 0] + reach >= bottoms[:, None])
                & (f.centre[None, :, 0] - reach <= tops[:, None])) | ~f.static[None, :]
        table = np.column_stack([f.centre, f.velocity, f.inflated]).reshape(-1, 5)
        return [(table[idx], idx) for idx in (np.flatnonzero(row) for row in near)]

    def _near_block(self, k: int) -> _Obstacles:
        """Obstacles that can touch a segment ending in block k (k = n_mid: the goal leg)."""
        lay, f = self.layout, self.problem.obstacles
        top = float(lay.start[0]) if k == 0 else float(lay.x_of(lay.x_count[k - 1], k - 1))
        bottom = float(lay.goal[0]) if k >= lay.n_mid else float(lay.x_of(0, k))
        reach = f.inflated + lay.x_res
        near = (f.centre[:, 0] + reach >= bottom) & (f.centre[:, 0] - reach <= top)
        idx = np.flatnonzero(near | ~f.static)
        col = (slice(None), None, None)
        return _Obstacles(
            index=idx, cx=f.centre[idx, 0][col], cy=f.centre[idx, 1][col],
            vx=f.velocity[idx, 0][col], vy=f.velocity[idx, 1][col], r=f.inflated[idx][col],
        )

    def grow(self, count: int, expired: Callable[[], bool] | None = None,
             ) -> tuple[np.ndarray, np.ndarray]:
        """Walk `count` individuals to the goal; (levels, grown). `expired()` is asked
        before every draw: once it is True no walk is finished."""
        lay = self.layout
        levels = np.zeros((count, lay.n_genes), dtype=np.int64)
        alive = np.ones(count, dtype=bool)
        greedy = self.rng.random(count) < 0.5
        join_x = self.rng.uniform(self.run_in, float(lay.start[0]), size=count)
        start = (lay.start[0], lay.start[1], 0.0, lay.start_speed, self.start_slope)
        walk = _Walk(np.vstack([np.repeat(np.array(start)[:, None], count, axis=1),
                                join_x, self._aim_y(count)]), greedy)
        draw = self._draw_compiled if self.compiled else self._draw
        for k in range(lay.n_mid):
            pending = np.flatnonzero(alive)
            for attempt in range(self.opts.preheat_retries):
                if pending.size == 0:
                    break
                if expired is not None and expired():
                    alive[:] = False
                    return levels, alive
                pending = pending[~draw(k, walk, pending, levels, wide=attempt > 0)]
            if pending.size:
                alive[pending] = False
                self.report.blocked_at[k] = self.report.blocked_at.get(k, 0) + int(pending.size)
        return levels, alive

    def _draw(
        self, k: int, walk: _Walk, idx: np.ndarray, levels: np.ndarray, wide: bool = False
    ) -> np.ndarray:
        """One draw of candidates for waypoint k of individuals `idx`; True where placed.

        `wide` draws bearings uniformly over the whole admissible window.
        """
        lay, prob, rng = self.layout, self.problem, self.rng
        n, c = idx.size, self.opts.candidates
        px, py, pt, pv, slope0, join_x, aim_y = walk.state[:, idx, None]
        last = k == lay.n_mid - 1

        xl = rng.integers(0, lay.x_count[k], size=(n, c))
        x = lay.x_of(xl, k)
        dx = px - x  # > 0: the path steps towards the goal
        ax, ay = self._aim(k, px, join_x, aim_y)
        taper = min(1.0, max(0.2, (lay.n_mid - 1 - k) / 3.0))
        offset = rng.uniform(-1.0, 1.0, size=(n, c))
        if k == 0 and math.isnan(self.start_slope):
            lo, hi = -_MAX_SLOPE, _MAX_SLOPE
        else:
            lo = np.maximum(slope0 - prob.turn_max, -_MAX_SLOPE)
            hi = np.minimum(slope0 + prob.turn_max, _MAX_SLOPE)
        if wide:
            slope = lo + (hi - lo) * (offset + 1.0) / 2.0
        else:
            slope = np.arctan2(ay - py, px - ax) + (taper * _SPREAD) * offset
        y = py + dx * np.tan(np.minimum(np.maximum(slope, lo), hi))
        if last and lay.cone_tan is not None:
            m = lay.cone_half_levels(xl)
            cell = np.minimum(np.maximum(np.rint(y / lay.y_res), -m), m)
            y, yl = cell * lay.y_res, (cell + m).astype(np.int64)
        else:
            yl = lay.y_level(y)
            y = lay.y_of(yl)
        dy = y - py
        slope = np.arctan2(dy, dx)
        seg = np.hypot(dx, dy)
        vl, v, t, good = self._speed(pv, pt, seg, -dx / seg, dy / seg)
        if k > 0 or not math.isnan(self.start_slope):
            good &= np.abs(slope - slope0) <= prob.turn_max + _EPS
        if prob.current != (0.0, 0.0):
            good &= ~water_speed_bad(x - px, dy, pv, v, prob, seg)
        good &= self._free(k, px, py, pt, x, y, t)
        if last:
            gx, gy = float(lay.goal[0]), float(lay.goal[1])
            gdx, gdy = gx - x, gy - y
            gseg = np.hypot(x - gx, y - gy)
            good &= np.abs(np.arctan2(gy - y, x - gx) - slope) <= prob.turn_max + _EPS
            gvl, gv, gt, gok = self._speed(v, t, gseg, gdx / gseg, gdy / gseg)
            if prob.current != (0.0, 0.0):
                gok &= ~water_speed_bad(gdx, gdy, v, gv, prob, gseg)
            good &= gok & self._free(k + 1, x, y, t, gx, gy, gt)

        placed = good.any(axis=1)
        key = np.where(walk.greedy[idx, None], np.abs(offset), rng.random((n, c)))
        col = np.argmin(np.where(good, key, np.inf), axis=1)
        rows = np.flatnonzero(placed)
        pick, who = (rows, col[rows]), idx[rows]
        levels[who, 3 * k] = xl[pick]
        levels[who, 3 * k + 1] = yl[pick]
        levels[who, 3 * k + 2] = vl[pick]
        walk.state[: _Walk.PLACED, who] = np.stack((x, y, t, v, slope))[:, rows, col[rows]]
        if last:
            levels[who, -1] = gvl[pick]
        return placed

    def _draw_compiled(
        self, k: int, walk: _Walk, idx: np.ndarray, levels: np.ndarray, wide: bool = False
    ) -> np.ndarray:
        """`_draw` in compiled calls (planning/kernel_preheat.py): the same random numbers,
        drawn in the same order, and the same points placed, bit for bit."""
        lay, prob, rng, kp = self.layout, self.problem, self.rng, kernel_preheat
        n, c = idx.size, self.opts.candidates
        last = k == lay.n_mid - 1
        xl = rng.integers(0, lay.x_count[k], size=(n, c))
        offset = rng.uniform(-1.0, 1.0, size=(n, c))
        u_speed = rng.uniform(0.0, 4.0, size=(n, c))
        u_goal = rng.uniform(0.0, 4.0, size=(n, c)) if last else u_speed
        key_rand = rng.random((n, c))
        state = walk.state
        if wide:
            aim = self.no_aim[:n]  # unused when wide
        else:
            gx, gy = float(lay.goal[0]), float(lay.goal[1])
            aim = np.arctan2(*kp.aim_args(state, idx, lay.cone_tan is None or last, gx, gy,
                                          self.run_in, lay.x_res))
        free_first = k == 0 and math.isnan(self.start_slope)
        taper = min(1.0, max(0.2, (lay.n_mid - 1 - k) / 3.0))
        tan_s = np.tan(kp.slopes(state, idx, offset, aim, wide, free_first, prob.turn_max,
                                 _MAX_SLOPE, taper * _SPREAD))
        x, y, yl, dx, dy, gnum, gden = kp.place_y(
            state, idx, xl, tan_s, lay.x_min, int(lay.x_base[k]), lay.x_res,
            last and lay.cone_tan is not None, lay.cone_m, lay.y_res, lay.y_lo, lay.y_count,
            float(lay.goal[0]), float(lay.goal[1]))
        slope = np.arctan2(dy, dx)
        goal_slope = np.arctan2(gnum, gden) if last else slope
        obs, index = self.near_rows[k]
        obs_goal, index_goal = self.near_rows[k + 1] if last else self.near_rows[k]
        return kp.finish(
            state, idx, walk.greedy, levels, k, last, xl, x, y, yl, dx, dy, slope, goal_slope,
            offset, u_speed, u_goal, key_rand, not free_first, prob.turn_max, self.goal,
            self.speed_limits, self.water, obs, index, obs_goal, index_goal,
            self.report.obstacle_hits)

    def _aim_y(self, count: int) -> np.ndarray:
        """A fifth of the individuals aim wide, anywhere in the y range, until their join_x, so
        that the population holds detours round walls longer than any local draw reaches."""
        lay = self.layout
        wide = self.rng.random(count) < 0.2
        y = self.rng.uniform(lay.y_lo, lay.y_of(lay.y_count - 1), size=count)
        return np.where(wide, y, float(lay.goal[1]))

    def _aim(self, k: int, px: np.ndarray, join_x: np.ndarray,
             aim_y: np.ndarray) -> tuple[np.ndarray, np.ndarray | float]:
        """Aim point (x, y): the goal, or a point on the ramp axis for a recovery."""
        lay = self.layout
        gx, gy = float(lay.goal[0]), float(lay.goal[1])
        if lay.cone_tan is None or k == lay.n_mid - 1:
            return np.full_like(px, gx), gy
        before = px > join_x + lay.x_res
        return np.where(before, join_x, self.run_in), np.where(before, aim_y, gy)

    def _speed(
        self, pv: np.ndarray, pt: np.ndarray, seg: np.ndarray, ux: Num = 1.0, uy: Num = 0.0,
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """A speed level reachable over `seg` within accel_max: (level, v, t, admissible)."""
        lay, prob = self.layout, self.problem
        reach, pv2 = (2.0 * prob.accel_max) * seg, pv * pv
        vlo = np.sqrt(np.maximum(pv2 - reach, self.v2min))
        vhi = np.sqrt(np.minimum(pv2 + reach, self.v2max))
        if prob.current != (0.0, 0.0):
            # ground speeds whose speed through the water lies in [speed_min, speed_max]
            cx, cy = prob.current
            along, across = ux * cx + uy * cy, ux * cy - uy * cx
            c2 = across * across
            vhi = np.minimum(vhi, along + np.sqrt(np.maximum(self.v2max - c2, 0.0)))
            vhi = np.where(c2 >= self.v2max, -1.0, vhi)
            vlo = np.maximum(vlo, along + np.sqrt(np.maximum(self.v2min - c2, 0.0)) + 1e-6)
        jlo, jhi = lay.v_level_range(vlo, vhi)
        # three quarters of the draws take the fastest reachable speed, the rest are uniform
        u = self.rng.uniform(0.0, 4.0, size=seg.shape)
        vl = np.where(u >= 1.0, jhi, np.minimum(jlo + (u * (jhi - jlo + 1)).astype(np.int64), jhi))
        v = lay.v_of(vl)
        return vl, v, pt + 2.0 * seg / (pv + v), jlo <= jhi

    def _free(self, k: int, px: Num, py: Num, pt: Num, x: Num, y: Num, t: Num) -> np.ndarray:
        """True where the segment ending in block k misses every inflated obstacle (eq. 9).

        A large draw (over `PRUNE_ELEMENTS` obstacle-candidate elements) tests only the
        obstacles, and with many of them the (obstacle, individual) pairs, whose boxes
        meet: the obstacle's circle swept over the time window against the box the
        candidate segments span (exact pruning, never drops a hit). A small draw tests
        every obstacle of the block, which costs less than pruning.
        """
        obs = self.near[k]
        shape = np.broadcast_shapes(np.shape(x), np.shape(px))
        if obs.index.size == 0:
            return np.ones(shape, dtype=bool)
        if obs.index.size * math.prod(shape) > PRUNE_ELEMENTS:  # else testing all is cheaper
            obs = _near_box(obs, px, py, pt, x, y, t)
        if obs.index.size == 0:
            return np.ones(shape, dtype=bool)
        if obs.index.size < _PAIR_MIN_OBSTACLES or len(shape) != 2:
            return self._free_all(obs, shape, px, py, pt, x, y, t)
        return self._free_paired(obs, shape, px, py, pt, x, y, t)

    def _free_all(self, obs: _Obstacles, shape: tuple[int, ...], px: Num, py: Num, pt: Num,
                  x: Num, y: Num, t: Num) -> np.ndarray:
        """Every candidate against every obstacle of `obs`, in memory-bounded passes."""
        free = np.ones(shape, dtype=bool)
        step = max(1, KERNEL_ELEMENTS // max(free.size, 1))
        for i in range(0, obs.index.size, step):
            part = obs if step >= obs.index.size else _Obstacles(*(
                a[i:i + step] for a in (obs.index, obs.cx, obs.cy, obs.vx, obs.vy, obs.r)))
            ex0, ey0 = part.relative(px, py, pt)
            ex1, ey1 = part.relative(x, y, t)
            hits = hits_from_relative(ex0, ey0, ex1, ey1, part.r)  # (m, n, C)
            self.report.obstacle_hits[part.index] += hits.sum(axis=(1, 2))
            free &= ~hits.any(axis=0)
        return free

    def _free_paired(self, obs: _Obstacles, shape: tuple[int, ...], px: Num, py: Num,
                     pt: Num, x: Num, y: Num, t: Num) -> np.ndarray:
        """Candidates (n, C) tested only against the obstacles that reach the box of their
        own individual's segments over its time window, in memory-bounded passes."""
        def per_row(a: Num, reduce: np.ufunc) -> Num:
            """Per individual: a (n, w) row reduced, or a scalar as it is (it broadcasts)."""
            return reduce.reduce(a, axis=1) if np.ndim(a) else a

        xlo = np.minimum(per_row(px, np.minimum), per_row(x, np.minimum))
        xhi = np.maximum(per_row(px, np.maximum), per_row(x, np.maximum))
        ylo = np.minimum(per_row(py, np.minimum), per_row(y, np.minimum))
        yhi = np.maximum(per_row(py, np.maximum), per_row(y, np.maximum))
        tlo, thi = per_row(pt, np.minimum), per_row(t, np.maximum)
        cx, cy, vx, vy, r = (a[:, 0, 0][:, None] for a in (obs.cx, obs.cy, obs.vx, obs.vy,
                                                             obs.r))
        near = ((cx + np.maximum(vx * tlo, vx * thi) + r >= xlo)
                & (cx + np.minimum(vx * tlo, vx * thi) - r <= xhi)
                & (cy + np.maximum(vy * tlo, vy * thi) + r >= ylo)
                & (cy + np.minimum(vy * tlo, vy * thi) - r <= yhi))  # (m, n)
        rows_all, j_all = np.nonzero(near.T)  # pairs sorted by individual
        free = np.ones(shape, dtype=bool)
        step = max(1, KERNEL_ELEMENTS // shape[1])  # pairs per pass
        for i in range(0, rows_all.size, step):
            row, j = rows_all[i:i + step], j_all[i:i + step]
            col = (j, slice(None), 0)
            e = [a if np.ndim(a) == 0 else np.asarray(a)[row] for a in (px, py, pt, x, y, t)]
            hits = hits_from_relative(
                e[0] - (obs.cx[col] + obs.vx[col] * e[2]),
                e[1] - (obs.cy[col] + obs.vy[col] * e[2]),
                e[3] - (obs.cx[col] + obs.vx[col] * e[5]),
                e[4] - (obs.cy[col] + obs.vy[col] * e[5]), obs.r[col])  # (pairs, C)
            self.report.obstacle_hits[obs.index] += np.bincount(
                j, weights=hits.sum(axis=1), minlength=obs.index.size).astype(np.int64)
            first = np.flatnonzero(np.r_[True, row[1:] != row[:-1]])
            free[row[first]] &= ~np.logical_or.reduceat(hits, first, axis=0)
        return free


def _near_box(obs: _Obstacles, px: Num, py: Num, pt: Num, x: Num, y: Num, t: Num) -> _Obstacles:
    """The obstacles whose circle, swept over the draw's time window, reaches the box that
    all candidate segments of the draw span (x-y-t pruning; exact, never drops a hit)."""
    lo, hi = np.minimum.reduce, np.maximum.reduce  # ufunc reductions: no wrapper overhead
    xlo, xhi = min(lo(px, None), lo(x, None)), max(hi(px, None), hi(x, None))
    ylo, yhi = min(lo(py, None), lo(y, None)), max(hi(py, None), hi(y, None))
    tlo, thi = lo(pt, None), hi(t, None)
    cx, cy, vx, vy, r = (a[:, 0, 0] for a in (obs.cx, obs.cy, obs.vx, obs.vy, obs.r))
    sx0, sx1, sy0, sy1 = vx * tlo, vx * thi, vy * tlo, vy * thi
    keep = ((cx + np.maximum(sx0, sx1) + r >= xlo) & (cx + np.minimum(sx0, sx1) - r <= xhi)
            & (cy + np.maximum(sy0, sy1) + r >= ylo) & (cy + np.minimum(sy0, sy1) - r <= yhi))
    if keep.all():
        return obs
    return _Obstacles(obs.index[keep], obs.cx[keep], obs.cy[keep], obs.vx[keep], obs.vy[keep],
                      obs.r[keep])


def preheat(
    layout: GeneLayout, problem: Problem, opts: IGAOptions, rng: np.random.Generator,
    count: int, need: int | None = None, expired: Callable[[], bool] | None = None,
    compiled: bool | None = None,
) -> tuple[np.ndarray, np.ndarray, PreheatReport]:
    """Grow `count` individuals; returns (levels (count, G), ok (count,), report).

    While fewer than `need` (default: all) are grown, the blocked ones are
    restarted from the start, at most `preheat_restarts` times. `compiled` (default:
    where numba is available) draws in compiled calls; False runs the NumPy reference,
    which grows the same individuals bit for bit.
    """
    need = count if need is None else need
    report = PreheatReport(requested=count)
    grower = _Grower(layout, problem, opts, rng, report, compiled)
    levels = np.zeros((count, layout.n_genes), dtype=np.int64)
    ok = np.zeros(count, dtype=bool)
    todo = np.arange(count)
    for _ in range(opts.preheat_restarts + 1):
        if todo.size == 0 or ok.sum() >= need:
            break
        lv, good = grower.grow(todo.size, expired)
        levels[todo[good]] = lv[good]
        ok[todo[good]] = True
        todo = todo[~good]
        if expired is not None and expired():
            break
    report.produced = int(ok.sum())
    return levels, ok, report


def random_levels(layout: GeneLayout, rng: np.random.Generator, count: int) -> np.ndarray:
    """EG1: an unheated population, uniform random bits decoded and mapped."""
    bits = rng.integers(0, 2, size=(count, layout.n_bits), dtype=np.uint8)
    return layout.codes_to_levels(layout.bits_to_codes(bits))
