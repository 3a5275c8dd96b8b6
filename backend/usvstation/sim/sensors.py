"""Sensor models of the simulated boat: GPS position noise and a battery. Seeded, no I/O."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np


@dataclass
class GpsNoise:
    """GPS position error: a first-order Gauss-Markov bias (slow wander, std `bias_std_m`,
    correlation time `tau_s`) plus white noise (`white_std_m`) per fix, in metres."""

    bias_std_m: float = 0.8
    tau_s: float = 60.0
    white_std_m: float = 0.4
    fix_type: int = 3
    satellites: int = 12
    hdop: float = 0.9
    seed: int = 0
    _rng: np.random.Generator = field(init=False, repr=False)
    _bias: np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self._rng = np.random.default_rng(self.seed)
        self._bias = self._rng.normal(0.0, self.bias_std_m, 2)

    def sample(self, dt: float) -> tuple[float, float]:
        """The position error (dx, dy) of a fix taken dt seconds after the previous one."""
        if self.tau_s > 0 and dt > 0:
            a = math.exp(-dt / self.tau_s)
            self._bias = a * self._bias + self._rng.normal(
                0.0, self.bias_std_m * math.sqrt(1 - a * a), 2)
        w = self._rng.normal(0.0, self.white_std_m, 2)
        return float(self._bias[0] + w[0]), float(self._bias[1] + w[1])


@dataclass
class Battery:
    """A 4S lithium pack: voltage falls linearly with the charge drawn by the thrusters."""

    full_v: float = 16.8
    empty_v: float = 13.2
    capacity_ah: float = 20.0
    idle_a: float = 0.5
    full_thrust_a: float = 30.0  # both thrusters at full
    used_ah: float = 0.0

    def step(self, dt: float, thrust_left: float, thrust_right: float) -> None:
        amps = self.idle_a + self.full_thrust_a * (abs(thrust_left) + abs(thrust_right)) / 2
        self.used_ah = min(self.capacity_ah, self.used_ah + amps * dt / 3600)

    @property
    def voltage(self) -> float:
        return self.full_v - (self.full_v - self.empty_v) * self.used_ah / self.capacity_ah


@dataclass
class NavSensors:
    """The boat's own navigation sensors as guidance sees them: white errors on the GNSS
    fix (`position_std_m` per axis), the GNSS velocity (`velocity_std_mps` per axis, so
    COG/SOG are noisy too) and the compass (`heading_std_rad`); the gyro is exact.
    Call it with a dynamics.VesselState to get a guidance.Measurement. Seeded, no I/O."""

    position_std_m: float = 0.05  # RTK-class fix
    velocity_std_mps: float = 0.05
    heading_std_rad: float = math.radians(0.5)
    seed: int = 0
    _rng: np.random.Generator = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self._rng = np.random.default_rng(self.seed)

    def __call__(self, state):
        from usvstation.guidance.observer import Measurement

        ex, ey = self._rng.normal(0.0, self.position_std_m, 2)
        nvx, nvy = self._rng.normal(0.0, self.velocity_std_mps, 2)
        vx, vy = state.velocity
        vx, vy = vx + nvx, vy + nvy
        sog = math.hypot(vx, vy)
        cog = math.atan2(vy, vx) if sog > 1e-9 else state.psi
        psi = state.psi + float(self._rng.normal(0.0, self.heading_std_rad))
        return Measurement(state.x + ex, state.y + ey, psi, sog, cog, state.r, state.t)
