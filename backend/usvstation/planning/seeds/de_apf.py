"""Paper 003: an artificial potential field whose parameters differential evolution evolves.

Field [003 eq. 2.6-2.7]: the repulsion of Ge & Cui (n = 2),
U_rep = 1/2 lambda (1/rho_o - 1/w0)^2 rho_g^n inside w0, with both force
terms F1 (obstacle -> boat) and F2 (boat -> goal; FIX: eq. 2.7 prints only
F1); a capped attraction (quadratic within d*, conic beyond, §3).
Moving obstacles are sampled at t = arc length / cruise speed. Walkers step
w <- w + s F/|F|; a walker stuck (|F| ~ 0 or no progress over 20 steps)
follows the nearest obstacle's edge on a seeded side until it is nearer the goal
than where it got stuck (PROPOSED escape, Bug-style; digest 4.3 proposes a
sideways kick, which does not leave a U shape).

DE [003 §2.4]: theta = (k_att, lambda, w0, d*) evolved by
scipy.optimize.differential_evolution (rand1bin, vectorized: every
candidate walks in lock-step, one NumPy pass per step); score g of
eq. 2.4 in the normalised form g = (g_a' + g_s' - g_l')/3 (digest 4.1),
infeasible walks penalised by their remaining distance. Max-turn smoothing
[003 eq. 2.5]: kappa = 2 arctan(s/D); a vertex turning more than kappa is
deleted when the new chord stays clear (PROPOSED check).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from usvstation.geometry import angle_diff
from usvstation.planning.seeds.common import World


@dataclass(frozen=True)
class DEAPFOptions:
    step: float
    turn_radius: float = 3.0
    popsize: int = 8
    maxiter: int = 15
    mutation: float = 0.5
    recombination: float = 0.9
    n_exp: float = 2.0
    paper_kappa: bool = True


BOUNDS = [(0.1, 10.0), (0.01, 100.0), (1.0, 30.0), (1.0, 60.0)]


def rollout(theta: np.ndarray, start: np.ndarray, goal: np.ndarray, world: World,
            cruise: float, o: DEAPFOptions, rng: np.random.Generator
            ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Walk S parameter sets in lock-step; paths (S, N, 2), arrived (S,), alive (S,)."""
    k_att, lam, w0, dstar = (theta[i][:, None] for i in range(4))
    s_n = theta.shape[1]
    dist0 = float(np.hypot(*(goal - start)))
    n_max = int(3.0 * dist0 / o.step) + 60
    pos = np.broadcast_to(start, (s_n, 2)).copy()
    paths = np.empty((s_n, n_max + 1, 2))
    paths[:, 0] = pos
    arrived = np.zeros(s_n, bool)
    alive = np.ones(s_n, bool)
    arc = np.zeros(s_n)
    last = np.full(s_n, n_max)
    follow = np.zeros(s_n, bool)        # walkers following an obstacle's boundary
    side = np.ones(s_n)                 # +1 counter-clockwise, -1 clockwise
    hit_d = np.zeros(s_n)               # distance to the goal where the walker got stuck
    for k in range(n_max):
        active = alive & ~arrived
        if not active.any():
            paths[:, k + 1:] = paths[:, k:k + 1]
            break
        t = arc / cruise
        to_goal = goal - pos
        rg = np.hypot(to_goal[:, 0], to_goal[:, 1])[:, None]
        ug = to_goal / np.maximum(rg, 1e-9)
        f = np.where(rg <= dstar, k_att * rg, k_att * dstar) * ug
        if world.count:
            cx = world.cx[None, :] + world.vx[None, :] * t[:, None]
            cy = world.cy[None, :] + world.vy[None, :] * t[:, None]
            dx, dy = pos[:, 0, None] - cx, pos[:, 1, None] - cy
            dc = np.hypot(dx, dy)
            rho = np.maximum(dc - world.inflated[None, :], 1e-3)
            inside = rho <= w0
            g = np.where(inside, 1.0 / rho - 1.0 / w0, 0.0)
            f1 = lam * g * rg**o.n_exp / rho**2
            f2 = 0.5 * o.n_exp * lam * g**2 * rg ** (o.n_exp - 1.0)
            f = f + np.stack([(f1 * dx / np.maximum(dc, 1e-9)).sum(1),
                              (f1 * dy / np.maximum(dc, 1e-9)).sum(1)], axis=1)
            f = f + f2.sum(1)[:, None] * ug
        fn = np.hypot(f[:, 0], f[:, 1])[:, None]
        direction = f / np.maximum(fn, 1e-12)
        stuck = (fn[:, 0] < 1e-9) & ~follow
        if k >= 20:
            stuck |= (np.hypot(*(pos - paths[:, k - 20]).T) < o.step) & ~follow
        if world.count:
            # a walker leaves the boundary once it is nearer the goal than where it got stuck
            follow &= rg[:, 0] >= hit_d - 2.0 * o.step
            start_follow = stuck & active
            side[start_follow] = rng.choice([-1.0, 1.0], size=int(start_follow.sum()))
            hit_d = np.where(start_follow, rg[:, 0], hit_d)
            follow |= start_follow
            if follow.any():
                direction[follow] = _along_boundary(pos[follow], dx[follow], dy[follow],
                                                    dc[follow], rho[follow], side[follow], o.step)
        elif stuck.any():
            perp = np.stack([-ug[stuck, 1], ug[stuck, 0]], axis=1)
            direction[stuck] = perp * rng.choice([-1.0, 1.0], size=int(stuck.sum()))[:, None]
        step = np.minimum(o.step, rg[:, 0])
        new = pos + direction * step[:, None]
        if world.count:
            hit = world.segments_hit(pos, t, new, t + step / cruise)
            alive &= ~(hit & active)
        new = np.where(active[:, None], new, pos)
        arc = arc + np.where(active, step, 0.0)
        pos = new
        paths[:, k + 1] = pos
        reached = active & (np.hypot(*(goal - pos).T) <= 1e-6)
        last = np.where(reached & ~arrived, k + 1, last)
        arrived |= reached
    return paths, arrived & alive, alive


def _along_boundary(pos: np.ndarray, dx: np.ndarray, dy: np.ndarray, dc: np.ndarray,
                    rho: np.ndarray, side: np.ndarray, step: float) -> np.ndarray:
    """Unit steps along the nearest obstacle's edge, about one step off it (PROPOSED).

    The escape of a walker caught in a local minimum (003's U shape, a wall
    across the start-goal line): Bug-style boundary following, tangent to
    the nearest inflated circle on the walker's side, pulled back towards
    (or pushed off) the edge so that it keeps a distance of one step.
    """
    j = np.argmin(rho, axis=1)
    rows = np.arange(len(pos))
    n = np.stack([dx[rows, j], dy[rows, j]], axis=1) / np.maximum(dc[rows, j], 1e-9)[:, None]
    tangent = np.stack([-n[:, 1], n[:, 0]], axis=1) * side[:, None]
    pull = np.clip((rho[rows, j] - step) / step, -1.0, 1.0)[:, None]
    d = tangent - 0.5 * pull * n
    return d / np.maximum(np.hypot(d[:, 0], d[:, 1]), 1e-12)[:, None]


def score(paths: np.ndarray, ok: np.ndarray, goal: np.ndarray, world: World, cruise: float,
          step: float, influence: float) -> np.ndarray:
    """Normalised eq. 2.4: (g_a' + g_s' - g_l') / 3; failures scored below every success."""
    start = paths[:, 0]
    seg = np.hypot(*np.moveaxis(np.diff(paths, axis=1), 2, 0))
    length = seg.sum(1)
    straight = np.maximum(np.hypot(*(goal - start).T), 1e-9)
    g_l = length / straight
    moved = seg > 1e-9
    n = np.maximum(moved.sum(1), 1)
    skip = np.hypot(*np.moveaxis(paths[:, 2:] - paths[:, :-2], 2, 0))
    g_s = (skip * moved[:, 1:]).sum(1) / np.maximum(n - 1, 1) / (2 * step)
    if world.count:
        t = np.concatenate([np.zeros((len(paths), 1)), np.cumsum(seg, 1)], 1) / cruise
        cx = world.cx[None, None] + world.vx[None, None] * t[..., None]
        cy = world.cy[None, None] + world.vy[None, None] * t[..., None]
        d = np.hypot(paths[..., 0, None] - cx, paths[..., 1, None] - cy) - world.inflated
        g_a = (np.minimum(d.min(1), influence) / influence).mean(1)
    else:
        g_a = np.ones(len(paths))
    g = (g_a + g_s - g_l) / 3.0
    rest = np.hypot(*(goal - paths[:, -1]).T) / straight
    return np.where(ok, g, -10.0 - rest)


def smooth_max_turn(path: np.ndarray, kappa_deg: float, world: World, cruise: float
                    ) -> np.ndarray:
    """[003 §2.2]: delete a vertex turning more than kappa if the new chord stays clear."""
    pts = [p for p in path]
    changed = True
    while changed and len(pts) > 2:
        changed = False
        i = 1
        while i < len(pts) - 1:
            a, b, c = pts[i - 1], pts[i], pts[i + 1]
            h1, h2 = math.atan2(*(b - a)[::-1]), math.atan2(*(c - b)[::-1])
            turn = abs(math.degrees(angle_diff(h2, h1)))
            if turn > kappa_deg:
                arr = np.array(pts[:i])
                s = float(np.hypot(*np.diff(arr, axis=0).T).sum()) if len(arr) > 1 else 0.0
                t0 = s / cruise
                t1 = t0 + float(np.hypot(*(c - a))) / cruise
                if not world.segments_hit(a[None], t0, c[None], t1)[0]:
                    del pts[i]
                    changed = True
                    continue
            i += 1
    return np.array(pts)


def plan_de_apf(start: np.ndarray, goal: np.ndarray, world: World, cruise: float, seed: int,
                o: DEAPFOptions) -> tuple[np.ndarray | None, dict]:
    influence = 10.0 * o.step

    def objective(x: np.ndarray) -> np.ndarray:
        x = np.atleast_2d(x.T).T if x.ndim == 1 else x
        world.spend(x.shape[1])
        world.check_budget()
        rng = np.random.default_rng([seed, x.shape[1]])
        paths, ok, _ = rollout(x, start, goal, world, cruise, o, rng)
        return -score(paths, ok, goal, world, cruise, o.step, influence)

    from scipy.optimize import differential_evolution  # here: serve starts without scipy

    res = differential_evolution(
        objective, BOUNDS, strategy="rand1bin", maxiter=o.maxiter, popsize=o.popsize,
        mutation=o.mutation, recombination=o.recombination, rng=seed, polish=False,
        vectorized=True, updating="deferred", tol=0.0)
    theta = res.x[:, None]
    paths, ok, _ = rollout(theta, start, goal, world, cruise, o,
                           np.random.default_rng([seed, 1]))
    stats = {"de_generations": int(res.nit), "de_evaluations": int(res.nfev),
             "theta": {k: round(float(v), 6) for k, v in
                       zip(("k_att", "lambda_rep", "omega0", "d_star"), res.x, strict=True)},
             "g003": round(float(-res.fun), 6)}
    if not ok[0]:
        return None, {**stats, "reason": "the evolved potential field did not reach the goal"}
    path = paths[0]
    keep = np.concatenate([[True], np.hypot(*np.diff(path, axis=0).T) > 1e-9])
    path = path[keep]
    kappa = 2.0 * math.degrees(math.atan(o.step / o.turn_radius)) if o.paper_kappa else \
        2.0 * math.degrees(math.asin(min(1.0, o.step / (2.0 * o.turn_radius))))
    stats["kappa_deg"] = round(kappa, 6)
    return smooth_max_turn(path, kappa, world, cruise), stats
