"""A closed tracking loop: sensors -> observer -> guidance -> autopilot -> vessel (pure, no I/O).

Sans-IO: the caller owns time and I/O (the simulated boat of the link, the
tracking benchmark, tests). Guidance and autopilot see only a
`guidance.Measurement` of the vessel (GNSS position, COG/SOG, heading, yaw
rate), never the simulator's state or environment; an optional
`DriftObserver` is updated every control period with that measurement and
the thrust the autopilot commanded. Guidance runs every `guidance_period`
(0.2 s, the paper's control period), the autopilot and the vessel model
every `control_period` (at most 0.05 s).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

from usvstation.control.autopilot import Autopilot
from usvstation.dynamics.environment import Environment
from usvstation.dynamics.vessel import ThrustCommand, Vessel, VesselState
from usvstation.guidance.los import GuidanceCommand, Pose
from usvstation.guidance.observer import DriftObserver, Measurement


class Guidance(Protocol):
    def update(self, pose: Pose, t: float) -> GuidanceCommand: ...


class TrackingLoop:
    """Drives a Vessel along a guidance law with an Autopilot, through its sensors only.

    `sensors(state) -> Measurement` adds sensor errors (default: exact
    GNSS/compass/gyro readings of the state).
    """

    def __init__(self, vessel: Vessel, guidance: Guidance, autopilot: Autopilot,
                 guidance_period: float = 0.2, control_period: float = 0.05,
                 observer: DriftObserver | None = None,
                 sensors: Callable[[VesselState], Measurement] | None = None) -> None:
        if not 0.0 < control_period <= guidance_period:
            raise ValueError("loop: need 0 < control_period <= guidance_period")
        self.vessel = vessel
        self.guidance = guidance
        self.autopilot = autopilot
        self.observer = observer
        self.sensors = sensors or Measurement.of
        self.guidance_period = guidance_period
        self.control_period = control_period
        self.command: GuidanceCommand | None = None
        self.thrust = ThrustCommand(*vessel.thrust)
        self.measurement = self.sensors(vessel.state)
        if observer is not None:
            observer.start(self.measurement, vessel.thrust)
        self._next_guidance = vessel.state.t

    @property
    def state(self) -> VesselState:
        return self.vessel.state

    def step(self, env: Environment) -> VesselState:
        """Advance one control period; returns the new vessel state."""
        meas = self.sensors(self.vessel.state)
        self.measurement = meas
        if self.observer is not None:
            self.observer.update(meas, (self.thrust.left, self.thrust.right),
                                 self.control_period)
        if self.command is None or meas.t >= self._next_guidance - 1e-9:
            self.command = self.guidance.update(meas, meas.t)
            self._next_guidance += self.guidance_period
        self.thrust = self.autopilot.update(self.command, meas, self.control_period)
        return self.vessel.step(self.thrust, env, self.control_period)
