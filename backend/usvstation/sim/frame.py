"""The moving ramp frame as the simulated boat knows it (pure).

The boat's physics runs in an earth-fixed plane (the vehicle's world frame: the ramp frame
of the scenario origin, where the ramp lies at the sea's t = 0); its mission's waypoints
are points of the ship-fixed ramp frame. `RampMotion` is the ramp frame's pose in that
plane at time t0 (origin, angle of its +x, velocity of its origin, yaw rate), extrapolated
to any instant at constant velocity and yaw rate (the velocity turns with the ship), and
maps a navigation fix into the ramp frame and back:

    p_r = R(-theta) (p - o),   v_r = R(-theta) (v - v_o - omega x (p - o)),
    psi_r = psi - theta,       r_r = r - omega.

The identity motion (all zero) is the paper's shore trial: the ramp frame is the world frame.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from usvstation.guidance.observer import Measurement


@dataclass(frozen=True)
class RampMotion:
    """The ramp frame's origin (x, y), the angle of its +x (rad, anticlockwise), the
    origin's velocity (vx, vy) and the yaw rate omega (rad/s, anticlockwise), all in the
    world frame at time t0 (s of the vehicle's clock)."""

    x: float = 0.0
    y: float = 0.0
    theta: float = 0.0
    vx: float = 0.0
    vy: float = 0.0
    omega: float = 0.0
    t0: float = 0.0

    @property
    def moving(self) -> bool:
        return self.vx != 0.0 or self.vy != 0.0 or self.omega != 0.0

    def at(self, t: float) -> RampMotion:
        """Extrapolated to t: the origin moves at its velocity turned by the yaw rate."""
        dt = t - self.t0
        if dt == 0.0:
            return self
        turn = self.omega * dt
        if abs(turn) < 1e-12:  # straight (also a yaw rate so small its turn underflows)
            return replace(self, x=self.x + self.vx * dt, y=self.y + self.vy * dt,
                           theta=self.theta + turn, t0=t)
        c, s = math.cos(turn / 2), math.sin(turn / 2)
        # the chord of a constant-rate turn: along the mid-turn velocity, |v| 2 sin(a/2)/omega
        chord = 2.0 * math.sin(turn / 2) / self.omega
        dx = chord * (c * self.vx - s * self.vy)
        dy = chord * (s * self.vx + c * self.vy)
        c2, s2 = math.cos(turn), math.sin(turn)
        return RampMotion(self.x + dx, self.y + dy, self.theta + turn,
                          c2 * self.vx - s2 * self.vy, s2 * self.vx + c2 * self.vy,
                          self.omega, t)

    def frozen(self, t: float) -> RampMotion:
        """The pose at t, held still from then on (an earth-fixed frame)."""
        m = self.at(t)
        return replace(m, vx=0.0, vy=0.0, omega=0.0)

    def to_ramp(self, x: float, y: float) -> tuple[float, float]:
        """A world point in the ramp frame (at this motion's t0)."""
        c, s = math.cos(self.theta), math.sin(self.theta)
        dx, dy = x - self.x, y - self.y
        return c * dx + s * dy, -s * dx + c * dy

    def to_world(self, x: float, y: float) -> tuple[float, float]:
        """A ramp-frame point in the world frame (at this motion's t0)."""
        c, s = math.cos(self.theta), math.sin(self.theta)
        return self.x + c * x - s * y, self.y + s * x + c * y

    def point_velocity(self, x: float, y: float) -> tuple[float, float]:
        """World velocity of the ramp-fixed point that is at world (x, y) now."""
        return self.vx - self.omega * (y - self.y), self.vy + self.omega * (x - self.x)

    @property
    def identity(self) -> bool:
        return self.x == 0.0 and self.y == 0.0 and self.theta == 0.0 and not self.moving

    def measure(self, m: Measurement) -> Measurement:
        """A world-frame fix as seen in the ramp frame (this motion as it is, at its t0:
        extrapolate it with `at` first)."""
        f = self
        if f.identity:
            return m
        x, y = f.to_ramp(m.x, m.y)
        vx, vy = m.velocity
        px, py = f.point_velocity(m.x, m.y)
        c, s = math.cos(f.theta), math.sin(f.theta)
        rx, ry = vx - px, vy - py
        ux, uy = c * rx + s * ry, -s * rx + c * ry
        sog = math.hypot(ux, uy)
        psi = m.psi - f.theta
        return Measurement(x, y, psi, sog, math.atan2(uy, ux) if sog > 1e-9 else psi,
                           m.r - f.omega, m.t)

    def unmeasure(self, m: Measurement) -> Measurement:
        """A ramp-frame fix in the world frame: the inverse of `measure`."""
        f = self
        if f.identity:
            return m
        x, y = f.to_world(m.x, m.y)
        ux, uy = m.velocity
        c, s = math.cos(f.theta), math.sin(f.theta)
        px, py = f.point_velocity(x, y)
        vx, vy = c * ux - s * uy + px, s * ux + c * uy + py
        sog = math.hypot(vx, vy)
        psi = m.psi + f.theta
        return Measurement(x, y, psi, sog, math.atan2(vy, vx) if sog > 1e-9 else psi,
                           m.r + f.omega, m.t)
