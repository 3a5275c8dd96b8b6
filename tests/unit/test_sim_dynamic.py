"""The simulated boat's dynamic vehicle: follows an IGA plan to the ramp end, holds, resumes."""

import math

import pytest

from usvstation.bench.tracking import scenario_for_vessel
from usvstation.dynamics import Environment, otter
from usvstation.planning.plan import plan_scenario
from usvstation.scenario import load_scenario
from usvstation.sim.dynamic import HOLD_RADIUS, DynamicVehicle
from usvstation.sim.runner import make_vehicle
from usvstation.sim.vehicle import Vehicle, Waypoint


@pytest.fixture(scope="module")
def mission():
    scenario = scenario_for_vessel(load_scenario("case1"), otter())
    plan = plan_scenario(scenario, seed=1)
    wps = [Waypoint(w["x"], w["y"], w["t"], w["speed"], math.radians(w["heading_deg"]))
           for w in plan["waypoints"]]
    return scenario, plan, wps


def vehicle_for(scenario, wps):
    env = Environment.from_scenario(scenario.environment)
    return DynamicVehicle(wps[0].x, wps[0].y, wps[0].heading, speed=wps[0].speed, env=env)


def test_it_is_a_vehicle():
    assert isinstance(make_vehicle("dynamic", load_scenario("case2")), Vehicle)
    with pytest.raises(ValueError, match="unknown kind 'boat'"):
        make_vehicle("boat", load_scenario("case2"))


def test_follows_the_plan_to_the_ramp_end(mission):
    scenario, plan, wps = mission
    v = vehicle_for(scenario, wps)
    v.set_mission(wps)
    for _ in range(20):  # not started: keeps station
        v.step(0.2)
    assert math.hypot(v.state.x - wps[0].x, v.state.y - wps[0].y) < HOLD_RADIUS + 1.0
    v.start()
    worst = 0.0
    while not v.state.mission_complete and v.state.t < plan["metrics"]["duration_s"] + 60:
        v.step(0.2)
        assert -1.0 <= v.state.thrust_left <= 1.0 and -1.0 <= v.state.thrust_right <= 1.0
        worst = max(worst, abs(v.state.cross_track_error))
    s = v.state
    assert s.mission_complete
    assert math.hypot(s.x, s.y) < 2.0  # at the ramp end
    assert abs(math.degrees(math.remainder(s.heading - math.pi, 2 * math.pi))) < 10.0
    assert s.waypoint_index == len(wps) - 1
    assert worst < 3.0
    t_done = s.t
    for _ in range(50):  # on the ramp: propellers stopped
        v.step(0.2)
    assert v.state.thrust_left == 0.0 and v.state.thrust_right == 0.0
    assert v.state.t == pytest.approx(t_done + 10.0)


def test_hold_keeps_station_and_resume_completes(mission):
    scenario, _, wps = mission
    v = vehicle_for(scenario, wps)
    v.set_mission(wps)
    v.start()
    for _ in range(40):
        v.step(0.2)
    v.hold()
    x0, y0 = v.state.x, v.state.y
    while v.state.speed >= 0.3:  # coasts to rest
        v.step(0.2)
        assert v.state.thrust_left == 0.0 and v.state.thrust_right == 0.0
    xs, ys = v.state.x, v.state.y
    assert math.hypot(xs - x0, ys - y0) < 15.0
    for _ in range(200):  # then 40 s of holding where it stopped
        v.step(0.2)
        assert math.hypot(v.state.x - xs, v.state.y - ys) < HOLD_RADIUS + 1.0
    assert not v.state.mission_complete and v.phase == "hold"
    v.resume()
    while not v.state.mission_complete and v.state.t < 300:
        v.step(0.2)
    assert v.state.mission_complete and math.hypot(v.state.x, v.state.y) < 2.0


def test_guided_mode_and_abort(mission):
    scenario, _, wps = mission
    v = vehicle_for(scenario, wps)
    v.set_mission(wps)
    v.start()
    v.set_guidance(math.pi / 2, 1.5)  # north-ish in the ramp frame at 1.5 m/s
    for _ in range(100):
        v.step(0.2)
    assert abs(math.remainder(v.state.course - math.pi / 2, 2 * math.pi)) < math.radians(10)
    assert v.state.speed == pytest.approx(1.5, abs=0.3)
    v.clear_guidance()
    assert v.phase == "track"
    v.abort()
    v.step(0.2)
    assert v.phase == "aborted"
    assert v.state.thrust_left == 0.0 and v.state.thrust_right == 0.0
    v.start()  # nothing to start after an abort
    assert v.phase == "aborted"
