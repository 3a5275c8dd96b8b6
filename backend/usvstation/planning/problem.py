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

from usvstation.planning.xyt import ObstacleField, inflate_radius
from usvstation.scenario import Scenario


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

    @classmethod
    def from_scenario(cls, scenario: Scenario, margin: float | None = None) -> Problem:
        """The scenario in the planning frame; obstacles inflated by eq. 7.

        `margin` replaces eq. 7's D_USV + R_c (the clearance fallback of
        plan_scenario); None keeps the full margin.
        """
        sx, sy = scenario.start.x, scenario.start.y
        gx, gy = scenario.goal.x, scenario.goal.y
        recovery = scenario.kind == "recovery"
        theta = 0.0 if recovery else math.atan2(sy - gy, sx - gx)
        offset = (gx, gy)
        obs = scenario.obstacles
        centre = np.array([[o.x, o.y] for o in obs], dtype=float).reshape(-1, 2)
        velocity = np.array([[o.vx, o.vy] for o in obs], dtype=float).reshape(-1, 2)
        radius = np.array([o.radius for o in obs], dtype=float)
        v = scenario.vessel
        inflated = (
            inflate_radius(radius, v.length, v.compensation_radius)
            if margin is None else radius + margin
        )
        rot = _rotation(-theta)
        field = ObstacleField(
            centre=(centre - np.array(offset)) @ rot.T,
            velocity=velocity @ rot.T,
            radius=radius,
            inflated=inflated,
        )
        start = (np.array([sx, sy]) - np.array(offset)) @ rot.T
        return cls(
            recovery=recovery,
            start=start,
            start_speed=float(np.clip(scenario.start.speed, v.speed_min, v.speed_max)),
            goal=np.zeros(2),
            obstacles=field,
            speed_min=v.speed_min,
            speed_max=v.speed_max,
            accel_max=v.accel_max,
            turn_max=math.radians(v.turn_max_deg),
            hull_length=v.length,
            theta=theta,
            offset=offset,
        )

    def to_scenario_frame(self, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Planning-frame points to the scenario (ramp) frame."""
        c, s = math.cos(self.theta), math.sin(self.theta)
        return c * x - s * y + self.offset[0], s * x + c * y + self.offset[1]

    @property
    def distance(self) -> float:
        """Straight-line distance from start to goal, m."""
        return float(np.hypot(*(self.start - self.goal)))


def _rotation(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s], [s, c]])
