"""The 3-DOF vessel model is physically plausible (issue 3 "Done when")."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from usvstation.dynamics import (
    Environment,
    KinematicBoat,
    ThrustCommand,
    Vessel,
    VesselState,
    WaveField,
    Wind,
    drift_coefficients,
    otter,
    trimaran,
    vessel_preset,
    wave_drift_force,
)

OTTER = otter()
CALM = Environment()


def run(vessel: Vessel, command: ThrustCommand, env: Environment, seconds: float,
        dt: float = 0.05) -> VesselState:
    for _ in range(round(seconds / dt)):
        vessel.step(command, env, dt)
    return vessel.state


def test_otter_matrices_match_fossens_data() -> None:
    m = OTTER.mass_matrix
    assert m[0, 0] == pytest.approx(85.5)  # 80 kg + X_udot = 0.1 x 55 kg
    assert m[1, 1] == pytest.approx(162.5)  # 80 kg + 1.5 x 55 kg
    assert m[2, 2] == pytest.approx(41.45, abs=0.01)  # "41.4" in Fossen's otter.py autopilot
    assert np.allclose(m, m.T)
    assert np.all(np.linalg.eigvalsh(m) > 0)
    assert OTTER.thrusters.thrust_max == pytest.approx(0.5 * 24.4 * 9.81)
    assert OTTER.calm_water_top_speed() == pytest.approx(6 * 0.5144)


def test_equal_thrust_settles_where_thrust_balances_drag() -> None:
    boat = Vessel(OTTER, VesselState(0.0, 0.0, 0.3))
    state = run(boat, ThrustCommand(50.0, 50.0), CALM, 40.0)
    assert state.u == pytest.approx(100.0 / OTTER.linear_damping[0], rel=1e-3)
    assert state.v == pytest.approx(0.0, abs=1e-9)
    assert state.r == pytest.approx(0.0, abs=1e-9)
    assert state.psi == pytest.approx(0.3, abs=1e-9)  # straight on: no turn


def test_trimaran_full_thrust_reaches_its_top_speed() -> None:
    tri = trimaran()
    full = tri.thrusters.thrust_max
    state = run(Vessel(tri, VesselState(0.0, 0.0, 0.0)), ThrustCommand(full, full), CALM, 60.0)
    assert state.u == pytest.approx(tri.top_speed, rel=1e-3)
    # Drag balances thrust: 74.38 u + 177.04 u^2 = 3000 N (Table I damping).
    assert 74.3802 * state.u + 177.037 * state.u**2 == pytest.approx(2 * full, rel=2e-3)


def test_without_thrust_the_boat_drifts_with_the_current() -> None:
    env = Environment.with_current(0.3, math.radians(60.0))
    cx, cy = env.current
    # Moving with the water, it stays moving with the water.
    psi = 1.0
    uc, vc = env.current_body(psi)
    boat = Vessel(OTTER, VesselState(0.0, 0.0, psi, uc, vc))
    state = run(boat, ThrustCommand(0.0, 0.0), env, 20.0)
    assert state.velocity == pytest.approx((cx, cy), abs=1e-6)
    assert (state.x, state.y) == pytest.approx((20.0 * cx, 20.0 * cy), abs=1e-4)
    # From rest it is carried off until it moves with the water.
    boat = Vessel(OTTER, VesselState(0.0, 0.0, psi))
    state = run(boat, ThrustCommand(0.0, 0.0), env, 120.0)
    vx, vy = state.velocity
    assert math.hypot(vx - cx, vy - cy) < 0.01


@pytest.mark.parametrize("params", [OTTER, trimaran()], ids=["otter", "trimaran"])
def test_thrust_difference_turns_towards_the_weaker_propeller(params) -> None:
    t = 0.5 * params.thrusters.thrust_max
    start = VesselState(0.0, 0.0, 0.0)
    left_turn = run(Vessel(params, start), ThrustCommand(0.6 * t, t), CALM, 5.0)
    right_turn = run(Vessel(params, start), ThrustCommand(t, 0.6 * t), CALM, 5.0)
    assert left_turn.r > 0 and left_turn.psi > 0  # more thrust on the right: turns left (port)
    assert left_turn.y > 0
    assert right_turn.r < 0 and right_turn.psi < 0
    assert right_turn.psi == pytest.approx(-left_turn.psi, rel=1e-9)  # mirror image


@settings(max_examples=40, deadline=None)
@given(
    u=st.floats(-2.0, 3.5), v=st.floats(-1.5, 1.5), r=st.floats(-1.0, 1.0),
    preset=st.sampled_from(["otter", "trimaran"]),
)
def test_kinetic_energy_never_grows_without_input_or_environment(u, v, r, preset) -> None:
    boat = Vessel(vessel_preset(preset), VesselState(0.0, 0.0, 0.0, u, v, r))
    energy = boat.kinetic_energy()
    for _ in range(60):
        boat.step(ThrustCommand(0.0, 0.0), CALM, 0.05)
        now = boat.kinetic_energy()
        assert now <= energy * (1.0 + 1e-9) + 1e-12
        energy = now


def test_propellers_saturate_and_lag() -> None:
    th = OTTER.thrusters
    boat = Vessel(OTTER, VesselState(0.0, 0.0, 0.0))
    boat.step(ThrustCommand(1e6, -1e6), CALM, th.time_constant)
    left, right = boat.shaft_speeds
    # First-order lag: 1 - e^-1 of the way after one time constant.
    assert left == pytest.approx(th.n_max * (1 - math.exp(-1)), rel=1e-4)
    assert right == pytest.approx(th.n_min * (1 - math.exp(-1)), rel=1e-4)
    run(boat, ThrustCommand(1e6, -1e6), CALM, 20.0)
    assert boat.thrust == pytest.approx((th.thrust_max, th.thrust_min), rel=1e-6)
    assert th.thrust_min == pytest.approx(-0.5 * 13.6 * 9.81)


def test_step_is_split_into_substeps_of_at_most_50_ms() -> None:
    a = Vessel(OTTER, VesselState(1.0, 2.0, 0.5, 1.0, 0.1, 0.05))
    b = Vessel(OTTER, VesselState(1.0, 2.0, 0.5, 1.0, 0.1, 0.05))
    env = Environment.with_current(0.2, 1.0)
    a.step(ThrustCommand(40.0, 70.0), env, 0.2)
    for _ in range(4):
        b.step(ThrustCommand(40.0, 70.0), env, 0.05)
    sa, sb = a.state, b.state
    assert (sa.x, sa.y, sa.psi, sa.u, sa.v, sa.r, sa.t) == pytest.approx(
        (sb.x, sb.y, sb.psi, sb.u, sb.v, sb.r, sb.t), abs=1e-12)


@pytest.mark.parametrize("dt", [0.0, -0.1, math.nan])
def test_step_refuses_a_bad_time_step(dt) -> None:
    with pytest.raises(ValueError, match="dt must be a positive number"):
        Vessel(OTTER, VesselState(0, 0, 0)).step(ThrustCommand(0, 0), CALM, dt)


def test_vessel_refuses_a_non_finite_start() -> None:
    with pytest.raises(ValueError, match="initial state must be finite"):
        Vessel(OTTER, VesselState(0.0, math.nan, 0.0))


def test_step_refuses_non_finite_thrust() -> None:
    with pytest.raises(ValueError, match="thrust command must be finite"):
        Vessel(OTTER, VesselState(0, 0, 0)).step(ThrustCommand(math.inf, 0), CALM, 0.05)


def test_unknown_preset_is_named() -> None:
    with pytest.raises(ValueError, match="unknown preset 'cat'; available: otter, trimaran"):
        vessel_preset("cat")


# ------------------------------------------------------------------ environment


def test_waves_from_wind_follow_eq5_with_the_dispersion_wavelength() -> None:
    w = WaveField.from_wind(0.0, 0.0)
    assert (w.height, w.period) == pytest.approx((1.5, 5.6))
    assert w.wavelength == pytest.approx(9.81 * 5.6**2 / (2 * math.pi))  # 48.96 m
    paper = WaveField.from_wind(0.0, 0.0, wavelength="paper")
    assert paper.wavelength == pytest.approx(0.54 * 5.6**2)  # eq. 5 as printed
    with pytest.raises(ValueError, match="unknown wavelength model 'airy'"):
        WaveField.from_wind(0.0, 0.0, wavelength="airy")
    w = WaveField.from_wind(10.0, 0.0)
    assert w.height == pytest.approx(0.015 * 100 + 1.5)
    assert w.period == pytest.approx(-1.0 + 4.2 + 5.6)


def test_sea_state_3_is_the_middle_of_the_wmo_band() -> None:
    w = WaveField.from_sea_state(3, 0.0)
    assert w.height == pytest.approx(0.875)
    assert w.wavelength == pytest.approx(77.72, abs=0.01)  # dispersion, T = 7.06 s
    assert WaveField.from_sea_state(3, 0.0, "paper").wavelength == pytest.approx(26.88, abs=0.01)
    with pytest.raises(ValueError, match=r"sea state must be 0\.\.8"):
        WaveField.from_sea_state(12, 0.0)


def test_drift_coefficients_follow_eq4_and_decay_past_their_fit() -> None:
    from usvstation.dynamics import drift_coefficients

    assert drift_coefficients(0.5) == pytest.approx((
        0.05 - 0.1 + 0.75 * 0.25 - 0.51 * 0.125,
        0.46 + 6.83 * 0.5 - 15.65 * 0.25 + 8.44 * 0.125,
        -0.11 + 0.34 - 0.79 * 0.25 + 0.21 * 0.125,
    ))
    assert drift_coefficients(5.0) == pytest.approx(
        tuple(c / 25.0 for c in drift_coefficients(1.0)))


def test_wave_drift_force_of_eq3_carries_g() -> None:
    """Eq. 3 in newtons: 1/2 rho g L xi^2 W (the printed form lacks g, 9.81x too small)."""
    params = otter()
    waves = WaveField(1.0, 3.0, 1.0, math.pi / 2)  # lambda / L = 0.5, beam seas
    f = wave_drift_force(params, waves, 0.0)
    _, wy, wn = drift_coefficients(0.5)
    q = 0.5 * 1025.0 * 9.81 * params.length * 0.5**2
    assert f[1] == pytest.approx(q * wy)
    assert f[2] == pytest.approx(q * params.length * wn)


def test_wave_drift_pushes_the_boat_the_way_the_waves_run() -> None:
    from usvstation.dynamics import wave_drift_force

    waves = WaveField.from_sea_state(3, 0.0)
    ahead = wave_drift_force(OTTER, waves, 0.0)  # following seas
    assert ahead[0] > 0 and ahead[1] == pytest.approx(0.0, abs=1e-9)
    head = wave_drift_force(OTTER, waves, math.pi)
    assert head[0] == pytest.approx(-ahead[0])
    beam = wave_drift_force(OTTER, waves, -math.pi / 2)  # waves run to the boat's port side
    assert beam[1] > 0 and beam[0] == pytest.approx(0.0, abs=1e-9)


def test_wind_pushes_back_in_a_headwind_and_to_leeward_abeam() -> None:
    from usvstation.dynamics import wind_force

    head = wind_force(OTTER, Wind(10.0, math.pi), 0.0, 0.0, 0.0)
    assert head[0] < 0 and head[1] == pytest.approx(0.0, abs=1e-9)
    # 0.5 rho_a V^2 c_x A_F
    assert head[0] == pytest.approx(-0.5 * 1.225 * 100 * 0.7 * OTTER.frontal_area_air)
    abeam = wind_force(OTTER, Wind(10.0, -math.pi / 2), 0.0, 0.0, 0.0)  # from port
    assert abeam[1] < 0
    # Driving at the wind's own velocity there is no relative wind.
    assert np.all(wind_force(OTTER, Wind(2.0, 0.0), 0.0, 2.0, 0.0) == 0.0)


def test_current_force_of_eq2_pushes_downstream() -> None:
    from usvstation.dynamics import current_force

    astern = current_force(OTTER, 0.5, 0.0)
    assert astern[0] > 0 and astern[1] == pytest.approx(0.0, abs=1e-12)
    beam = current_force(OTTER, 0.5, math.pi / 2)
    assert beam[1] == pytest.approx(0.5 * 1025 * 0.25 * OTTER.lateral_area_water * 1.0)


def test_environment_from_a_scenario_converts_degrees_at_the_edge() -> None:
    from usvstation.scenario import load_scenario

    env = Environment.from_scenario(load_scenario("case4").environment)  # 0.3 m/s to 120 deg
    assert env.current == pytest.approx((0.3 * math.cos(math.radians(120)),
                                         0.3 * math.sin(math.radians(120))))
    assert env.wind == Wind(5.0, math.radians(200.0))
    assert env.waves is None
    assert Environment.from_scenario(load_scenario("case1").environment).calm


def test_environment_refuses_negative_speeds() -> None:
    with pytest.raises(ValueError, match="current: speed must be >= 0"):
        Environment.with_current(-1.0, 0.0)
    with pytest.raises(ValueError, match="wind: speed must be >= 0"):
        Wind(-2.0, 0.0)


# ------------------------------------------------------------------ kinematic boat


def test_kinematic_boat_takes_the_heading_and_ramps_its_speed() -> None:
    boat = KinematicBoat(0.0, 0.0, accel_max=2.0)
    boat.step(math.pi / 2, 5.0, 0.2)
    assert boat.psi == math.pi / 2
    assert boat.speed == pytest.approx(0.4)
    assert (boat.x, boat.y) == pytest.approx((0.0, 0.04))  # average speed 0.2 m/s for 0.2 s
    for _ in range(20):
        boat.step(0.0, 1.0, 0.2)
    assert boat.speed == pytest.approx(1.0)
    boat.step(0.0, -3.0, 0.2)  # no going astern
    assert boat.speed == pytest.approx(0.6)


def test_a_push_acts_only_inside_its_area() -> None:
    """Paper 004's forces: a constant earth-frame push inside a rectangle (Table 7)."""
    from usvstation.dynamics import Push

    env = Environment(pushes=(Push(0.0, 15.0, -10.0, 10.0, -10.0, 10.0),))
    inside = run(Vessel(OTTER, VesselState(0.0, 0.0, 0.0)), ThrustCommand(0.0, 0.0), env, 2.0)
    outside = run(Vessel(OTTER, VesselState(50.0, 0.0, 0.0)), ThrustCommand(0.0, 0.0), env, 2.0)
    assert inside.velocity[1] > 0.05 and abs(inside.velocity[0]) < 0.01
    assert outside.velocity == (0.0, 0.0)
    with pytest.raises(ValueError, match="push: need x_min < x_max"):
        Push(1.0, 0.0, 5.0, -5.0)
