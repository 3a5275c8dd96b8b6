"""`usv-station bench arrival`: the last 30 metres under perturbations (issue 24).

Every episode is one IGA plan of a public scenario (case1..case4, planned for the Otter
as `bench tracking` does) flown by the simulated boat itself (`sim.dynamic.DynamicVehicle`:
its sensors, its observer, its guidance, its approach gates and go-around), in sea state 3
with the family's current, compass and hull. The boat knows only what its sensor profile
measures; the judge below knows the truth:

- arrived: the true hull crosses the ramp end (x = 0) within `offset` (0.3 m) of the axis
  and `heading` (5 deg) of the arrival heading;
- bad: a crossing beyond `contact_offset` (0.5 m) or `contact_heading` (8 deg);
- go_around: the boat called a go-around (it is then followed for `after_s` more seconds:
  a crossing then is judged like any other, so a go-around that still hits counts as a
  contact, never as a go-around);
- marginal (between the two tolerances) and timeout are counted apart.

Rows: {family, method, sensor, episodes, arrived, go_around, bad, p95_offset_m,
p95_heading_deg} (offsets and heading errors over the crossings, true values). Methods:
`approach` (compensated AV-LOS to the approach, then the ramp approach with gates and
go-around), `approach_ilos` (ILOS to the approach, then the same), `legacy` (compensated
AV-LOS with its once-bent final approach and no gates: the boat before issue 24),
`approach_straight` (as `approach`, on plans made with the planner's `final_straight`:
the last leg along the ramp axis from the first gate in; the planning extension, apart).
Plans of seeds 21-24 (`PLAN_SEEDS`) are reported; nothing was tuned on them (tuning used
seeds 1-8, `TUNING_SEEDS`).
"""

from __future__ import annotations

import math
import platform
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from usvstation.clock import Stopwatch
from usvstation.dynamics.environment import Environment, WaveField
from usvstation.dynamics.params import HullMismatch, otter
from usvstation.geometry import angle_diff
from usvstation.guidance.approach import ArrivalLimits
from usvstation.guidance.trajectory import Trajectory

PLAN_SEEDS = (21, 22, 23, 24)
TUNING_SEEDS = tuple(range(1, 9))
SCENARIOS = ("case1", "case2", "case3", "case4")
SENSORS = ("rtk-moving-base", "rtk", "gnss")
METHODS = ("approach", "approach_ilos", "legacy", "approach_straight")
STEP_S = 0.2  # s of boat time per vehicle step
AFTER_S = 20.0  # s a go-around is followed for
TIMEOUT_S = 60.0  # s after the plan's end without a crossing or a go-around


@dataclass(frozen=True)
class CurrentChange:
    """The current changes to (speed, direction) over `ramp_s` seconds once the boat is
    `at_m` metres from the ramp end (true distance)."""

    at_m: float
    speed: float
    direction_deg: float
    ramp_s: float = 5.0


@dataclass(frozen=True)
class Family:
    """One perturbation: the current (and its change), the compass and the hull."""

    name: str
    description: str
    current: float = 0.3
    direction_deg: float = 90.0  # flows to +y: across the ramp axis
    change: CurrentChange | None = None
    compass_bias_deg: float = 0.0
    hull: HullMismatch = field(default_factory=HullMismatch)


FAMILIES: dict[str, Family] = {f.name: f for f in (
    Family("bench", "0.3 m/s across the axis, sea state 3 (bench tracking's conditions)"),
    Family("current_step", "0.3 m/s across, stepping to 0.7 m/s at 45 deg 40 m out",
           change=CurrentChange(40.0, 0.7, 45.0)),
    Family("current_reverses", "0.3 m/s across, reversing 50 m out",
           change=CurrentChange(50.0, 0.3, -90.0)),
    Family("current_mirrored", "0.3 m/s across the other way", direction_deg=-90.0),
    Family("current_0.5", "0.5 m/s across", current=0.5),
    Family("following_0.5", "0.5 m/s along the axis towards the ramp", current=0.5,
           direction_deg=180.0),
    Family("compass_bias_2", "compass reads 2 deg high", compass_bias_deg=2.0),
    Family("compass_bias_5", "compass reads 5 deg high", compass_bias_deg=5.0),
    Family("drag_+25", "hull drag +25 % of the model", hull=HullMismatch(drag_scale=1.25)),
    Family("thrust_-15", "thrust -15 % of the model", hull=HullMismatch(thrust_scale=0.85)),
    Family("beam_1.5", "1.5 m/s across the axis", current=1.5),
    Family("beam_2.5", "2.5 m/s across the axis", current=2.5),
)}


@dataclass(frozen=True)
class Outcome:
    kind: str  # arrived | marginal | bad | go_around | timeout
    offset: float | None = None  # m, true lateral offset at the crossing
    heading: float | None = None  # deg, true heading error at the crossing
    reason: str = ""


def environment(family: Family, speed: float, direction_deg: float) -> Environment:
    waves = WaveField.from_sea_state(3, 0.0)
    return Environment.with_current(speed, math.radians(direction_deg), waves=waves)


def _path_check(scenario: Any) -> Callable[[Trajectory], bool] | None:
    from usvstation.bench.tracking import _path_check as check

    return check(scenario)


def fly(plan: dict[str, Any], scenario: Any, family: Family, method: str, sensor: str,
        seed: int, limits: ArrivalLimits | None = None) -> Outcome:
    """One episode, judged on the truth."""
    from usvstation.bench.tracking import start_state
    from usvstation.sim.dynamic import DynamicVehicle
    from usvstation.sim.sensors import sensor_profile
    from usvstation.sim.vehicle import Waypoint

    params = otter()
    env = environment(family, family.current, family.direction_deg)
    initial = start_state(plan, params, env)
    wps = [Waypoint(w["x"], w["y"], w["t"], w["speed"], math.radians(w["heading_deg"]))
           for w in plan["waypoints"]]
    profile = sensor_profile(sensor)
    if family.compass_bias_deg:
        profile = profile.with_compass_bias(family.compass_bias_deg)
    legacy = method == "legacy"
    v = DynamicVehicle(wps[0].x, wps[0].y, wps[0].heading, speed=wps[0].speed, params=params,
                       env=env, accel=scenario.vessel.accel_max,
                       guidance="ilos" if method == "approach_ilos" else "avlos_comp",
                       sensors=profile, hull=family.hull, seed=seed,
                       arrival=None if legacy else (limits or ArrivalLimits.from_vessel(
                           scenario.vessel)),
                       path_check=_path_check(scenario), initial=initial.state)
    v.set_mission(wps)
    v.start()
    lim = limits or ArrivalLimits.from_vessel(scenario.vessel)
    goal = (wps[-1].x, wps[-1].y)
    arrival = math.atan2(wps[-1].y - wps[-2].y, wps[-1].x - wps[-2].x)
    changed = False
    prev = v.truth
    around_at: float | None = None
    end = wps[-1].t + TIMEOUT_S
    while True:
        t = v.truth
        if family.change is not None and not changed and \
                math.hypot(t.x - goal[0], t.y - goal[1]) <= family.change.at_m:
            changed = True
            _change_current(v, family, env)
        v.step(STEP_S)
        _ramp_current(v)
        now = v.truth
        crossing = _crossing(prev, now, goal, arrival)
        if crossing is None and now.mission_complete:  # on the ramp: judged where it stopped
            crossing = _offsets(now, goal, arrival)
        if crossing is not None:
            offset, heading = crossing
            kind = "arrived" if offset <= lim.offset and heading <= math.degrees(lim.heading) \
                else "bad" if offset > lim.contact_offset or \
                heading > math.degrees(lim.contact_heading) else "marginal"
            return Outcome(kind, offset, heading, v.go_around or "")
        if v.go_around is not None and around_at is None:
            around_at = now.t
        if around_at is not None and now.t - around_at >= AFTER_S:
            return Outcome("go_around", reason=v.go_around or "")
        if around_at is None and now.t > end:
            return Outcome("timeout")
        prev = now


def _change_current(v: Any, family: Family, env: Environment) -> None:
    ch = family.change
    v._current_ramp = (v.truth.t, env.current, (
        ch.speed * math.cos(math.radians(ch.direction_deg)),
        ch.speed * math.sin(math.radians(ch.direction_deg))), ch.ramp_s)


def _ramp_current(v: Any) -> None:
    """Move the current linearly from its old to its new value over the change's ramp."""
    ramp = getattr(v, "_current_ramp", None)
    if ramp is None:
        return
    t0, (ax, ay), (bx, by), span = ramp
    w = min(max((v.truth.t - t0) / span, 0.0), 1.0)
    cx, cy = ax + w * (bx - ax), ay + w * (by - ay)
    speed = math.hypot(cx, cy)
    v.env = Environment.with_current(speed, math.atan2(cy, cx), waves=v.env.waves)
    if w >= 1.0:
        v._current_ramp = None


def _crossing(a: Any, b: Any, goal: tuple[float, float],
              arrival: float) -> tuple[float, float] | None:
    """(|offset| m, |heading error| deg) where the true hull crosses the ramp end's line."""
    c, s = math.cos(arrival), math.sin(arrival)
    da = (a.x - goal[0]) * c + (a.y - goal[1]) * s  # negative before the ramp end
    db = (b.x - goal[0]) * c + (b.y - goal[1]) * s
    if not da < 0.0 <= db:
        return None
    w = -da / (db - da)
    x, y = a.x + w * (b.x - a.x), a.y + w * (b.y - a.y)
    offset = abs(-(x - goal[0]) * s + (y - goal[1]) * c)
    psi = a.heading + w * angle_diff(b.heading, a.heading)
    return offset, abs(math.degrees(angle_diff(psi, arrival)))


def _offsets(state: Any, goal: tuple[float, float], arrival: float) -> tuple[float, float]:
    c, s = math.cos(arrival), math.sin(arrival)
    offset = abs(-(state.x - goal[0]) * s + (state.y - goal[1]) * c)
    return offset, abs(math.degrees(angle_diff(state.heading, arrival)))


def plans(seeds: tuple[int, ...] = PLAN_SEEDS, scenarios: tuple[str, ...] = SCENARIOS,
          final_straight: bool = False) -> list[tuple[str, int, Any, dict[str, Any]]]:
    """(scenario name, seed, scenario, plan document) for every plan flown (`final_straight`:
    planned with the planner's final straight along the ramp axis, docs/planner.md)."""
    from usvstation.bench.tracking import scenario_for_vessel
    from usvstation.planning.plan import plan_scenario
    from usvstation.scenario import load_scenario

    out = []
    for name in scenarios:
        scenario = scenario_for_vessel(load_scenario(name), otter())
        for seed in seeds:
            out.append((name, seed, scenario, plan_scenario(
                scenario, seed=seed, final_straight=final_straight).to_document()))
    return out


def _p95(values: list[float]) -> float | None:
    return round(float(np.percentile(values, 95)), 3) if values else None


def _row(family: Family, method: str, sensor: str,
         outcomes: list[Outcome]) -> tuple[dict[str, Any], dict[str, Any]]:
    crossings = [o for o in outcomes if o.offset is not None]
    row = {"family": family.name, "method": method, "sensor": sensor,
           "episodes": len(outcomes),
           "arrived": sum(o.kind == "arrived" for o in outcomes),
           "go_around": sum(o.kind == "go_around" for o in outcomes),
           "bad": sum(o.kind == "bad" for o in outcomes),
           "p95_offset_m": _p95([o.offset for o in crossings]),
           "p95_heading_deg": _p95([o.heading for o in crossings])}
    reasons: dict[str, int] = {}
    for o in outcomes:
        if o.kind == "go_around":  # "gate 15 m: cross-track 1.20 m > 1.27 m" -> cross-track
            why = o.reason.split(":", 1)[-1] if o.reason.startswith("gate") else o.reason
            key = re.sub(r"\s*[\d.]+.*$", "", why).strip()
            reasons[key] = reasons.get(key, 0) + 1
    other = {"family": family.name, "method": method, "sensor": sensor,
             "marginal": sum(o.kind == "marginal" for o in outcomes),
             "timeout": sum(o.kind == "timeout" for o in outcomes),
             "go_around_at": _gates(outcomes), "go_around_why": dict(sorted(reasons.items()))}
    return row, other


def _gates(outcomes: list[Outcome]) -> dict[str, int]:
    at: dict[str, int] = {}
    for o in outcomes:
        if o.kind == "go_around":
            key = o.reason.split(":")[0] if o.reason.startswith("gate") else "entry"
            at[key] = at.get(key, 0) + 1
    return dict(sorted(at.items()))


def run_family(family: Family, method: str, sensor: str,
               flown: list[tuple[str, int, Any, dict[str, Any]]]) -> tuple[dict[str, Any],
                                                                             list[Outcome]]:
    """One row: every plan flown once (sensor seed from the plan seed and its index)."""
    outcomes = [fly(plan, scenario, family, method, sensor, seed=1000 * seed + k)
                for k, (_, seed, scenario, plan) in enumerate(flown)]
    return _row(family, method, sensor, outcomes)[0], outcomes


def _task(args: tuple[str, str, str, tuple[int, ...], tuple[str, ...]]) -> list[Outcome]:
    family, method, sensor, seeds, scenarios = args
    return run_family(FAMILIES[family], method, sensor,
                      plans(seeds, scenarios, final_straight=method == "approach_straight"))[1]


QUICK = {"families": ("bench", "beam_2.5"), "methods": ("approach", "legacy"),
         "sensors": ("rtk-moving-base", "gnss"), "seeds": (21,),
         "scenarios": ("case1", "case2")}


def run_arrival_bench(families: tuple[str, ...] | None = None,
                      methods: tuple[str, ...] = METHODS, sensors: tuple[str, ...] = SENSORS,
                      seeds: tuple[int, ...] = PLAN_SEEDS,
                      scenarios: tuple[str, ...] = SCENARIOS, quick: bool = False,
                      workers: int = 1,
                      progress: Callable[[str], None] | None = None) -> dict[str, Any]:
    """Everything `usv-station bench arrival` prints (`quick`: two families, two methods,
    two sensors, two plans: a smoke test, not figures for the record)."""
    watch = Stopwatch()
    if quick:
        families = families or QUICK["families"]
        methods, sensors = QUICK["methods"], QUICK["sensors"]
        seeds, scenarios = QUICK["seeds"], QUICK["scenarios"]
    names = families or tuple(FAMILIES)
    unknown = [n for n in names if n not in FAMILIES]
    if unknown:
        raise ValueError(f"bench arrival: unknown family {unknown[0]!r}; available: "
                         f"{', '.join(FAMILIES)}")
    tasks = [(name, method, sensor, seeds, scenarios)
             for name in names for sensor in sensors for method in methods]
    if workers > 1:
        from concurrent.futures import ProcessPoolExecutor

        with ProcessPoolExecutor(max_workers=workers) as pool:
            results = list(pool.map(_task, tasks))
    else:
        results = []
        for task in tasks:
            if progress:
                progress(f"arrival {task[0]} {task[1]} {task[2]}")
            results.append(_task(task))
    rows, others = [], []
    for (name, method, sensor, _, _), outcomes in zip(tasks, results, strict=True):
        row, other = _row(FAMILIES[name], method, sensor, outcomes)
        rows.append(row)
        others.append(other)
    limits = ArrivalLimits()
    return {
        "rows": rows,
        "other_outcomes": others,
        "families": {n: FAMILIES[n].description for n in names},
        "methods": {"approach": "compensated AV-LOS, then the ramp approach (gates, go-around)",
                    "approach_ilos": "ILOS, then the ramp approach (gates, go-around)",
                    "legacy": "compensated AV-LOS with its once-bent final approach, no gates "
                              "(the boat before issue 24)",
                    "approach_straight": "as approach, on plans with the planner's final "
                                         "straight along the ramp axis from the first gate in "
                                         "(planner option final_straight)"},
        "sensors": {n: _describe(n) for n in sensors},
        "conditions": {
            "plans": [f"{name} seed {seed}" for name in scenarios for seed in seeds],
            "plan_seeds": list(seeds), "tuning_seeds": list(TUNING_SEEDS),
            "vessel": "otter (plans made for it, bench tracking's scenario_for_vessel)",
            "sea_state": 3, "wave_dir_deg": 0.0,
            "arrival": {"offset_m": limits.offset,
                        "heading_deg": round(math.degrees(limits.heading), 3),
                        "bad_offset_m": limits.contact_offset,
                        "bad_heading_deg": round(math.degrees(limits.contact_heading), 3)},
            "gates_m": list(limits.gates), "standby_m": limits.standby,
            "judge": "the true hull where it crosses the ramp end's line (or stops on the "
                     "ramp); a go-around followed for 20 s more (a crossing then counts)",
            "quick": quick,
        },
        "elapsed_s": round(watch.elapsed(), 2),
        "machine": {"python": platform.python_version(), "platform": platform.platform()},
    }


def _describe(sensor: str) -> str:
    from usvstation.sim.sensors import sensor_profile

    g = sensor_profile(sensor).gnss
    kind = "relative to the ramp (moving-baseline RTK)" if g.relative else "absolute"
    return (f"GNSS {kind}: {g.cep_m:.2f} m CEP ({g.white_std_m:g} m white, {g.bias_std_m:g} m "
            f"wander over {g.bias_tau_s:g} s), {g.rate_hz:g} Hz, {g.latency_s:g} s latency; "
            "compass 0.5 deg noise, 0.2 s lag")


def render_markdown(result: dict[str, Any]) -> str:
    """The RESULTS.md table of a saved `bench arrival --json` result."""
    lines = ["| family | method | sensor | episodes | arrived | go-around | bad | "
             "p95 offset m | p95 heading deg |", "|---|---|---|---|---|---|---|---|---|"]
    for r in result["rows"]:
        lines.append(f"| {r['family']} | {r['method']} | {r['sensor']} | {r['episodes']} | "
                     f"{r['arrived']} | {r['go_around']} | {r['bad']} | "
                     f"{r['p95_offset_m'] if r['p95_offset_m'] is not None else '-'} | "
                     f"{r['p95_heading_deg'] if r['p95_heading_deg'] is not None else '-'} |")
    return "\n".join(lines) + "\n"
