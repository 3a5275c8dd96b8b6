"""DRNN-PI heading control of paper 004 (sec. 4.2, eq. 13-23, Alg. 2), and its plain-PI baseline.

Heading law (eq. 23): a yaw-rate command r_c = K_p e + K_i int(e) on the
wrapped heading error e, saturated to the boat's turn-rate limit; an inner
rate loop turns r_c into a yaw moment (m66 k_r (r_c - r) + d_r r_c).
`HeadingPI` keeps K_p, K_i fixed; `DRNNPI` has a diagonal recurrent network
choose them each step:

    h = relu(W1 x + w_r * h_prev + b1),   [K_p, K_i] = 2 scale * sigmoid(W2 h + b2)

with x = (psi_d, psi, r) / (pi, pi, rate_max) (the paper's three inputs),
4 hidden units, 2 outputs (Table 4), learnt online by RMSProp (learning rate
0.01, momentum 0.1, Table 4) on L = e^2 / 2 one step later, through the
plant sensitivity de/dr_c = -dt (PROPOSED; the paper does not say how its
Jacobian is obtained). Weights are bounded to +/-5 and the recurrence to
+/-0.9 (online RMSProp moves each weight by about the learning rate per
step, 20 steps a second, so an unbounded network diverges within minutes);
the output layer is a sigmoid giving gains within (0, 2x) the PI's, where
the paper's ReLU output is unbounded (with it the gains ran away and the
boat circled); no learning step is taken while r_c is saturated (the
sensitivity is zero there). Deviation from the paper, documented: the initial
weights are seeded small random numbers (N(0, 0.1^2)), not all ones; with
all-ones every hidden unit is the same forever. The speed loop is the
Autopilot's.
"""

from __future__ import annotations

import math

import numpy as np

from usvstation.control.autopilot import Autopilot, AutopilotGains
from usvstation.dynamics.params import VesselParams
from usvstation.dynamics.vessel import VesselState
from usvstation.geometry import angle_diff

HIDDEN = 4
LEARNING_RATE = 0.01
MOMENTUM = 0.1
RMS_DECAY = 0.9
INTEGRAL_ZONE = math.radians(10.0)  # integral separation (eq. 23 anti-windup)
WEIGHT_LIMIT = 5.0  # |w| bound on every weight (RMSProp steps are ~ the learning rate each)
RECURRENCE_LIMIT = 0.9


class HeadingPI(Autopilot):
    """Paper 004's baseline: fixed-gain PI on the heading giving a yaw-rate command."""

    def __init__(self, params: VesselParams, gains: AutopilotGains | None = None,
                 kp: float = 0.8, ki: float = 0.05, rate_loop: float = 3.0) -> None:
        super().__init__(params, gains)
        self.kp, self.ki = kp, ki
        self.rate_loop = rate_loop
        self.heading_integral = 0.0

    def reset(self) -> None:
        super().reset()
        self.heading_integral = 0.0

    def _pi_gains(self, heading: float, state: VesselState, e: float, dt: float
                  ) -> tuple[float, float]:
        return self.kp, self.ki

    def _yaw_moment(self, heading: float, state: VesselState, dt: float) -> float:
        e = angle_diff(heading, state.psi)
        kp, ki = self._pi_gains(heading, state, e, dt)
        if abs(e) < INTEGRAL_ZONE:
            self.heading_integral += e * dt
        else:
            self.heading_integral = 0.0
        rate_max = self.gains.rate_max
        r_c = min(max(kp * e + ki * self.heading_integral, -rate_max), rate_max)
        m66 = float(self.params.mass_matrix[2, 2])
        moment = m66 * self.rate_loop * (r_c - state.r) + self.params.linear_damping[2] * r_c
        limit = self.heading_pid.out_max
        return min(max(moment, -limit), limit)

    def _back_off(self, surge: float, surge_cmd: float, yaw: float, yaw_cmd: float) -> None:
        self.speed_pid.back_off(surge, surge_cmd)


def _sigmoid(z: np.ndarray) -> np.ndarray:
    return 0.5 * (1.0 + np.tanh(0.5 * z))


class DRNNPI(HeadingPI):
    """Paper 004's DRNN-PI: a diagonal recurrent network tunes the heading PI online."""

    def __init__(self, params: VesselParams, gains: AutopilotGains | None = None,
                 seed: int = 1, kp_scale: float = 0.8, ki_scale: float = 0.05) -> None:
        super().__init__(params, gains)
        self.seed = seed
        self.kp_scale, self.ki_scale = kp_scale, ki_scale
        rng = np.random.default_rng(seed)
        self.params_nn = {
            "W1": rng.normal(0.0, 0.1, (HIDDEN, 3)), "wr": rng.normal(0.0, 0.1, HIDDEN),
            "b1": np.zeros(HIDDEN), "W2": rng.normal(0.0, 0.1, (2, HIDDEN)), "b2": np.zeros(2),
        }
        self._ms = {k: np.zeros_like(v) for k, v in self.params_nn.items()}
        self._mom = {k: np.zeros_like(v) for k, v in self.params_nn.items()}
        self.hidden = np.zeros(HIDDEN)
        self._pending: tuple | None = None  # what the last step needs for its gradient
        self.gains_history: list[tuple[float, float]] = []

    def reset(self) -> None:
        super().reset()
        if hasattr(self, "hidden"):
            self.hidden = np.zeros(HIDDEN)
            self._pending = None

    def _learn(self, e_now: float, dt: float) -> None:
        """One RMSProp step on L = e^2/2 for the gains chosen one step ago."""
        if self._pending is None:
            return
        x, h_prev, pre1, h, z2, e_prev, integral, saturated = self._pending
        if saturated:
            return
        p = self.params_nn
        # dL/dr_c = e * de/dr_c = -e dt; dr_c/dK = (e_prev, integral).
        d_rc = -e_now * dt
        sig = _sigmoid(z2)
        d_z2 = np.array([d_rc * e_prev * self.kp_scale, d_rc * integral * self.ki_scale]) * (
            2.0 * sig * (1.0 - sig))
        grads = {"W2": np.outer(d_z2, h), "b2": d_z2}
        d_h = p["W2"].T @ d_z2
        d_pre = d_h * (pre1 > 0.0)
        grads.update(W1=np.outer(d_pre, x), wr=d_pre * h_prev, b1=d_pre)
        for k, g in grads.items():
            self._ms[k] = RMS_DECAY * self._ms[k] + (1.0 - RMS_DECAY) * g * g
            step = LEARNING_RATE * g / (np.sqrt(self._ms[k]) + 1e-8)
            self._mom[k] = MOMENTUM * self._mom[k] + step
            p[k] = np.clip(p[k] - self._mom[k], -WEIGHT_LIMIT, WEIGHT_LIMIT)
        # A diagonal recurrence below 1 keeps the hidden state bounded.
        p["wr"] = np.clip(p["wr"], -RECURRENCE_LIMIT, RECURRENCE_LIMIT)

    def _pi_gains(self, heading: float, state: VesselState, e: float, dt: float
                  ) -> tuple[float, float]:
        self._learn(e, dt)
        p = self.params_nn
        x = np.array([heading / math.pi, state.psi / math.pi, state.r / self.gains.rate_max])
        h_prev = self.hidden
        pre1 = p["W1"] @ x + p["wr"] * h_prev + p["b1"]
        h = np.maximum(pre1, 0.0)
        z2 = p["W2"] @ h + p["b2"]
        out = 2.0 * _sigmoid(z2)
        kp, ki = float(self.kp_scale * out[0]), float(self.ki_scale * out[1])
        self.hidden = h
        rc = kp * e + ki * self.heading_integral
        self._pending = (x, h_prev, pre1, h, z2, e, self.heading_integral,
                         abs(rc) >= self.gains.rate_max)
        self.gains_history.append((kp, ki))
        return kp, ki
