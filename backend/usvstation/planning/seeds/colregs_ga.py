"""Paper 001: a GA per 1 s step over acceleration and yaw rate, with COLREGs and fuzzy risk.

Every step (Delta t = 1 s, [001 §II.C]) a population of 50 (a, r) pairs is
evolved (roulette selection, discrete crossover p_c = 0.8, Gaussian
mutation p_m = 0.02, retention of the best, deletion + replacement of a yaw
rate that heads into an obstacle's radar sector by the best's [001 §III.C])
and the best pair moves the boat one step (explicit Euler, digest 2.2).
Fitness [001 eq. 15] with the AHP weights k = (0.112, 0.444, 0.444)
(Tab. I, fixed matrix), lambda = 2 inside/outside a sector; "normalised"
mode (default) uses c' = 1 - d/d_start and d0, d1 capped at D_ca so the
goal term matters, "paper" mode the literal c = 1e5/d.

COLREGs (the `colregs` module): each moving target's class is latched at
first risk; while u >= u_act for a head-on or give-way crossing target, a
turn to port (r > 0, counter-clockwise) is divided by lambda, so the boat
turns to starboard; stand-on keeps course (|r| penalised) until
in-extremis (u >= 0.9 or range <= l1). A collision within the look-ahead
(constant a, r for `lookahead_s`) is a hard penalty, an addition to the
paper, which has no other safety gate.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from usvstation.planning import colregs as cr
from usvstation.planning.seeds.common import GeneticOperators, World

K_AHP = np.array([0.112, 0.444, 0.444])
PAPER_001_GA = GeneticOperators(population=50, crossover=0.8, mutation=0.02)


@dataclass(frozen=True)
class GAStepOptions:
    """The GA run at every step and the constants of its fitness and COLREGs rules.

    `ga` population, p_c, p_m; at most `generations` per step, fewer once `stall` pass
    without improvement; the (a, r) search box from `accel_max` (m/s^2) and
    `yaw_rate_max_deg` (deg/s); `lam` the sector factor lambda; `d_ca` (m) the distance
    that caps d0, d1 and the goal room; a target's fuzzy risk scaled by `risk_scale_m`,
    its rule applied from risk `u_act` or when on a collision course within
    `detect_range_m`; the hard collision gate looks `lookahead_s` ahead at constant
    (a, r); `improved` the Tab. III operators; `paper_fitness` eq. 15 as printed
    (c = 1e5 / d); at most `max_steps` steps.
    """

    ga: GeneticOperators = PAPER_001_GA
    generations: int = 40
    stall: int = 6
    accel_max: float = 2.0
    yaw_rate_max_deg: float = 15.0
    lam: float = 2.0
    d_ca: float = 10.0
    risk_scale_m: float = 20.0
    u_act: float = 0.3
    lookahead_s: float = 12.0
    detect_range_m: float = 150.0
    improved: bool = True   # retention, deletion and replacement (Tab. III "improved")
    paper_fitness: bool = False
    max_steps: int = 2000


@dataclass
class StepStats:
    generations: list[int]
    fitness: list[float]


def _sectors(p: np.ndarray, world: World, t: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Centre bearing (rad), half-width (rad) and range of every obstacle seen from p."""
    cx, cy = world.cx + world.vx * t, world.cy + world.vy * t
    rng = np.hypot(cx - p[0], cy - p[1])
    bearing = np.arctan2(cy - p[1], cx - p[0])
    half = np.arcsin(np.minimum(1.0, world.inflated / np.maximum(rng, 1e-9)))
    return bearing, half, rng


def plan_colregs_ga(start: np.ndarray, heading: float, speed0: float, target: np.ndarray,
                    world: World, vmin: float, vmax: float, accel_max: float,
                    rng: np.random.Generator, o: GAStepOptions
                    ) -> tuple[np.ndarray | None, np.ndarray, dict]:
    """Route (K, 2), speeds (K,) and statistics; route None when the step budget runs out."""
    p, psi, v = start.astype(float).copy(), float(heading), float(speed0)
    d_start = float(np.hypot(*(target - p)))
    a_hi = min(o.accel_max, accel_max * 0.95)
    r_hi = math.radians(o.yaw_rate_max_deg)
    lo, hi = np.array([-a_hi, -r_hi]), np.array([a_hi, r_hi])
    moving = np.flatnonzero(world.moving)
    latch = cr.EncounterLatch()
    pts, speeds = [p.copy()], [v]
    gens, best_f = [], []
    t = 0.0
    reach = max(4.0, 3.0 * vmax)
    h = np.linspace(1.0, o.lookahead_s, max(2, int(o.lookahead_s)))
    # water the goal itself leaves to the static obstacles: wanting more than that near
    # the goal would keep the boat from ever reaching it (PROPOSED; 001 has no goal rule)
    still = ~world.moving
    goal_room = float((np.hypot(world.cx[still] - target[0], world.cy[still] - target[1])
                       - world.inflated[still]).min()) if still.any() else o.d_ca
    d_cap0 = float(np.clip(goal_room, 1.0, o.d_ca))
    steps_max = min(o.max_steps, int(3.0 * d_start / max(0.5 * vmax, vmin)) + 60)
    for _ in range(steps_max):
        if np.hypot(*(target - p)) <= reach:
            pts.append(target.copy())
            speeds.append(speeds[-1])
            break
        # COLREGs state of each moving target at this step
        course = cr.course_from_ramp_heading(psi)
        v_own = cr.velocity(course, v)
        starboard_only = stand_on = False
        for j in moving:
            pt = np.array([world.cx[j] + world.vx[j] * t, world.cy[j] + world.vy[j] * t])
            vt = np.array([world.vx[j], world.vy[j]])
            dcpa, tcpa = cr.cpa(p, v_own, pt, vt)
            ct = cr.wrap360(math.degrees(math.atan2(vt[0], vt[1])))
            beta, alpha = cr.relative_angles(p, course, pt, ct)
            rel = vt - v_own
            opening = float((pt - p) @ rel) > 0.0
            risk = cr.fuzzy_risk(dcpa, tcpa, float(np.hypot(*rel)), beta, o.risk_scale_m,
                                 opening=opening)
            course_set = cr.on_collision_course(float(np.hypot(*(pt - p))), risk, o.detect_range_m)
            enc = latch.update(int(j), 1.0 if course_set else risk.u, beta, alpha)
            if enc is None or tcpa < 0.0 or (risk.u < o.u_act and not course_set):
                continue
            urgent = risk.u >= 0.9 and float(np.hypot(*(pt - p))) <= risk.l1
            if enc in cr.GIVE_WAY_STARBOARD:
                starboard_only = True
            elif enc in (cr.Encounter.CROSSING_STAND_ON, cr.Encounter.OVERTAKING_STAND_ON):
                stand_on = stand_on or not urgent
        bearing, half, rng_o = _sectors(p, world, t + 1.0)
        # an obstacle beyond the goal does not block it (PROPOSED; the paper has no goal rule)
        watch = (rng_o < o.d_ca) & (rng_o - world.inflated < float(np.hypot(*(target - p))))

        def fitness(genes: np.ndarray, p: np.ndarray = p, psi: float = psi, v: float = v,
                    t: float = t, bearing: np.ndarray = bearing, half: np.ndarray = half,
                    watch: np.ndarray = watch, starboard_only: bool = starboard_only,
                    stand_on: bool = stand_on, reach: float = reach
                    ) -> tuple[np.ndarray, np.ndarray]:
            world.spend(len(genes))
            world.check_budget()
            a, r = genes[:, 0], genes[:, 1]
            v1 = np.clip(v + a, vmin, vmax)
            psi1 = psi + r
            step = np.stack([np.cos(psi1), np.sin(psi1)], axis=1) * v1[:, None]
            p1 = p + step
            d = np.hypot(*(target - p1).T)
            # look-ahead: keep a and r for `lookahead_s`, exact per-second samples
            ang = psi + r[:, None] * (1.0 + h[None, :])
            vv = np.clip(v + a[:, None] * (1.0 + h[None, :]), vmin, vmax)
            fut = p1[:, None, :] + np.cumsum(
                np.stack([np.cos(ang), np.sin(ang)], axis=2) * vv[:, :, None], axis=1)
            all_pts = np.concatenate([p1[:, None, :], fut], axis=1)
            times = t + 1.0 + np.concatenate([[0.0], h])
            if world.count:
                cx = world.cx[None, None, :] + world.vx[None, None, :] * times[None, :, None]
                cy = world.cy[None, None, :] + world.vy[None, None, :] * times[None, :, None]
                dist = np.hypot(all_pts[..., 0, None] - cx, all_pts[..., 1, None] - cy) \
                    - world.inflated
                # the look-ahead ends where it reaches the goal
                at_goal = np.hypot(*np.moveaxis(all_pts - target, 2, 0)) <= reach
                past = np.cumsum(at_goal, axis=1) > 0
                past[:, 1:] = past[:, :-1].copy()
                past[:, 0] = False
                dist = np.where(past[..., None], np.inf, dist)
                near = dist.min(axis=1)
                hit_now = world.segments_hit(np.broadcast_to(p, p1.shape), t, p1, t + 1.0)
                d0 = near[:, ~world.moving].min(axis=1) if (~world.moving).any() \
                    else np.full(len(a), o.d_ca)
                d1 = near[:, world.moving].min(axis=1) if world.moving.any() \
                    else np.full(len(a), o.d_ca)
                crash = hit_now | (near.min(axis=1) < 0.0)
                dh = np.abs(np.mod(psi1[:, None] - bearing[None, :] + np.pi, 2 * np.pi) - np.pi)
                in_sector = ((dh <= half[None, :]) & watch[None, :]).any(axis=1)
            else:
                d0 = d1 = np.full(len(a), o.d_ca)
                crash = np.zeros(len(a), bool)
                in_sector = np.zeros(len(a), bool)
            if o.paper_fitness:  # eq. 15 as printed: c = 1e5 / d
                core = K_AHP[0] * 1e5 / np.maximum(d, 1e-3) + K_AHP[1] * d0 + K_AHP[2] * d1
            else:
                core = (K_AHP[0] * (1.0 - d / d_start) * 4.0
                        + K_AHP[1] * np.clip(d0, 0.0, d_cap0) / d_cap0
                        + K_AHP[2] * np.clip(d1, 0.0, o.d_ca) / o.d_ca)
                core = core - core.min() + 1e-3 if core.min() <= 0 else core
            f = np.where(in_sector, core / o.lam, core * o.lam)
            if starboard_only:
                f = np.where(r > 0.0, f / o.lam**2, f)
            if stand_on:
                f = np.where(np.abs(r) > math.radians(1.0), f / o.lam, f)
            f = np.where(crash, f * 1e-4, f)
            return f, in_sector

        ga = o.ga
        pop = rng.uniform(lo, hi, size=(ga.population, 2))
        f, sect = fitness(pop)
        best = pop[int(np.argmax(f))].copy()
        best_val, stall, used = float(f.max()), 0, 0
        for g in range(1, o.generations + 1):
            used = g
            parents, mates = ga.roulette_pairs(pop, f - f.min() + 1e-12, rng)
            cross = rng.random(ga.population) < ga.crossover
            take = rng.random((ga.population, 2)) < 0.5
            child = np.where(cross[:, None] & take, mates, parents)
            mut = rng.random((ga.population, 2)) < ga.mutation
            child = np.where(mut, child + rng.normal(0.0, 0.25 * (hi - lo), child.shape), child)
            child = np.clip(child, lo, hi)
            if o.improved:
                child[0] = best  # retention
                f_c, sect = fitness(child)
                child[sect, 1] = best[1]  # deletion + replacement of r
                f_c, _ = fitness(child)
            else:
                f_c, _ = fitness(child)
            pop, f = child, f_c
            k = int(np.argmax(f))
            if f[k] > best_val * (1 + 1e-6):
                best, best_val, stall = pop[k].copy(), float(f[k]), 0
            else:
                stall += 1
                if stall >= o.stall:
                    break
        gens.append(used)
        best_f.append(best_val)
        v = float(np.clip(v + best[0], vmin, vmax))
        psi += float(best[1])
        p = p + v * np.array([math.cos(psi), math.sin(psi)])
        t += 1.0
        pts.append(p.copy())
        speeds.append(v)
    else:
        return None, np.array(pts), {"reason": f"goal not reached in {steps_max} steps"}
    stats = {"generations": int(np.sum(gens)), "steps": len(gens),
             "generations_per_step_mean": float(np.mean(gens)) if gens else 0.0,
             "fitness_final": best_f[-1] if best_f else None,
             "encounters": {str(k): e.value for k, e in latch.classes.items()}}
    return np.array(pts), np.array(speeds), stats
