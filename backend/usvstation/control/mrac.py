"""PID-MRAC autopilot of paper 002 (sec. II.D, eq. 30-35, Table IV), MIT rule.

Two model-reference adaptive loops:

- surge: reference model G_m(s) = 1 / (16 s + 1) (eq. 34) driven by the
  commanded speed; PI on e = u_cmd - u giving the surge force;
- heading: reference model G_m(s) = 1 / (4.9 s + 1) (eq. 35) driven by the
  commanded heading; PD on the wrapped e = psi_cmd - psi giving the yaw
  moment (paper 002 steers a propeller angle; this boat has differential
  thrust, so the PD output is a moment).

Each gain follows the MIT rule d theta / dt = -gamma dJ/d theta with
J = e_m^2 / 2 (eq. 31 printed without the square), e_m = y - y_m (eq. 30),
and the PID's own regressor as the output sensitivity:
K_p' = -gamma_P e_m e, K_i' = -gamma_I e_m int(e), K_d' = -gamma_D e_m e'
(PROPOSED reading of eq. 32-33, see shared notes). gamma from Table IV:
surge (60, 1, 0), heading (100, 0, 1400). The paper's units, sample time and
initial gains are not given: errors here are in m/s and rad, T_s is the
control period, the gains start at the pole-placement values of
`AutopilotGains.for_vessel` and are kept within [0, 4x] of them.
"""

from __future__ import annotations

import math

from usvstation.control.autopilot import Autopilot, AutopilotGains
from usvstation.dynamics.params import VesselParams
from usvstation.dynamics.vessel import VesselState
from usvstation.geometry import angle_diff

SURGE_GAMMA = (60.0, 1.0, 0.0)  # Table IV, MRAC 1
HEADING_GAMMA = (100.0, 0.0, 1400.0)  # Table IV, MRAC 2
SURGE_TAU = 16.0  # s, eq. 34
HEADING_TAU = 4.9  # s, eq. 35


class PIDMRAC(Autopilot):
    """Autopilot with the two MIT-rule PID-MRAC loops of paper 002."""

    def __init__(self, params: VesselParams, gains: AutopilotGains | None = None) -> None:
        super().__init__(params, gains)
        kp, _, kd = self.gains.heading
        skp, ski = self.gains.speed
        self.initial = {"surge": (skp, ski), "heading": (kp, kd)}
        self.reset()

    def reset(self) -> None:
        super().reset()
        (skp, ski), (kp, kd) = self.initial["surge"], self.initial["heading"]
        self.surge_gains = [skp, ski]
        self.heading_gains = [kp, kd]
        self.surge_model: float | None = None
        self.heading_model: float | None = None
        self.surge_integral = 0.0

    def _yaw_moment(self, heading: float, state: VesselState, dt: float) -> float:
        if self.heading_model is None:
            self.heading_model = state.psi
        # Reference model 1/(4.9 s + 1) on the wrapped command (exact discretisation).
        a = math.exp(-dt / HEADING_TAU)
        self.heading_model += (1.0 - a) * angle_diff(heading, self.heading_model)
        e = angle_diff(heading, state.psi)
        e_m = angle_diff(state.psi, self.heading_model)
        de = -state.r  # the command is piecewise constant: e' = -r
        g_p, _, g_d = HEADING_GAMMA
        kp0, kd0 = self.initial["heading"]
        kp, kd = self.heading_gains
        # Normalised by the initial gain so Table IV's gammas act on a unit scale.
        kp = min(max(kp - g_p * e_m * e * dt * kp0 / 100.0, 0.0), 4.0 * kp0)
        kd = min(max(kd - g_d * e_m * de * dt * kd0 / 1400.0, 0.0), 4.0 * kd0)
        self.heading_gains = [kp, kd]
        moment_max = self.heading_pid.out_max
        return min(max(kp * e + kd * de, -moment_max), moment_max)

    def _surge_force(self, speed: float, water: float | None, state: VesselState,
                     dt: float) -> float:
        if self.surge_model is None:
            self.surge_model = state.u
        a = math.exp(-dt / SURGE_TAU)
        self.surge_model = speed + a * (self.surge_model - speed)
        e = speed - state.u
        e_m = state.u - self.surge_model
        g_p, g_i, _ = SURGE_GAMMA
        kp0, ki0 = self.initial["surge"]
        kp, ki = self.surge_gains
        kp = min(max(kp - g_p * e_m * e * dt * kp0 / 60.0, 0.0), 4.0 * kp0)
        ki = min(max(ki - g_i * e_m * self.surge_integral * dt * ki0, 0.0), 4.0 * ki0)
        self.surge_gains = [kp, ki]
        th = self.params.thrusters
        raw = kp * e + ki * self.surge_integral
        out = min(max(raw, 2.0 * th.thrust_min), 2.0 * th.thrust_max)
        if out == raw:
            self.surge_integral += e * dt
        return out

    def _back_off(self, surge: float, surge_cmd: float, yaw: float, yaw_cmd: float) -> None:
        return None
