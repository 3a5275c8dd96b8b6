"""A scenario in the planner's frame, as NumPy arrays.

Recoveries plan in the ramp frame itself (goal at the ramp end, x out to
sea). Transits plan in a frame whose origin is the goal and whose +x axis
runs from the goal to the start, so the same x-stepped encoding (eq. 10-11)
applies; waypoints are rotated back to the scenario frame afterwards.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from usvstation.geometry import inflated_radius
from usvstation.planning.hull import keepout_circles
from usvstation.planning.xyt import ObstacleField
from usvstation.scenario import Scenario


@dataclass(frozen=True)
class StartState:
    """Where a plan (or a leg of it) starts, in the scenario frame: position, hull heading,
    speed, and the time since the scenario's t = 0 (obstacles are propagated to it)."""

    x: float
    y: float
    heading: float  # rad, hull heading, counter-clockwise from +x
    speed: float  # m/s over ground: the plan's first waypoint speed
    t: float = 0.0
    bound: bool = False  # True: the first leg must stay within turn_max of `heading`
    course: float | None = None  # rad, course over ground (default: the heading)


@dataclass(frozen=True)
class Problem:
    """Start, goal, obstacles and vessel limits in the planning frame (SI, radians)."""

    recovery: bool
    start: np.ndarray  # (2,)
    start_speed: float
    goal: np.ndarray  # (2,)
    obstacles: ObstacleField
    speed_min: float
    speed_max: float
    accel_max: float
    turn_max: float  # rad
    hull_length: float
    # planning frame -> scenario frame: p_scn = R(theta) p + offset
    theta: float = 0.0
    offset: tuple[float, float] = (0.0, 0.0)
    start_heading: float | None = None  # planning-frame hull heading the first leg must respect
    current: tuple[float, float] = (0.0, 0.0)  # planning-frame current, m/s
    start_course: float | None = None  # planning-frame course over ground at the start

    @classmethod
    def from_scenario(
        cls, scenario: Scenario, margin: float | None = None, state: StartState | None = None,
        time_margin_s: float | None = None,
    ) -> Problem:
        """The scenario in the planning frame; obstacles inflated by eq. 7.

        `margin` replaces eq. 7's D_USV + R_c (the clearance fallback of
        plan_scenario); None keeps the full margin. `state` starts the plan
        elsewhere than the scenario's start (a leg, or a boat under way);
        obstacles are then propagated to its time. Moving obstacles are swept
        over +-`time_margin_s` (default: the vessel's time_margin_s) as a chain
        of circles whose union covers the swept capsule.
        """
        v = scenario.vessel
        if state is None:
            state = StartState(scenario.start.x, scenario.start.y,
                               math.radians(scenario.start.heading_deg), scenario.start.speed)
        sx, sy = state.x, state.y
        gx, gy = scenario.goal.x, scenario.goal.y
        recovery = scenario.kind == "recovery"
        theta = 0.0 if recovery else math.atan2(sy - gy, sx - gx)
        offset = (gx, gy)
        obs = scenario.obstacles
        centre = np.array([[o.x + o.vx * state.t, o.y + o.vy * state.t] for o in obs],
                          dtype=float).reshape(-1, 2)
        velocity = np.array([[o.vx, o.vy] for o in obs], dtype=float).reshape(-1, 2)
        radius = np.array([o.radius for o in obs], dtype=float)
        inflated = (
            inflated_radius(radius, v.length, v.compensation_radius)
            if margin is None else radius + margin
        )
        tm = v.time_margin_s if time_margin_s is None else time_margin_s
        centre, velocity, radius, inflated, source = sweep_moving(
            centre, velocity, radius, inflated, tm
        )
        full = inflated_radius(0.0, v.length, v.compensation_radius)
        ship_c, ship_r = keepout_circles(scenario, full if margin is None else margin)
        if ship_r.size:  # the mother ship's hull: static circles, source -1 (planning/hull.py)
            centre = np.vstack([centre, ship_c])
            velocity = np.vstack([velocity, np.zeros_like(ship_c)])
            radius = np.concatenate([radius, np.zeros_like(ship_r)])
            inflated = np.concatenate([inflated, ship_r])
            source = np.concatenate([source, np.full(ship_r.size, -1)])
        rot = _rotation(-theta)
        field = ObstacleField(
            centre=(centre - np.array(offset)) @ rot.T,
            velocity=velocity @ rot.T,
            radius=radius,
            inflated=inflated,
            source=source,
        )
        start = (np.array([sx, sy]) - np.array(offset)) @ rot.T
        env = scenario.environment
        ca = math.radians(env.current_dir_deg) - theta
        current = (env.current_speed * math.cos(ca), env.current_speed * math.sin(ca))
        return cls(
            recovery=recovery,
            start=start,
            start_speed=float(np.clip(state.speed, v.speed_min, v.speed_max)),
            goal=np.zeros(2),
            obstacles=field,
            speed_min=v.speed_min,
            speed_max=v.speed_max,
            accel_max=v.accel_max,
            turn_max=math.radians(v.turn_max_deg),
            hull_length=v.length,
            theta=theta,
            offset=offset,
            start_heading=(state.heading - theta) if state.bound else None,
            start_course=(
                (state.heading if state.course is None else state.course) - theta
                if state.bound else None
            ),
            current=current,
        )

    def to_scenario_frame(self, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Planning-frame points to the scenario (ramp) frame."""
        c, s = math.cos(self.theta), math.sin(self.theta)
        return c * x - s * y + self.offset[0], s * x + c * y + self.offset[1]

    @property
    def distance(self) -> float:
        """Straight-line distance from start to goal, m."""
        return float(np.hypot(*(self.start - self.goal)))


def sweep_moving(
    centre: np.ndarray, velocity: np.ndarray, radius: np.ndarray, inflated: np.ndarray,
    margin_s: float,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Replace each moving circle by circles at shifts d in [-margin_s, margin_s] (issue 12).

    The circles sit s = R_l / 2 apart along the track, each of radius
    sqrt(R_l^2 + (s / 2)^2), so their union covers the capsule swept by the
    circle of radius R_l (the worst point lies midway between two centres).
    An obstacle that moves less than R_l / 2 in margin_s stays a single
    circle of radius R_l + |v| margin_s, which covers the capsule too.
    Returns (centre, velocity, radius, inflated, source index).
    """
    n = radius.shape[0]
    source = np.arange(n)
    speed = np.hypot(velocity[:, 0], velocity[:, 1]) if n else np.zeros(0)
    moving = speed > 0.0
    if margin_s <= 0.0 or not moving.any():
        return centre, velocity, radius, inflated, source
    sweep = margin_s * speed
    # a slow drifter (sweep within half its radius) stays one circle, grown by the sweep
    single = moving & (sweep <= 0.5 * inflated)
    inflated = np.where(single, inflated + sweep, inflated)
    copies = sweep_copies(speed, inflated, margin_s)
    src = np.repeat(source, copies)
    first = np.repeat(np.cumsum(copies) - copies, copies)
    k = np.arange(src.shape[0]) - first
    cnt = copies[src]
    shift = np.where(cnt > 1, -margin_s + 2.0 * margin_s * k / np.maximum(cnt - 1, 1), 0.0)
    gap = np.where(cnt > 1, 2.0 * margin_s * speed[src] / np.maximum(cnt - 1, 1), 0.0)
    infl = np.sqrt(inflated[src] ** 2 + (gap / 2.0) ** 2)
    new_centre = centre[src] + velocity[src] * shift[:, None]
    return new_centre, velocity[src], radius[src], infl, src


def sweep_copies(speed: np.ndarray, inflated: np.ndarray, margin_s: float) -> np.ndarray:
    """Circles `sweep_moving` puts in place of each obstacle (1 for a static one or a slow
    drifter, whose radius then already includes the sweep)."""
    sweep = margin_s * speed
    chain = (speed > 0.0) & (sweep > 0.5 * inflated) & (margin_s > 0.0)
    return np.where(chain, np.ceil(2.0 * sweep / np.where(chain, inflated / 2.0, 1.0)), 0.0
                    ).astype(np.int64) + 1


def _rotation(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s], [s, c]])
