"""`usv-station bench tracking`: how well plans are followed (paper 000 sec. 4.2 and 3.1).

Two parts, printed as one JSON object:

- paper_reproduction: the AV-LOS vs LOS simulation of paper 000 sec. 4.2
  under the paper's assumptions (kinematic boat, heading set each 0.2 s
  period, speed ramping at most 2 m/s^2), trajectory P1..P4, R = 3 m, 50
  random starts in a 6 m x 6 m square around P1 at rest, 10 repetitions each;
  mean eq. 14 deviation (desired vs actual position at the same time).
- disturbed: the IGA plans of the public scenarios (seed 1) tracked by the
  3-DOF Otter model in a 0.3 m/s current across the ramp axis and sea-state-3
  waves, for each guidance method, with deviation and arrival figures. The
  waves run out along the ramp axis (head seas for the boat, as astern of a
  ship steaming into the sea); `disturbed_quartering_seas` repeats the runs
  with waves from the quarter on the current's side, the harder case.
"""

from __future__ import annotations

import math
import platform
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from usvstation.control.autopilot import Autopilot
from usvstation.control.loop import TrackingLoop
from usvstation.dynamics.environment import Environment, WaveField
from usvstation.dynamics.kinematic import KinematicBoat
from usvstation.dynamics.params import VesselParams, otter
from usvstation.dynamics.vessel import ThrustCommand, Vessel, VesselState
from usvstation.guidance.compensation import CompensatedAVLOS, DisturbancePredictor
from usvstation.guidance.los import AVLOSGuidance, LOSGuidance
from usvstation.guidance.sliding_curve import SlidingCurveGuidance
from usvstation.guidance.trajectory import Trajectory

PAPER_TRAJECTORY = ((0.0, 0.0, 0.0), (0.0, 20.0, 8.0), (30.0, 20.0, 14.0), (30.0, 0.0, 22.0))
PAPER_LOS_M, PAPER_AVLOS_M = 2.0402, 0.8161
METHODS = ("los", "avlos", "avlos_comp", "sliding_curve")
PUBLIC_SCENARIOS = ("case1", "case2", "case3", "case4")
# Waves running towards the ramp from the quarter, pushing the same way as the current.
QUARTERING_WAVE_DIR = math.radians(135.0)


@dataclass(frozen=True)
class PaperSetup:
    """Paper 000 sec. 4.2: period T = 0.2 s, R = 3 m, 50 starts x 10 repetitions."""

    period: float = 0.2
    lookahead: float = 3.0
    accel_max: float = 2.0  # m/s^2, the kinematic boat's speed ramp
    square: float = 6.0  # m, side of the start square centred on P1
    starts: int = 50
    repetitions: int = 10
    seed: int = 1
    speed_max: float = 8.0  # m/s, AV-LOS saturation (above the 5 m/s the plan needs)
    avlos_accel: float = 1.5  # m/s^2, AV-LOS refinements: 0.75 x the boat's ramp


@dataclass(frozen=True)
class DisturbedSetup:
    """The disturbed tracking runs: Otter, current across the ramp axis, sea state 3."""

    current_speed: float = 0.3  # m/s
    current_dir: float = math.pi / 2  # flows to +y: across the ramp axis
    sea_state: int = 3
    wave_dir: float = 0.0  # waves run out along the ramp axis: head seas for the boat
    lookahead: float = 8.0  # m (4 boat lengths; 3 m makes the Otter weave)
    guidance_period: float = 0.2  # s
    control_period: float = 0.05  # s
    overrun: float = 15.0  # m of path past the ramp end
    plan_accel: float = 0.5  # m/s^2, the scenarios' vessel.accel_max
    timeout: float = 40.0  # s after the plan's end without reaching x = 0
    seed: int = 1

    def environment(self) -> Environment:
        waves = WaveField.from_sea_state(self.sea_state, self.wave_dir)
        return Environment.with_current(self.current_speed, self.current_dir, waves=waves)


# ---------------------------------------------------------------- paper 000 sec. 4.2


def kinematic_run(make_guidance: Callable[[], Any], trajectory: Trajectory, x0: float, y0: float,
                  setup: PaperSetup) -> float:
    """Mean eq. 14 deviation of one kinematic run, sampled every period over the plan."""
    guidance = make_guidance()
    boat = KinematicBoat(x0, y0, 0.0, 0.0, setup.accel_max)
    steps = round((trajectory.end_time - trajectory.start_time) / setup.period)
    total = 0.0
    for k in range(steps + 1):
        t = trajectory.start_time + k * setup.period
        dx, dy = trajectory.position_at(t)
        total += math.hypot(boat.x - dx, boat.y - dy)
        if k == steps:
            break
        command = guidance.update(boat.state, t)
        boat.step(command.heading, command.speed, setup.period)
    return total / (steps + 1)


def paper_reproduction(setup: PaperSetup | None = None) -> dict[str, Any]:
    """LOS vs AV-LOS mean deviation on the paper's P1..P4 trajectory (eq. 14)."""
    s = setup or PaperSetup()
    traj = Trajectory.from_xyt(PAPER_TRAJECTORY)
    rng = np.random.default_rng(s.seed)
    starts = rng.uniform(-s.square / 2, s.square / 2, size=(s.starts, 2))
    makers = {
        "los": lambda: LOSGuidance(traj, s.lookahead, speed_max=s.speed_max),
        "avlos": lambda: AVLOSGuidance(traj, s.lookahead, speed_max=s.speed_max,
                                       accel=s.avlos_accel),
        "avlos_eq13": lambda: AVLOSGuidance(traj, s.lookahead, speed_max=s.speed_max),
    }
    means = {}
    for name, make in makers.items():
        runs = [
            kinematic_run(make, traj, float(x0), float(y0), s)
            for x0, y0 in starts
            for _ in range(s.repetitions)
        ]
        means[name] = float(np.mean(runs))
    return {
        "los_mean_dev_m": round(means["los"], 4),
        "avlos_mean_dev_m": round(means["avlos"], 4),
        "runs": s.starts * s.repetitions,
        "avlos_to_los": round(means["avlos"] / means["los"], 4),
        "avlos_eq13_only_mean_dev_m": round(means["avlos_eq13"], 4),
        "paper_los_mean_dev_m": PAPER_LOS_M,
        "paper_avlos_mean_dev_m": PAPER_AVLOS_M,
        "setup": {
            "period_s": s.period, "lookahead_m": s.lookahead, "accel_max": s.accel_max,
            "start_square_m": s.square, "starts": s.starts, "repetitions": s.repetitions,
            "seed": s.seed, "avlos_speed_max": s.speed_max, "avlos_accel": s.avlos_accel,
        },
    }


# ---------------------------------------------------------------- disturbed tracking


def make_guidance(method: str, trajectory: Trajectory, params: VesselParams, env: Environment,
                  setup: DisturbedSetup) -> Any:
    """The guidance object for `method` on `trajectory`."""
    common = {"speed_max": params.top_speed, "overrun": setup.overrun}
    if method == "los":
        return LOSGuidance(trajectory, setup.lookahead, **common)
    if method == "avlos":
        return AVLOSGuidance(trajectory, setup.lookahead, accel=setup.plan_accel, **common)
    if method == "avlos_comp":
        return CompensatedAVLOS(trajectory, DisturbancePredictor(params, env), setup.lookahead,
                                accel=setup.plan_accel, **common)
    if method == "sliding_curve":
        return SlidingCurveGuidance(trajectory, setup.lookahead, **common)
    raise ValueError(f"method: unknown guidance {method!r}; available: {', '.join(METHODS)}")


def start_state(plan: dict[str, Any], params: VesselParams, env: Environment) -> Vessel:
    """A vessel on the plan's first waypoint in steady motion along the first leg.

    It makes good the waypoint's speed along the leg's heading, crabbing
    into the drift as any autopilot holding that line would (the same start
    for every method), propellers in trim.
    """
    w = plan["waypoints"][0]
    course, speed = math.radians(w["heading_deg"]), w["speed"]
    vx, vy = speed * math.cos(course), speed * math.sin(course)
    psi, _ = DisturbancePredictor(params, env).compensate(vx, vy, course)
    c, s = math.cos(psi), math.sin(psi)
    u, v = c * vx + s * vy, -s * vx + c * vy
    vessel = Vessel(params, VesselState(w["x"], w["y"], psi, u, v))
    uc, _ = env.current_body(psi)
    trim = 0.5 * params.surge_drag(u - uc)
    vessel.set_initial_thrust(ThrustCommand(trim, trim))
    return vessel


def track_plan(plan: dict[str, Any], method: str, params: VesselParams, env: Environment,
               setup: DisturbedSetup) -> dict[str, Any]:
    """Fly one plan with one method; deviation over the plan and the arrival at x = 0."""
    traj = Trajectory.from_plan(plan)
    vessel = start_state(plan, params, env)
    loop = TrackingLoop(vessel, make_guidance(method, traj, params, env, setup),
                        Autopilot(params), setup.guidance_period, setup.control_period)
    every = round(setup.guidance_period / setup.control_period)
    devs: list[float] = []
    crossing: tuple[float, float, float] | None = None
    state, k = vessel.state, 0
    while state.t <= traj.end_time + setup.timeout:
        if k % every == 0 and state.t <= traj.end_time + 1e-9:
            dx, dy = traj.position_at(state.t)
            devs.append(math.hypot(state.x - dx, state.y - dy))
        new = loop.step(env)
        k += 1
        if state.x > 0.0 >= new.x:
            w = state.x / (state.x - new.x)
            dpsi = math.remainder(new.psi - state.psi, 2 * math.pi)
            crossing = (state.y + w * (new.y - state.y), state.psi + w * dpsi,
                        state.t + w * (new.t - state.t))
            break
        state = new
    result: dict[str, Any] = {
        "mean_dev_m": round(float(np.mean(devs)), 4),
        "max_dev_m": round(float(np.max(devs)), 4),
        "arrival_offset_m": None,
        "arrival_heading_err_deg": None,
        "arrival_delay_s": None,
    }
    if crossing is not None:
        y, psi, t = crossing
        result["arrival_offset_m"] = round(y, 4)
        result["arrival_heading_err_deg"] = round(
            math.degrees(math.remainder(psi - math.pi, 2 * math.pi)), 3)
        result["arrival_delay_s"] = round(t - traj.end_time, 3)
    return result


SPEED_HEADROOM = 0.8  # plan at most this share of the simulated boat's calm-water top speed


def scenario_for_vessel(scenario: Any, params: VesselParams,
                        headroom: float = SPEED_HEADROOM) -> Any:
    """The scenario with its vessel limits replaced by those of the boat that will sail it.

    A plan must be sailable by the boat that executes it: hull length from
    the model, top planned speed `headroom` times its calm-water top speed
    (rounded down to 0.1 m/s) so that it can still catch up in current and
    waves; the other limits stay the scenario's.
    """
    from usvstation.scenario import parse_scenario

    data = scenario.model_dump()
    speed_max = math.floor(10.0 * headroom * params.top_speed) / 10.0
    data["vessel"].update(length=params.length,
                          speed_max=max(speed_max, data["vessel"]["speed_min"] + 0.2))
    return parse_scenario(data)


def disturbed(setup: DisturbedSetup | None = None, scenarios: tuple[str, ...] = PUBLIC_SCENARIOS,
              methods: tuple[str, ...] = METHODS, params: VesselParams | None = None,
              progress: Callable[[str], None] | None = None) -> list[dict[str, Any]]:
    """One row per (scenario, method): {scenario, method, mean_dev_m, max_dev_m, arrival_*}."""
    from usvstation.planning.plan import plan_scenario
    from usvstation.scenario import load_scenario

    s = setup or DisturbedSetup()
    vessel = params or otter()
    env = s.environment()
    rows = []
    for name in scenarios:
        plan = plan_scenario(scenario_for_vessel(load_scenario(name), vessel), seed=s.seed)
        for method in methods:
            if progress:
                progress(f"tracking {name} with {method}")
            rows.append({"scenario": name, "method": method,
                         **track_plan(plan, method, vessel, env, s)})
    return rows


def run_tracking_bench(progress: Callable[[str], None] | None = None) -> dict[str, Any]:
    """Everything `usv-station bench tracking` prints."""
    t0 = time.perf_counter()
    if progress:
        progress("paper 000 sec. 4.2 reproduction (kinematic boat)")
    paper = paper_reproduction()
    t1 = time.perf_counter()
    setup = DisturbedSetup()
    rows = disturbed(setup, progress=progress)
    quartering = DisturbedSetup(wave_dir=QUARTERING_WAVE_DIR)
    rows_quartering = disturbed(quartering, progress=progress)
    t2 = time.perf_counter()
    waves = setup.environment().waves
    assert waves is not None
    vessel = otter()
    return {
        "paper_reproduction": paper,
        "disturbed": rows,
        "disturbed_quartering_seas": rows_quartering,
        "disturbed_conditions": {
            "vessel": vessel.name,
            "vessel_top_speed_mps": round(vessel.top_speed, 3),
            "plan_vessel": {
                "length_m": vessel.length,
                "speed_max_mps": math.floor(10.0 * SPEED_HEADROOM * vessel.top_speed) / 10.0,
                "note": "public scenarios planned with the simulated boat's own limits",
            },
            "current_speed_mps": setup.current_speed,
            "current_dir_deg": round(math.degrees(setup.current_dir), 1),
            "sea_state": setup.sea_state,
            "wave_height_m": round(waves.height, 3),
            "wave_period_s": round(waves.period, 3),
            "wavelength_m": round(waves.wavelength, 3),
            "wave_dir_deg": round(math.degrees(setup.wave_dir), 1),
            "quartering_wave_dir_deg": round(math.degrees(quartering.wave_dir), 1),
            "lookahead_m": setup.lookahead,
            "guidance_period_s": setup.guidance_period,
            "control_period_s": setup.control_period,
            "plan_seed": setup.seed,
        },
        "elapsed_s": {"paper_reproduction": round(t1 - t0, 3), "disturbed": round(t2 - t1, 3)},
        "machine": {"python": platform.python_version(), "platform": platform.platform()},
    }
