"""Sensors, not truth (issue 23 item 3): named, seeded sensor profiles and a hull that is not
the model; the simulated boat steers on what it measures and reports it."""

import math
from dataclasses import replace

import numpy as np
import pytest

from usvstation.dynamics import Environment, HullMismatch, VesselState, otter
from usvstation.geo import RampFrame
from usvstation.link.mavlink import usv_recovery as mav
from usvstation.scenario import load_scenario
from usvstation.sim.dynamic import DynamicVehicle
from usvstation.sim.frame import RampMotion
from usvstation.sim.runner import make_boat, make_vehicle
from usvstation.sim.sensors import (
    SENSOR_PROFILES,
    BoatSensors,
    GnssSpec,
    SensorProfile,
    sensor_profile,
)


def _moving(t: float, vx: float = 1.5, vy: float = 0.5) -> VesselState:
    return VesselState(10.0 + vx * t, -3.0 + vy * t, math.atan2(vy, vx), math.hypot(vx, vy),
                       0.0, 0.0, t)


def _run(sensors: BoatSensors, seconds: float, dt: float = 0.05, truth=_moving):
    out = []
    for k in range(round(seconds / dt)):
        t = k * dt
        out.append((truth(t), sensors.measure(truth(t), t)))
    return out


def test_profiles_by_name_and_a_clear_error_for_an_unknown_one():
    assert set(SENSOR_PROFILES) == {"exact", "rtk", "gnss", "rtk-moving-base"}
    assert sensor_profile("rtk").gnss.white_std_m == 0.02
    assert sensor_profile("gnss").gnss.cep_m == pytest.approx(1.5, abs=0.02)
    assert sensor_profile("rtk-moving-base").gnss.relative
    p = SensorProfile("mine")
    assert sensor_profile(p) is p
    with pytest.raises(ValueError, match="unknown profile 'dgps'; available: exact, rtk"):
        sensor_profile("dgps")
    with pytest.raises(ValueError, match="white_std_m must be finite and >= 0"):
        GnssSpec(white_std_m=-1.0)
    with pytest.raises(ValueError, match="drag_scale must be within"):
        HullMismatch(drag_scale=0.0)


def test_exact_sensors_read_the_truth():
    for truth, m in _run(BoatSensors("exact"), 5.0):
        assert (m.x, m.y, m.psi, m.r) == pytest.approx((truth.x, truth.y, truth.psi, truth.r))
        assert m.sog == pytest.approx(truth.speed) and m.cog == pytest.approx(truth.course)


@pytest.mark.parametrize("name", ["rtk", "gnss", "rtk-moving-base"])
def test_the_same_seed_gives_the_same_measurements_and_another_seed_others(name):
    a = [m for _, m in _run(BoatSensors(name, seed=4), 20.0)]
    b = [m for _, m in _run(BoatSensors(name, seed=4), 20.0)]
    c = [m for _, m in _run(BoatSensors(name, seed=5), 20.0)]
    assert a == b and a != c


def test_plain_gnss_errs_by_its_cep_and_rtk_by_centimetres():
    def radial(name: str) -> np.ndarray:
        errors = []
        for seed in range(300):  # one fix each, many receivers: the stationary spread
            truth, m = _run(BoatSensors(name, seed=seed), 0.1)[-1]
            errors.append(math.hypot(m.x - truth.x, m.y - truth.y))
        return np.array(errors)

    assert np.median(radial("gnss")) == pytest.approx(1.5, rel=0.2)
    assert np.percentile(radial("rtk"), 95) < 0.06


def test_plain_gnss_error_wanders_slowly():
    """Most of the error is the random walk: consecutive fixes differ far less than 1.5 m."""
    runs = _run(BoatSensors("gnss", seed=2), 60.0)
    err = np.array([(m.x - t.x, m.y - t.y) for t, m in runs])
    step = np.hypot(*np.diff(err[::4], axis=0).T)  # 0.2 s apart (the 5 Hz fixes)
    assert np.median(step) < 0.8 < np.max(np.hypot(*err.T))


def test_latency_and_outages_are_dead_reckoned_from_the_last_fix():
    spec = GnssSpec(rate_hz=5.0, latency_s=0.3, dropout_per_min=60.0, dropout_s=2.0)
    sensors = BoatSensors(SensorProfile("late", spec), seed=1)
    outages = 0
    for truth, m in _run(sensors, 60.0):
        # a straight run at constant velocity: extrapolating the old fix is exact
        assert (m.x, m.y) == pytest.approx((truth.x, truth.y), abs=1e-9)
        outages += not sensors.fix_ok
    assert outages > 0  # about one outage a second, each dead-reckoned
    turning = BoatSensors(SensorProfile("late", GnssSpec(rate_hz=5.0, latency_s=0.3)))

    def circle(t: float) -> VesselState:
        return VesselState(10 * math.cos(0.2 * t), 10 * math.sin(0.2 * t), 0.2 * t + math.pi / 2,
                           2.0, 0.0, 0.2, t)

    late = [math.hypot(m.x - s.x, m.y - s.y) for s, m in _run(turning, 20.0, truth=circle)]
    assert 0.01 < max(late) < 0.5  # in a turn the extrapolated fix lags the truth a little


def test_a_compass_bias_reads_high_by_its_bias_and_lags():
    p = SensorProfile("biased").with_compass_bias(3.0)
    for truth, m in _run(BoatSensors(p), 2.0):
        assert math.degrees(m.psi - truth.psi) == pytest.approx(3.0)
    lagging = BoatSensors(replace(p, compass=replace(p.compass, lag_s=1.0, bias_deg=0.0)))
    lagging.measure(_moving(0.0), 0.0)
    turned = replace(_moving(0.1), psi=_moving(0.1).psi + 0.5)
    assert lagging.measure(turned, 0.1).psi - _moving(0.0).psi == pytest.approx(
        0.5 * (1 - math.exp(-0.1)), rel=1e-6)


def test_moving_base_rtk_measures_against_the_true_ramp():
    """The fix is relative to the ramp itself: where the ship is, and what the boat was told
    about it, do not enter."""
    ramp = RampMotion(100.0, 50.0, 0.4, 2.0, -1.0, 0.01, 0.0)
    sensors = BoatSensors(SensorProfile("mb", GnssSpec(relative=True)))
    for t in (0.0, 3.0, 7.5):
        truth = _moving(t)
        m = sensors.measure(truth, t, ramp.at(t))
        want = ramp.at(t).measure(BoatSensors("exact").measure(truth, t))
        assert (m.x, m.y, m.sog, m.cog) == pytest.approx((want.x, want.y, want.sog, want.cog))


def test_hull_mismatch_scales_drag_and_thrust_and_lowers_top_speed():
    p = otter()
    assert HullMismatch().apply(p) is p
    fouled = HullMismatch(drag_scale=1.25, thrust_scale=0.85).apply(p)
    assert fouled.surge_drag(2.0) == pytest.approx(1.25 * p.surge_drag(2.0))
    assert fouled.thrusters.thrust_max == pytest.approx(0.85 * p.thrusters.thrust_max)
    assert fouled.damping(0.0, 0.5, 0.1)[1] == pytest.approx(1.25 * p.damping(0.0, 0.5, 0.1)[1])
    assert fouled.top_speed < 0.9 * p.top_speed


def test_the_boat_holds_on_what_it_measures_and_its_truth_is_offset_by_the_error():
    """A GNSS offset that does not wander (one draw, a very long correlation time): the boat
    keeps its *measured* position on the hold point, so its true position sits off it by
    the error. The truth is there for the judge; the boat never uses it."""
    spec = GnssSpec(bias_std_m=2.0, bias_tau_s=1e9)
    v = DynamicVehicle(40.0, 0.0, math.pi, env=Environment.with_current(0.5, math.pi / 2),
                       sensors=SensorProfile("offset", spec), seed=11)
    bias = v.sensors._bias.copy()
    assert math.hypot(*bias) > 1.0
    for _ in range(600):  # READY keeps station on its start point  # 120 s
        v.step(0.2)
    s, t = v.state, v.truth
    assert math.hypot(s.x - 40.0, s.y) < 1.0
    assert (t.x, t.y) == pytest.approx((40.0 - bias[0], -bias[1]), abs=0.8)
    assert (s.x - t.x, s.y - t.y) == pytest.approx(tuple(bias), abs=0.01)  # 50 ms apart


def test_a_slower_hull_than_the_model_still_holds_its_heading_and_arrives():
    scenario = load_scenario("case2")
    v = make_vehicle("dynamic", scenario, sensors="rtk", hull=HullMismatch(1.25, 0.85), seed=1)
    assert v.true_params.top_speed < v.params.top_speed
    assert v.truth != v.state


def test_the_telemetry_reports_what_the_boat_measures():
    spec = GnssSpec(bias_std_m=3.0, bias_tau_s=1e9)
    vehicle = DynamicVehicle(40.0, 0.0, math.pi, sensors=SensorProfile("off", spec), seed=2)
    frame = RampFrame(30.5, 114.4, 90.0)
    boat = make_boat(frame, vehicle=vehicle)  # gnss_error on: not added to a sensed vehicle
    parser = mav.MAVLink(None)
    parser.robust_parsing = True
    now = boat.last_now
    for k in range(1, 11):
        boat.update(now + 0.2 * k)
    msgs = parser.parse_buffer(boat.data_to_send(now + 2.0)) or []
    fixes = [m for m in msgs if m.get_type() == "GLOBAL_POSITION_INT"]
    raw = [m for m in msgs if m.get_type() == "GPS_RAW_INT"]
    assert fixes and raw and raw[-1].fix_type == 3
    x, y = frame.to_ramp(fixes[-1].lat / 1e7, fixes[-1].lon / 1e7)
    s, t = vehicle.state, vehicle.truth
    assert math.hypot(float(x) - s.x, float(y) - s.y) < 0.05  # the measured position
    assert math.hypot(float(x) - t.x, float(y) - t.y) > 1.0  # not the true one
