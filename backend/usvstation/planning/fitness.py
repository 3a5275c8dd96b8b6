"""Fitness of paper 000 eq. 12, evaluated for a whole population at once.

    Fitness = G_acc G_vel G_col G_turn * A / (a Fit_d + b Fit_T + c Fit_ang + d Fit_mal)

    Fit_d   = sum of segment lengths / straight start-goal distance
    Fit_T   = sum of segment durations / (N - 1)              (mean segment time, s)
    Fit_ang = sum over inner waypoints of (pi - theta) / pi    (theta: inner angle)
    Fit_mal = sum of |y_i| / N                                 (malposition, m)

With `terms = "normalised"` (the default, issue 12) the fitness uses
Fit_T and Fit_mal without units, so that the weights mean the same for an
85 m recovery and a 2 km transit (D: straight start-goal distance):

    Fit_T'   = t_end v_max / D                            (1: straight at top speed)
    Fit_mal' = Fit_mal / D

The hard gates are 1 when the constraint holds on every segment and 0
otherwise: G_acc (|dv|/dT <= accel_max), G_vel (speed_min <= v <= speed_max),
G_col (no segment enters an inflated obstacle, eq. 9), and G_turn, the
vessel's turn limit, which this project adds as a further gate. A transit
drops the ramp alignment term (d = 0).

The weights and why they were chosen are in docs/planner.md.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from usvstation.planning.encoding import PathBatch
from usvstation.planning.kernel import AVAILABLE as KERNEL
from usvstation.planning.kernel import eq12_batch
from usvstation.planning.problem import Problem
from usvstation.planning.xyt import (
    PRUNE_ELEMENTS,
    Num,
    hits_from_relative,
    polyline_hits,
    relative_positions,
)
from usvstation.scenario.options import IGAOptions

_EPS = 1e-9
BRUTE_CHUNK = 1 << 18  # elements per eq. 9 pass: 2 MB a temporary


@dataclass(frozen=True)
class Evaluation:
    """Fitness, its four terms and the hard gates for every path of a batch."""

    fitness: np.ndarray
    fit_d: np.ndarray
    fit_t: np.ndarray
    fit_ang: np.ndarray
    fit_mal: np.ndarray
    fit_t_norm: np.ndarray  # t_end v_max / D: 1 for a straight run at top speed
    fit_mal_norm: np.ndarray  # Fit_mal / D
    g_acc: np.ndarray
    g_vel: np.ndarray
    g_col: np.ndarray
    g_turn: np.ndarray
    violations: np.ndarray  # count of violated segment/waypoint constraints

    @property
    def feasible(self) -> np.ndarray:
        return self.g_acc & self.g_vel & self.g_col & self.g_turn

    def row(self, i: int) -> dict[str, float | bool]:
        return {
            name: (bool(val[i]) if val.dtype == bool else float(val[i]))
            for name, val in self.__dict__.items()
        }


def segment_headings(paths: PathBatch) -> np.ndarray:
    """Heading of every segment, radians anticlockwise from +x."""
    return np.arctan2(paths.seg_dy, paths.seg_dx)


def turn_angles(headings: np.ndarray) -> np.ndarray:
    """|pi - theta| at every inner waypoint: the change of heading, radians in [0, pi]."""
    d = headings[:, 1:] - headings[:, :-1]
    return np.abs(np.mod(d + np.pi, 2.0 * np.pi) - np.pi)


def first_turn(paths: PathBatch, problem: Problem) -> np.ndarray:
    """Turn of the hull from the start heading onto the first leg, rad (issue 12)."""
    return first_turn_of(np.arctan2(paths.seg_dy[:, 0], paths.seg_dx[:, 0]), paths.v[:, 0],
                         problem)


def first_turn_of(h0: np.ndarray, v0: np.ndarray, problem: Problem) -> np.ndarray:
    """`first_turn` of first legs of course h0 (rad) sailed at v0 (over ground)."""
    cx, cy = problem.current
    hull = np.arctan2(v0 * np.sin(h0) - cy, v0 * np.cos(h0) - cx)
    return np.abs(np.mod(hull - problem.start_heading + np.pi, 2.0 * np.pi) - np.pi)


def water_speed_bad(dx: Num, dy: Num, v0: Num, v1: Num, problem: Problem,
                    length: Num | None = None) -> np.ndarray:
    """True where a segment's speed through the water (ground velocity minus current) leaves
    [speed_min, speed_max] at either end, or the hull would make way astern (issue 12).

    `length` is np.hypot(dx, dy) when the caller has it. With u the unit course and c
    the current, the water velocity is v u - c:
    |v u - c|^2 = v (v - 2 u.c) + |c|^2, and its component along u is v - u.c.
    """
    cx, cy = problem.current
    if length is None:
        length = np.hypot(dx, dy)
    along = (dx * cx + dy * cy) / np.maximum(length, _EPS)
    c2 = cx * cx + cy * cy
    lo2, hi2 = (problem.speed_min * (1 - 1e-6)) ** 2, (problem.speed_max * (1 + 1e-6)) ** 2
    w0, w1 = v0 * (v0 - 2.0 * along) + c2, v1 * (v1 - 2.0 * along) + c2
    return ((w0 < lo2) | (w0 > hi2) | (v0 <= along) | (w1 < lo2) | (w1 > hi2)
            | (v1 <= along))


def collision_matrix(paths: PathBatch, problem: Problem) -> np.ndarray:
    """(M, S, P): segment s of path p enters inflated obstacle m (eq. 9)."""
    f = problem.obstacles
    ex, ey = relative_positions(paths.x.T, paths.y.T, paths.t.T, f)  # (M, N, P)
    return polyline_hits(ex, ey, f.inflated[:, None, None], axis=1)


class Evaluator:
    """Eq. 12 for batches of paths of one problem.

    Collisions (eq. 9) are counted exactly per (segment, obstacle) pair.
    Given the x-range every segment can span (the encoding fixes it:
    segment s runs between waypoint blocks s-1 and s), static obstacles
    whose inflated circle cannot reach that range are never tested against
    it, and the remaining pairs are pruned by the batch's box in x-y-t.
    Without ranges every pair is tested (in chunks of `BRUTE_CHUNK`
    elements). Both give the same counts.
    """

    def __init__(self, problem: Problem, opts: IGAOptions,
                 segment_x_range: tuple[np.ndarray, np.ndarray] | None = None) -> None:
        self.problem, self.opts = problem, opts
        self.distance = max(problem.distance, _EPS)
        self.pairs: tuple[np.ndarray, np.ndarray] | None = None
        f = problem.obstacles
        if segment_x_range is not None and f.count:
            lo, hi = segment_x_range
            cx, r = f.centre[:, 0], f.inflated
            near = (cx[None, :] + r >= lo[:, None]) & (cx[None, :] - r <= hi[:, None])
            seg, obs = np.nonzero(near | ~f.static[None, :])
            col = f.centre[obs], f.velocity[obs]
            self.pairs = (seg, obs)
            self._pair_obs = tuple(a[:, None] for a in (  # (pairs, 1): against (pairs, P)
                col[0][:, 0], col[0][:, 1], col[1][:, 0], col[1][:, 1], r[obs]))

    def collisions(self, paths: PathBatch) -> np.ndarray:
        """Number of (segment, obstacle) pairs in collision, per path (exact)."""
        if self.problem.obstacles.count == 0:
            return np.zeros(len(paths), dtype=np.int64)
        if self.pairs is None:
            m, (p, n) = self.problem.obstacles.count, paths.x.shape
            step = max(1, BRUTE_CHUNK // (m * n))  # bounds memory: paths per pass
            return np.concatenate([
                collision_matrix(paths.rows(slice(k, k + step)), self.problem).sum(axis=(0, 1))
                for k in range(0, p, step)])
        return self._pair_collisions(paths.x.T, paths.y.T, paths.t.T)

    def _pair_collisions(self, x: np.ndarray, y: np.ndarray, t: np.ndarray) -> np.ndarray:
        """`collisions` over the precomputed pairs, of waypoints given as (N, P) arrays (one
        path per column, so that gathering a segment's end points reads whole rows).

        With more than `PRUNE_ELEMENTS` pair-path elements the pairs are first pruned by
        the batch's x-y-t boxes; below that testing them all costs less than pruning.
        """
        seg_all = self.pairs[0]
        n_paths = x.shape[1]
        keep_all = None
        if seg_all.size * n_paths > PRUNE_ELEMENTS:
            seg_all, keep_all = self._pairs_near(x, y, t)
        total = np.zeros(n_paths, dtype=np.int64)
        step = max(1, BRUTE_CHUNK // max(n_paths, 1))  # bounds memory on huge inputs
        for k in range(0, seg_all.size, step):
            part = slice(k, k + step)
            s0 = seg_all[part]
            s1 = s0 + 1
            pick = part if keep_all is None else keep_all[part]
            cx, cy, vx, vy, r = (a[pick] for a in self._pair_obs)
            t0, t1 = t[s0], t[s1]
            hits = hits_from_relative(
                x[s0] - (cx + vx * t0), y[s0] - (cy + vy * t0),
                x[s1] - (cx + vx * t1), y[s1] - (cy + vy * t1), r,
            )  # (pairs, P)
            total += np.add.reduce(hits, axis=0, dtype=np.int64)
        return total

    def _pairs_near(self, x: np.ndarray, y: np.ndarray, t: np.ndarray,
                    ) -> tuple[np.ndarray, np.ndarray]:
        """The precomputed pairs whose obstacle can reach the batch's segment boxes
        (waypoints as (N, P) arrays)."""
        seg = self.pairs[0]
        lo, hi = np.minimum, np.maximum
        xlo = lo.reduce(lo(x[:-1], x[1:]), axis=1)[seg]
        xhi = hi.reduce(hi(x[:-1], x[1:]), axis=1)[seg]
        ylo = lo.reduce(lo(y[:-1], y[1:]), axis=1)[seg]
        yhi = hi.reduce(hi(y[:-1], y[1:]), axis=1)[seg]
        tlo, thi = lo.reduce(t[:-1], axis=1)[seg], hi.reduce(t[1:], axis=1)[seg]
        cx, cy, vx, vy, r = (a[:, 0] for a in self._pair_obs)
        ox_lo = cx + lo(vx * tlo, vx * thi) - r
        ox_hi = cx + hi(vx * tlo, vx * thi) + r
        oy_lo = cy + lo(vy * tlo, vy * thi) - r
        oy_hi = cy + hi(vy * tlo, vy * thi) + r
        keep = np.flatnonzero((ox_hi >= xlo) & (ox_lo <= xhi) & (oy_hi >= ylo) & (oy_lo <= yhi))
        return seg[keep], keep

    def _gate_masks(self, paths: PathBatch, turns: np.ndarray) -> dict[str, list[np.ndarray]]:
        """Per gate but G_col, its violated constraints: (P, k) masks per segment or waypoint
        and (P,) masks per path (the first turn)."""
        problem = self.problem
        v2 = paths.v * paths.v
        # |dv| / dT <= a_max with dT = 2 L / (v0 + v1)  <=>  |v1^2 - v0^2| <= 2 a_max L
        acc_bad = np.abs(v2[:, 1:] - v2[:, :-1]) > (2.0 * problem.accel_max * (1.0 + _EPS)) * (
            paths.seg_len + _EPS
        )
        acc_bad |= paths.seg_len <= _EPS
        vel = [(paths.v < problem.speed_min - _EPS) | (paths.v > problem.speed_max + _EPS)]
        turn = [turns > problem.turn_max + _EPS]
        if problem.start_heading is not None:
            turn.append(first_turn(paths, problem) > problem.turn_max)
        if problem.current != (0.0, 0.0):
            vel.append(water_speed_bad(
                paths.seg_dx, paths.seg_dy, paths.v[:, :-1], paths.v[:, 1:], problem,
                paths.seg_len))
        return {"acc": [acc_bad], "vel": vel, "turn": turn}

    def _gate_counts(self, paths: PathBatch, turns: np.ndarray,
                     ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Violated acceleration, speed and turn constraints per path (every gate but G_col)."""
        masks = self._gate_masks(paths, turns)
        return tuple(  # type: ignore[return-value]
            sum(m.sum(axis=1) if m.ndim == 2 else m.astype(np.int64) for m in masks[gate])
            for gate in ("acc", "vel", "turn"))

    def _gate_any(self, paths: PathBatch, turns: np.ndarray) -> np.ndarray:
        """True where any gate but G_col fails: `_gate_counts` reduced to one flag per path."""
        any_of = np.logical_or.reduce  # the ufunc itself: no wrapper per call
        flags = [any_of(m, axis=1) if m.ndim == 2 else m
                 for masks in self._gate_masks(paths, turns).values() for m in masks]
        return any_of(flags)

    def _terms(self, paths: PathBatch, turns: np.ndarray) -> dict[str, np.ndarray]:
        """The four terms of eq. 12, raw and normalised, per path."""
        n, dist = paths.x.shape[1], self.distance
        fit_mal = np.abs(paths.y).sum(axis=1) / n
        return {
            "fit_d": paths.seg_len.sum(axis=1) / dist, "fit_t": paths.t[:, -1] / (n - 1),
            "fit_ang": turns.sum(axis=1) / np.pi, "fit_mal": fit_mal,
            "fit_t_norm": paths.t[:, -1] * self.problem.speed_max / dist,
            "fit_mal_norm": fit_mal / dist,
        }

    def _eq12(self, terms: dict[str, np.ndarray], feasible: np.ndarray) -> np.ndarray:
        """Eq. 12: A over the weighted terms where every gate holds, else 0."""
        opts = self.opts
        normalised = opts.terms == "normalised"
        t_term = terms["fit_t_norm"] if normalised else terms["fit_t"]
        mal_term = terms["fit_mal_norm"] if normalised else terms["fit_mal"]
        d = opts.weight_d if self.problem.recovery else 0.0
        denom = opts.weight_a * terms["fit_d"] + opts.weight_b * t_term
        denom += opts.weight_c * terms["fit_ang"]
        denom += d * mal_term
        return np.where(feasible, opts.scale_A / denom, 0.0)

    def fitness(self, paths: PathBatch) -> np.ndarray:
        """The GA's inner loop: `self(paths).fitness`, the same values, in one compiled
        call (planning/kernel.py) where numba is available, else `fitness_numpy`."""
        args = self._kernel_args()
        if args is None:
            return self.fitness_numpy(paths)
        problem = self.problem
        first_bad = (first_turn(paths, problem) > problem.turn_max
                     if problem.start_heading is not None else self._no_flags(len(paths)))
        heading = segment_headings(paths)
        return eq12_batch(paths.x.T, paths.y.T, paths.v.T, paths.t.T, paths.seg_len.T,
                          heading.T, first_bad, *args)

    def _no_flags(self, n: int) -> np.ndarray:
        flags = self.__dict__.get("_flags")
        if flags is None or flags.shape[0] < n:
            flags = self.__dict__["_flags"] = np.zeros(max(n, 256), dtype=bool)
        return flags[:n]

    def _kernel_args(self) -> tuple[np.ndarray, ...] | None:
        """The kernel's constant arguments, or None where it does not apply (no numba, EG3's
        linear fitness, no precomputed pairs with obstacles present)."""
        if "_kargs" in self.__dict__:
            return self.__dict__["_kargs"]
        problem, opts = self.problem, self.opts
        args: tuple[np.ndarray, ...] | None = None
        if KERNEL and opts.fitness == "eq12" and (
                self.pairs is not None or problem.obstacles.count == 0):
            if self.pairs is None:
                seg, obs = np.zeros(0, np.int64), np.zeros((0, 5))
            else:
                seg = self.pairs[0].astype(np.int64)
                obs = np.ascontiguousarray(np.column_stack([a[:, 0] for a in self._pair_obs]))
            limits = np.array([problem.accel_max, problem.speed_min, problem.speed_max,
                               problem.turn_max, problem.current[0], problem.current[1],
                               self.distance])
            weights = np.array([opts.weight_a, opts.weight_b, opts.weight_c,
                                opts.weight_d if problem.recovery else 0.0, opts.scale_A,
                                1.0 if opts.terms == "normalised" else 0.0])
            args = (seg, obs, limits, weights)
        self.__dict__["_kargs"] = args
        return args

    def fitness_numpy(self, paths: PathBatch) -> np.ndarray:
        """The NumPy reference of `fitness`: `self(paths).fitness`, the same values, with
        the collision test (the costly gate) run only on the paths that pass every other
        gate."""
        if self.opts.fitness == "linear":
            return self(paths).fitness
        turns = turn_angles(segment_headings(paths))
        feasible = ~self._gate_any(paths, turns)
        rows = np.flatnonzero(feasible)
        if rows.size and self.problem.obstacles.count:
            if self.pairs is None:
                feasible[rows] = self.collisions(paths.rows(rows)) == 0
            else:
                pick = slice(None) if rows.size == len(paths) else rows
                x, y, t = (a.T[:, pick] for a in (paths.x, paths.y, paths.t))
                feasible[rows] = self._pair_collisions(x, y, t) == 0
        return self._eq12(self._terms(paths, turns), feasible)

    def __call__(self, paths: PathBatch) -> Evaluation:
        """Gates, terms and fitness (eq. 12, or the EG3 linear penalty) of every path."""
        turns = turn_angles(segment_headings(paths))
        n_acc, n_vel, n_turn = self._gate_counts(paths, turns)
        n_col = self.collisions(paths)
        terms = self._terms(paths, turns)
        violations = n_acc + n_vel + n_turn + n_col
        if self.opts.fitness == "linear":
            fitness = _linear_penalty(terms["fit_d"], violations, self.opts)
        else:
            fitness = self._eq12(terms, violations == 0)
        return Evaluation(
            fitness=fitness, **terms, g_acc=n_acc == 0, g_vel=n_vel == 0, g_col=n_col == 0,
            g_turn=n_turn == 0, violations=violations,
        )


def evaluate(paths: PathBatch, problem: Problem, opts: IGAOptions) -> Evaluation:
    """Eq. 12 for any batch of paths, testing every segment against every obstacle."""
    return Evaluator(problem, opts)(paths)


def _linear_penalty(fit_d: np.ndarray, violations: np.ndarray, opts: IGAOptions) -> np.ndarray:
    """EG3 (section 4.2): a simple linear penalty on length and violated constraints.

    F = A (1 - (Fit_d - 1)) - A/4 * violations, floored at 0. It has no time,
    turning or malposition term and no hard gates.
    """
    raw = opts.scale_A * (2.0 - fit_d) - 0.25 * opts.scale_A * violations
    return np.where(np.isfinite(raw), np.maximum(raw, 0.0), 0.0)
