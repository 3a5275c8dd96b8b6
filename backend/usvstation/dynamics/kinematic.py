"""The kinematic boat of paper 000 sec. 4.2: heading follows the command, speed ramps linearly.

At the start of each control period the boat takes the commanded heading at
once ("the hysteresis effect in heading control is disregarded") and its speed
moves linearly towards the commanded speed, at most `accel_max` m/s^2.
"""

from __future__ import annotations

import math

from usvstation.dynamics.vessel import VesselState


class KinematicBoat:
    """Point boat for the AV-LOS vs LOS reproduction (paper 000 sec. 4.2)."""

    def __init__(self, x: float, y: float, psi: float = 0.0, speed: float = 0.0,
                 accel_max: float = 2.0, t: float = 0.0) -> None:
        if not accel_max > 0.0:
            raise ValueError(f"accel_max must be > 0 (got {accel_max})")
        self.x, self.y, self.psi, self.speed = x, y, psi, speed
        self.accel_max = accel_max
        self.t = t

    @property
    def state(self) -> VesselState:
        return VesselState(self.x, self.y, self.psi, self.speed, 0.0, 0.0, self.t)

    def step(self, heading: float, speed: float, dt: float) -> VesselState:
        """Hold `heading` and ramp towards `speed` (>= 0) for one period of dt seconds."""
        if not dt > 0.0:
            raise ValueError(f"step: dt must be > 0 (got {dt})")
        target = max(speed, 0.0)
        change = max(-self.accel_max * dt, min(self.accel_max * dt, target - self.speed))
        new_speed = self.speed + change
        distance = 0.5 * (self.speed + new_speed) * dt
        self.psi = heading
        self.x += distance * math.cos(heading)
        self.y += distance * math.sin(heading)
        self.speed = new_speed
        self.t += dt
        return self.state
