"""RRT*, B-spline RRT* and VPF-RRT* of paper 004 (Alg. 1, eq. 7-12), seeded, NumPy + cKDTree.

Paper 004 plans among static obstacles; here an edge is checked against the
moving circles at the times the boat would pass (tree cost / cruise speed,
paper 000 eq. 9), so every obstacle of the scenario counts. Choices the
paper leaves open (docs/planners.md): step p, iterations n, 5 % goal bias,
r_near = min(gamma (ln N / N)^(1/2), 3p), cKDTree rebuilt every 64 nodes.

VPF (eq. 7-12) with E = B (digest 5.2): L' = -E F_c / (m w^2 sin a), i.e.
a new node is pulled onto the start-goal "gravity line" and pushed away
from the nearest obstacle by B eta R_min^3 (1/d - 1/rho)^2 / sin(alpha),
each move capped at the step p; the moved node is kept only when it and
its parent edge stay clear.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from usvstation.planning.seeds.common import World

if TYPE_CHECKING:
    from scipy.spatial import cKDTree


@dataclass(frozen=True)
class RRTOptions:
    step: float
    iterations: int
    goal_bias: float = 0.05
    goal_tolerance: float | None = None
    rebuild_every: int = 64
    vpf: bool = False
    vpf_b: float = 8.0        # 004 Tab. 3, inertia coefficient B (= E)
    vpf_eta: float = 6.0      # 004 Tab. 3
    vpf_rmin: float = 3.0     # 004 Tab. 3, minimum turning radius R
    vpf_rho: float | None = None  # influence range; default 2 p


@dataclass
class Tree:
    pts: np.ndarray
    parent: np.ndarray
    cost: np.ndarray
    n: int


def rrt_star(start: np.ndarray, goal: np.ndarray, world: World, cruise: float,
             bounds: tuple[float, float, float, float], opts: RRTOptions,
             rng: np.random.Generator) -> np.ndarray | None:
    """A path start -> goal (array (K, 2)) or None; Alg. 1 of paper 004 (with VPF if asked).

    One iteration is one evaluation of the world's budget; when the budget is spent the
    tree stops growing and its best branch to the goal so far is the path (anytime).
    """
    budget, world = world.budget, replace(world, budget=None)  # checked once per iteration
    cap = opts.iterations + 2
    tree = Tree(np.zeros((cap, 2)), np.full(cap, -1), np.zeros(cap), 1)
    tree.pts[0] = start
    children: list[list[int]] = [[] for _ in range(cap)]
    from scipy.spatial import cKDTree  # here: serve starts without scipy

    kd: cKDTree | None = None
    kd_n = 0
    xmin, xmax, ymin, ymax = bounds
    area = (xmax - xmin) * (ymax - ymin)
    gamma = 2.0 * math.sqrt(1.5) * math.sqrt(area / math.pi) * 1.01
    tol = opts.goal_tolerance or opts.step
    best_goal, best_cost = -1, math.inf
    line = goal - start
    line_len = float(np.hypot(*line))
    line_u = line / max(line_len, 1e-9)
    rho = opts.vpf_rho or 2.0 * opts.step

    def near_indices(q: np.ndarray, r: float) -> np.ndarray:
        parts = []
        if kd is not None:
            parts.append(np.asarray(kd.query_ball_point(q, r), dtype=int))
        if tree.n > kd_n:
            d = np.hypot(*(tree.pts[kd_n:tree.n] - q).T)
            parts.append(np.flatnonzero(d <= r) + kd_n)
        return np.concatenate(parts) if parts else np.zeros(0, int)

    def nearest(q: np.ndarray) -> int:
        best, bd = 0, math.inf
        if kd is not None:
            bd, best = kd.query(q)
        if tree.n > kd_n:
            d = np.hypot(*(tree.pts[kd_n:tree.n] - q).T)
            k = int(np.argmin(d))
            if d[k] < bd:
                best = kd_n + k
        return int(best)

    def edge_free(frm: np.ndarray, q: np.ndarray) -> np.ndarray:
        """Edges from nodes `frm` to q, timed by cost-to-come / cruise."""
        p0 = tree.pts[frm]
        seg = np.hypot(*(p0 - q).T)
        t0 = tree.cost[frm] / cruise
        t1 = t0 + seg / cruise
        return ~world.segments_hit(p0, t0, np.broadcast_to(q, p0.shape), t1)

    def vpf_adjust(q: np.ndarray) -> np.ndarray:
        rel = q - start
        along = float(rel @ line_u)
        perp = rel - along * line_u
        lval = float(np.hypot(*perp))
        # eq. 9 with the node-obstacle distance d (digest 5.2); E = B so (1 - E/B) L = 0
        push = np.zeros(2)
        if world.count:
            t = along / cruise
            dist = world.distance(q[None], max(t, 0.0))[0]
            j = int(np.argmin(dist))
            d = max(float(dist[j]), 1e-3)
            if d < rho:
                sin_a = max(abs(math.sin(math.atan2(lval, max(along, 1e-9)))),
                            math.sin(math.radians(5)))
                mag = opts.vpf_b * opts.vpf_eta * opts.vpf_rmin**3 * (1 / d - 1 / rho) ** 2 / sin_a
                cj = np.array([world.cx[j] + world.vx[j] * t, world.cy[j] + world.vy[j] * t])
                away = q - cj
                push = away / max(float(np.hypot(*away)), 1e-9) * mag
        move = -perp + push  # eq. 11-12: towards the gravity line, away from the obstacle
        m = float(np.hypot(*move))
        if m > opts.step:
            move *= opts.step / m
        return q + move

    for _ in range(opts.iterations):
        if budget is not None:
            if budget.exhausted():
                break  # anytime: the best branch to the goal so far
            budget.spend(1)
        if tree.n - kd_n >= opts.rebuild_every:
            kd, kd_n = cKDTree(tree.pts[:tree.n]), tree.n
        if rng.random() < opts.goal_bias:
            q_rand = goal.copy()
        else:
            q_rand = np.array([rng.uniform(xmin, xmax), rng.uniform(ymin, ymax)])
        i_near = nearest(q_rand)
        d = q_rand - tree.pts[i_near]
        dn = float(np.hypot(*d))
        if dn < 1e-9:
            continue
        q_new = tree.pts[i_near] + d * min(1.0, opts.step / dn)
        r = min(gamma * math.sqrt(math.log(tree.n + 1) / (tree.n + 1)), 3.0 * opts.step)
        r = max(r, opts.step)
        candidates = [vpf_adjust(q_new), q_new] if opts.vpf else [q_new]
        chosen = None
        for q in candidates:
            nb = near_indices(q, r)
            if nb.size == 0:
                nb = np.array([nearest(q)])
            cost = tree.cost[nb] + np.hypot(*(tree.pts[nb] - q).T)
            order = np.argsort(cost)
            nb, cost = nb[order], cost[order]
            ok = edge_free(nb, q)
            if ok.any():
                k = int(np.argmax(ok))
                chosen = (q, int(nb[k]), float(cost[k]), nb, ok)
                break
        if chosen is None:
            continue
        q, parent, cost, nb, ok = chosen
        i = tree.n
        tree.pts[i], tree.parent[i], tree.cost[i] = q, parent, cost
        children[parent].append(i)
        tree.n += 1
        # rewire (Alg. 1): neighbours reached more cheaply through the new node
        new_cost = cost + np.hypot(*(tree.pts[nb] - q).T)
        better = new_cost < tree.cost[nb] - 1e-9
        better &= nb != parent
        if better.any():
            cand = nb[better]
            seg = np.hypot(*(tree.pts[cand] - q).T)
            free = ~world.segments_hit(np.broadcast_to(q, (cand.size, 2)), cost / cruise,
                                       tree.pts[cand], (cost + seg) / cruise)
            for j, c_new in zip(cand[free], new_cost[better][free], strict=True):
                old = int(tree.parent[j])
                children[old].remove(int(j))
                children[i].append(int(j))
                tree.parent[j] = i
                delta = c_new - tree.cost[j]
                stack = [int(j)]
                while stack:
                    s = stack.pop()
                    tree.cost[s] += delta
                    stack.extend(children[s])
        # goal connection
        dg = float(np.hypot(*(goal - q)))
        if dg <= max(tol, opts.step):
            if edge_free(np.array([i]), goal)[0] and cost + dg < best_cost:
                best_goal, best_cost = i, cost + dg
        elif best_goal >= 0:
            best_cost = tree.cost[best_goal] + float(np.hypot(*(goal - tree.pts[best_goal])))
    if best_goal < 0:
        return None
    path = [goal]
    k = best_goal
    while k >= 0:
        path.append(tree.pts[k].copy())
        k = int(tree.parent[k])
    return np.array(path[::-1])


def vpf_path(path: np.ndarray, world: World, cruise: float, opts: RRTOptions,
             passes: int = 3) -> np.ndarray:
    """Eq. 7-12 on the final path: move interior nodes towards the gravity line while clear."""
    pts = path.copy()
    start, goal = pts[0], pts[-1]
    u = (goal - start) / max(float(np.hypot(*(goal - start))), 1e-9)
    for _ in range(passes):
        for i in range(1, len(pts) - 1):
            rel = pts[i] - start
            perp = rel - (rel @ u) * u
            for frac in (1.0, 0.5, 0.25):
                q = pts[i] - frac * perp
                trial = pts.copy()
                trial[i] = q
                seg = np.hypot(*np.diff(trial, axis=0).T)
                t = np.concatenate([[0.0], np.cumsum(seg)]) / cruise
                if not world.segments_hit(trial[i - 1:i + 1], t[i - 1:i + 1],
                                          trial[i:i + 2], t[i:i + 2]).any():
                    pts = trial
                    break
    return pts


def bspline_path(path: np.ndarray, spacing: float) -> np.ndarray:
    """Cubic interpolating B-spline through the RRT* nodes, sampled every ~`spacing` m.

    The spline passes through every node, so it is never shorter than the
    polyline (004 Tab. 5/6: B-spline-RRT* 1.13-1.30 of RRT*).
    """
    keep = np.concatenate([[True], np.hypot(*np.diff(path, axis=0).T) > 1e-6])
    path = path[keep]
    if len(path) < 4:
        return path
    seg = np.hypot(*np.diff(path, axis=0).T)
    u = np.concatenate([[0.0], np.cumsum(np.sqrt(seg))])  # centripetal parameter
    from scipy.interpolate import make_interp_spline

    spl = make_interp_spline(u, path, k=3)
    n = max(int(seg.sum() / spacing), len(path) * 3)
    return spl(np.linspace(0.0, u[-1], n + 1))
