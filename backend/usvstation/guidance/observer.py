"""What a boat knows about itself, and an online drift observer (pure, no I/O).

Guidance and control see a `Measurement` only: GNSS position, course and
speed over ground, heading (compass) and yaw rate (gyro), plus the thrust
they commanded themselves. The simulator's environment is hidden from them.

`DriftObserver` estimates the drift velocity c (the current plus the steady slip
wind and waves push the hull to) together with what makes the boat's own model of
itself wrong: a speed scale s (the hull is slower or faster through the water than
the model says: fouling, a weak propeller), a compass bias b and the sideways slip of
a turn (scale k). It runs a nominal model of the boat's own propellers (first-order
shaft lag of the commanded thrust) and surge (m11 u' = T - d(u), the hull's
calm-water drag) to know its model speed through the water u, and explains the
measured ground velocity v as

    v = c + (1 + s) u h(psi_m - b) + (1 + k) v_s h(psi_m + pi/2)
      ~ c + u h(psi) + v_s h(psi + pi/2) + s u h(psi) - b u h(psi + pi/2)
          + k v_s h(psi + pi/2),

h(a) = (cos a, sin a), linear in x = (c_x, c_y, s, b, k); v_s is the sway of the
nominal hull turning at the measured yaw rate (its sway equation, M22 v' + m u r +
Y_D(u, v, r) = 0, driven by the gyro). A Kalman filter with
random-walk states estimates x (Fossen 2021 ch. 13 for the observer form; the
regression is the standard one of GNSS-aided speed-log and compass calibration).
The current's process noise sets how fast a changing current is followed
(`time_constant`, 5 s); s, b and k are nearly constant. The slip term keeps the
estimate honest through a turn instead of freezing it: a turn's slip is explained,
not mistaken for drift. With one heading only, c and (s, b) cannot be told apart:
the prior (b 0 +- 4 deg) then leaves the difference in c, which is what
the compensation needs at that heading; every turn makes s and b observable. Bounded
regressors and a positive definite R keep the filter stable (a linear Kalman filter
on an observable random-walk model converges; unobservable directions stay at their
prior).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from usvstation.dynamics.params import VesselParams
from usvstation.geometry import Pose, require_finite


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
    """Online estimate of the drift, speed scale, compass bias and turn slip from a boat's
    own sensors (see the module docstring)."""

    def __init__(self, params: VesselParams, time_constant: float = 5.0,
                 initial: tuple[float, float] = (0.0, 0.0),
                 noise: float = 0.15, bias_std: float = math.radians(4.0)) -> None:
        if not time_constant > 0.0:
            raise ValueError(f"observer: time_constant must be > 0 (got {time_constant})")
        self.params = params
        self.time_constant = time_constant
        self.noise = noise
        self.x = np.array([float(initial[0]), float(initial[1]), 0.0, 0.0])
        self.P = np.diag([1.0, 1.0, bias_std**2, 0.3**2])
        # random walks (per second): the current follows a change within time_constant;
        # the hull, the compass and the slip hardly change
        q_c = noise**2 * NOMINAL_DT / time_constant**2
        self.Q = np.diag([q_c, q_c, 1e-8, 1e-6])
        self.water_speed = 0.0  # model surge speed through the water (m/s)
        self.sway = 0.0  # model sway speed through the water in a turn (m/s, to port)
        self._shaft = [0.0, 0.0]  # nominal shaft speeds of the propeller model (rad/s)
        self._started = False
        self._age = 0.0  # s since start
        self.fast = (float(initial[0]), float(initial[1]))  # drift low-passed over FAST_S

    @property
    def estimate(self) -> tuple[float, float]:
        """Drift velocity (m/s, ramp frame)."""
        return float(self.x[0]), float(self.x[1])

    @estimate.setter
    def estimate(self, value: tuple[float, float]) -> None:
        self.x[0], self.x[1] = float(value[0]), float(value[1])
        self.fast = self.estimate

    @property
    def speed(self) -> float:
        """Estimated drift speed (m/s)."""
        return math.hypot(self.x[0], self.x[1])

    @property
    def compass_bias(self) -> float:
        """Estimated compass bias (rad; the compass reads this much anticlockwise)."""
        return float(self.x[2])

    @property
    def slip_scale(self) -> float:
        """Estimated true / model sideways slip in a turn (1: as modelled)."""
        return 1.0 + float(self.x[3])

    def heading(self, meas: Measurement) -> float:
        """The measured heading corrected for the estimated compass bias (rad)."""
        return meas.psi - self.compass_bias

    def start(self, meas: Measurement, thrust: tuple[float, float] | None = None) -> None:
        """Initialise from a first fix: water speed = surge over ground, propellers at `thrust`."""
        th = self.params.thrusters
        if thrust is not None:
            self._shaft = [th.shaft_speed_for(thrust[0]), th.shaft_speed_for(thrust[1])]
        self.water_speed = meas.u - (self.x[0] * math.cos(meas.psi)
                                     + self.x[1] * math.sin(meas.psi))
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
        u = self.water_speed
        # the sway of the nominal hull turning at the measured rate (semi-implicit: the
        # cross-flow drag is stiff): M22 v' + m u r + Y_D(u, v, r) = 0
        m22 = float(p.mass_matrix[1, 1])
        force = p.mass * u * meas.r + p.damping(u, self.sway, meas.r)[1]
        slope = p.damping(u, self.sway + 1e-3, meas.r)[1] - p.damping(u, self.sway, meas.r)[1]
        self.sway -= dt * force / (m22 + dt * max(slope / 1e-3, 0.0))
        v = self.sway
        c, sn = math.cos(meas.psi), math.sin(meas.psi)
        # v_ground - (u h(psi) + v h(psi + pi/2)) = H x + noise
        H = np.array([[1.0, 0.0, u * sn, -v * sn],
                      [0.0, 1.0, -u * c, v * c]])
        vx, vy = meas.velocity
        z = np.array([vx - u * c + v * sn, vy - u * sn - v * c])
        self.P = self.P + self.Q * (dt / NOMINAL_DT)
        # trust a fix less in a hard turn and while the model has just started (its sway
        # and surge states are guesses then): transients are not drift
        self._age += dt
        # (a turn at station-keeping speed slips little: it counts in full there)
        turning = (meas.r / TURN_RATE * min(meas.sog / 1.5, 1.0)) ** 2 + (v / SLIP_SPEED) ** 2
        settling = max(0.0, 1.0 - self._age / SETTLE_S) * 20.0
        R = np.eye(2) * self.noise**2 * (1.0 + turning + settling)
        S = H @ self.P @ H.T + R
        K = np.linalg.solve(S, H @ self.P).T
        # the fast estimate: the drift this fix alone shows (the bias and the turn slip
        # from the filter), low-passed over FAST_S: what station keeping reacts to
        raw = z - H[:, 2:] @ self.x[2:]
        a_f = 1.0 - math.exp(-dt / FAST_S)
        self.fast = (self.fast[0] + a_f * (raw[0] - self.fast[0]),
                     self.fast[1] + a_f * (raw[1] - self.fast[1]))
        self.x = self.x + K @ (z - H @ self.x)
        self.P = (np.eye(4) - K @ H) @ self.P
        self.P = 0.5 * (self.P + self.P.T)
        self.x[2] = min(max(self.x[2], -0.35), 0.35)
        self.x[3] = min(max(self.x[3], -0.8), 0.8)
        return self.estimate


NOMINAL_DT = 0.05  # s, the control period the process noise is stated for
TURN_RATE = math.radians(6.0)  # rad/s: at this yaw rate a fix counts half
SLIP_SPEED = 0.3  # m/s of modelled sway: at this slip a fix counts half
SETTLE_S = 5.0  # s after start during which fixes count little
FAST_S = 1.0  # s: the fast drift estimate's low-pass
