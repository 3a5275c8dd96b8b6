"""Paper 002: GA global path (4 grid waypoints) and local GA re-planning on a collision course.

GA [002 §II.B, Tab. II]: population 20, roulette selection, single-point
crossover p_c = 0.9 (x and y chromosomes cut at the same gene), uniform
integer mutation p_m = 0.35 per chromosome, elitism 1; 30 generations for
the global path, 20 for a local re-plan. A chromosome is 4 waypoints in
cells of a 40 x 40 grid over the area (10 m cells on the 400 m map of
Tab. V). Fitness 1 / (L + P n_hits) (eq. 28-29 plus the PROPOSED
collision penalty P = 1e4 m, digest 3.2), hits by the exact timed
segment test (paper 000 eq. 9).

Re-planning [002 §II.B.3]: the global path sees only static obstacles;
sailing it at cruise speed, when a moving obstacle is within the unsafe
range (100 m) and the rest of the route is predicted to meet it, a local GA
plans from the current position against every obstacle, seeded with the
remaining global waypoints (digest 3.3, PROPOSED). Each re-plan's latency
is measured.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from usvstation.planning.budget import wall_clock
from usvstation.planning.seeds.common import GeneticOperators, World

PENALTY_M = 1e4
PAPER_002_GA = GeneticOperators(population=20, crossover=0.9, mutation=0.35)


@dataclass(frozen=True)
class Replanning:
    """When the boat sailing the global path re-plans [002 §II.B.3]: a moving obstacle
    within `unsafe_range_m` (beyond its inflated radius) whose path meets the rest of the
    route less than `horizon_s` ahead; at most `max_replans` times."""

    unsafe_range_m: float = 100.0
    horizon_s: float = 120.0
    max_replans: int = 20


@dataclass(frozen=True)
class ReplanOptions:
    """`ga` population, single-point crossover and per-chromosome mutation probabilities;
    `generations_global` for the global path, `generations_local` for each local re-plan;
    a chromosome is `waypoints` cells of a `grid` x `grid` grid over the area."""

    ga: GeneticOperators = PAPER_002_GA
    generations_global: int = 30
    generations_local: int = 20
    grid: int = 40
    waypoints: int = 4
    replanning: Replanning = Replanning()


def _evaluate(paths: np.ndarray, world: World, cruise: float, t0: float) -> tuple[np.ndarray, ...]:
    seg = np.hypot(*np.moveaxis(np.diff(paths, axis=1), 2, 0))  # (P, S)
    length = seg.sum(axis=1)
    t = t0 + np.concatenate([np.zeros((len(paths), 1)), np.cumsum(seg, axis=1)], axis=1) / cruise
    n, s = seg.shape
    world.spend(len(paths))
    hits = world.segments_hit(paths[:, :-1].reshape(-1, 2), t[:, :-1].ravel(),
                              paths[:, 1:].reshape(-1, 2), t[:, 1:].ravel()).reshape(n, s)
    nh = hits.sum(axis=1)
    return 1.0 / (length + PENALTY_M * nh), nh


def ga_path(start: np.ndarray, goal: np.ndarray, world: World, cruise: float, t0: float,
            bounds: tuple[float, float, float, float], generations: int,
            rng: np.random.Generator, o: ReplanOptions,
            seed_paths: list[np.ndarray] | None = None) -> tuple[np.ndarray, int]:
    """Best path start -> 4 waypoints -> goal and its number of colliding segments."""
    xmin, xmax, ymin, ymax = bounds
    cell = np.array([(xmax - xmin) / o.grid, (ymax - ymin) / o.grid])
    lo = np.array([xmin, ymin])

    def decode(genes: np.ndarray) -> np.ndarray:
        wp = lo + genes * cell
        n = len(genes)
        return np.concatenate([np.broadcast_to(start, (n, 1, 2)), wp,
                               np.broadcast_to(goal, (n, 1, 2))], axis=1)

    ga = o.ga
    pop = rng.integers(0, o.grid + 1, size=(ga.population, o.waypoints, 2))
    line = start + np.linspace(0, 1, o.waypoints + 2)[1:-1, None] * (goal - start)
    seeds = [line, *list(seed_paths or [])]
    for k, sp in enumerate(seeds[: ga.population]):
        pop[k] = np.clip(np.rint((sp - lo) / cell), 0, o.grid).astype(int)
    f, nh = _evaluate(decode(pop), world, cruise, t0)
    for _ in range(generations):
        elite = pop[int(np.argmax(f))].copy()
        par, mates = ga.roulette_pairs(pop, f, rng)
        cut = rng.integers(1, o.waypoints, size=ga.population)
        cross = rng.random(ga.population) < ga.crossover
        mask = (np.arange(o.waypoints)[None, :] >= cut[:, None]) & cross[:, None]
        child = np.where(mask[:, :, None], mates, par)
        for axis in (0, 1):  # uniform mutation, one gene per chromosome (x and y)
            m = rng.random(ga.population) < ga.mutation
            g = rng.integers(0, o.waypoints, size=ga.population)
            child[m, g[m], axis] = rng.integers(0, o.grid + 1, size=int(m.sum()))
        child[0] = elite
        pop = child
        f, nh = _evaluate(decode(pop), world, cruise, t0)
    k = int(np.argmax(f))
    return decode(pop[k:k + 1])[0], int(nh[k])


def plan_replan(start: np.ndarray, goal: np.ndarray, world: World, cruise: float,
                bounds: tuple[float, float, float, float], rng: np.random.Generator,
                o: ReplanOptions) -> tuple[np.ndarray | None, dict]:
    """Global GA on the static map, then sail and re-plan locally; the executed route."""
    static = ~world.moving
    sw, mw = world.subset(static), world.subset(~static)
    route, nh = ga_path(start, goal, sw, cruise, 0.0, bounds, o.generations_global, rng, o)
    latencies: list[float] = []
    done = [start.copy()]
    pos, t = start.copy(), 0.0
    remaining = route[1:]
    while True:
        rest = np.vstack([pos, remaining])
        seg = np.hypot(*np.diff(rest, axis=0).T)
        tt = t + np.concatenate([[0.0], np.cumsum(seg)]) / cruise
        if mw.count and len(latencies) < o.replanning.max_replans:
            near = np.hypot(mw.cx + mw.vx * t - pos[0], mw.cy + mw.vy * t - pos[1]) \
                <= o.replanning.unsafe_range_m + mw.inflated
            if near.any():
                sub = mw.subset(near)
                within = tt[:-1] - t < o.replanning.horizon_s
                hit = sub.segments_hit(rest[:-1], tt[:-1], rest[1:], tt[1:]) & within
                if hit.any():
                    t0 = wall_clock()
                    new, nh = ga_path(pos, goal, world, cruise, t, bounds, o.generations_local,
                                      rng, o, seed_paths=[_resample(rest, o.waypoints)])
                    latencies.append(wall_clock() - t0)
                    if np.hypot(*(done[-1] - pos)) > 1e-6:
                        done.append(pos.copy())  # the route turns where it was re-planned
                    remaining = new[1:]
                    rest = np.vstack([pos, remaining])
                    seg = np.hypot(*np.diff(rest, axis=0).T)
        if len(rest) <= 1 or seg.sum() < 1e-9:
            break
        # sail one second along the route
        adv = cruise * 1.0
        while adv > 0.0 and len(remaining):
            d = float(np.hypot(*(remaining[0] - pos)))
            if d <= adv:
                pos = remaining[0].copy()
                done.append(pos.copy())
                remaining = remaining[1:]
                adv -= d
            else:
                pos = pos + (remaining[0] - pos) * (adv / d)
                adv = 0.0
        t += 1.0
        if not len(remaining):
            break
    path = np.array(done)
    if np.hypot(*(path[-1] - goal)) > 1e-6:
        path = np.vstack([path, goal])
    stats = {"replans": len(latencies),
             "replan_latency_ms": [round(x * 1000.0, 3) for x in latencies],
             "global_hits": nh}
    return path, stats


def _resample(path: np.ndarray, n: int) -> np.ndarray:
    """n points evenly spaced by arc length strictly inside a polyline."""
    seg = np.hypot(*np.diff(path, axis=0).T)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    q = np.linspace(0.0, s[-1], n + 2)[1:-1]
    return np.stack([np.interp(q, s, path[:, 0]), np.interp(q, s, path[:, 1])], axis=1)
