"""A closed tracking loop: guidance -> autopilot -> vessel, advanced one control step at a time.

Sans-IO: the caller owns time and I/O (the simulated boat of the link, the
tracking benchmark, tests). Guidance runs every `guidance_period` (0.2 s, the
paper's control period), the autopilot and the vessel model every
`control_period` (at most 0.05 s).
"""

from __future__ import annotations

from typing import Protocol

from usvstation.control.autopilot import Autopilot
from usvstation.dynamics.environment import Environment
from usvstation.dynamics.vessel import ThrustCommand, Vessel, VesselState
from usvstation.guidance.los import GuidanceCommand, Pose


class Guidance(Protocol):
    def update(self, pose: Pose, t: float) -> GuidanceCommand: ...


class TrackingLoop:
    """Drives a Vessel along a guidance law with an Autopilot."""

    def __init__(self, vessel: Vessel, guidance: Guidance, autopilot: Autopilot,
                 guidance_period: float = 0.2, control_period: float = 0.05) -> None:
        if not 0.0 < control_period <= guidance_period:
            raise ValueError("loop: need 0 < control_period <= guidance_period")
        self.vessel = vessel
        self.guidance = guidance
        self.autopilot = autopilot
        self.guidance_period = guidance_period
        self.control_period = control_period
        self.command: GuidanceCommand | None = None
        self.thrust = ThrustCommand(0.0, 0.0)
        self._next_guidance = vessel.state.t

    @property
    def state(self) -> VesselState:
        return self.vessel.state

    def step(self, env: Environment) -> VesselState:
        """Advance one control period; returns the new vessel state."""
        state = self.vessel.state
        if self.command is None or state.t >= self._next_guidance - 1e-9:
            self.command = self.guidance.update(state, state.t)
            self._next_guidance += self.guidance_period
        self.thrust = self.autopilot.update(self.command, state, self.control_period)
        return self.vessel.step(self.thrust, env, self.control_period)
