"""Station keeping on GNSS position with the drift observer (pure, no I/O).

A boat told to HOLD must stay where it is in a current, so "at rest" means
at rest over ground at the hold point, not a low speed over ground. The law
asks for a ground velocity back to the hold point,

    v_d = sat(k (p_hold - p), v_max),

and turns it into a heading and speed through the water with the drift
estimate. In a current (estimate above `weathervane_current`) the boat
weathervanes: its bow stays within `max_offset` (60 deg) of straight into
the current and its water speed along that heading (astern if need be) is
the projection of v_d - c, so it never swings round through a full turn
near the point. In slack water it goes for the point (`EstimatedDrift.solve`)
and, close to it, keeps its heading and stops its propellers.

`over_capacity` is true when the estimated drift needs more than
`capacity` x the top speed through the water: the boat then cannot hold
and says so (the simulated boat reports it in a STATUSTEXT).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from usvstation.geometry import angle_diff, wrap_angle
from usvstation.guidance.compensation import EstimatedDrift
from usvstation.guidance.los import GuidanceCommand, Pose, check_pose


@dataclass(frozen=True)
class StationCommand:
    """Heading (rad), surge over ground and speed through the water (m/s) for the autopilot."""

    heading: float
    speed: float
    water_speed: float | None
    idle: bool  # propellers may stop: in slack water at the point


class StationKeeper:
    """Hold a point with the drift estimate: position loop -> compensation -> autopilot."""

    def __init__(self, drift: EstimatedDrift, gain: float = 0.2, speed_max: float = 0.5,
                 idle_speed: float = 0.15, capacity: float = 0.9,
                 weathervane_current: float = 0.15,
                 max_offset: float = math.radians(60.0)) -> None:
        if not gain > 0.0 or not speed_max > 0.0:
            raise ValueError("station keeping: gain and speed_max must be > 0")
        self.drift = drift
        self.gain = gain
        self.speed_max = speed_max
        self.idle_speed = idle_speed
        self.capacity = capacity
        self.weathervane_current = weathervane_current
        self.max_offset = max_offset
        self.point: tuple[float, float] | None = None

    def hold_at(self, x: float, y: float) -> None:
        if not (math.isfinite(x) and math.isfinite(y)):
            raise ValueError(f"station keeping: hold point must be finite (got {x}, {y})")
        self.point = (x, y)

    @property
    def over_capacity(self) -> bool:
        top = self.drift.observer.params.top_speed
        return self.drift.observer.speed > self.capacity * top

    def update(self, pose: Pose, t: float) -> StationCommand:
        check_pose(pose, t)
        if self.point is None:
            self.point = (pose.x, pose.y)
        dx, dy = self.point[0] - pose.x, self.point[1] - pose.y
        dist = math.hypot(dx, dy)
        speed = min(self.gain * dist, self.speed_max)
        vx, vy = (speed * dx / dist, speed * dy / dist) if dist > 1e-9 else (0.0, 0.0)
        cx, cy = self.drift.observer.estimate
        if math.hypot(cx, cy) < self.weathervane_current:
            sol = self.drift.solve(vx, vy, pose.psi)
            if sol.water_speed < self.idle_speed and math.hypot(vx, vy) < self.idle_speed:
                return StationCommand(pose.psi, 0.0, None, True)
            return StationCommand(sol.heading, sol.surge, sol.water_speed, False)
        # Weathervane: the bow stays within `max_offset` of straight into the
        # current, and the water speed along it (astern if need be) makes the
        # best of the wanted ground velocity.
        wx, wy = vx - cx, vy - cy
        into = math.atan2(-cy, -cx)
        want = math.atan2(wy, wx)
        off = angle_diff(want, into)
        psi = wrap_angle(into + min(max(off, -self.max_offset), self.max_offset))
        c, s = math.cos(psi), math.sin(psi)
        water = wx * c + wy * s
        surge = water + cx * c + cy * s
        return StationCommand(psi, surge, water, False)

    def command(self, pose: Pose, t: float) -> GuidanceCommand:
        """The same as a GuidanceCommand (for a TrackingLoop); `finished` is never set."""
        c = self.update(pose, t)
        point = self.point or (pose.x, pose.y)
        return GuidanceCommand(c.heading, c.speed, point, t, 0, False, c.water_speed)
