"""PID controller with output saturation and anti-windup (conditional integration)."""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass
class PID:
    """u = ff + kp e + ki integral(e) + kd de/dt, clamped to [out_min, out_max].

    The integrator stops while the output is saturated and the error pushes
    further into saturation (conditional integration), and while |error|
    exceeds `integral_zone` (large set-point steps are the proportional
    term's job), so it never winds up.
    Pass `rate` (de/dt measured directly, e.g. minus the yaw rate) to avoid
    differentiating a stepping set-point.
    """

    kp: float
    ki: float = 0.0
    kd: float = 0.0
    out_min: float = -math.inf
    out_max: float = math.inf
    integral_zone: float = math.inf
    integral: float = 0.0
    _prev_error: float | None = None

    def __post_init__(self) -> None:
        if min(self.kp, self.ki, self.kd) < 0.0:
            raise ValueError("PID: gains must be >= 0")
        if not self.out_min < self.out_max:
            raise ValueError(f"PID: out_min must be below out_max ({self.out_min}, {self.out_max})")

    def reset(self) -> None:
        self.integral = 0.0
        self._prev_error = None

    def update(self, error: float, dt: float, rate: float | None = None,
               feedforward: float = 0.0) -> float:
        """One control step of dt seconds; returns the saturated output."""
        if not dt > 0.0:
            raise ValueError(f"PID: dt must be > 0 (got {dt})")
        if rate is None:
            rate = 0.0 if self._prev_error is None else (error - self._prev_error) / dt
        self._prev_error = error
        raw = feedforward + self.kp * error + self.ki * self.integral + self.kd * rate
        out = min(max(raw, self.out_min), self.out_max)
        winding_up = (raw > self.out_max and error > 0.0) or (raw < self.out_min and error < 0.0)
        if not winding_up and abs(error) <= self.integral_zone:
            self.integral += error * dt
        return out

    def back_off(self, achieved: float, commanded: float) -> None:
        """Tell the controller a downstream limit cut its output (tracking anti-windup).

        Removes from the integrator the part of the last step's integration
        that pushed against the limit.
        """
        if self.ki > 0.0 and achieved != commanded:
            excess = (commanded - achieved) / self.ki
            if excess * self.integral > 0.0:
                self.integral -= math.copysign(min(abs(excess), abs(self.integral)), excess)
