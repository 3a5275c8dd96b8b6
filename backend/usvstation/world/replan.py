"""Re-planning on the fly (pure): when to re-plan, and the problem to re-plan.

`decide` is the policy of `--replan auto|confirm|off` for one alert: only warnings of the
kinds a new plan can cure (predicted clearance below the margin, a collision course the
plan does not clear, schedule slip beyond the time margin) start a re-plan, never while
one is being planned or awaits the operator, and not again within `cooldown_s`.
`replan_scenario` builds the new problem from the boat's predicted state a moment ahead
(`lead_s`: the time planning and the swap take) and the world's targets, in the
ship-fixed ramp frame: targets move with their velocity relative to the ramp, and the
ship's own motion enters as an apparent current (the water flows past the ramp at
-V_ship).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np

from usvstation.geometry import inflated_radius
from usvstation.scenario import MAX_COORD, Environment, Obstacle, Scenario, Start
from usvstation.world.monitor import Assessment, TargetState

Policy = Literal["auto", "confirm", "off"]
Action = Literal["none", "propose", "apply"]
REPLAN_KINDS = frozenset({"clearance", "collision_course", "slip"})


@dataclass(frozen=True)
class ReplanState:
    in_flight: bool = False  # a re-plan is being planned or swapped
    awaiting_operator: bool = False  # a proposal waits for confirm/reject
    last_t: float | None = None  # station time of the last re-plan started


def decide(policy: Policy, level: str, kind: str, state: ReplanState, t: float,
           cooldown_s: float = 10.0) -> Action:
    """What to do about one alert under `policy`."""
    if policy == "off" or level not in ("warning", "alarm") or kind not in REPLAN_KINDS:
        return "none"
    if state.in_flight or state.awaiting_operator:
        return "none"
    if state.last_t is not None and t - state.last_t < cooldown_s:
        return "none"
    return "apply" if policy == "auto" else "propose"


class ReplanImpossible(ValueError):
    """The boat's state admits no re-planning problem (one line, naming why)."""


def replan_scenario(base: Scenario, a: Assessment, targets: list[TargetState],
                    speed: float, frame_velocity: tuple[float, float] = (0.0, 0.0),
                    lead_s: float = 1.0, seed: int = 1) -> tuple[Scenario, list[str]]:
    """The re-planning problem and the ids of targets left out (those whose inflated
    circle already holds the start: no plan can keep them clear any more)."""
    path = a.path
    k = int(np.searchsorted(path[:, 2], lead_s))
    k = min(k, len(path) - 1)
    x, y = float(path[k, 0]), float(path[k, 1])
    j = min(k + 1, len(path) - 1)
    dx, dy = path[j, 0] - path[max(j - 1, 0), 0], path[j, 1] - path[max(j - 1, 0), 1]
    heading = math.degrees(math.atan2(dy, dx)) if math.hypot(dx, dy) > 1e-6 else 180.0
    if base.kind == "recovery" and x <= 0.0:
        raise ReplanImpossible(f"start.x: the boat is at the ramp (x = {x:.1f} m)")
    lead = path[k, 2]
    vessel = base.vessel
    obstacles, dropped = [], []
    for t in targets:
        ox, oy = t.x + t.vx * lead, t.y + t.vy * lead
        if max(abs(ox), abs(oy)) > MAX_COORD:
            dropped.append(t.id)  # beyond the scenario's 20 km range
            continue
        r_l = inflated_radius(t.radius, vessel.length, vessel.compensation_radius)
        if math.hypot(x - ox, y - oy) < r_l or math.hypot(ox, oy) < r_l:
            dropped.append(t.id)
            continue
        obstacles.append(Obstacle(x=ox, y=oy, radius=t.radius, vx=t.vx, vy=t.vy))
    environment = apparent_environment(base.environment, frame_velocity)
    planner = (base.planner.model_copy(update={"seed": seed}) if base.planner is not None
               else None)
    speed = min(max(speed, vessel.speed_min), vessel.speed_max)
    scenario = Scenario.model_validate({
        **base.model_dump(mode="python", exclude={"start", "obstacles", "environment",
                                                  "planner", "name"}),
        "name": f"{base.name} (re-plan)"[:200],
        "start": Start(x=x, y=y, heading_deg=heading, speed=speed),
        "obstacles": obstacles, "environment": environment, "planner": planner,
    }, strict=False)
    return scenario, dropped


def apparent_environment(env: Environment, frame_velocity: tuple[float, float]
                         ) -> Environment:
    """The current seen in a ramp frame moving at `frame_velocity` (ramp axes, m/s): the
    water's current (`env`'s, plus any frame velocity already folded into it) minus the
    frame's. Folding the same frame in twice is folding it in once."""
    c = math.radians(env.current_dir_deg)
    cx = env.current_speed * math.cos(c) + env.frame_vx - frame_velocity[0]
    cy = env.current_speed * math.sin(c) + env.frame_vy - frame_velocity[1]
    speed = math.hypot(cx, cy)
    return env.model_copy(update={
        "current_speed": speed, "frame_vx": frame_velocity[0], "frame_vy": frame_velocity[1],
        "current_dir_deg": math.degrees(math.atan2(cy, cx)) % 360.0 if speed > 1e-9
        else env.current_dir_deg})


def world_scenario(base: Scenario, targets: list[TargetState],
                   frame_velocity: tuple[float, float] = (0.0, 0.0)) -> tuple[Scenario,
                                                                               list[str]]:
    """`base` planned against the world as it is now: its obstacles are the world's
    targets (ramp frame, relative velocities; the `manual` ones are base's own obstacles)
    and the ship's motion is an apparent current. Targets whose inflated circle holds the
    start or the goal, and targets beyond the scenario's 20 km range, are left out and
    named."""
    vessel = base.vessel
    obstacles, dropped = [], []
    for t in targets:
        if max(abs(t.x), abs(t.y)) > MAX_COORD:
            dropped.append(t.id)  # far beyond the plan: no planning problem holds it
            continue
        r_l = inflated_radius(t.radius, vessel.length, vessel.compensation_radius)
        if math.hypot(base.start.x - t.x, base.start.y - t.y) < r_l \
                or math.hypot(base.goal.x - t.x, base.goal.y - t.y) < r_l:
            dropped.append(t.id)
            continue
        obstacles.append(Obstacle(x=t.x, y=t.y, radius=t.radius, vx=t.vx, vy=t.vy))
    return base.model_copy(update={
        "obstacles": obstacles,
        "environment": apparent_environment(base.environment, frame_velocity)}), dropped
