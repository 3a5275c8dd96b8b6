"""One planner interface: every planner by name, its paper and capabilities.

`plan_with(scenario, name, seed, **options)` returns a typed `Plan` (planning/model.py;
`Plan.to_document()` is the stable plan format, DESIGN.md "Plan output") or raises
NoFeasiblePlan; every plan has passed
the independent checker (`planning.validate.plan_violations`) before it
leaves. Options are validated per planner (one line naming the field).

To add a planner: write a function `(scenario, seed, options) -> Plan`
that ends with `seeds.common.finish_plan` (or calls the checker itself), a
pydantic options model, and one `PlannerInfo` entry in `PLANNERS`.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, ValidationError

from usvstation.geometry import angle_diff, inflated_radius
from usvstation.planning.budget import Budget, BudgetExhausted, Clock, cpu_clock
from usvstation.planning.errors import NoFeasiblePlan
from usvstation.planning.model import Plan
from usvstation.planning.seeds.common import (
    World,
    cruise_speed,
    finish_plan,
    path_metrics,
    recovery_gates,
)
from usvstation.planning.validate import MOVING_START_SPEED, current_vector
from usvstation.scenario import Scenario

MOVING = "moving-obstacles"
MOVING_TIMED = "moving-obstacles-timed-at-cruise"
SWEPT = "moving-obstacles-as-swept-corridors"
RAMP = "ramp-alignment"
RUN_IN = "run-in-along-ramp-axis"
COLREGS = "colregs"
REPLAN = "re-planning"
SPEED = "speed-profile"
SEEDED = "seeded-deterministic"


@dataclass(frozen=True)
class PlannerInfo:
    name: str
    paper: str
    title: str
    capabilities: tuple[str, ...]
    options: type[BaseModel]
    run: Callable[[Scenario, int, Any, float | None, Clock], Plan]

    def describe(self) -> dict[str, Any]:
        """The `GET /api/planners` entry: {name, paper, title, capabilities}."""
        return {"name": self.name, "paper": self.paper, "title": self.title,
                "capabilities": list(self.capabilities)}


class SeedOptions(BaseModel):
    """Options every seed planner takes."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)
    cruise_speed: float | None = Field(None, gt=0.0, description="m/s; default the start speed")
    attempts: int = Field(4, ge=1, le=50, description="seeds/gates tried before giving up")
    corner_cut_m: float = Field(6.0, gt=0.0, le=100.0)
    time_budget_s: float = Field(
        5.0, gt=0.0, le=600.0,
        description="wall-clock safety net: past it the best plan so far (RRT*) with a "
        "warning, or none")
    max_evaluations: int | None = Field(
        None, ge=1, le=50_000_000,
        description="deterministic budget over all attempts: tree iterations (RRT*), "
        "individuals evaluated (GAs), trial parameter sets (DE); default: the planner's own "
        "options bound it")


class RRTStarOptions(SeedOptions):
    step_m: float | None = Field(None, gt=0.0,
                                 description="steer step p; default dist/12 in [2, 20]")
    iterations: int = Field(1500, ge=50, le=200_000)
    goal_bias: float = Field(0.05, ge=0.0, le=1.0)


def _drive(scenario: Scenario, seed: int, opts: SeedOptions, name: str,
           core: Callable[[Scenario, World, np.ndarray, float, np.random.Generator], tuple],
           speeds_from: dict[str, Any] | None = None, static_only: bool = False,
           started: float | None = None, clock: Clock = cpu_clock) -> Plan:
    """Common attempt loop: gate (recovery), seed, clearance; first plan passing the checker.

    A planner whose paper knows only static obstacles (`static_only`) plans
    first against the movers' swept corridors (`World.swept_window`), then,
    if that finds nothing the timed checker accepts, against the movers
    timed at cruise speed; `metrics.obstacle_model` says which one gave the plan.
    All attempts share one budget (planning/budget.py), carried by the worlds they plan in.
    """
    budget = Budget(opts.max_evaluations, opts.time_budget_s, clock, started)
    cruise = cruise_speed(scenario, opts.cruise_speed)
    v = scenario.vessel
    margins = (inflated_radius(0.0, v.length, v.compensation_radius), v.length)  # eq. 7, R_c = 0
    last: str = "no path found"
    full = World.from_scenario(scenario, margins[0])
    gates = recovery_gates(scenario, full) if scenario.kind == "recovery" else [None]
    base_cruise = cruise
    for attempt in range(opts.attempts):
        margin = margins[0] if attempt < max(1, opts.attempts // 2) or opts.attempts == 1 \
            else margins[1]
        # another speed shifts every meeting in time: a way past a mover that crosses the
        # run-in at the boat's arrival, which a static-only method cannot see (PROPOSED)
        cruise = cruise_speed(scenario, base_cruise * SPEED_TRIES[attempt % len(SPEED_TRIES)])
        world = World.from_scenario(scenario, margin, budget)
        gate = gates[attempt % len(gates)]
        target = np.array([scenario.goal.x, scenario.goal.y]) if gate is None else gate
        for model, seen in _obstacle_models(scenario, world, target, cruise, static_only):
            if budget.exhausted():
                break
            rng = np.random.default_rng([seed, attempt])
            try:
                route, extra = core(scenario, seen, target, cruise, rng)
            except BudgetExhausted:
                break
            if route is None:
                last = extra.get("reason", last) if isinstance(extra, dict) else last
                continue
            plan, last = _finish_attempt(scenario, route, extra, gate, speeds_from, name, seed,
                                         cruise, budget, opts, attempt, margin, model, last)
            if plan is None:
                continue
            if margin < margins[0]:
                plan = plan.warned(f"reduced clearance: planned with {margin:g} m "
                                   f"instead of eq. 7's {margins[0]:g} m")
            plan = plan.with_metrics(evaluations=budget.evaluations,
                                     stop_reason=budget.stop_reason() or "found")
            return plan.warned(budget.warning()) if budget.time_fired else plan
        if budget.exhausted():
            break
    raise NoFeasiblePlan(f"no feasible plan{budget.failure()}: {name}: {last}")


SPEED_TRIES = (1.0, 1.3, 0.75, 1.0)  # cruise speed factor of attempt k (mod 4)


def _lead_in_course(scenario: Scenario, route: np.ndarray) -> float | None:
    """Course of a first leg along the start heading, or None when the route needs none.

    A boat under way may turn at most its limit from the start heading onto the first leg
    (issue 12's first-turn rule). The lead-in's course is the heading's, set by the current
    (so that the hull keeps its heading); the turn-limit pass then rounds the corner at its end.
    """
    v, st = scenario.vessel, scenario.start
    if st.speed < MOVING_START_SPEED or len(route) < 2:
        return None
    h = math.radians(st.heading_deg)
    cx, cy = current_vector(scenario)
    course = math.atan2(st.speed * math.sin(h) + cy, st.speed * math.cos(h) + cx)
    first = math.atan2(route[1][1] - route[0][1], route[1][0] - route[0][0])
    if abs(math.degrees(angle_diff(first, course))) <= v.turn_max_deg - 0.5:
        return None
    return course


def _with_lead_in(route: np.ndarray, course: float, length: float) -> np.ndarray:
    lead = route[0] + length * np.array([math.cos(course), math.sin(course)])
    return np.vstack([route[:1], lead[None], route[1:]])


def _obstacle_models(scenario: Scenario, world: World, target: np.ndarray, cruise: float,
                     static_only: bool) -> list[tuple[str, World]]:
    """The obstacle models to try in turn: swept corridors first for a static-only planner."""
    if not static_only or not world.moving.any():
        return [("timed", world)]
    start = np.array([scenario.start.x, scenario.start.y])
    horizon = 1.3 * float(np.hypot(*(target - start))) / cruise + 30.0
    return [("swept", world.swept_window(start, cruise, horizon)), ("timed", world)]


def _finish_attempt(scenario: Scenario, route: np.ndarray, extra: Any, gate: np.ndarray | None,
                    speeds_from: dict[str, Any] | None, name: str, seed: int, cruise: float,
                    budget: Budget, opts: SeedOptions, attempt: int, margin: float, model: str,
                    last: str) -> tuple[Plan | None, str]:
    """The plan of one route (run-in appended, checked), or None and the checker's reason."""
    speeds = None
    routes = [route]
    if speeds_from is not None and "speeds" in speeds_from:
        speeds = np.asarray(speeds_from["speeds"], float)
    elif (course := _lead_in_course(scenario, route)) is not None:
        # a long lead-in first, a short one if the long one meets an obstacle
        routes = [_with_lead_in(route, course, k * opts.corner_cut_m) for k in (2.0, 0.5)]
    if gate is not None:
        routes = [np.vstack([r, [[0.0, 0.0]]]) for r in routes]
        if speeds is not None:
            speeds = np.append(speeds, speeds[-1])
    for candidate in routes:
        try:
            plan = finish_plan(scenario, candidate, name, seed, cruise, budget.elapsed_s(),
                               {**(extra or {}), "attempts": attempt + 1,
                                "inflation_m": round(margin, 6), "obstacle_model": model},
                               cut=opts.corner_cut_m, speeds=speeds)
        except NoFeasiblePlan as exc:
            last = str(exc).removeprefix("no feasible plan: ").removeprefix(f"{name}: ")
            continue
        return plan.with_metrics(elapsed_s=round(budget.elapsed_s(), 6)), last
    return None, last


def _bounds(scenario: Scenario, target: np.ndarray, pad: float | None = None
            ) -> tuple[float, float, float, float]:
    pts = np.array([[scenario.start.x, scenario.start.y], target,
                    [scenario.goal.x, scenario.goal.y]])
    dist = float(np.hypot(*(pts[0] - pts[1])))
    pad = max(20.0, 0.35 * dist) if pad is None else pad
    lo, hi = pts.min(axis=0) - pad, pts.max(axis=0) + pad
    return float(lo[0]), float(hi[0]), float(lo[1]), float(hi[1])


def _rrt_family(kind: str) -> Callable[[Scenario, int, RRTStarOptions], dict[str, Any]]:
    from usvstation.planning.seeds.rrt import RRTOptions, bspline_path, rrt_star, vpf_path

    def core(sc: Scenario, world: World, target: np.ndarray, cruise: float,
             rng: np.random.Generator, o: RRTStarOptions) -> tuple:
        start = np.array([sc.start.x, sc.start.y])
        dist = float(np.hypot(*(target - start)))
        step = o.step_m or float(np.clip(dist / 12.0, 2.0, 20.0))
        ro = RRTOptions(step=step, iterations=o.iterations, goal_bias=o.goal_bias,
                        vpf=kind == "vpf")
        path = rrt_star(start, target, world, cruise, _bounds(sc, target), ro, rng)
        if path is None:
            return None, {"reason": f"no tree branch reached the goal in {o.iterations} iterations"}
        raw_len = float(np.hypot(*np.diff(path, axis=0).T).sum())
        if kind == "vpf":  # post-processing of a path found within the budget: bounded
            path = vpf_path(path, replace(world, budget=None), cruise, ro)
        elif kind == "bspline":
            path = bspline_path(path, step / 3.0)
        own = path_metrics(path)  # the algorithm's own path, before the common finish
        return path, {"tree_path_length_m": round(raw_len, 6), "step_m": round(step, 6),
                      "iterations": o.iterations,
                      "algorithm_path_length_m": round(own["length_m"], 6),
                      "algorithm_total_turn_deg": round(own["total_turn_deg"], 6)}

    def run(sc: Scenario, seed: int, o: RRTStarOptions, started: float | None = None,
            clock: Clock = cpu_clock) -> Plan:
        name = {"rrt": "rrt-star", "bspline": "bspline-rrt-star", "vpf": "vpf-rrt-star"}[kind]
        return _drive(sc, seed, o, name, lambda *a: core(*a, o), static_only=True,
                      started=started, clock=clock)

    return run


def _run_iga(scenario: Scenario, seed: int, options: Any, started: float | None = None,
             clock: Clock = cpu_clock) -> Plan:
    from usvstation.planning.plan import plan_scenario

    return plan_scenario(scenario, planner="iga", seed=seed, started=started, clock=clock,
                         **options)  # checked there


class _IGAPassThrough(BaseModel):
    """IGA options are validated by `IGAOptions` (scenario/options.py)."""

    model_config = ConfigDict(extra="allow")


PLANNERS: dict[str, PlannerInfo] = {}


def _register(info: PlannerInfo) -> None:
    PLANNERS[info.name] = info


_register(PlannerInfo(
    "iga", "000", "Improved genetic algorithm in x-y-t (IGA)",
    (MOVING, RAMP, SPEED, SEEDED), _IGAPassThrough, _run_iga))
_register(PlannerInfo(
    "rrt-star", "004", "RRT* (Alg. 1 without the VPF step)",
    (SWEPT, MOVING_TIMED, RUN_IN, SEEDED), RRTStarOptions, _rrt_family("rrt")))
_register(PlannerInfo(
    "bspline-rrt-star", "004", "RRT* smoothed by an interpolating cubic B-spline",
    (SWEPT, MOVING_TIMED, RUN_IN, SEEDED), RRTStarOptions, _rrt_family("bspline")))
_register(PlannerInfo(
    "vpf-rrt-star", "004", "RRT* with the virtual potential field node adjustment (eq. 7-12)",
    (SWEPT, MOVING_TIMED, RUN_IN, SEEDED), RRTStarOptions, _rrt_family("vpf")))


def planner_names() -> list[str]:
    return list(PLANNERS)


def describe_planners() -> list[dict[str, Any]]:
    """JSON list of {name, paper, title, capabilities: [str]} in registry order."""
    return [p.describe() for p in PLANNERS.values()]


class PlannerOptionError(ValueError):
    """Bad planner option; the message is one line naming the field."""


BUDGET_OPTIONS = ("time_budget_s", "max_evaluations")  # every planner takes these


def plan_with(scenario: Scenario, name: str = "iga", seed: int | None = None,
              started: float | None = None, clock: Clock = cpu_clock, **options: Any) -> Plan:
    """Plan with the named planner; the plan has passed the independent checker.

    Every planner honours the budget (`time_budget_s`, `max_evaluations`) given as an
    option or in the scenario's `planner` section; its wall deadline counts from `started`
    (a `clock()` value; default: now); tests inject `clock`.
    """
    info = PLANNERS.get(name)
    if info is None:
        raise PlannerOptionError(
            f"planner: unknown planner {name!r}; available: {', '.join(PLANNERS)}")
    if name == "iga":
        return info.run(scenario, seed, options, started, clock)  # type: ignore[arg-type]
    base = dict(scenario.planner.model_dump(exclude_unset=True)) if scenario.planner else {}
    seed = seed if seed is not None else int(base.get("seed", 1))
    options = {**{k: base[k] for k in BUDGET_OPTIONS if k in base}, **options}
    try:
        opts = info.options(**options)
    except ValidationError as exc:
        err = exc.errors(include_url=False)[0]
        loc = ".".join(str(p) for p in err["loc"])
        raise PlannerOptionError(f"planner.{loc}: {err['msg']}") from None
    return info.run(scenario, seed, opts, started, clock)


class ColregsGAOptions(SeedOptions):
    population: int = Field(50, ge=4, le=2000)
    generations: int = Field(40, ge=1, le=1000)
    stall_generations: int = Field(6, ge=1, le=1000)
    yaw_rate_max_deg: float = Field(15.0, gt=0.0, le=90.0, description="paper: 5 deg/s")
    d_ca_m: float = Field(10.0, gt=0.0, description="range where obstacle terms saturate")
    risk_scale_m: float = Field(20.0, gt=0.0, description="L_d of l1 = 1.5 rho L_d")
    improved: bool = True
    mode: str = Field("station", pattern="^(station|paper)$")


def _run_colregs_ga(sc: Scenario, seed: int, o: ColregsGAOptions,
                    started: float | None = None, clock: Clock = cpu_clock) -> Plan:
    import math

    from usvstation.planning.seeds.colregs_ga import PAPER_001_GA, GAStepOptions, plan_colregs_ga

    paper = o.mode == "paper"
    go = GAStepOptions(
        ga=replace(PAPER_001_GA, population=o.population),
        generations=300 if paper else o.generations,
        stall=20 if paper else o.stall_generations,
        yaw_rate_max_deg=5.0 if paper else o.yaw_rate_max_deg,
        d_ca=o.d_ca_m, risk_scale_m=o.risk_scale_m, improved=o.improved, paper_fitness=paper)
    holder: dict[str, Any] = {}

    def core(s: Scenario, world: World, target: np.ndarray, cruise: float,
             rng: np.random.Generator) -> tuple:
        v = s.vessel
        route, speeds, stats = plan_colregs_ga(
            np.array([s.start.x, s.start.y]), math.radians(s.start.heading_deg),
            min(max(s.start.speed, v.speed_min), v.speed_max), target, world,
            v.speed_min, min(v.speed_max, cruise * 1.5), v.accel_max, rng, go)
        holder["speeds"] = speeds
        stats["mode"] = o.mode
        return route, stats

    return _drive(sc, seed, o, "colregs-ga", core, speeds_from=holder, started=started,
                  clock=clock)


_register(PlannerInfo(
    "colregs-ga", "001", "Per-step GA over acceleration and yaw rate with COLREGs and fuzzy risk",
    (MOVING, COLREGS, RUN_IN, SPEED, SEEDED), ColregsGAOptions, _run_colregs_ga))


class ReplanGAOptions(SeedOptions):
    population: int = Field(20, ge=4, le=2000)
    generations_global: int = Field(30, ge=1, le=2000)
    generations_local: int = Field(20, ge=1, le=2000)
    unsafe_range_m: float = Field(100.0, gt=0.0)


def _run_replan_ga(sc: Scenario, seed: int, o: ReplanGAOptions,
                   started: float | None = None, clock: Clock = cpu_clock) -> Plan:
    from usvstation.planning.seeds.replan_ga import (
        PAPER_002_GA,
        Replanning,
        ReplanOptions,
        plan_replan,
    )

    ro = ReplanOptions(ga=replace(PAPER_002_GA, population=o.population),
                       generations_global=o.generations_global,
                       generations_local=o.generations_local,
                       replanning=Replanning(unsafe_range_m=o.unsafe_range_m))

    def core(s: Scenario, world: World, target: np.ndarray, cruise: float,
             rng: np.random.Generator) -> tuple:
        start = np.array([s.start.x, s.start.y])
        return plan_replan(start, target, world, cruise, _bounds(s, target, pad=None), rng, ro)

    return _drive(sc, seed, o, "replan-ga", core, started=started, clock=clock)


class DEAPFOptionsModel(SeedOptions):
    step_m: float | None = Field(None, gt=0.0,
                                 description="APF step s; default dist/40 in [0.5, 5]")
    turn_radius_m: float = Field(3.0, gt=0.0, description="D of eq. 2.5")
    popsize: int = Field(8, ge=2, le=200)
    maxiter: int = Field(15, ge=1, le=1000)
    kappa: str = Field("paper", pattern="^(paper|chord)$")


def _run_de_apf(sc: Scenario, seed: int, o: DEAPFOptionsModel,
                started: float | None = None, clock: Clock = cpu_clock) -> Plan:
    from usvstation.planning.seeds.de_apf import DEAPFOptions, plan_de_apf

    def core(s: Scenario, world: World, target: np.ndarray, cruise: float,
             rng: np.random.Generator) -> tuple:
        start = np.array([s.start.x, s.start.y])
        dist = float(np.hypot(*(target - start)))
        step = o.step_m or float(np.clip(dist / 40.0, 0.5, 5.0))
        do = DEAPFOptions(step=step, turn_radius=o.turn_radius_m, popsize=o.popsize,
                          maxiter=o.maxiter, paper_kappa=o.kappa == "paper")
        return plan_de_apf(start, target, world, cruise, int(rng.integers(2**31)), do)

    return _drive(sc, seed, o, "de-apf", core, static_only=True, started=started, clock=clock)


_register(PlannerInfo(
    "replan-ga", "002", "GA global path on a grid with local GA re-planning on collision course",
    (MOVING, REPLAN, RUN_IN, SEEDED), ReplanGAOptions, _run_replan_ga))
_register(PlannerInfo(
    "de-apf", "003", "Potential field with parameters evolved by differential evolution",
    (SWEPT, MOVING_TIMED, RUN_IN, SEEDED), DEAPFOptionsModel, _run_de_apf))
_ORDER = ("iga", "colregs-ga", "replan-ga", "de-apf", "rrt-star", "bspline-rrt-star",
          "vpf-rrt-star")
PLANNERS = {k: PLANNERS[k] for k in _ORDER}
