"""What a boat knows about itself, and an online current / crab observer (pure, no I/O).

Guidance and control see a `Measurement` only: GNSS position, course and
speed over ground, heading (compass) and yaw rate (gyro), plus the thrust
they commanded themselves. The simulator's environment is hidden from them.

`DriftObserver` estimates the drift velocity: the earth-frame velocity the
boat makes good beyond its own water velocity along its heading (the
current, plus the steady slip wind and waves push the hull to). It runs a
nominal model of the boat's own propellers (first-order shaft lag of the
commanded thrust) and surge (m11 u_r' = T - d(u_r), the hull's calm-water
drag) to know its speed through the water u_r, and low-passes the residual

    c_raw = v_ground - u_r (cos psi, sin psi),    c' = (c_raw - c) / T_c.

Sway through the water is taken as zero: steady crab is what the
compensation must undo anyway, so it belongs in the estimate; the
transient sway of a turn is filtered by T_c (10 s by default) and the
update is weighted by exp(-(r_p / r_0 min(SOG / 1.5 m/s, 1))^2) (r_0 =
3 deg/s, r_p the yaw rate peak-held with a 3 s decay, as the slip outlasts
the turn), so the estimate holds through a turn at speed instead of
learning its slip, and keeps learning at station-keeping speeds. The
estimate is only as good as the nominal surge model; the simulator uses
the same hull as the observer, so the figures of `bench tracking` carry no
model mismatch (docs/tracking.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from usvstation.dynamics.params import VesselParams
from usvstation.geometry import Pose, require_finite

TURN_MEMORY = 3.0  # s, decay of the peak-held yaw rate that gates the update
SLIP_SPEED = 1.5  # m/s, speed over ground from which a turn's slip gates fully


@dataclass(frozen=True)
class Measurement(Pose):
    """One navigation fix: what a boat's sensors give (SI units, ramp frame).

    x, y GNSS position (m); sog speed over ground (m/s); cog course over
    ground (rad); psi heading (rad); r yaw rate (rad/s); t (s).
    """

    sog: float = 0.0
    cog: float = 0.0
    r: float = 0.0
    t: float = 0.0

    def __post_init__(self) -> None:
        require_finite(self, "measurement")

    @classmethod
    def of(cls, state, dx: float = 0.0, dy: float = 0.0, dpsi: float = 0.0) -> Measurement:
        """From a simulator state (dynamics.VesselState), with optional sensor errors."""
        vx, vy = state.velocity
        sog = math.hypot(vx, vy)
        cog = math.atan2(vy, vx) if sog > 1e-9 else state.psi
        return cls(state.x + dx, state.y + dy, state.psi + dpsi, sog, cog, state.r, state.t)

    @property
    def velocity(self) -> tuple[float, float]:
        """Velocity over ground (m/s, ramp frame)."""
        return self.sog * math.cos(self.cog), self.sog * math.sin(self.cog)

    @property
    def u(self) -> float:
        """Surge speed over ground (m/s): the ground velocity along the heading."""
        return self.sog * math.cos(self.cog - self.psi)

    @property
    def v(self) -> float:
        """Sway speed over ground (m/s, to port)."""
        return self.sog * math.sin(self.cog - self.psi)


class DriftObserver:
    """Online estimate of the drift velocity (current + steady crab) from a boat's own sensors."""

    def __init__(self, params: VesselParams, time_constant: float = 5.0,
                 initial: tuple[float, float] = (0.0, 0.0),
                 turn_rate: float = math.radians(3.0)) -> None:
        if not time_constant > 0.0:
            raise ValueError(f"observer: time_constant must be > 0 (got {time_constant})")
        self.params = params
        self.time_constant = time_constant
        self.turn_rate = turn_rate
        self.estimate = (float(initial[0]), float(initial[1]))
        self.water_speed = 0.0  # estimated surge speed through the water (m/s)
        self._shaft = [0.0, 0.0]  # nominal shaft speeds of the propeller model (rad/s)
        self._started = False
        self._turn = 0.0  # peak-held yaw rate (rad/s), decaying over TURN_MEMORY

    @property
    def speed(self) -> float:
        """Estimated drift speed (m/s)."""
        return math.hypot(*self.estimate)

    def start(self, meas: Measurement, thrust: tuple[float, float] | None = None) -> None:
        """Initialise from a first fix: water speed = surge over ground, propellers at `thrust`."""
        th = self.params.thrusters
        if thrust is not None:
            self._shaft = [th.shaft_speed_for(thrust[0]), th.shaft_speed_for(thrust[1])]
        self.water_speed = meas.u - (self.estimate[0] * math.cos(meas.psi)
                                     + self.estimate[1] * math.sin(meas.psi))
        self._started = True

    def update(self, meas: Measurement, thrust: tuple[float, float],
               dt: float) -> tuple[float, float]:
        """Advance dt seconds with the fix `meas` and the thrust commanded over the last dt."""
        if not dt > 0.0:
            raise ValueError(f"observer: dt must be > 0 (got {dt})")
        if not (math.isfinite(thrust[0]) and math.isfinite(thrust[1])):
            raise ValueError(f"observer: thrust must be finite (got {thrust})")
        if not self._started:
            self.start(meas, thrust)
        p = self.params
        th = p.thrusters
        a = math.exp(-dt / th.time_constant)
        for i in (0, 1):
            self._shaft[i] = th.shaft_speed_for(thrust[i]) + a * (
                self._shaft[i] - th.shaft_speed_for(thrust[i]))
        force = th.thrust(self._shaft[0]) + th.thrust(self._shaft[1])
        m11 = float(p.mass_matrix[0, 0])
        # Semi-implicit Euler of the nominal surge model (stable at any dt).
        d = p.linear_damping[0] + p.quadratic_damping[0] * abs(self.water_speed)
        self.water_speed = (m11 * self.water_speed + dt * force) / (m11 + dt * d)
        vx, vy = meas.velocity
        raw_x = vx - self.water_speed * math.cos(meas.psi)
        raw_y = vy - self.water_speed * math.sin(meas.psi)
        # Turning: the hull slips sideways through the water (not drift); trust
        # the residual less the faster the boat turns.
        self._turn = max(abs(meas.r), self._turn * math.exp(-dt / TURN_MEMORY))
        # The slip of a turn grows with speed: at station-keeping speeds the
        # observer keeps learning while the boat turns.
        slip = self._turn / self.turn_rate * min(meas.sog / SLIP_SPEED, 1.0)
        trust = math.exp(-(slip**2))
        w = trust * (1.0 - math.exp(-dt / self.time_constant))
        cx, cy = self.estimate
        self.estimate = (cx + w * (raw_x - cx), cy + w * (raw_y - cy))
        return self.estimate
