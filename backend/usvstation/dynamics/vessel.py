"""The 3-DOF vessel: state, thrust commands and fixed-step RK4 integration.

    eta' = R(psi) nu                                   (kinematics)
    M nu_r' + C_RB(nu_r) nu_r + D(nu_r) nu_r = tau + tau_env,   nu_r = nu - nu_c

nu_c is the current in the body frame; for a uniform current
nu_c' = [r v_c, -r u_c, 0] (Fossen 2021, sec. 10.3). tau comes from the two
propellers (shaft-speed lag and saturation), tau_env from waves and wind.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from usvstation.dynamics.environment import Environment
from usvstation.dynamics.params import VesselParams
from usvstation.geometry import Pose, wrap_angle

MAX_STEP = 0.05  # s: the model is integrated at 20 Hz or faster


@dataclass(frozen=True)
class ThrustCommand:
    """Requested thrust of the left (port) and right (starboard) propellers, in newtons."""

    left: float
    right: float


@dataclass(frozen=True)
class VesselState(Pose):
    """Pose in the ramp frame and velocities over ground in the body frame.

    x, y (m); psi heading (rad, anticlockwise from +x); u surge, v sway (m/s,
    v to port); r yaw rate (rad/s, anticlockwise); t (s).
    """

    u: float = 0.0
    v: float = 0.0
    r: float = 0.0
    t: float = 0.0

    @property
    def velocity(self) -> tuple[float, float]:
        """Velocity over ground in the ramp frame (m/s)."""
        c, s = math.cos(self.psi), math.sin(self.psi)
        return c * self.u - s * self.v, s * self.u + c * self.v

    @property
    def speed(self) -> float:
        """Speed over ground (m/s)."""
        return math.hypot(self.u, self.v)

    @property
    def course(self) -> float:
        """Course over ground (rad); the heading when the boat is at rest."""
        if self.u == 0.0 and self.v == 0.0:
            return self.psi
        vx, vy = self.velocity
        return math.atan2(vy, vx)


class Vessel:
    """A twin-propeller USV simulated step by step (sans-IO: no clock, no I/O).

    Example: ``Vessel(otter(), VesselState(50.0, 0.0, math.pi)).step(ThrustCommand(60.0,
    60.0), Environment(), 0.05)``. The propellers start stopped unless
    `set_initial_thrust` says otherwise.
    """

    def __init__(self, params: VesselParams, state: VesselState) -> None:
        values = (state.x, state.y, state.psi, state.u, state.v, state.r, state.t)
        if not all(math.isfinite(v) for v in values):
            raise ValueError(f"vessel: initial state must be finite (got {state})")
        self.params = params
        self._thrusters = params.thrusters
        self._x = np.array([*values[:6], 0.0, 0.0], dtype=float)
        self._t = state.t
        self._shaft_cmd = (0.0, 0.0)

    @property
    def state(self) -> VesselState:
        x = self._x
        return VesselState(
            float(x[0]), float(x[1]), wrap_angle(float(x[2])),
            float(x[3]), float(x[4]), float(x[5]), self._t,
        )

    @property
    def shaft_speeds(self) -> tuple[float, float]:
        """Actual left and right propeller shaft speeds (rad/s)."""
        return float(self._x[6]), float(self._x[7])

    @property
    def thrust(self) -> tuple[float, float]:
        """Actual left and right propeller thrust (N)."""
        th = self._thrusters
        return th.thrust(float(self._x[6])), th.thrust(float(self._x[7]))

    def kinetic_energy(self, env: Environment | None = None) -> float:
        """0.5 nu_r^T M nu_r (J): the energy of the hull and its added mass of water."""
        x = self._x
        uc, vc = env.current_body(float(x[2])) if env is not None else (0.0, 0.0)
        nu_r = np.array([x[3] - uc, x[4] - vc, x[5]])
        return 0.5 * float(nu_r @ self.params.mass_matrix @ nu_r)

    def set_initial_thrust(self, command: ThrustCommand) -> None:
        """Start the propellers already turning at `command` (no spin-up lag)."""
        th = self._thrusters
        self._x[6] = th.shaft_speed_for(command.left)
        self._x[7] = th.shaft_speed_for(command.right)

    def step(self, command: ThrustCommand, env: Environment, dt: float) -> VesselState:
        """Hold `command` for dt seconds (RK4 sub-steps of at most 50 ms); return the new state."""
        if not dt > 0.0 or not math.isfinite(dt):
            raise ValueError(f"step: dt must be a positive number of seconds (got {dt})")
        if not (math.isfinite(command.left) and math.isfinite(command.right)):
            raise ValueError(f"step: thrust command must be finite (got {command})")
        th = self._thrusters
        self._shaft_cmd = (th.shaft_speed_for(command.left), th.shaft_speed_for(command.right))
        n = max(1, math.ceil(dt / MAX_STEP - 1e-9))
        h = dt / n
        for _ in range(n):
            self._x = self._rk4(self._x, env, h)
            self._t += h
        self._x[2] = wrap_angle(float(self._x[2]))
        return self.state

    def _rk4(self, x: np.ndarray, env: Environment, h: float) -> np.ndarray:
        k1 = self.derivative(x, env)
        k2 = self.derivative(x + 0.5 * h * k1, env)
        k3 = self.derivative(x + 0.5 * h * k2, env)
        k4 = self.derivative(x + h * k3, env)
        return x + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4)

    def derivative(self, x: np.ndarray, env: Environment) -> np.ndarray:
        """d/dt of [x, y, psi, u, v, r, n_left, n_right] under the held shaft-speed command."""
        p = self.params
        th = self._thrusters
        psi, u, v, r = float(x[2]), float(x[3]), float(x[4]), float(x[5])
        uc, vc = env.current_body(psi)
        ur, vr = u - uc, v - vc
        t_left, t_right = th.thrust(float(x[6])), th.thrust(float(x[7]))
        tau = np.array([t_left + t_right, 0.0, th.lever_arm * (t_right - t_left)])
        if env.waves is not None or env.wind is not None:
            tau = tau + env.forces(p, psi, u, v)
        if env.pushes:
            bx, by = env.push_body(float(x[0]), float(x[1]), psi)
            tau = tau + np.array([bx, by, 0.0])
        rhs = tau - p.coriolis(ur, vr, r) - p.damping(ur, vr, r)
        nu_r_dot = p.mass_matrix_inv @ rhs
        c, s = math.cos(psi), math.sin(psi)
        tn = th.time_constant
        return np.array([
            c * u - s * v,
            s * u + c * v,
            r,
            nu_r_dot[0] + r * vc,
            nu_r_dot[1] - r * uc,
            nu_r_dot[2],
            (self._shaft_cmd[0] - float(x[6])) / tn,
            (self._shaft_cmd[1] - float(x[7])) / tn,
        ])
