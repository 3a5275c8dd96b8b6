"""PID with anti-windup, thrust allocation, the autopilot and the closed tracking loop."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from usvstation.control import PID, Autopilot, TrackingLoop, allocate
from usvstation.dynamics import Environment, ThrustCommand, Vessel, VesselState, otter, trimaran
from usvstation.geometry import angle_diff
from usvstation.guidance.los import AVLOSGuidance
from usvstation.guidance.trajectory import Trajectory

OTTER = otter()


# ------------------------------------------------------------------ PID


def test_pid_terms() -> None:
    pid = PID(kp=2.0, ki=0.5, kd=0.1)
    assert pid.update(1.0, 0.1) == pytest.approx(2.0)  # first step: no derivative, no integral
    assert pid.integral == pytest.approx(0.1)
    assert pid.update(1.0, 0.1) == pytest.approx(2.0 + 0.05)
    assert pid.update(2.0, 0.1, rate=-3.0, feedforward=1.0) == pytest.approx(
        1.0 + 4.0 + 0.5 * 0.2 - 0.3)


def test_pid_does_not_wind_up_while_saturated() -> None:
    pid = PID(kp=1.0, ki=1.0, out_min=-2.0, out_max=2.0)
    for _ in range(100):
        assert pid.update(5.0, 0.1) == 2.0
    assert pid.integral == 0.0  # integrating would only push further into the limit
    assert pid.update(-0.5, 0.1) == pytest.approx(-0.5 - 0.0)  # responds at once on reversal


def test_pid_integral_zone_and_back_off() -> None:
    pid = PID(kp=1.0, ki=1.0, integral_zone=0.5)
    pid.update(3.0, 0.1)
    assert pid.integral == 0.0
    pid.update(0.2, 1.0)
    assert pid.integral == pytest.approx(0.2)
    pid.back_off(achieved=1.0, commanded=1.1)
    assert pid.integral == pytest.approx(0.1)
    with pytest.raises(ValueError, match="out_min must be below out_max"):
        PID(kp=1.0, out_min=1.0, out_max=0.0)


# ------------------------------------------------------------------ allocation


def test_allocation_splits_surge_and_yaw() -> None:
    th = OTTER.thrusters
    a = allocate(100.0, 0.0, th)
    assert (a.command.left, a.command.right) == pytest.approx((50.0, 50.0))
    b = allocate(100.0, 7.9, th)  # positive N (turn to port): more thrust on the right
    assert b.command.right - b.command.left == pytest.approx(7.9 / th.lever_arm)
    assert (b.surge_force, b.yaw_moment) == pytest.approx((100.0, 7.9))


@given(st.floats(-500.0, 500.0), st.floats(-200.0, 200.0))
def test_allocation_stays_in_range_and_gives_yaw_priority(surge, yaw) -> None:
    th = OTTER.thrusters
    a = allocate(surge, yaw, th)
    for t in (a.command.left, a.command.right):
        assert th.thrust_min - 1e-9 <= t <= th.thrust_max + 1e-9
    if abs(yaw) / th.lever_arm <= th.thrust_max - th.thrust_min:
        assert a.yaw_moment == pytest.approx(yaw, abs=1e-9)  # the moment is kept...
    half = 0.5 * abs(yaw) / th.lever_arm
    if th.thrust_min + half <= 0.5 * surge <= th.thrust_max - half:
        assert a.surge_force == pytest.approx(surge, abs=1e-6)  # ...and surge when it fits


# ------------------------------------------------------------------ autopilot


def settle(params, heading_deg: float, speed: float, seconds: float) -> VesselState:
    boat = Vessel(params, VesselState(0.0, 0.0, 0.0, speed))
    trim = 0.5 * params.surge_drag(speed)
    boat.set_initial_thrust(ThrustCommand(trim, trim))
    pilot = Autopilot(params)
    command = SimpleNamespace(heading=math.radians(heading_deg), speed=speed)
    for _ in range(round(seconds / 0.05)):
        boat.step(pilot.update(command, boat.state, 0.05), Environment(), 0.05)
    return boat.state


@pytest.mark.parametrize("step_deg", [-60.0, 20.0, 90.0])
def test_autopilot_turns_to_the_commanded_heading(step_deg) -> None:
    state = settle(OTTER, step_deg, 2.0, 25.0)
    assert math.degrees(angle_diff(state.psi, math.radians(step_deg))) == pytest.approx(0, abs=0.5)
    assert state.u == pytest.approx(2.0, abs=0.03)


def test_autopilot_turns_the_short_way_round() -> None:
    boat = Vessel(OTTER, VesselState(0.0, 0.0, math.radians(170.0), 1.5))
    pilot = Autopilot(OTTER)
    command = SimpleNamespace(heading=math.radians(-170.0), speed=1.5)
    for _ in range(20):
        boat.step(pilot.update(command, boat.state, 0.05), Environment(), 0.05)
    assert boat.state.r > 0  # anticlockwise through 180, not clockwise through 0


def test_autopilot_changes_speed_and_holds_it_in_a_head_current() -> None:
    env = Environment.with_current(0.3, math.pi)  # against the boat
    boat = Vessel(OTTER, VesselState(0.0, 0.0, 0.0, 0.5))
    pilot = Autopilot(OTTER)
    command = SimpleNamespace(heading=0.0, speed=2.0)
    for _ in range(round(40 / 0.05)):
        boat.step(pilot.update(command, boat.state, 0.05), env, 0.05)
    assert boat.state.u == pytest.approx(2.0, abs=0.02)  # over ground: integral takes the current


def test_autopilot_gains_suit_the_trimaran_too() -> None:
    state = settle(trimaran(), 30.0, 2.0, 60.0)
    assert math.degrees(angle_diff(state.psi, math.radians(30.0))) == pytest.approx(0, abs=1.0)


# ------------------------------------------------------------------ closed loop


def test_tracking_loop_follows_a_timed_line_in_calm_water() -> None:
    traj = Trajectory.from_xyt([(0.0, 0.0, 0.0), (80.0, 0.0, 40.0)])
    boat = Vessel(OTTER, VesselState(0.0, 3.0, 0.0, 2.0))
    boat.set_initial_thrust(ThrustCommand(0.5 * OTTER.surge_drag(2.0), 0.5 * OTTER.surge_drag(2.0)))
    loop = TrackingLoop(boat, AVLOSGuidance(traj, 8.0, speed_max=3.0, accel=0.5),
                        Autopilot(OTTER))
    lowest = 3.0
    for _ in range(round(35.0 / 0.05)):
        state = loop.step(Environment())
        lowest = min(lowest, state.y)
    assert abs(state.y) < 0.05  # converged onto the line from 3 m off
    assert lowest > -0.6  # overshooting it by less than a third of the boat's length
    assert state.x == pytest.approx(traj.position_at(state.t)[0], abs=1.0)  # and on schedule
    assert loop.command is not None and loop.command.segment == 0


def test_tracking_loop_runs_guidance_at_its_own_period() -> None:
    calls: list[float] = []

    class Recorder:
        def update(self, pose, t):
            calls.append(t)
            return SimpleNamespace(heading=0.0, speed=1.0)

    loop = TrackingLoop(Vessel(OTTER, VesselState(0.0, 0.0, 0.0)), Recorder(), Autopilot(OTTER),
                        guidance_period=0.2, control_period=0.05)
    for _ in range(20):
        loop.step(Environment())
    assert calls == pytest.approx([0.2 * k for k in range(5)])
    with pytest.raises(ValueError, match="control_period <= guidance_period"):
        TrackingLoop(Vessel(OTTER, VesselState(0, 0, 0)), Recorder(), Autopilot(OTTER), 0.05, 0.2)


# ------------------------------------------------------------------ robust to the hull (issue 24)


def _heading_poles(thrust: float, drag: float) -> np.ndarray:
    """Closed-loop poles of the heading loop, linearised: yaw m66 r' + drag d_r r = thrust N
    behind the propellers' first-order lag tau, PID (kp e + ki int e - kd r) of the nominal
    hull's pole placement. Characteristic polynomial:
    m66 tau s^4 + (m66 + drag d_r tau) s^3 + (drag d_r + thrust kd) s^2 + thrust kp s
    + thrust ki (the reference model and the feed-forward do not enter it)."""
    from usvstation.control.autopilot import AutopilotGains
    from usvstation.dynamics import otter

    p = otter()
    kp, ki, kd = AutopilotGains.for_vessel(p).heading
    m66, d, tau = float(p.mass_matrix[2, 2]), p.linear_damping[2], p.thrusters.time_constant
    return np.roots([m66 * tau, m66 + drag * d * tau, drag * d + thrust * kd, thrust * kp,
                     thrust * ki])


def _surge_poles(thrust: float, drag: float) -> np.ndarray:
    """The speed loop likewise: m11 u' + drag d_u u = thrust X, PI, the same lag."""
    from usvstation.control.autopilot import AutopilotGains
    from usvstation.dynamics import otter

    p = otter()
    kp, ki = AutopilotGains.for_vessel(p).speed
    m11, d, tau = float(p.mass_matrix[0, 0]), p.linear_damping[0], p.thrusters.time_constant
    return np.roots([m11 * tau, m11 + drag * d * tau, drag * d + thrust * kp, thrust * ki])


@pytest.mark.parametrize("drag", [0.75, 1.0, 1.25])
@pytest.mark.parametrize("thrust", [0.85, 1.0])
def test_the_autopilot_stays_stable_on_a_hull_that_is_not_its_model(drag, thrust):
    """The stability argument of docs/tracking.md: the gains are placed on the nominal
    Otter, the hull has +-25 % drag and 15 % less thrust; every closed-loop pole keeps a
    negative real part (the slowest, the integrators', below -0.05 1/s)."""
    assert max(_heading_poles(thrust, drag).real) < -0.05
    assert max(_surge_poles(thrust, drag).real) < -0.04


def test_the_heading_loop_keeps_a_wide_gain_margin():
    for thrust in (0.1, 0.5, 2.0, 10.0):
        assert max(_heading_poles(thrust, 1.0).real) < 0.0
