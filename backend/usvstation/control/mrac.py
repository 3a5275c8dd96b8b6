"""PID-MRAC autopilot of paper 002 (sec. II.D, eq. 30-35, Table IV), MIT rule.

Two model-reference adaptive loops:

- surge: reference model G_m(s) = 1 / (16 s + 1) (eq. 34) driven by the
  commanded speed; PI on e = u_cmd - u giving the surge force;
- heading: reference model G_m(s) = 1 / (4.9 s + 1) (eq. 35) driven by the
  commanded heading; PD on the wrapped e = psi_cmd - psi giving the yaw
  moment (paper 002 steers a propeller angle; this boat has differential
  thrust, so the PD output is a moment).

Each gain follows the MIT rule d theta / dt = -gamma dJ/d theta (eq. 32) with
J = e_m^2 / 2 (eq. 31, printed without the square), e_m = y - y_m (eq. 30),
and the PID's own regressor standing for the output sensitivity dy/d theta:

    K_p' = -gamma_P e_m e,   K_i' = -gamma_I e_m int(e),   K_d' = -gamma_D e_m e',

with Table IV's gammas as printed: surge (60, 1, 0), heading (100, 0, 1400). The paper
gives no units; here the gammas act on the controller in the units of its actuator, as
the paper's autopilot drives a propeller angle and a throttle: the output is a fraction
of the actuator's range (yaw moment / its maximum, surge force / full thrust of both
propellers), errors in rad and m/s, the sample time the control period. So the gains
are dimensionless and of order one, and Table IV's gammas move them by tens of percent
within a manoeuvre: they act. They start at the pole-placement values of
`AutopilotGains.for_vessel` (expressed the same way) and stay within [0, 4x] of them
(a bound, not in the paper, against the MIT rule's known drift). A second-order
reference for the heading, the drag feed-forward and the anti-windup of `Autopilot` are
not used: this is the paper's loop. `gammas` can be changed (a test shows it changes the
response).
"""

from __future__ import annotations

import math

from usvstation.control.autopilot import Autopilot, AutopilotGains
from usvstation.dynamics.params import VesselParams
from usvstation.dynamics.vessel import VesselState
from usvstation.geometry import angle_diff

SURGE_GAMMA = (60.0, 1.0, 0.0)  # Table IV, MRAC 1 (P, I, D)
HEADING_GAMMA = (100.0, 0.0, 1400.0)  # Table IV, MRAC 2 (P, I, D)
SURGE_TAU = 16.0  # s, eq. 34
HEADING_TAU = 4.9  # s, eq. 35
GAIN_RANGE = 4.0  # the gains stay within [0, 4x] their start


class PIDMRAC(Autopilot):
    """Autopilot with the two MIT-rule PID-MRAC loops of paper 002."""

    def __init__(self, params: VesselParams, gains: AutopilotGains | None = None,
                 surge_gamma: tuple[float, float, float] = SURGE_GAMMA,
                 heading_gamma: tuple[float, float, float] = HEADING_GAMMA) -> None:
        super().__init__(params, gains)
        th = params.thrusters
        self.moment_max = th.lever_arm * (th.thrust_max - th.thrust_min)
        self.force_max = 2.0 * th.thrust_max
        kp, _, kd = self.gains.heading
        skp, ski = self.gains.speed
        self.surge_gamma = surge_gamma
        self.heading_gamma = heading_gamma
        # in actuator fractions per rad (per rad/s) and per m/s (per m)
        self.initial = {"surge": (skp / self.force_max, ski / self.force_max),
                        "heading": (kp / self.moment_max, kd / self.moment_max)}
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
        g_p, _, g_d = self.heading_gamma
        kp0, kd0 = self.initial["heading"]
        kp, kd = self.heading_gains
        kp = min(max(kp - g_p * e_m * e * dt, 0.0), GAIN_RANGE * kp0)
        kd = min(max(kd - g_d * e_m * de * dt, 0.0), GAIN_RANGE * kd0)
        self.heading_gains = [kp, kd]
        return min(max(kp * e + kd * de, -1.0), 1.0) * self.moment_max

    def _surge_force(self, speed: float, water: float | None, state: VesselState,
                     dt: float) -> float:
        if self.surge_model is None:
            self.surge_model = state.u
        a = math.exp(-dt / SURGE_TAU)
        self.surge_model = speed + a * (self.surge_model - speed)
        e = speed - state.u
        e_m = state.u - self.surge_model
        g_p, g_i, _ = self.surge_gamma
        kp0, ki0 = self.initial["surge"]
        kp, ki = self.surge_gains
        kp = min(max(kp - g_p * e_m * e * dt, 0.0), GAIN_RANGE * kp0)
        ki = min(max(ki - g_i * e_m * self.surge_integral * dt, 0.0), GAIN_RANGE * ki0)
        self.surge_gains = [kp, ki]
        th = self.params.thrusters
        raw = (kp * e + ki * self.surge_integral) * self.force_max
        out = min(max(raw, 2.0 * th.thrust_min), 2.0 * th.thrust_max)
        if out == raw:
            self.surge_integral += e * dt
        return out

    def _back_off(self, surge: float, surge_cmd: float, yaw: float, yaw_cmd: float) -> None:
        return None
