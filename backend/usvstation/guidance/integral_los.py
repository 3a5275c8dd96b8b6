"""Integral LOS and adaptive LOS: heading laws that learn the crab on their own (pure, no I/O).

Both follow the current leg (the look-ahead tracker's segment) with its
path angle pi_p and the cross-track error e (positive left of the leg),
and take their speed from AV-LOS (paper 000 eq. 13, with the same
refinements when `accel` is given), so only the heading law differs from
AVLOSGuidance:

- ILOS (Fossen and Lekkas 2017, "Direct and indirect adaptive integral
  line-of-sight path-following controllers for marine craft exposed to
  ocean currents", eq. for the integral state with its anti-windup):
      psi_d = pi_p - atan(Kp e + Ki y_int),
      y_int' = Delta e / ((e + kappa y_int)^2 + Delta^2),  Kp = 1/Delta.
- ALOS (Fossen 2023, "An adaptive line-of-sight (ALOS) guidance law for
  path following of aircraft and marine craft", IEEE TCST):
      psi_d = pi_p - beta_hat - atan(e / Delta),
      beta_hat' = gamma Delta / sqrt(Delta^2 + e^2) e.

The integral state and beta_hat are kept across leg switches (the drift
does not change with the leg). `crab_estimate` is the heading offset each
has learnt (rad, heading minus course), reported by `bench tracking`.
"""

from __future__ import annotations

import math

from usvstation.geometry import cross_track_error, wrap_angle
from usvstation.guidance.los import AVLOSGuidance, GuidanceCommand, Pose
from usvstation.guidance.trajectory import Trajectory


class _PathAngleLaw(AVLOSGuidance):
    def __init__(self, trajectory: Trajectory, lookahead: float, speed_max: float,
                 accel: float | None, overrun: float, arrive_radius: float) -> None:
        super().__init__(trajectory, lookahead, speed_max, 0.0, accel,
                         arrive_radius=arrive_radius, overrun=overrun)
        self._last_t: float | None = None

    def _leg(self, pose: Pose) -> tuple[float, float]:
        """(path angle, cross-track error positive to the left) on the tracker's leg."""
        ax, ay, bx, by = self.trajectory.segment(self.tracker.segment)
        return (self.trajectory.segment_heading(self.tracker.segment),
                cross_track_error(pose.x, pose.y, ax, ay, bx, by))

    def _dt(self, t: float) -> float:
        dt = 0.0 if self._last_t is None else max(t - self._last_t, 0.0)
        self._last_t = t
        return dt

    def update(self, pose: Pose, t: float) -> GuidanceCommand:
        la, los_heading, speed, t_la = self.velocity(pose, t)
        if self.finished:
            return self._command(la, los_heading, speed, t_la)
        path, e = self._leg(pose)
        heading = self._heading(path, e, self._dt(t))
        return self._command(la, heading, speed, t_la)

    def _heading(self, path: float, e: float, dt: float) -> float:  # pragma: no cover
        raise NotImplementedError


class IntegralLOS(_PathAngleLaw):
    """ILOS of Fossen and Lekkas (2017) with AV-LOS speed."""

    def __init__(self, trajectory: Trajectory, lookahead: float = 8.0, speed_max: float = 3.0,
                 accel: float | None = None, overrun: float = 0.0, arrive_radius: float = 0.5,
                 ki: float | None = None, kappa: float = 2.0) -> None:
        super().__init__(trajectory, lookahead, speed_max, accel, overrun, arrive_radius)
        self.kp = 1.0 / lookahead
        self.ki = ki if ki is not None else 0.2 * self.kp
        self.kappa = kappa
        self.y_int = 0.0

    def _heading(self, path: float, e: float, dt: float) -> float:
        delta = self.lookahead
        self.y_int += dt * delta * e / ((e + self.kappa * self.y_int) ** 2 + delta * delta)
        return wrap_angle(path - math.atan(self.kp * e + self.ki * self.y_int))

    @property
    def crab_estimate(self) -> float:
        """Heading offset the integral holds on a straight leg at e = 0 (rad, heading - course)."""
        return -math.atan(self.ki * self.y_int)


class AdaptiveLOS(_PathAngleLaw):
    """ALOS of Fossen (2023) with AV-LOS speed."""

    def __init__(self, trajectory: Trajectory, lookahead: float = 8.0, speed_max: float = 3.0,
                 accel: float | None = None, overrun: float = 0.0, arrive_radius: float = 0.5,
                 gamma: float = 0.0006) -> None:
        super().__init__(trajectory, lookahead, speed_max, accel, overrun, arrive_radius)
        self.gamma = gamma
        self.beta_hat = 0.0

    def _heading(self, path: float, e: float, dt: float) -> float:
        delta = self.lookahead
        self.beta_hat += dt * self.gamma * delta / math.sqrt(delta * delta + e * e) * e
        return wrap_angle(path - self.beta_hat - math.atan(e / delta))

    @property
    def crab_estimate(self) -> float:
        """Learnt crab (rad, heading - course) = -beta_hat."""
        return -self.beta_hat
