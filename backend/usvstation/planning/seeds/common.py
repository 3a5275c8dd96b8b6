"""Shared geometry for the seed planners: timed collision checks, speed profile, turn limit.

Every seed planner produces a polyline in the scenario frame; `finish_plan`
turns it into a typed `Plan` (planning/model.py) with the
same speed profile, the same turn-limit pass and the same recovery run-in
along the ramp axis, then asks the independent checker
(`planning.validate.plan_violations`) before anything leaves.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from usvstation.geometry import inflated_radius
from usvstation.planning.budget import Budget
from usvstation.planning.errors import NoFeasiblePlan
from usvstation.planning.hull import keepout_circles, outline_clearance
from usvstation.planning.model import Plan, PlanMetrics, Waypoint
from usvstation.planning.validate import plan_violations
from usvstation.planning.xyt import segments_hit_circles
from usvstation.scenario import Scenario


@dataclass(frozen=True)
class World:
    """Obstacle circles of a scenario (frame of the scenario) with a planning inflation.

    A world that carries the plan's `budget` checks it on every collision query and raises
    BudgetExhausted once it is spent (the planner catches it): so no seed planner runs past
    its budget, whatever its own options say.
    """

    cx: np.ndarray
    cy: np.ndarray
    vx: np.ndarray
    vy: np.ndarray
    radius: np.ndarray
    inflated: np.ndarray
    budget: Budget | None = field(default=None, compare=False, repr=False)
    ship: np.ndarray | None = field(default=None, compare=False, repr=False)  # hull.py circles

    @classmethod
    def from_scenario(cls, scenario: Scenario, margin: float | None = None,
                      budget: Budget | None = None) -> World:
        """Circles inflated by `margin` (default paper 000 eq. 7: D_USV + R_c)."""
        v = scenario.vessel
        m = inflated_radius(0.0, v.length, v.compensation_radius) if margin is None else margin
        obs = scenario.obstacles
        arr = np.array([[o.x, o.y, o.vx, o.vy, o.radius] for o in obs], float).reshape(-1, 5)
        inflated = arr[:, 4] + m
        ship_c, ship_r = keepout_circles(scenario, m)
        if ship_r.size:  # the mother ship's hull: static circles of raw radius 0
            z = np.zeros((ship_r.size, 5))
            z[:, :2] = ship_c
            arr, inflated = np.vstack([arr, z]), np.concatenate([inflated, ship_r])
        ship = np.arange(len(arr)) >= len(obs)
        return cls(arr[:, 0], arr[:, 1], arr[:, 2], arr[:, 3], arr[:, 4], inflated, budget,
                   ship)

    def spend(self, n: int) -> None:
        """Count `n` evaluations against the budget (none without one)."""
        if self.budget is not None:
            self.budget.spend(n)

    def check_budget(self) -> None:
        """Raise BudgetExhausted when the budget is spent or its wall deadline passed."""
        if self.budget is not None:
            self.budget.check()

    @property
    def count(self) -> int:
        return int(self.cx.size)

    def subset(self, keep: np.ndarray) -> World:
        """The circles where `keep` is True (same budget)."""
        return World(self.cx[keep], self.cy[keep], self.vx[keep], self.vy[keep],
                     self.radius[keep], self.inflated[keep], self.budget,
                     None if self.ship is None else self.ship[keep])

    @property
    def moving(self) -> np.ndarray:
        return (self.vx != 0.0) | (self.vy != 0.0)

    def swept_window(self, start: np.ndarray, cruise: float, horizon_s: float,
                     slow: float = 1.3, fast: float = 1.1) -> World:
        """Static corridors: each mover's track over [0, horizon] where the boat could meet it.

        For planners whose paper knows only static obstacles (003, 004). A
        piece of the track at time s is kept when its distance from the start
        lies within [s cruise / slow - r, s cruise fast + r] (r the inflated
        radius): where a boat sailing at about `cruise` on a path up to `slow`
        times the straight line could be at that time. A mover thus becomes a
        static wall over the stretch of water where it could cross the boat's
        way; its track elsewhere is left open. Static circles are kept as they are.
        Pieces are spaced at most 0.7 inflated radii apart, so their union covers the
        corridor to 0.7 radii either side of the track.
        """
        still = ~self.moving
        cx, cy, r, ri = [self.cx[still]], [self.cy[still]], [self.radius[still]], \
            [self.inflated[still]]
        ship = [self._ship_mask()[still]]
        for i in np.flatnonzero(self.moving):
            speed = math.hypot(self.vx[i], self.vy[i])
            n = 2 + math.ceil(speed * horizon_s / max(0.7 * self.inflated[i], 0.25))
            s = np.linspace(0.0, horizon_s, n)
            px, py = self.cx[i] + self.vx[i] * s, self.cy[i] + self.vy[i] * s
            d = np.hypot(px - start[0], py - start[1])
            keep = (d >= s * cruise / slow - self.inflated[i]) & \
                (d <= s * cruise * fast + self.inflated[i])
            cx.append(px[keep])
            cy.append(py[keep])
            ship.append(np.zeros(int(keep.sum()), bool))
            r.append(np.full(int(keep.sum()), self.radius[i]))
            ri.append(np.full(int(keep.sum()), self.inflated[i]))
        cxa, cya = np.concatenate(cx), np.concatenate(cy)
        z = np.zeros_like(cxa)
        return World(cxa, cya, z, z.copy(), np.concatenate(r), np.concatenate(ri), self.budget,
                     np.concatenate(ship))

    def _ship_mask(self) -> np.ndarray:
        return np.zeros(self.count, bool) if self.ship is None else self.ship

    def segments_hit(self, p0: np.ndarray, t0: np.ndarray, p1: np.ndarray, t1: np.ndarray,
                     radius: np.ndarray | None = None) -> np.ndarray:
        """(N,) True where segment i (timed, paper 000 eq. 9) enters any inflated circle."""
        self.check_budget()
        if self.count == 0:
            return np.zeros(len(p0), dtype=bool)
        r = self.inflated if radius is None else radius
        p0, p1 = np.asarray(p0, float).reshape(-1, 2), np.asarray(p1, float).reshape(-1, 2)
        t0 = np.broadcast_to(np.asarray(t0, float), (len(p0),))
        t1 = np.broadcast_to(np.asarray(t1, float), (len(p1),))
        hit = segments_hit_circles(
            p0[:, 0, None], p0[:, 1, None], t0[:, None], p1[:, 0, None], p1[:, 1, None],
            t1[:, None], self.cx, self.cy, self.vx, self.vy, r,
        )
        return hit.any(axis=1)

    def points_free(self, p: np.ndarray, t: np.ndarray | float) -> np.ndarray:
        """(N,) True where point i at time t_i lies outside every inflated circle."""
        self.check_budget()
        p = np.asarray(p, float).reshape(-1, 2)
        if self.count == 0:
            return np.ones(len(p), dtype=bool)
        t = np.broadcast_to(np.asarray(t, float), (len(p),))
        dx = p[:, 0, None] - (self.cx + self.vx * t[:, None])
        dy = p[:, 1, None] - (self.cy + self.vy * t[:, None])
        return ((dx * dx + dy * dy) >= self.inflated**2).all(axis=1)

    def distance(self, p: np.ndarray, t: np.ndarray | float) -> np.ndarray:
        """(N, M) distance from point i at time t_i to obstacle j's inflated edge."""
        self.check_budget()
        p = np.asarray(p, float).reshape(-1, 2)
        t = np.broadcast_to(np.asarray(t, float), (len(p),))
        dx = p[:, 0, None] - (self.cx + self.vx * t[:, None])
        dy = p[:, 1, None] - (self.cy + self.vy * t[:, None])
        return np.hypot(dx, dy) - self.inflated


@dataclass(frozen=True)
class GeneticOperators:
    """A genetic algorithm's population size and its crossover and mutation probabilities
    (per individual or per gene, as each planner's paper says)."""

    population: int
    crossover: float
    mutation: float

    def roulette_pairs(self, pop: np.ndarray, weights: np.ndarray,
                       rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
        """Roulette-wheel selection: `population` parents drawn with probability in
        proportion to `weights` (non-negative, not all zero), each paired with a mate, a
        random permutation of the parents."""
        idx = rng.choice(self.population, size=self.population, p=weights / weights.sum())
        parents = pop[idx]
        return parents, parents[rng.permutation(self.population)]


def cruise_speed(scenario: Scenario, requested: float | None = None) -> float:
    """Planning speed: the requested one, else the start speed, inside the vessel's limits."""
    v = scenario.vessel
    want = requested if requested is not None else (scenario.start.speed or 1.0)
    return float(min(max(want, v.speed_min), v.speed_max))


def speed_profile(pts: np.ndarray, scenario: Scenario, cruise: float,
                  wanted: np.ndarray | None = None) -> tuple[np.ndarray, ...]:
    """Times and speeds of a polyline: from the start speed towards `cruise` at accel_max.

    v_{i+1} = min(cruise, sqrt(v_i^2 + 2 a s_i)) (or the mirror when slowing
    down), so |v_{i+1} - v_i| / dt_i = |v_{i+1}^2 - v_i^2| / (2 s_i) <= a with
    dt_i = 2 s_i / (v_i + v_{i+1}), position linear in time on each segment.
    `wanted` (one speed per point) replaces the constant cruise target.
    """
    v = scenario.vessel
    # ground speeds that keep the speed through the water within [speed_min, speed_max]
    # whatever the leg's direction (issue 12): |v u - c| lies within v -+ |c|
    c = scenario.environment.current_speed
    lo = v.speed_min + c
    hi = max(lo, v.speed_max - c)
    seg = np.hypot(*np.diff(pts, axis=0).T)
    speeds = np.empty(len(pts))
    speeds[0] = min(max(scenario.start.speed, lo), hi)
    cruise = min(max(cruise, lo), hi)
    a = v.accel_max * (1.0 - 1e-4)  # margin for the 6-decimal rounding of the plan
    for i, s in enumerate(seg):
        vi = speeds[i]
        goal = cruise if wanted is None else float(np.clip(wanted[i + 1], lo, hi))
        if vi < goal:
            speeds[i + 1] = min(goal, math.sqrt(vi * vi + 2.0 * a * s))
        else:
            speeds[i + 1] = max(goal, math.sqrt(max(vi * vi - 2.0 * a * s, 0.0)))
    dt = 2.0 * seg / (speeds[:-1] + speeds[1:])
    return np.concatenate([[0.0], np.cumsum(dt)]), speeds


def dedupe(pts: np.ndarray, tol: float = 1e-3) -> np.ndarray:
    """Drop points closer than `tol` to their predecessor; the first and last points are
    always kept (both, even when they are closer than `tol`)."""
    pts = np.asarray(pts, float)
    keep = [0]
    for i in range(1, len(pts)):
        if np.hypot(*(pts[i] - pts[keep[-1]])) > tol:
            keep.append(i)
        elif i == len(pts) - 1:
            if len(keep) > 1:
                keep[-1] = i
            else:
                keep.append(i)
    return pts[keep].copy()


def turns_deg(pts: np.ndarray) -> np.ndarray:
    """Turn at every interior vertex, degrees (wrap180 of successive segment headings)."""
    h = np.arctan2(*np.diff(pts, axis=0).T[::-1])
    if h.size < 2:
        return np.zeros(0)
    return np.degrees(np.abs(np.mod(np.diff(h) + np.pi, 2 * np.pi) - np.pi))


def limit_turns(pts: np.ndarray, turn_max_deg: float, cut: float) -> np.ndarray:
    """Cut every corner sharper than the turn limit until none is left.

    A corner V between A and B becomes two points at distance c (at most
    `cut`, at most 45 % of either leg) before and after V on its legs: each
    new corner turns half as much. Endpoints never move. Points closer than 1 % of `cut`
    merge first: two corners millimetres apart are one (a reversal there is a spike).
    """
    tol = max(1e-3, 0.01 * cut)
    pts = dedupe(pts, tol)
    for _ in range(len(pts)):  # a reversal (turn ~180 deg) cannot be cut: drop the spike
        tr = turns_deg(pts)
        spikes = np.flatnonzero(tr > 179.0) + 1
        if spikes.size == 0:
            break
        pts = dedupe(np.delete(pts, spikes[:1], axis=0), tol)
    for _ in range(64):
        tr = turns_deg(pts)
        bad = np.flatnonzero(tr > turn_max_deg - 0.5) + 1
        if bad.size == 0:
            return pts
        out = [pts[0]]
        for i in range(1, len(pts) - 1):
            if i in set(bad.tolist()):
                a, v, b = pts[i - 1], pts[i], pts[i + 1]
                la, lb = np.hypot(*(a - v)), np.hypot(*(b - v))
                c = min(cut, 0.45 * la, 0.45 * lb)
                out.append(v + (a - v) * (c / la))
                out.append(v + (b - v) * (c / lb))
            else:
                out.append(pts[i])
        out.append(pts[-1])
        pts = dedupe(np.array(out))
    return pts


def timed_hits(pts: np.ndarray, world: World, scenario: Scenario, cruise: float) -> np.ndarray:
    """Segments of a polyline (timed by `speed_profile`) that enter an inflated circle."""
    t, _ = speed_profile(pts, scenario, cruise)
    return world.segments_hit(pts[:-1], t[:-1], pts[1:], t[1:])


def recovery_gates(scenario: Scenario, world: World) -> list[np.ndarray]:
    """Candidate run-in gates (g, 0) on the ramp axis; from each the boat runs straight in.

    A gate is kept when it and the straight run-in to the ramp end are clear
    of static obstacles (the mother ship's hull included); nearest-first
    distances 15, 10, 20, 6, 30 m, within the start's distance out, or any of
    them for a start that is not out at sea (behind or beside the ramp: the
    boat goes out to the gate first).
    """
    static = world.subset(~world.moving)
    out = []
    for g in (15.0, 10.0, 20.0, 6.0, 30.0, 4.0):
        p = np.array([[g, 0.0], [0.0, 0.0]])
        if not static.segments_hit(p[:1], 0.0, p[1:], 1.0)[0]:
            out.append(p[0])
    ahead = [p for p in out if p[0] < scenario.start.x - 1.0]
    if ahead:
        return ahead
    if out and scenario.start.x < out[0][0]:
        return out
    return [np.array([max(min(10.0, scenario.start.x / 2.0), 1.0), 0.0])]


def path_metrics(pts: np.ndarray) -> dict[str, float]:
    """Length, normalisation index (004 Tab. 5/6), total and maximum turn."""
    seg = np.hypot(*np.diff(pts, axis=0).T)
    length = float(seg.sum())
    straight = float(np.hypot(*(pts[-1] - pts[0])))
    tr = turns_deg(pts)
    return {
        "length_m": length,
        "normalization_index": length / straight if straight > 0 else 1.0,
        "total_turn_deg": float(tr.sum()),
        "max_turn_deg": float(tr.max()) if tr.size else 0.0,
    }


def finish_plan(
    scenario: Scenario, route: np.ndarray, planner: str, seed: int, cruise: float,
    elapsed_s: float, extra: dict[str, Any] | None = None, cut: float = 6.0,
    speeds: np.ndarray | None = None,
) -> Plan:
    """The plan of a route start -> ... -> goal, checked by the validator.

    For a recovery the route must already end with the run-in along the ramp
    axis (gate, then (0, 0)). Raises NoFeasiblePlan with the checker's first
    complaint when the plan breaks a rule.
    """
    route = np.asarray(route, float)
    route[0] = (scenario.start.x, scenario.start.y)
    route[-1] = (scenario.goal.x, scenario.goal.y)
    world = World.from_scenario(scenario, margin=scenario.vessel.length / 2.0)
    if speeds is not None:  # a planner with its own speeds: speed of the nearest route point
        pts = limit_turns(route, scenario.vessel.turn_max_deg, min(cut, 1.0))
        keep = [int(np.argmin(np.hypot(*(route - q).T))) for q in pts]
        wanted = np.asarray(speeds, float)[keep]
        t, v = speed_profile(pts, scenario, cruise, wanted)
        return _assemble(scenario, pts, t, v, planner, seed, elapsed_s, extra)
    pts = limit_turns(route, scenario.vessel.turn_max_deg, cut)
    for c in (cut / 2, cut / 4, cut / 8):
        if not timed_hits(pts, world, scenario, cruise).any():
            break
        pts = limit_turns(route, scenario.vessel.turn_max_deg, c)
    t, v = speed_profile(pts, scenario, cruise)
    return _assemble(scenario, pts, t, v, planner, seed, elapsed_s, extra)


def _assemble(scenario: Scenario, pts: np.ndarray, t: np.ndarray, v: np.ndarray, planner: str,
              seed: int, elapsed_s: float, extra: dict[str, Any] | None) -> Plan:
    h = np.degrees(np.arctan2(*np.diff(pts, axis=0).T[::-1]))
    h = np.append(h, h[-1]) % 360.0
    waypoints = [
        Waypoint(_r(p[0]), _r(p[1]), _r(tt), _r(vv), _r(hh))  # type: ignore[arg-type]
        for p, tt, vv, hh in zip(pts, t, v, h, strict=True)
    ]
    waypoints[0] = replace(waypoints[0], x=scenario.start.x, y=scenario.start.y)
    waypoints[-1] = replace(waypoints[-1], x=scenario.goal.x, y=scenario.goal.y)
    pm = path_metrics(pts)
    clear = World.from_scenario(scenario, margin=0.0)
    metrics: dict[str, Any] = {
        "fitness": None,
        **{k: _r(val) for k, val in pm.items()},
        "duration_s": _r(float(t[-1])),
        "min_clearance_m": _r(min_clearance(pts, t, clear, scenario.vessel.length / 2.0)),
        "collision_free": True,
        "generations": 0,
        "elapsed_s": round(elapsed_s, 6),
        "arrival_heading_deg": _r(float(h[-1])),
    }
    ship = outline_clearance(scenario, pts[:, 0], pts[:, 1])
    if ship is not None:
        metrics["ship_clearance_m"] = _r(ship)
    metrics.update(extra or {})
    plan = Plan(planner, scenario.name, seed, tuple(waypoints), PlanMetrics(metrics))
    bad = plan_violations(plan.to_document(), scenario)
    if bad:
        raise NoFeasiblePlan(f"no feasible plan: {planner}: {bad[0]}")
    return plan


def min_clearance(pts: np.ndarray, t: np.ndarray, world: World, half_hull: float) -> float | None:
    """Least water between the hull and an obstacle edge over the timed polyline, m (the
    mother ship's keep-out circles are not obstacles: `ship_clearance_m` measures it)."""
    world = world.subset(~world._ship_mask())
    if world.count == 0:
        return None
    dt = np.diff(t)[:, None]
    ex = pts[:-1, 0, None] - (world.cx + world.vx * t[:-1, None])
    ey = pts[:-1, 1, None] - (world.cy + world.vy * t[:-1, None])
    dx = np.diff(pts[:, 0])[:, None] - world.vx * dt
    dy = np.diff(pts[:, 1])[:, None] - world.vy * dt
    dd = dx * dx + dy * dy
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.clip(np.where(dd > 0, -(ex * dx + ey * dy) / dd, 0.0), 0.0, 1.0)
    d = np.hypot(ex + s * dx, ey + s * dy) - world.radius - half_hull
    return float(d.min())


def _r(value: float | None) -> float | None:
    """Rounded to the micrometre; None (no obstacle, so no clearance) stays None."""
    return None if value is None else round(float(value), 6)
