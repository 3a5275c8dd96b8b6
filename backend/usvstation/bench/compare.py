"""`usv-station bench compare`: every planner of the registry on the seed papers' families.

Families (digest 9.2): recovery (the public suite, plus seeded random
recoveries), transit (002 Tab. V, 400 m), dense (004, corrected start/goal
pairs of Tab. 5/6 on seeded 1 km maps), colregs (single-target head-on,
crossings both ways, overtaking both ways, two mixes) and traps (003); on
request walls (004's maps at its difficulty: walls that force a slalom) and
encounters (001's encounter classes at its scale: 50 kn, 800 m, 15 km).
Metrics per plan: success, length, normalisation index, duration, water
clearance, total and maximum turn, plan time and, on COLREGs encounters,
the compliance score of `planning.colregs.compliance`, and the tracked
deviation when the simulated boat sails the plan. Each family has public
scenarios and seeded hidden ones (`hidden`, from seed `hidden_from`).
Summaries:
`table_004` (ratios on the dense family, beside the paper's),
`replan_002` (re-planning latency percentiles), `colregs_001` (starboard
rule on head-on and give-way crossings; improved vs conventional GA).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from usvstation.bench.render import markdown_table
from usvstation.clock import Stopwatch
from usvstation.planning.errors import NoFeasiblePlan
from usvstation.planning.registry import plan_with, planner_names
from usvstation.scenario import Scenario, load_scenario, parse_scenario

FAMILIES = ("recovery", "transit", "dense", "colregs", "traps")
# on request (--families): paper 004's difficulty and paper 001's scale (issue 27)
EXTRA_FAMILIES = ("walls", "encounters")
PAPER_004 = {"vpf_over_rrt_length": [0.949, 0.978], "bspline_over_rrt_length": [1.126, 1.297],
             "vpf_over_rrt_tta": [0.552, 0.978], "bspline_over_rrt_tta": [1.115, 2.758]}
DENSE_PAIRS = (((423.0, 440.0), (-411.0, -411.0)), ((-94.0, 27.0), (347.0, -451.0)),
               ((400.0, 400.0), (-400.0, -400.0)), ((400.0, -400.0), (-400.0, 400.0)))


def _transit(name: str, start: tuple, goal: tuple, obstacles: list[dict], vessel: dict,
             speed: float, heading_deg: float | None = None) -> Scenario:
    h = heading_deg if heading_deg is not None else math.degrees(
        math.atan2(goal[1] - start[1], goal[0] - start[0]))
    return parse_scenario({
        "name": name, "kind": "transit",
        "start": {"x": start[0], "y": start[1], "heading_deg": round(h % 360, 3), "speed": speed},
        "goal": {"x": goal[0], "y": goal[1]}, "obstacles": obstacles, "vessel": vessel})


TRIMARAN = {"length": 6.0, "speed_min": 0.5, "speed_max": 3.9, "accel_max": 0.5,
            "turn_max_deg": 60.0, "compensation_radius": 1.0}
USV = {"length": 2.0, "speed_min": 0.3, "speed_max": 3.0, "accel_max": 0.5,
       "turn_max_deg": 60.0, "compensation_radius": 1.0}


def transit_002(speed: float = 3.0) -> Scenario:
    """002 Tab. V: (0, 0) -> (400, 400); math-angle headings; third mover's velocity guessed."""
    def mover(x: float, y: float, v: float, deg: float) -> dict:
        return {"x": x, "y": y, "radius": 5.0, "vx": round(v * math.cos(math.radians(deg)), 6),
                "vy": round(v * math.sin(math.radians(deg)), 6)}
    obs = [{"x": 100.0, "y": 170.0, "radius": 30.0}, {"x": 260.0, "y": 260.0, "radius": 21.2},
           mover(300.0, 0.0, 4.5, 154.8), mover(200.0, 360.0, 3.0, -90.0),
           mover(400.0, 200.0, 3.0, 180.0)]
    return _transit(f"transit-002-{speed:g}", (0.0, 0.0), (400.0, 400.0), obs, TRIMARAN, speed)


def dense_004(pair: int, seed: int, count: int = 40) -> Scenario:
    """004: 1 km map, `count` circles of radius 8 m (a = b = 8 m), seeded; pair from Tab. 5/6."""
    rng = np.random.default_rng([4, pair, seed, count])
    start, goal = DENSE_PAIRS[pair]
    obs: list[dict] = []
    while len(obs) < count:
        x, y = rng.uniform(-480.0, 480.0, size=2)
        if min(math.hypot(x - start[0], y - start[1]), math.hypot(x - goal[0], y - goal[1])) < 40:
            continue
        obs.append({"x": round(float(x), 2), "y": round(float(y), 2), "radius": 8.0})
    vessel = dict(USV, compensation_radius=6.0)   # R_s = 6 m safety range (Tab. 3)
    return _transit(f"dense-{pair}-{seed}", start, goal, obs, vessel, 3.0)


def walls_004(pair: int, seed: int) -> Scenario:
    """Paper 004's difficulty (NI 1.36-1.45 in Tab. 5/6), which scattered circles do not
    reach (the difficulty sweep): its 1 km map with 40 circles of 8 m, plus three walls of
    touching 8 m circles across the straight line at about a quarter, half and three
    quarters of the way, turned up to 15 degrees, alternating sides, each reaching 10-13.5 %
    of the start-goal distance past the line and 600 m the other way: the shortest way is a
    slalom round their ends (OMPL's BIT*: 1.36-1.51 times the straight line on the first
    eight maps)."""
    base = dense_004(pair, seed)
    rng = np.random.default_rng([40, pair, seed])
    (sx, sy), (gx, gy) = DENSE_PAIRS[pair]
    dist = math.hypot(gx - sx, gy - sy)
    ux, uy = (gx - sx) / dist, (gy - sy) / dist
    side = float(rng.choice([-1.0, 1.0]))
    obs = [o.model_dump() for o in base.obstacles]
    for frac in (0.25, 0.5, 0.75):
        f = frac + rng.uniform(-0.04, 0.04)
        cx, cy = sx + f * dist * ux, sy + f * dist * uy
        turn = math.radians(rng.uniform(-15.0, 15.0))
        nx = -uy * math.cos(turn) - ux * math.sin(turn)  # the line's normal, turned
        ny = ux * math.cos(turn) - uy * math.sin(turn)
        reach = rng.uniform(0.10, 0.135) * dist
        for k in np.arange(-600.0, reach + 1e-9, 12.0):  # 8 m circles 12 m apart: a wall
            obs.append({"x": round(cx + side * k * nx, 2), "y": round(cy + side * k * ny, 2),
                        "radius": 8.0})
        side = -side
    start, goal = DENSE_PAIRS[pair]
    obs = [o for o in obs if min(math.hypot(o["x"] - start[0], o["y"] - start[1]),
                                 math.hypot(o["x"] - goal[0], o["y"] - goal[1])) > 40.0]
    vessel = dict(USV, compensation_radius=6.0)
    return _transit(f"walls-{pair}-{seed}", start, goal, obs, vessel, 3.0)


def colregs_cases() -> list[Scenario]:
    """Own boat (0, 0) northwards (+y) at 2 m/s to (0, 500); targets meet it at t = 120 s."""
    def target(course_deg: float, speed: float, t_meet: float = 120.0) -> dict:
        vx = speed * math.sin(math.radians(course_deg))
        vy = speed * math.cos(math.radians(course_deg))
        return {"x": round(-vx * t_meet, 3), "y": round(2.0 * t_meet - vy * t_meet, 3),
                "radius": 4.0, "vx": round(vx, 6), "vy": round(vy, 6)}
    cases = {
        "head-on": [target(180.0, 2.0)],
        "crossing-give-way-a": [target(300.0, 2.0)],
        "crossing-give-way-b": [target(270.0, 2.0)],
        "crossing-stand-on": [target(90.0, 2.0)],
        "overtaking": [target(0.0, 0.8)],
        "overtaken": [target(0.0, 3.4)],
        "mix-ho-crgw": [target(180.0, 2.0, 100.0), target(270.0, 2.0, 160.0)],
        "mix-ho-crso": [target(180.0, 2.0, 100.0), target(90.0, 2.0, 160.0)],
    }
    vessel = dict(USV, speed_max=2.2)  # cannot simply outrun the crossing target
    return [_transit(f"colregs-{k}", (0.0, 0.0), (0.0, 500.0), v, vessel, 2.0, 90.0)
            for k, v in cases.items()]


def trap_cases() -> list[Scenario]:
    """003's classic APF failures: goal beside an obstacle, obstacle on the line, U shape."""
    u_shape = [{"x": 60.0 + 4.0 * math.cos(a), "y": 0.0 + 14.0 * math.sin(a), "radius": 3.0}
               for a in np.linspace(-math.pi / 2, math.pi / 2, 7)]
    u_shape = [{k: round(float(v), 3) for k, v in o.items()} for o in u_shape]
    return [
        _transit("trap-goal-beside-obstacle", (0.0, 0.0), (100.0, 0.0),
                 [{"x": 100.0, "y": 9.0, "radius": 4.0}], USV, 1.5),
        _transit("trap-obstacle-on-line", (0.0, 0.0), (100.0, 0.0),
                 [{"x": 50.0, "y": 0.0, "radius": 8.0}], USV, 1.5),
        _transit("trap-u-shape", (0.0, 0.0), (100.0, 0.0), u_shape, USV, 1.5),
    ]


KNOT = 0.514444  # m/s
SHIP_001 = {"length": 20.0, "speed_min": 2.0, "speed_max": 28.0, "accel_max": 2.0,
            "turn_max_deg": 60.0, "compensation_radius": 680.0}  # R_l = 800 m with r = 100 m
ENCOUNTERS_001 = {  # relative course (deg, clockwise from own) and speed (m/s) at 001's scale
    "head-on": ((170.0, 190.0), (20.0, 28.0)),
    "crossing-give-way": ((240.0, 300.0), (15.0, 25.0)),
    "crossing-stand-on": ((60.0, 120.0), (15.0, 25.0)),
    "overtaking": ((-10.0, 10.0), (6.0, 12.0)),
    "overtaken": ((-10.0, 10.0), (29.0, 30.0)),  # faster than own 50 kn (25.7 m/s)
}
MEET_001 = {"overtaken": (400.0, 550.0)}  # s; the others 120-240 s


def encounter_001(seed: int) -> Scenario:
    """Paper 001's setting (Tab. II): own ship at 50 kn from (0, 0) northwards to (0, 15 km)
    in its 30 km x 20 km area, keeping 800 m from every target (targets of radius 100 m,
    R_c = 680 m, 20 m hull: R_l = 800 m); one or two targets of the encounter classes of its
    section II.B (head-on, crossing give-way and stand-on, overtaking, overtaken) on a
    collision course with a miss distance of up to 300 m, meeting 120-240 s out (an
    overtaking one 400-550 s; avoidance starts at 2 km in the paper). Seed 0-4: one target
    of each class in turn."""
    rng = np.random.default_rng([101, seed])
    kinds = list(ENCOUNTERS_001)
    own = 50.0 * KNOT
    chosen = [kinds[seed]] if seed < len(kinds) else [
        kinds[int(rng.integers(len(kinds)))] for _ in range(int(rng.integers(1, 3)))]
    obs = []
    for k, kind in enumerate(chosen):
        (c_lo, c_hi), (v_lo, v_hi) = ENCOUNTERS_001[kind]
        course = math.radians(rng.uniform(c_lo, c_hi))
        speed = rng.uniform(v_lo, v_hi)
        t_meet = rng.uniform(*MEET_001.get(kind, (120.0, 240.0))) + 90.0 * k
        vx, vy = speed * math.sin(course), speed * math.cos(course)
        mx, my = rng.uniform(-300.0, 300.0), own * t_meet
        obs.append({"x": round(mx - vx * t_meet, 1), "y": round(my - vy * t_meet, 1),
                    "radius": 100.0, "vx": round(vx, 4), "vy": round(vy, 4)})
    obs = [o for o in obs if math.hypot(o["x"], o["y"]) > 1000.0
           and math.hypot(o["x"], o["y"] - 15_000.0) > 1000.0]
    return _transit(f"encounter-001-{seed}-{'+'.join(chosen)}", (0.0, 0.0), (0.0, 15_000.0),
                    obs, SHIP_001, own, 90.0)


def transit_hidden(seed: int) -> Scenario:
    """002 Tab. V's map moved: obstacles shifted up to 25 m, movers' courses turned up to 20
    degrees and their speeds scaled by 0.8-1.2, the boat at 2-3 m/s."""
    rng = np.random.default_rng([2, seed])
    base = transit_002(3.0)
    obs = []
    for o in base.obstacles:
        dx, dy = rng.uniform(-25.0, 25.0, size=2)
        turn = math.radians(rng.uniform(-20.0, 20.0)) if o.vx or o.vy else 0.0
        k = rng.uniform(0.8, 1.2) if o.vx or o.vy else 1.0
        c, s_ = math.cos(turn), math.sin(turn)
        obs.append({"x": round(o.x + dx, 2), "y": round(o.y + dy, 2), "radius": o.radius,
                    "vx": round(k * (c * o.vx - s_ * o.vy), 6),
                    "vy": round(k * (s_ * o.vx + c * o.vy), 6)})
    obs = [o for o in obs if min(math.hypot(o["x"], o["y"]),
                                 math.hypot(o["x"] - 400.0, o["y"] - 400.0)) > o["radius"] + 20.0]
    speed = round(float(rng.uniform(2.0, 3.0)), 2)
    return _transit(f"transit-hidden-{seed}", (0.0, 0.0), (400.0, 400.0), obs, TRIMARAN, speed)


ENCOUNTERS = {  # relative course of the target (deg, clockwise from the boat's) and speed (m/s)
    "head-on": ((170.0, 190.0), (1.5, 2.5)),
    "crossing-give-way": ((240.0, 300.0), (1.5, 2.5)),
    "crossing-stand-on": ((60.0, 120.0), (1.5, 2.5)),
    "overtaking": ((-10.0, 10.0), (0.5, 1.0)),
    "overtaken": ((-10.0, 10.0), (3.0, 3.8)),
}


def colregs_hidden(seed: int) -> Scenario:
    """A seeded encounter of one or two targets of the five kinds, meeting the boat (northwards
    at 2 m/s to (0, 500)) 80-160 s out with a miss distance of up to 10 m."""
    rng = np.random.default_rng([1, seed])
    kinds = list(ENCOUNTERS)
    obs = []
    chosen = []
    for k in range(int(rng.integers(1, 3))):
        kind = kinds[int(rng.integers(len(kinds)))]
        chosen.append(kind)
        (c_lo, c_hi), (v_lo, v_hi) = ENCOUNTERS[kind]
        course = math.radians(rng.uniform(c_lo, c_hi))
        speed = rng.uniform(v_lo, v_hi)
        t_meet = rng.uniform(80.0, 160.0) + 60.0 * k
        vx, vy = speed * math.sin(course), speed * math.cos(course)
        mx, my = rng.uniform(-10.0, 10.0), 2.0 * t_meet
        obs.append({"x": round(mx - vx * t_meet, 3), "y": round(my - vy * t_meet, 3),
                    "radius": round(float(rng.uniform(3.0, 6.0)), 2),
                    "vx": round(vx, 6), "vy": round(vy, 6)})
    obs = [o for o in obs if math.hypot(o["x"], o["y"]) > o["radius"] + 15.0]
    vessel = dict(USV, speed_max=2.2)
    return _transit(f"colregs-hidden-{seed}-{'+'.join(chosen)}", (0.0, 0.0), (0.0, 500.0), obs,
                    vessel, 2.0, 90.0)


def trap_hidden(seed: int) -> Scenario:
    """One of 003's three traps at a seeded scale, size and side, turned to a seeded bearing."""
    rng = np.random.default_rng([3, seed])
    kind = ("goal-beside-obstacle", "obstacle-on-line", "u-shape")[seed % 3]
    dist = float(rng.uniform(80.0, 150.0))
    if kind == "goal-beside-obstacle":
        r = rng.uniform(3.0, 5.0)
        local = [(dist + rng.uniform(-3.0, 3.0), rng.choice([-1.0, 1.0]) * (r + rng.uniform(4.0,
                  7.0)), r)]
    elif kind == "obstacle-on-line":
        local = [(dist * rng.uniform(0.35, 0.65), rng.uniform(-2.0, 2.0), rng.uniform(5.0, 12.0))]
    else:
        depth, half = rng.uniform(3.0, 8.0), rng.uniform(10.0, 20.0)
        x0 = dist * rng.uniform(0.45, 0.65)
        local = [(x0 + depth * math.cos(a), half * math.sin(a), 3.0)
                 for a in np.linspace(-math.pi / 2, math.pi / 2, 2 + int(half / 2.5))]
    bearing = rng.uniform(0.0, 2.0 * math.pi)
    c, s_ = math.cos(bearing), math.sin(bearing)
    obs = [{"x": round(c * x - s_ * y, 3), "y": round(s_ * x + c * y, 3), "radius": round(r, 3)}
           for x, y, r in local]
    goal = (round(c * dist, 3), round(s_ * dist, 3))
    return _transit(f"trap-hidden-{seed}-{kind}", (0.0, 0.0), goal, obs, USV, 1.5)


HIDDEN_FROM = 1000  # seeds of the hidden scenarios; the public ones are fixed


def family_scenarios(family: str, hidden: int = 0, dense_maps: int = 2,
                     hidden_from: int = HIDDEN_FROM) -> list[Scenario]:
    """The family's public scenarios, then `hidden` seeded ones from seed `hidden_from` on."""
    seeds = range(hidden_from, hidden_from + hidden)
    if family == "recovery":
        from usvstation.bench.scenarios import random_recovery

        return [load_scenario(f"case{i}") for i in range(1, 5)] + [random_recovery(s)
                                                                   for s in seeds]
    if family == "transit":
        return [transit_002(3.0), transit_002(2.0)] + [transit_hidden(s) for s in seeds]
    if family == "dense":
        return ([dense_004(p, s) for p in range(len(DENSE_PAIRS)) for s in range(dense_maps)]
                + [dense_004(s % len(DENSE_PAIRS), s) for s in seeds])
    if family == "colregs":
        return colregs_cases() + [colregs_hidden(s) for s in seeds]
    if family == "traps":
        return trap_cases() + [trap_hidden(s) for s in seeds]
    if family == "walls":
        return ([walls_004(p, s) for p in range(len(DENSE_PAIRS)) for s in range(dense_maps)]
                + [walls_004(s % len(DENSE_PAIRS), s) for s in seeds])
    if family == "encounters":
        return [encounter_001(s) for s in range(len(ENCOUNTERS_001))] + [
            encounter_001(s) for s in seeds]
    raise ValueError(f"family: unknown family {family!r}; available: "
                     f"{', '.join(FAMILIES + EXTRA_FAMILIES)}")


def tracked_deviation(scenario: Scenario, plan: dict[str, Any]) -> dict[str, Any]:
    """The simulated boat (3-DOF Otter, paper 000's AV-LOS, the scenario's current and wind,
    calm sea) sails the plan: mean and largest distance from the timed plan, m."""
    from usvstation.bench.tracking import DisturbedSetup, track_plan
    from usvstation.dynamics.environment import Environment
    from usvstation.dynamics.params import otter

    setup = DisturbedSetup(sea_state=0)
    res = track_plan(plan, "avlos", otter(), Environment.from_scenario(scenario.environment),
                     setup, scenario, stop_at_ramp=scenario.kind == "recovery")
    return {"track_mean_dev_m": res["mean_dev_m"], "track_max_dev_m": res["max_dev_m"]}


def evaluate(scenario: Scenario, family: str, planner: str, seed: int,
             track: bool = False) -> dict[str, Any]:
    """One episode: plan, check, metrics (the plan already passed the checker); with `track`
    the simulated boat also sails the plan (`tracked_deviation`)."""
    watch = Stopwatch()
    row: dict[str, Any] = {"planner": planner, "family": family, "scenario": scenario.name,
                           "seed": seed}
    try:  # in the stable format, as the OMPL episodes' plans come (from their process)
        plan = plan_with(scenario, planner, seed).to_document()
    except NoFeasiblePlan as exc:
        return {**row, "success": False, "error": str(exc)[:300],
                "plan_time_ms": watch.elapsed() * 1000.0}
    row = _row_from_plan(row, scenario, family, plan, watch.elapsed() * 1000.0)
    if track:
        row.update(tracked_deviation(scenario, plan))
    return row


def evaluate_ompl(scenario: Scenario, family: str, planner: str, seed: int) -> dict[str, Any]:
    """One OMPL baseline episode in its own process (bench.ompl_baseline)."""
    from usvstation.bench.ompl_baseline import run_in_process

    row: dict[str, Any] = {"planner": f"ompl:{planner}", "family": family,
                           "scenario": scenario.name, "seed": seed}
    watch = Stopwatch()
    res = run_in_process(scenario.model_dump(mode="json"), planner, seed)
    if not res["success"]:
        return {**row, "success": False, "error": res["error"][:300],
                "plan_time_ms": watch.elapsed() * 1000.0}
    return _row_from_plan(row, scenario, family, res["plan"], res["plan_time_ms"])


def _row_from_plan(row: dict[str, Any], scenario: Scenario, family: str, plan: dict[str, Any],
                   plan_time_ms: float) -> dict[str, Any]:
    m = plan["metrics"]
    wps = plan["waypoints"]
    pts = np.array([[w["x"], w["y"]] for w in wps])
    from usvstation.planning.seeds.common import path_metrics

    pm = path_metrics(pts)
    row.update(success=True, error=None, length_m=pm["length_m"],
               normalization_index=pm["normalization_index"], duration_s=m["duration_s"],
               min_clearance_m=m["min_clearance_m"], total_turn_deg=pm["total_turn_deg"],
               max_turn_deg=pm["max_turn_deg"], plan_time_ms=plan_time_ms,
               replan_latency_ms=m.get("replan_latency_ms", []),
               straight_m=float(np.hypot(*(pts[-1] - pts[0]))),
               algorithm_path_length_m=m.get("algorithm_path_length_m"),
               algorithm_total_turn_deg=m.get("algorithm_total_turn_deg"))
    if family == "colregs":
        row.update(colregs_metrics(scenario, plan))
    row["path"] = pts.round(3).tolist()
    return row


def colregs_metrics(scenario: Scenario, plan: dict[str, Any]) -> dict[str, Any]:
    from usvstation.planning.colregs import GIVE_WAY_STARBOARD, compliance

    wps = plan["waypoints"]
    # resample the plan every second (position linear in time on each segment)
    t = np.array([w["t"] for w in wps])
    xy = np.array([[w["x"], w["y"]] for w in wps])
    ts = np.arange(0.0, t[-1], 1.0)
    track = np.stack([np.interp(ts, t, xy[:, 0]), np.interp(ts, t, xy[:, 1])], axis=1)
    tg = np.array([[o.x, o.y] for o in scenario.obstacles])
    tv = np.array([[o.vx, o.vy] for o in scenario.obstacles])
    res = compliance(track, ts, tg, tv)
    gw = [r for r in res if r.encounter in {e.value for e in GIVE_WAY_STARBOARD}]
    return {"colregs_score": sum(r.passed for r in res) / max(len(res), 1),
            "colregs_targets": [r.__dict__ for r in res],
            "starboard_cases": len(gw),
            "starboard_ok": all(r.first_action_side == "starboard" for r in gw)}


def run_compare(planners: list[str] | None = None, families: list[str] | None = None,
                seeds: int = 2, hidden: int = 6, dense_maps: int = 2,
                progress: Callable[[str], None] | None = None,
                plots: Path | None = None, ompl: bool = False, first_seed: int = 1,
                hidden_from: int = HIDDEN_FROM, track: bool = True,
                sweep: list[int] | None = None, sweep_maps: int = 30,
                curves: list[float] | None = None, curve_maps: int = 4) -> dict[str, Any]:
    """Every planner on every family; `ompl` adds OMPL RRT*, Informed RRT*, BIT* if installed.

    Planner seeds are first_seed .. first_seed + seeds - 1; each family has its public
    scenarios and `hidden` seeded ones from `hidden_from` on. With `track` the simulated
    boat sails the plan of the first seed of every planner and scenario.
    """
    unknown = [p for p in planners or [] if p not in planner_names()]
    if unknown:
        raise ValueError(f"planners: unknown planner {unknown[0]!r}; "
                         f"available: {', '.join(planner_names())}")
    planners = planners or planner_names()
    if ompl:
        from usvstation.bench.ompl_baseline import OMPL_PLANNERS, available

        if not available():
            raise ValueError("--ompl: OMPL is not installed (pip install ompl)")
    families = families or list(FAMILIES)
    rows = []
    for fam in families:
        scenarios = family_scenarios(fam, hidden, dense_maps, hidden_from)
        n_public = len(scenarios) - hidden  # the hidden ones come last
        for k, sc in enumerate(scenarios):
            for pl in planners:
                for seed in range(first_seed, first_seed + seeds):
                    row = evaluate(sc, fam, pl, seed, track=track and seed == first_seed)
                    row["hidden"] = k >= n_public
                    rows.append(row)
                    if progress:
                        progress(f"{fam} {sc.name} {pl} seed {seed}: "
                                 f"{'ok' if row['success'] else 'FAIL'} "
                                 f"{row['plan_time_ms']:.0f} ms")
            for pl in (OMPL_PLANNERS if ompl else ()):
                for seed in range(first_seed, first_seed + seeds):
                    row = evaluate_ompl(sc, fam, pl, seed)
                    rows.append(row)
                    if progress:
                        progress(f"{fam} {sc.name} ompl:{pl} seed {seed}: "
                                 f"{'ok' if row['success'] else 'FAIL'}")
    encounters = [sc for fam in families if fam in ("colregs", "encounters")
                  for sc in family_scenarios(fam, hidden, dense_maps, hidden_from)]
    result = {"planners": planners, "families": families, "seeds": seeds,
              "first_seed": first_seed, "hidden": hidden, "hidden_from": hidden_from,
              "summary": summarise(rows), "table_004": table_004(rows),
              "difficulty": difficulty(rows),
              "replan_002": replan_002(rows),
              "colregs_001": colregs_001(rows, seeds, progress, encounters or None),
              "rows": [{k: v for k, v in r.items() if k != "path"} for r in rows]}
    if "walls" in families:
        result["table_004_walls"] = table_004(rows, "walls")
    result["orderings"] = paper_orderings(result)
    if sweep:
        if progress:
            progress(f"difficulty sweep over {sweep} obstacles, {sweep_maps} maps each")
        result["difficulty_sweep"] = difficulty_sweep(sweep, sweep_maps)
    if curves:
        if progress:
            progress(f"cost-versus-time curves at {curves} s on {curve_maps} maps")
        result["cost_curves"] = cost_curves(curves, curve_maps, ompl=ompl)
    if plots is not None:
        from usvstation.bench.compare_plots import write_plots

        scenarios = {sc.name: sc for fam in {r["family"] for r in rows}
                     for sc in family_scenarios(fam, hidden=0, dense_maps=1)}
        result["plots"] = write_plots(rows, plots, scenarios)
        if "cost_curves" in result:
            from usvstation.bench.compare_plots import write_curves

            result["plots"].append(write_curves(result["cost_curves"], plots))
    return result


def summarise(rows: list[dict[str, Any]]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for r in rows:
        out.setdefault(r["planner"], {}).setdefault(r["family"], []).append(r)
    table: dict[str, Any] = {}
    for pl, fams in out.items():
        for fam, rs in fams.items():
            ok = [r for r in rs if r["success"]]
            def med(key: str, ok: list = ok) -> float | None:
                vals = [r[key] for r in ok if r.get(key) is not None]
                return round(float(np.median(vals)), 4) if vals else None
            entry = {"episodes": len(rs), "success_rate": round(len(ok) / len(rs), 4),
                     "success_ci95": wilson(len(ok), len(rs)),
                     "normalization_index_ci95": mean_ci(
                         [r["normalization_index"] for r in ok]),
                     "length_m": med("length_m"), "normalization_index": med("normalization_index"),
                     "duration_s": med("duration_s"), "min_clearance_m": med("min_clearance_m"),
                     "total_turn_deg": med("total_turn_deg"), "max_turn_deg": med("max_turn_deg"),
                     "plan_time_ms": round(float(np.median([r["plan_time_ms"] for r in rs])), 2),
                     "track_mean_dev_m": med("track_mean_dev_m"),
                     "public_success": _share([r for r in rs if not r.get("hidden")]),
                     "hidden_success": _share([r for r in rs if r.get("hidden")])}
            if fam == "colregs":
                entry["colregs_score"] = med("colregs_score")
            table.setdefault(pl, {})[fam] = entry
    return table


def wilson(k: int, n: int, z: float = 1.96) -> list[float] | None:
    """95 % Wilson score interval of a share k / n."""
    if n == 0:
        return None
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return [round(max(centre - half, 0.0), 4), round(min(centre + half, 1.0), 4)]


def mean_ci(values: list[float], z: float = 1.96) -> list[float] | None:
    """Mean +- 1.96 standard errors (normal approximation; n >= 2)."""
    vals = [v for v in values if v is not None]
    if len(vals) < 2:
        return None
    m, se = float(np.mean(vals)), float(np.std(vals, ddof=1)) / math.sqrt(len(vals))
    return [round(m - z * se, 4), round(m + z * se, 4)]


def difficulty(rows: list[dict[str, Any]]) -> dict[str, Any]:
    """Per family: the path/straight-line ratio of the shortest plan any planner found for each
    (scenario, seed): how far the maps force a detour (paper 004's maps: 1.36-1.45)."""
    best: dict[tuple, float] = {}
    fam_of: dict[tuple, str] = {}
    for r in rows:
        if r["success"] and r.get("straight_m"):
            key = (r["scenario"], r["seed"])
            ratio = r["length_m"] / r["straight_m"]
            best[key] = min(best.get(key, math.inf), ratio)
            fam_of[key] = r["family"]
    out: dict[str, Any] = {}
    for fam in sorted(set(fam_of.values())):
        vals = [v for k, v in best.items() if fam_of[k] == fam]
        out[fam] = {"n": len(vals), "ratio_median": round(float(np.median(vals)), 4),
                    "ratio_mean": round(float(np.mean(vals)), 4), "ratio_ci95": mean_ci(vals)}
    return out


def difficulty_sweep(counts: list[int], maps: int, seed: int = 1,
                     planner: str = "rrt-star") -> list[dict[str, Any]]:
    """Paper 004's 1 km map with more and more circles: `planner`'s path/straight-line ratio
    (median, 95 % interval) and success per obstacle count, over `maps` maps per count."""
    out = []
    for count in counts:
        ratios, ok = [], 0
        for k in range(maps):
            sc = dense_004(k % len(DENSE_PAIRS), k, count)
            try:
                plan = plan_with(sc, planner, seed).to_document()
            except NoFeasiblePlan:
                continue
            ok += 1
            ratios.append(plan["metrics"]["length_m"] / math.hypot(
                sc.start.x - sc.goal.x, sc.start.y - sc.goal.y))
        out.append({"count": count, "maps": maps, "planner": planner, "success": ok,
                    "ratio_median": round(float(np.median(ratios)), 4) if ratios else None,
                    "ratio_ci95": mean_ci(ratios)})
    return out


def cost_curves(budgets: list[float], maps: int, seed: int = 1,
                ompl: bool = True) -> dict[str, Any]:
    """Cost versus CPU-time budget on paper 004's map (the first `maps` of the dense family):
    the raw path's length over the straight line, median over the maps, for our RRT* (one
    try, anytime within `time_budget_s`) and OMPL's RRT*, BIT* and PRM* (a fresh planner
    per budget; PRM* on OMPL's own wall-clock timer; with `ompl`), with the maps solved."""
    from usvstation.bench.ompl_baseline import CURVE_PLANNERS, available, curve_in_process

    scenarios = [dense_004(k % len(DENSE_PAIRS), k // len(DENSE_PAIRS)) for k in range(maps)]
    costs: dict[str, list[list[float | None]]] = {"rrt-star": []}
    for sc in scenarios:
        straight = math.hypot(sc.start.x - sc.goal.x, sc.start.y - sc.goal.y)
        row = []
        for b in budgets:
            try:
                plan = plan_with(sc, "rrt-star", seed, iterations=200_000, attempts=1,
                                 time_budget_s=b)
                row.append(plan.metrics["tree_path_length_m"] / straight)
            except NoFeasiblePlan:
                row.append(None)
        costs["rrt-star"].append(row)
        for pl in (CURVE_PLANNERS if ompl and available() else ()):
            res = curve_in_process(sc.model_dump(mode="json"), pl, seed, budgets)
            got = res.get("costs", [None] * len(budgets))
            costs.setdefault(f"ompl:{pl}", []).append(
                [None if c is None else c / straight for c in got])
    out: dict[str, Any] = {"budgets_s": budgets, "maps": maps, "planners": {}}
    for pl, rows in costs.items():
        cols = list(zip(*rows, strict=True))
        out["planners"][pl] = {
            "median_ratio": [round(float(np.median([c for c in col if c is not None])), 4)
                             if any(c is not None for c in col) else None for col in cols],
            "solved": [sum(c is not None for c in col) for col in cols]}
    return out


def _share(rows: list[dict[str, Any]]) -> float | None:
    return round(sum(r["success"] for r in rows) / len(rows), 4) if rows else None


def table_004(rows: list[dict[str, Any]], family: str = "dense") -> dict[str, Any]:
    """Means over the family (004's maps: dense, or walls at its difficulty) of per-episode
    ratios to RRT* (same scenario and seed)."""
    by = {(r["planner"], r["scenario"], r["seed"]): r for r in rows
          if r["family"] == family and r["success"]}
    ratios: dict[str, list[float]] = {k: [] for k in PAPER_004}
    ratios.update(vpf_over_rrt_time=[], bspline_over_rrt_time=[])
    raw: dict[str, list[float]] = {k: [] for k in PAPER_004}
    for (pl, sc, seed), r in by.items():
        if pl != "rrt-star":
            continue
        for other, tag in (("vpf-rrt-star", "vpf"), ("bspline-rrt-star", "bspline")):
            o = by.get((other, sc, seed))
            if o is None:
                continue
            ratios[f"{tag}_over_rrt_length"].append(o["length_m"] / r["length_m"])
            if r["total_turn_deg"] > 0:
                ratios[f"{tag}_over_rrt_tta"].append(o["total_turn_deg"] / r["total_turn_deg"])
            ratios[f"{tag}_over_rrt_time"].append(o["plan_time_ms"] / r["plan_time_ms"])
            if r.get("algorithm_path_length_m") and o.get("algorithm_path_length_m"):
                raw[f"{tag}_over_rrt_length"].append(
                    o["algorithm_path_length_m"] / r["algorithm_path_length_m"])
                if r.get("algorithm_total_turn_deg"):
                    raw[f"{tag}_over_rrt_tta"].append(
                        o["algorithm_total_turn_deg"] / r["algorithm_total_turn_deg"])
    out: dict[str, Any] = {k: (round(float(np.mean(v)), 4) if v else None)
                           for k, v in ratios.items()}
    # finished: the plans as they leave (run-in, turn limit, speed profile); raw: the
    # algorithms' own paths (RRT* tree path, after VPF or B-spline), before that finish
    out["finished"] = {k: {"mean": out[k], "ci95": mean_ci(v), "n": len(v)}
                       for k, v in ratios.items() if k in PAPER_004}
    out["raw"] = {k: {"mean": round(float(np.mean(v)), 4) if v else None, "ci95": mean_ci(v),
                      "n": len(v)} for k, v in raw.items()}
    out["pairs"] = len(ratios["vpf_over_rrt_length"])
    out["paper"] = PAPER_004
    out["family"] = family
    dense = [r for r in rows if r["family"] == family]
    for pl in ("rrt-star", "bspline-rrt-star", "vpf-rrt-star", "ompl:RRTstar",
               "ompl:InformedRRTstar", "ompl:BITstar"):
        rs = [r for r in dense if r["planner"] == pl and r["success"]]
        if rs:
            out[pl] = {k: round(float(np.mean([r[k] for r in rs])), 4) for k in
                       ("length_m", "total_turn_deg", "plan_time_ms", "duration_s",
                        "normalization_index")}
    return out


def _side(ci: list[float] | None, below: bool, ref: float = 1.0) -> str:
    """'holds' when the 95 % interval lies on the expected side of `ref`, 'does not hold'
    when it lies on the other, else 'undecided'."""
    if not ci:
        return "not measured"
    lo, hi = ci
    if (hi < ref) if below else (lo > ref):
        return "holds"
    if (lo > ref) if below else (hi < ref):
        return "does not hold"
    return "undecided (the interval spans 1)"


def paper_orderings(result: dict[str, Any]) -> list[dict[str, Any]]:
    """Each seed paper's orderings as measured here, in words, with the 95 % intervals they
    rest on: 004 Tables 5-6 on its maps (dense: its density; walls: its difficulty), on
    the algorithms' own paths and on the finished plans; 002's re-planning time and success
    on its 400 m map; 001 Table III (improved against conventional GA) on its encounters."""
    out: list[dict[str, Any]] = []
    for key in ("table_004", "table_004_walls"):
        t = result.get(key)
        if not t or not t.get("pairs"):
            continue
        for basis in ("raw", "finished"):
            for ratio, below, text in (
                    ("vpf_over_rrt_length", True, "VPF-RRT* is shorter than RRT*"),
                    ("vpf_over_rrt_tta", True, "VPF-RRT* turns less than RRT*"),
                    ("bspline_over_rrt_length", False, "B-spline-RRT* is longer than RRT*"),
                    ("bspline_over_rrt_tta", False, "B-spline-RRT* turns more than RRT*")):
                e = t[basis].get(ratio) or {}
                lo, hi = PAPER_004[ratio]
                mean = e.get("mean")
                out.append({
                    "paper": "004", "family": t["family"], "basis": basis,
                    "ordering": text, "verdict": _side(e.get("ci95"), below),
                    "mean": mean, "ci95": e.get("ci95"), "n": e.get("n"),
                    "paper_range": [lo, hi],
                    "in_paper_range": None if mean is None else lo <= mean <= hi})
    summary = result.get("summary", {}).get("replan-ga", {}).get("transit")
    r = result.get("replan_002", {})
    if summary:
        rate = summary["success_rate"]
        out.append({"paper": "002", "family": "transit",
                    "ordering": "the GA plans the 400 m map with its moving ships",
                    "verdict": "holds" if rate == 1.0 else "holds in part" if rate > 0.0
                    else "does not hold", "success": rate,
                    "ci95": summary["success_ci95"], "n": summary["episodes"]})
    if r.get("count"):
        out.append({"paper": "002", "family": "transit",
                    "ordering": "re-planning takes less than the paper's 0.98 s",
                    "verdict": "holds" if r["p99_ms"] < 980.0 else "does not hold",
                    "p50_ms": r["p50_ms"], "p99_ms": r["p99_ms"], "n": r["count"]})
    trend = result.get("colregs_001", {}).get("table_iii")
    if trend:
        imp, con = trend["improved"], trend["conventional"]
        out.append(_compare_001("the improved GA is faster per step (160 -> 100 ms)",
                                imp.get("ms_per_step_mean_ci95"),
                                con.get("ms_per_step_mean_ci95"), lower=True))
        out.append(_compare_001("the improved GA succeeds more often (85 -> 98 %)",
                                imp.get("success_ci95"), con.get("success_ci95"), lower=False))
        out.append(_compare_001("the improved GA needs fewer generations (300-400 -> 200-300)",
                                imp.get("generations_per_step_ci95"),
                                con.get("generations_per_step_ci95"), lower=True))
        a, b = imp.get("final_fitness_std"), con.get("final_fitness_std")
        out.append({"paper": "001", "family": "colregs, encounters",
                    "ordering": "the improved GA's final fitness varies less (1.876 -> 0.945)",
                    "verdict": "not measured" if a is None or b is None else
                    ("holds" if a < b else "does not hold"), "improved": a, "conventional": b})
    return out


def _compare_001(text: str, improved: list[float] | None, conventional: list[float] | None,
                 lower: bool) -> dict[str, Any]:
    """001 Table III: 'holds' when the improved GA's interval lies wholly on the better side
    of the conventional one's, 'does not hold' when wholly on the worse, else 'undecided'."""
    if not improved or not conventional:
        verdict = "not measured"
    elif (improved[1] < conventional[0]) if lower else (improved[0] > conventional[1]):
        verdict = "holds"
    elif (improved[0] > conventional[1]) if lower else (improved[1] < conventional[0]):
        verdict = "does not hold"
    else:
        verdict = "undecided (the intervals overlap)"
    return {"paper": "001", "family": "colregs, encounters", "ordering": text,
            "verdict": verdict, "improved_ci95": improved, "conventional_ci95": conventional}


def replan_002(rows: list[dict[str, Any]]) -> dict[str, Any]:
    lat = [x for r in rows if r["planner"] == "replan-ga" and r["success"]
           for x in r.get("replan_latency_ms", [])]
    transit = [r for r in rows if r["planner"] == "replan-ga" and r["family"] == "transit"]
    return {"count": len(lat),
            "p50_ms": round(float(np.percentile(lat, 50)), 3) if lat else None,
            "p99_ms": round(float(np.percentile(lat, 99)), 3) if lat else None,
            "max_ms": round(float(max(lat)), 3) if lat else None,
            "transit_success": (sum(r["success"] for r in transit) / len(transit))
            if transit else None,
            "paper_s": 0.98}


def colregs_001(rows: list[dict[str, Any]], seeds: int,
                progress: Callable[[str], None] | None = None,
                scenarios: list[Scenario] | None = None) -> dict[str, Any]:
    """Starboard rule over colregs-ga's COLREGs episodes; Tab. III improved vs conventional
    over `scenarios` (default: the colregs family's public cases), with 95 % intervals."""
    mine = [r for r in rows if r["planner"] == "colregs-ga" and r["family"] == "colregs"]
    if not mine:
        return {"cases": 0, "starboard_ok": None}
    gw = [r for r in mine if r["success"] and r["starboard_cases"]]
    failed = [r for r in mine if not r["success"]]
    out: dict[str, Any] = {
        "cases": len(gw), "episodes": len(mine),
        "starboard_ok": bool(gw) and all(r["starboard_ok"] for r in gw) and not any(
            "give-way" in r["scenario"] or "head-on" in r["scenario"] or "mix" in r["scenario"]
            for r in failed),
        "score_mean": round(float(np.mean([r["colregs_score"] for r in mine if r["success"]])), 4)
        if any(r["success"] for r in mine) else None,
    }
    trend = {}
    for label, improved in (("improved", True), ("conventional", False)):
        times, succ, gens, fit = [], [], [], []
        for sc in scenarios or colregs_cases():
            for seed in range(1, seeds + 1):
                watch = Stopwatch()
                try:
                    p = plan_with(sc, "colregs-ga", seed, improved=improved, attempts=1)
                except NoFeasiblePlan:
                    succ.append(False)
                    continue
                m = p.metrics
                succ.append(True)
                times.append(watch.elapsed() * 1000.0 / max(m["steps"], 1))
                gens.append(m["generations_per_step_mean"])
                fit.append(m["fitness_final"])
        trend[label] = {"ms_per_step": round(float(np.median(times)), 3) if times else None,
                        "ms_per_step_mean_ci95": mean_ci(times),
                        "success_rate": round(sum(succ) / max(len(succ), 1), 4),
                        "success_ci95": wilson(sum(succ), len(succ)), "runs": len(succ),
                        "generations_per_step": round(float(np.mean(gens)), 3) if gens else None,
                        "generations_per_step_ci95": mean_ci(gens),
                        "final_fitness_std": round(float(np.std(fit)), 6) if fit else None}
        if progress:
            progress(f"colregs-ga {label}: {trend[label]}")
    out["table_iii"] = trend
    out["paper_table_iii"] = {"conventional": {"ms": 160, "success": 0.85, "std": 1.876,
                                               "iterations": "300-400"},
                              "improved": {"ms": 100, "success": 0.98, "std": 0.945,
                                           "iterations": "200-300"}}
    return out


def render_markdown(result: dict[str, Any]) -> str:
    lines = markdown_table(
        ["planner", "family", "episodes", "success", "public", "hidden", "length m", "NI",
         "duration s", "clearance m", "total turn deg", "max turn deg", "plan ms",
         "tracked dev m", "COLREGs"],
        ([pl, fam, e["episodes"], f"{e['success_rate']:.2f}", _f(e.get("public_success"), 2),
          _f(e.get("hidden_success"), 2), _f(e["length_m"]), _f(e["normalization_index"], 3),
          _f(e["duration_s"]), _f(e["min_clearance_m"], 2), _f(e["total_turn_deg"]),
          _f(e["max_turn_deg"]), _f(e["plan_time_ms"]), _f(e.get("track_mean_dev_m"), 2),
          _f(e.get("colregs_score"), 2)]
         for pl, fams in result["summary"].items() for fam, e in fams.items()))
    for key in ("table_004", "table_004_walls"):
        t = result.get(key)
        if not t or not t.get("pairs"):
            continue
        lines += ["", f"Paper 004 Tab. 5/6 shape ({t.get('family', 'dense')} family, means over "
                  "maps and seeds):", ""]
        lines += markdown_table(
            ["algorithm", "length m", "TTA deg", "plan ms", "sailing s", "NI"],
            ([pl, f"{e['length_m']:.1f}", f"{e['total_turn_deg']:.1f}",
              f"{e['plan_time_ms']:.0f}", f"{e['duration_s']:.1f}",
              f"{e['normalization_index']:.3f}"]
             for pl in ("rrt-star", "bspline-rrt-star", "vpf-rrt-star", "ompl:RRTstar",
                        "ompl:InformedRRTstar", "ompl:BITstar") if pl in t for e in (t[pl],)))
        lines += [""]
        lines += markdown_table(
            ["ratio", "finished (mean, 95 % interval)", "raw", "paper"],
            ([k, _mean_ci(t.get("finished", {}).get(k)), _mean_ci(t.get("raw", {}).get(k)),
              f"{rng[0]}-{rng[1]}"] for k, rng in PAPER_004.items()))
    if result.get("difficulty"):
        lines += ["", "Difficulty (the shortest plan any planner found, over the straight "
                  "line; paper 004's maps: 1.36-1.45):", ""]
        lines += markdown_table(
            ["family", "n", "median", "mean", "95 % interval"],
            ([fam, d["n"], _f(d["ratio_median"], 3), _f(d["ratio_mean"], 3),
              "-" if not d["ratio_ci95"] else f"[{d['ratio_ci95'][0]:.3f}, "
              f"{d['ratio_ci95'][1]:.3f}]"] for fam, d in result["difficulty"].items()))
    orderings = paper_orderings(result)  # from the figures, by the rules of this version
    if orderings:
        lines += ["", "The seed papers' orderings on these maps:", ""]
        for o in orderings:
            where = f"{o['family']}" + (f", {o['basis']} paths" if "basis" in o else "")
            ci = o.get("ci95") or o.get("improved_ci95")
            lines.append(f"- {o['paper']} ({where}): {o['ordering']}: {o['verdict']}"
                         + ("" if o.get("mean") is None else f" (mean {o['mean']}, 95 % "
                            f"interval {ci}, n = {o['n']}; paper {o['paper_range']})")
                         + ("" if "improved_ci95" not in o else
                            f" (improved {o['improved_ci95']}, conventional "
                            f"{o['conventional_ci95']})")
                         + ("" if "success" not in o else
                            f" (success {o['success']}, 95 % interval {o['ci95']}, "
                            f"n = {o['n']})")
                         + ("" if "p99_ms" not in o else
                            f" (p50 {o['p50_ms']} ms, p99 {o['p99_ms']} ms, n = {o['n']})")
                         + ("" if "conventional" not in o else
                            f" (improved {o['improved']}, conventional {o['conventional']})"))
    r = result["replan_002"]
    lines += ["", f"Re-planning (002): {r['count']} re-plans, p50 {_f(r['p50_ms'], 2)} ms, "
              f"p99 {_f(r['p99_ms'], 2)} ms (paper 0.98 s in MATLAB)."]
    c = result["colregs_001"]
    lines += ["", f"COLREGs (001): starboard_ok {c.get('starboard_ok')} over {c.get('cases')} "
              "give-way/head-on episodes."]
    if "table_iii" in c:
        lines += [""]
        lines += markdown_table(
            ["GA (001 Tab. III)", "runs", "ms per step (median; mean 95 %)",
             "success (95 %)", "generations per step (95 %)", "final fitness std"],
            ([label, e.get("runs", "-"),
              f"{_f(e['ms_per_step'], 2)} ({e.get('ms_per_step_mean_ci95')})",
              f"{e['success_rate']:.2f} ({e.get('success_ci95')})",
              f"{_f(e['generations_per_step'], 1)} ({e.get('generations_per_step_ci95')})",
              _f(e["final_fitness_std"], 4)]
             for label, e in c["table_iii"].items()))
    return "\n".join(lines) + "\n"


def _mean_ci(e: dict[str, Any] | None) -> str:
    if not e or e.get("mean") is None:
        return "-"
    ci = e.get("ci95")
    return f"{e['mean']:.3f}" + ("" if not ci else f" [{ci[0]:.3f}, {ci[1]:.3f}]") + \
        f" (n {e.get('n')})"


def _f(v: float | None, nd: int = 1) -> str:
    return "-" if v is None else f"{v:.{nd}f}"
