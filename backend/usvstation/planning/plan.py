"""Plan a scenario with the IGA and build its typed `Plan` (planning/model.py)."""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import replace
from typing import Any

import numpy as np

from usvstation.geometry import inflated_radius
from usvstation.planning.budget import Budget, Clock, cpu_clock
from usvstation.planning.encoding import GeneLayout, InfeasibleProblem
from usvstation.planning.errors import NoFeasiblePlan
from usvstation.planning.hull import keepout_circles, outline_clearance
from usvstation.planning.iga import IGAResult, run_iga
from usvstation.planning.limits import check_memory
from usvstation.planning.model import Plan, PlanMetrics, SmoothedPath, Waypoint
from usvstation.planning.problem import Problem, sweep_moving
from usvstation.planning.smoothing import smooth_path
from usvstation.planning.start import Prefix, needs_prefix, prefixes, start_state, x_needed
from usvstation.planning.validate import current_vector, hull_clearance, plan_violations
from usvstation.planning.warm import compiled, warm
from usvstation.planning.xyt import ObstacleField
from usvstation.scenario import Scenario, scenario_at
from usvstation.scenario.options import IGAOptions

PLANNERS = ("iga",)
MIN_WATER_M = 0.05  # least water between hull and obstacle a plan may keep, m


def plan_scenario(
    scenario: Scenario, planner: str = "iga", seed: int | None = None,
    started: float | None = None, clock: Clock = cpu_clock, **overrides: Any,
) -> Plan:
    """Plan `scenario`; return the plan or raise NoFeasiblePlan.

    Every plan returned has passed the exact validator (`plan_violations`):
    true hull clearance, first turn, speed through the water, timing margin.
    All attempts (clearance margins, run-outs) share one budget
    (planning/budget.py): `planner.max_evaluations` decides where the search
    stops; past the wall-clock safety net `planner.time_budget_s` (counted
    from `started`, a `clock()` value, default now) the best valid plan
    so far is returned with a warning. A plan whose memory estimate exceeds
    the bound raises PlanTooLarge (`limits.check_memory`) before anything
    large is allocated.
    """
    if planner not in PLANNERS:
        raise ValueError(f"planner: unknown planner {planner!r}; available: {', '.join(PLANNERS)}")
    if seed is not None:
        overrides["seed"] = seed
    opts = scenario.planner_options(**overrides)
    check_memory(scenario, opts)
    straight = final_straight_options(scenario, opts)
    if straight is not None:  # the final straight first, else the paper's run-in
        try:
            return plan_with(scenario, straight, clock, started)
        except NoFeasiblePlan as exc:
            return plan_with(scenario, opts, clock, started).warned(
                f"no plan with a final straight of {straight.approach_length:g} m along the "
                f"ramp axis ({exc}); planned with the {opts.approach_length:g} m run-in")
    return plan_with(scenario, opts, clock, started)


STRAIGHT_ALIGN_DEG = 1.0  # the final straight's last waypoint: within 1 deg of the axis


def final_straight_options(scenario: Scenario, opts: IGAOptions) -> IGAOptions | None:
    """The options of a recovery with `final_straight` (issue 24; an extension of paper
    000): the last intermediate waypoint at least the first approach gate's distance out
    (`vessel.gates_m[0]`) and within STRAIGHT_ALIGN_DEG of the ramp axis, so the last leg
    is a straight along the axis on which the boat's gates can all be met. A start inside
    the arrival cone (already coming in) keeps the straight it has room for without a
    run-out. None: not asked for, not a recovery, or no longer than the paper's run-in."""
    if not opts.final_straight or scenario.kind != "recovery":
        return None
    s = scenario.start
    length = float(scenario.vessel.gates_m[0])
    if abs(s.y) <= s.x * math.tan(math.radians(opts.align_max_deg)):
        length = min(length, s.x - (x_needed(opts) - opts.approach_length))
    if length <= opts.approach_length:
        return None
    return IGAOptions(**{**opts.model_dump(), "approach_length": length,
                         "align_max_deg": min(opts.align_max_deg, STRAIGHT_ALIGN_DEG)})


def plan_with(scenario: Scenario, opts: IGAOptions, clock: Clock = cpu_clock,
              started: float | None = None) -> Plan:
    """`plan_scenario` with these options (one budget for every attempt)."""
    budget = Budget(opts.evaluation_budget, opts.time_budget_s, clock, started)
    budget.excluding(warm, when=compiled)  # kernels loaded once per process; compiling is
    # not planning (planning/warm.py)
    first: tuple[Problem, IGAResult] | None = None
    reasons: list[str] = []
    direct = not needs_prefix(scenario, opts)
    for margin, warning in clearance_margins(scenario, opts.clearance_fallback):
        for prefix in _starts(scenario, opts, margin, direct):
            state = start_state(scenario) if prefix is None else prefix.end
            problem = Problem.from_scenario(scenario, margin, state=state)
            try:
                layout = GeneLayout.build(problem, opts)
                blocked = run_in_blockers(problem, layout)
                if blocked:  # no arrival along the ramp axis is free: no GA run can help
                    names = ", ".join(dict.fromkeys(obstacle_name(problem.obstacles, i)
                                                    for i in blocked))
                    reasons.append(
                        f"the run-in along the ramp axis is blocked: {names} (inflated by "
                        f"eq. 7) cross every arrival within "
                        f"{math.degrees(math.atan(layout.cone_tan)):g} deg of the axis")
                    continue
                result = run_iga(problem, opts, layout, budget)
            except InfeasibleProblem as exc:
                reasons.append(str(exc))
                continue
            if result.feasible:
                plan = build_plan(scenario, problem, opts, result, prefix)
                bad = plan_violations(plan.to_document(), scenario)
                if not bad:
                    full = margin == clearance_margins(scenario, False)[0][0]
                    plan = plan.with_metrics(inflation_m=_r(margin), margin_kept=full)
                    if warning:  # the margin's warning comes first
                        plan = replace(plan, warnings=(warning, *plan.warnings))
                    if budget.time_fired:
                        plan = plan.warned(budget.warning())
                    return plan
                reasons.append("the exact check refused the best path: " + bad[0])
            first = first or (problem, result)
            if budget.exhausted():
                break
        if budget.exhausted():
            break
    head = "no feasible plan" + budget.failure()
    if first is None:
        raise NoFeasiblePlan(f"{head}: " + (reasons[0] if reasons else
                             "no collision-free way to turn the boat towards the goal"))
    raise NoFeasiblePlan(f"{head}: {explain_infeasible(*first)}")


def _starts(scenario: Scenario, opts: IGAOptions, margin: float,
            direct: bool) -> Iterator[Prefix | None]:
    """Where the IGA's leg begins, in the order tried: the start itself (None) when the boat
    can leave it directly, then the run-outs (computed only once the direct plan failed);
    the start itself also when no run-out is needed after all (a hull already crabbing
    right)."""
    if direct:
        yield None
    runouts = prefixes(scenario, opts, margin)
    if not runouts and not direct:
        yield None
    yield from runouts


def replan_from(
    scenario: Scenario, x: float, y: float, heading_deg: float, speed: float, t: float,
    planner: str = "iga", seed: int | None = None, **overrides: Any,
) -> Plan:
    """Plan from a boat under way (ramp frame position, hull heading, speed over ground) at
    `t` s after the scenario's t = 0: obstacles are propagated to that instant (eq. 8)
    and the plan's t = 0 is that instant."""
    at_now = scenario_at(scenario, x, y, heading_deg, speed, t)
    return plan_scenario(at_now, planner=planner, seed=seed, **overrides)


def clearance_margins(scenario: Scenario, fallback: bool) -> list[tuple[float, str | None]]:
    """Obstacle margins to try: eq. 7's D_USV + R_c, then R_c = 0, then half the hull plus 5 cm.

    Half the hull length is where the hull touches; a plan made with less
    than eq. 7's margin says so in its warnings and `metrics.margin_kept`.
    """
    v = scenario.vessel
    full = inflated_radius(0.0, v.length, v.compensation_radius)  # eq. 7's margin
    levels: list[tuple[float, str | None]] = [(full, None)]
    if fallback:
        least = v.length / 2.0 + MIN_WATER_M
        for margin, what in ((v.length, "R_c = 0"), (least, "half the hull length + 5 cm")):
            if margin < levels[-1][0]:
                levels.append((margin, (
                    f"reduced clearance: no plan keeps eq. 7's margin of {full:g} m "
                    f"(D_USV + R_c); planned with {margin:g} m ({what})"
                )))
    return levels


def build_plan(
    scenario: Scenario, problem: Problem, opts: IGAOptions, result: IGAResult,
    prefix: Prefix | None = None,
) -> Plan:
    """Waypoints in the scenario frame plus metrics, the encoding and the history; the
    smoothed path when it keeps clear, else a warning that it was dropped.

    `heading_deg` is the hull heading leaving each waypoint (through the
    water, so it crabs into a current), `course_deg` the course over ground.
    """
    best, ev = result.best, result.evaluation
    xs, ys = problem.to_scenario_frame(best.x[0], best.y[0])
    t, v = best.t[0], best.v[0]
    if prefix is not None:
        xs = np.concatenate([prefix.x[:-1], xs])
        ys = np.concatenate([prefix.y[:-1], ys])
        t = np.concatenate([prefix.t[:-1], t + prefix.end.t])
        v = np.concatenate([prefix.v[:-1], v])
    seg_heading = np.arctan2(np.diff(ys), np.diff(xs))
    course = np.append(seg_heading, seg_heading[-1])
    cx, cy = current_vector(scenario)
    hull = np.arctan2(v * np.sin(course) - cy, v * np.cos(course) - cx)
    course_deg = np.degrees(course) % 360.0
    heading_deg = np.degrees(hull) % 360.0
    waypoints = tuple(
        Waypoint(_r(x), _r(y), _r(tt), _r(vv), _r(h), _r(c))  # type: ignore[arg-type]
        for x, y, tt, vv, h, c in zip(xs, ys, t, v, heading_deg, course_deg, strict=True)
    )
    row = ev.row(0)
    clearance = _r(hull_clearance({"waypoints": [w.to_document() for w in waypoints]},
                                  scenario))
    metrics = PlanMetrics({
        "fitness": _r(row["fitness"]),
        "fit_d": _r(row["fit_d"]),
        "fit_t": _r(row["fit_t"]),
        "fit_mal": _r(row["fit_mal"]),
        "fit_ang": _r(row["fit_ang"]),
        "fit_t_norm": _r(row["fit_t_norm"]),
        "fit_mal_norm": _r(row["fit_mal_norm"]),
        "terms": opts.terms,
        "length_m": _r(float(np.hypot(np.diff(xs), np.diff(ys)).sum())),
        "duration_s": _r(float(t[-1])),
        "min_clearance_m": clearance,
        "collision_free": bool(row["g_col"]),
        "generations": result.generations,
        "elapsed_s": round(result.elapsed_s, 6),
        "stop_reason": result.stop_reason,
        "evaluations": result.evaluations,
        "max_turn_deg": _r(_max_turn_deg(seg_heading)),
        "arrival_heading_deg": _r(float(course_deg[-1])),
        "time_margin_s": scenario.vessel.time_margin_s,
        "prefix_legs": 0 if prefix is None else prefix.legs,
    })
    if scenario.kind == "recovery":
        metrics = metrics.updated(final_straight_m=_r(straight_length(xs, ys)))
    ship = outline_clearance(scenario, xs, ys)
    if ship is not None:
        metrics = metrics.updated(ship_clearance_m=_r(ship))
    sections = {
        "encoding": {
            "intermediate_waypoints": result.layout.n_mid,
            "bits": {
                "x": int(result.layout.gene_bits[0]),
                "y": int(result.layout.gene_bits[1]),
                "speed": int(result.layout.gene_bits[2]),
            },
            "total_bits": result.layout.n_bits,
        },
        "history": {
            "best": [_r(f) for f in result.history_best],
            "elite_mean": [_r(f) for f in result.history_elite_mean],
        },
    }
    plan = Plan("iga", scenario.name, opts.seed, waypoints, metrics, sections=sections)
    own = float(np.clip(scenario.start.speed, scenario.vessel.speed_min,
                        scenario.vessel.speed_max))
    if abs(float(v[0]) - own) > 1e-9:
        plan = plan.warned(
            f"start speed {scenario.start.speed:g} m/s over ground: the boat cannot keep it "
            f"on its first leg in this current (through the water within [speed_min, "
            f"speed_max]); planned from {float(v[0]):.3g} m/s")
    if opts.smoothing:
        smoothed = smooth_path(xs, ys, t, hull_field(scenario))
        if smoothed["collision_free"]:
            smoothed["min_clearance_m"] = _r(hull_clearance({"waypoints": smoothed["points"]},
                                                            scenario))
            plan = replace(plan, smoothed=SmoothedPath.from_document(smoothed))
        else:
            plan = plan.warned("smoothed path dropped: it would bring the hull too close to an "
                               "obstacle; follow the waypoints")
    return plan


def straight_length(xs: np.ndarray, ys: np.ndarray, tolerance: float = 0.5) -> float:
    """Length of a recovery path's final straight: its last legs whose points all lie
    within `tolerance` m of the ramp axis (y = 0), m."""
    on = np.abs(ys) <= tolerance
    k = len(xs) - 1
    while k > 0 and on[k] and on[k - 1]:
        k -= 1
    return float(np.hypot(np.diff(xs[k:]), np.diff(ys[k:])).sum())


def hull_field(scenario: Scenario) -> ObstacleField:
    """Obstacles as the hull's centre must see them: radius + half the hull, + 5 cm of water."""
    f = scenario_field(scenario)
    v = scenario.vessel
    grown = f.radius + v.length / 2.0 + MIN_WATER_M
    c, w, r, infl, src = sweep_moving(f.centre, f.velocity, f.radius, grown, v.time_margin_s)
    return with_ship(ObstacleField(c, w, r, infl, src), scenario, v.length / 2.0 + MIN_WATER_M)


def with_ship(field: ObstacleField, scenario: Scenario, margin: float) -> ObstacleField:
    """`field` and the mother ship's keep-out circles at `margin` (planning/hull.py), static,
    raw radius 0, source -1."""
    c, r = keepout_circles(scenario, margin)
    if r.size == 0:
        return field
    src = field.source if field.source is not None else np.arange(field.count)
    return ObstacleField(np.vstack([field.centre, c]),
                         np.vstack([field.velocity, np.zeros_like(c)]),
                         np.concatenate([field.radius, np.zeros_like(r)]),
                         np.concatenate([field.inflated, r]),
                         np.concatenate([src, np.full(r.size, -1)]))


def obstacle_name(field: ObstacleField, i: int) -> str:
    """How a failure names circle i of a field: `obstacles[k]` or the mother ship's hull."""
    k = int(field.source[i]) if field.source is not None else i
    return "the mother ship's hull" if k < 0 else f"obstacles[{k}]"


def scenario_field(scenario: Scenario) -> ObstacleField:
    """Obstacles of a scenario in its own frame (raw and inflated radii)."""
    obs = scenario.obstacles
    v = scenario.vessel
    radius = np.array([o.radius for o in obs], dtype=float)
    return ObstacleField(
        centre=np.array([[o.x, o.y] for o in obs], dtype=float).reshape(-1, 2),
        velocity=np.array([[o.vx, o.vy] for o in obs], dtype=float).reshape(-1, 2),
        radius=radius,
        inflated=inflated_radius(radius, v.length, v.compensation_radius),
    )


def explain_infeasible(problem: Problem, result: IGAResult) -> str:
    """Why no plan was found: an enclosed goal, or where candidate paths were blocked."""
    blocked = approach_blockers(problem, result)
    f = problem.obstacles
    if blocked:
        names = ", ".join(dict.fromkeys(obstacle_name(f, i) for i in blocked))
        return (
            f"the run-in along the ramp axis is blocked: {names} (inflated by eq. 7) "
            f"cross every arrival within {math.degrees(math.atan(result.layout.cone_tan)):g} deg "
            "of the axis"
        )
    enclosed = enclosing_obstacles(problem)
    if enclosed is not None:
        names = ", ".join(dict.fromkeys(obstacle_name(f, i) for i in enclosed))
        return (
            f"the goal is enclosed: {names} (inflated by eq. 7) leave no free water "
            "between start and goal"
        )
    report = result.preheat
    parts = [
        f"no path met the turn limit ({math.degrees(problem.turn_max):g} deg), the "
        f"acceleration limit ({problem.accel_max:g} m/s^2) and clearance in "
        f"{result.generations} generations"
    ]
    if report and report.blocked_at:
        k = max(report.blocked_at, key=report.blocked_at.get)
        parts.append(f"candidates were blocked most often at intermediate waypoint {k + 1}")
    if report is not None and report.obstacle_hits is not None and report.obstacle_hits.any():
        top = np.argsort(-report.obstacle_hits)[:3]
        top = [int(i) for i in top if report.obstacle_hits[i] > 0]
        parts.append("mostly by " + ", ".join(dict.fromkeys(obstacle_name(f, i) for i in top)))
    return "; ".join(parts)


def approach_blockers(problem: Problem, result: IGAResult) -> list[int]:
    """Static obstacles that cut every straight arrival inside the ramp-axis cone."""
    return run_in_blockers(problem, result.layout)


def run_in_blockers(problem: Problem, lay: GeneLayout) -> list[int]:
    """Static obstacles that cut every straight arrival inside the ramp-axis cone."""
    f = problem.obstacles
    if lay.cone_tan is None or f.count == 0:
        return []
    # sample arrivals from every admissible last waypoint (x, y) of the cone to the goal
    xs = lay.x_of(np.arange(lay.x_count[-1]), lay.n_mid - 1)
    m = lay.cone_m
    ends = [(x, j * lay.y_res) for x, mm in zip(xs, m, strict=True) for j in range(-mm, mm + 1)]
    static = np.flatnonzero(f.static)
    blockers: set[int] = set()
    for x, y in ends:
        s = np.linspace(0.0, 1.0, 50)
        px, py = x * (1 - s), y * (1 - s)
        d = np.hypot(px[:, None] - f.centre[static, 0], py[:, None] - f.centre[static, 1])
        hit = (d < f.inflated[static]).any(axis=0)
        if not hit.any():
            return []
        blockers.update(int(i) for i in static[hit])
    return sorted(blockers)


def enclosing_obstacles(problem: Problem, cell: float = 0.5) -> list[int] | None:
    """Static obstacles that cut the goal off from the start, or None if water connects them.

    Rasterises the inflated static circles and labels the free water
    (scipy.ndimage); used to explain a failure, not to plan.
    """
    f = problem.obstacles
    static = np.flatnonzero(f.static)
    if static.size == 0:
        return None
    pts = np.vstack([problem.start, problem.goal, f.centre[static]])
    r = f.inflated[static]
    lo = pts.min(axis=0) - r.max() - 5.0
    hi = pts.max(axis=0) + r.max() + 5.0
    cell = max(cell, float(np.max(hi - lo)) / 500.0)
    gx = np.arange(lo[0], hi[0], cell)
    gy = np.arange(lo[1], hi[1], cell)
    xx, yy = np.meshgrid(gx, gy, indexing="ij")
    blocked = np.zeros(xx.shape, dtype=bool)
    boxes = [_cells(c, rad, gx, gy) for c, rad in zip(f.centre[static], r, strict=True)]
    for c, rad, box in zip(f.centre[static], r, boxes, strict=True):
        blocked[box] |= (xx[box] - c[0]) ** 2 + (yy[box] - c[1]) ** 2 < rad**2
    from scipy import ndimage  # here: serve starts without scipy

    labels, _ = ndimage.label(~blocked)

    def label_at(p: np.ndarray) -> int:
        i, j = np.clip(((p - lo) / cell).astype(int), 0, np.array(xx.shape) - 1)
        return int(labels[i, j])

    goal_label, start_label = label_at(problem.goal), label_at(problem.start)
    if goal_label == 0 or goal_label == start_label:
        return None
    ring = ndimage.binary_dilation(labels == goal_label) & blocked
    near = [
        int(i) for i, c, rad, box in zip(static, f.centre[static], r, boxes, strict=True)
        if np.any(ring[box] & ((xx[box] - c[0]) ** 2 + (yy[box] - c[1]) ** 2 < rad**2))
    ]
    return near


def _cells(c: np.ndarray, rad: float, gx: np.ndarray, gy: np.ndarray) -> tuple[slice, slice]:
    """The grid cells (a slice of the raster) that a circle's bounding box covers."""
    i0, i1 = np.searchsorted(gx, [c[0] - rad, c[0] + rad], side="left")
    j0, j1 = np.searchsorted(gy, [c[1] - rad, c[1] + rad], side="left")
    return slice(max(int(i0) - 1, 0), int(i1) + 1), slice(max(int(j0) - 1, 0), int(j1) + 1)


def _max_turn_deg(headings: np.ndarray) -> float:
    if headings.size < 2:
        return 0.0
    d = np.abs(np.mod(np.diff(headings) + np.pi, 2 * np.pi) - np.pi)
    return float(np.degrees(d.max()))


def _r(value: float | None) -> float | None:
    return None if value is None else round(float(value), 6)
