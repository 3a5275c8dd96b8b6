"""Recoveries against a strong current (issue 12 rule 3; issue 15's mother ship under way).

A ship making way along -x (the ramp points astern) puts an apparent current of 1-2 m/s along
+x into the ramp frame: a boat heading for the ramp at 0.5 m/s through the water is set back
over ground. Every plan must keep the speed through the water in [speed_min, speed_max], the
first leg within turn_max of the hull heading, and pass both the planner's exact validator and
the bench's independent checker.
"""

import math

import pytest

from usvstation.bench.checker import check_plan
from usvstation.planning.plan import plan_scenario
from usvstation.planning.start import start_state
from usvstation.planning.validate import first_turn_deg, plan_violations, water_speeds
from usvstation.scenario import parse_scenario

# the bench's boat: the Otter (2 m), planned at most 2.47 m/s through the water
VESSEL = {"length": 2.0, "speed_min": 0.2, "speed_max": 2.47, "accel_max": 0.5,
          "turn_max_deg": 60.0, "compensation_radius": 1.0}
OBSTACLES = [{"x": 45.0, "y": 4.0, "radius": 3.0}, {"x": 25.0, "y": -8.0, "radius": 2.5},
             {"x": 60.0, "y": -12.0, "radius": 2.0, "vx": 0.0, "vy": 0.4}]


def recovery(current: float, direction_deg: float, speed: float = 0.5, heading: float = 180.0,
             y: float = 6.0, obstacles: list | None = None):
    return parse_scenario({
        "name": "strong-current", "start": {"x": 82.0, "y": y, "heading_deg": heading,
                                            "speed": speed},
        "vessel": VESSEL, "obstacles": OBSTACLES if obstacles is None else obstacles,
        "environment": {"current_speed": current, "current_dir_deg": direction_deg},
    })


def assert_valid(plan, sc):
    assert plan_violations(plan, sc) == []
    report = check_plan(plan, sc)
    assert report.problems == []
    v = sc.vessel
    for lo, hi, forward in water_speeds(plan, sc):
        assert v.speed_min - 1e-4 <= lo <= hi <= v.speed_max + 1e-4
        assert forward
    if sc.start.speed >= 0.5:
        assert first_turn_deg(plan, sc) <= v.turn_max_deg + 1e-6
    if sc.obstacles:
        assert plan["metrics"]["min_clearance_m"] > 0.0


@pytest.mark.parametrize("current", [1.0, 1.5, 2.0])
@pytest.mark.parametrize("direction_deg", [0.0, 90.0, 270.0])
def test_recovery_against_a_strong_current_is_planned_and_valid(current, direction_deg):
    sc = recovery(current, direction_deg)
    plan = plan_scenario(sc, seed=1).to_document()
    assert_valid(plan, sc)
    last = plan["waypoints"][-1]
    assert (last["x"], last["y"]) == (0.0, 0.0)


@pytest.mark.parametrize("current", [1.0, 1.5])
def test_a_boat_making_way_against_the_current_starts_from_its_speed_over_ground(current):
    # 0.5 m/s over ground towards the ramp against `current` along +x (0.5 + current through
    # the water): the plan starts from 0.5 m/s, the first leg towards the ramp
    sc = recovery(current, 0.0)
    state = start_state(sc)
    assert state.course == pytest.approx(math.pi)
    assert state.speed == 0.5
    plan = plan_scenario(sc, seed=1).to_document()
    assert_valid(plan, sc)
    assert plan["waypoints"][0]["speed"] == 0.5
    assert not any("start speed" in w for w in plan["warnings"])


def test_a_boat_set_back_by_the_current_is_planned_along_its_hull():
    # 0.5 m/s over ground against 2 m/s along +x: making way towards the ramp would take
    # 2.5 m/s through the water, above speed_max 2.47, so the boat is set back (1.5 m/s
    # through the water, drifting away). Its first leg still runs towards the ramp within
    # turn_max of its hull, from the fastest ground speed that leg admits (0.47 m/s), and
    # the plan says that it could not start from 0.5 m/s
    sc = recovery(2.0, 0.0)
    state = start_state(sc)
    assert state.course == pytest.approx(math.pi)
    assert state.speed == pytest.approx(2.47 - 2.0)
    plan = plan_scenario(sc, seed=1).to_document()
    assert_valid(plan, sc)
    first = plan["waypoints"][0]
    assert first["speed"] == pytest.approx(2.47 - 2.0)
    assert math.cos(math.radians(first["heading_deg"])) < 0.0  # hull towards the ramp
    assert any("start speed 0.5 m/s over ground" in w for w in plan["warnings"])


@pytest.mark.parametrize(("current", "direction_deg", "heading", "speed"),
                         [(0.8, 180.0, 180.0, 1.0), (0.8, 0.0, 180.0, 1.0),
                          (1.2, 90.0, 180.0, 1.6), (0.5, 135.0, 200.0, 1.0),
                          (1.0, 270.0, 160.0, 1.0)])
def test_in_a_current_the_plan_starts_from_the_start_speed_over_ground(
        current, direction_deg, heading, speed):
    """The start speed is over ground: the first waypoint's speed is exactly it (no jump to
    the ground speed the hull makes through the water plus the current, 1.0 -> 1.8 m/s
    before), and the first leg reaches the next waypoint's speed within accel_max."""
    sc = recovery(current, direction_deg, speed=speed, heading=heading)
    plan = plan_scenario(sc, seed=2).to_document()
    assert_valid(plan, sc)
    a, b = plan["waypoints"][:2]
    assert a["speed"] == speed
    assert not any("start speed" in w for w in plan["warnings"])
    assert abs(b["speed"] - a["speed"]) / (b["t"] - a["t"]) <= VESSEL["accel_max"] * (1 + 1e-6)


def test_a_start_faster_than_the_cross_current_allows_is_planned_with_a_warning():
    """1 m/s over ground with the hull across a 1.2 m/s cross current cannot be: the plan
    starts from a speed its first leg admits and says so."""
    sc = recovery(1.2, 90.0, speed=1.0, heading=180.0)
    plan = plan_scenario(sc, seed=2).to_document()
    assert_valid(plan, sc)
    assert any("start speed 1 m/s over ground" in w for w in plan["warnings"])


def test_stronger_current_takes_longer_over_ground():
    durations = [plan_scenario(recovery(c, 0.0), seed=1).to_document()["metrics"]["duration_s"]
                 for c in (1.0, 1.5, 2.0)]
    assert durations == sorted(durations)
    # 82 m at most speed_max - current over ground
    assert durations[-1] >= 82.0 / (2.47 - 2.0)


@pytest.mark.parametrize("current", [1.0, 2.0])
def test_a_still_boat_in_a_strong_current_is_planned(current):
    sc = recovery(current, 0.0, speed=0.0)
    assert_valid(plan_scenario(sc, seed=1).to_document(), sc)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_bench_episode_with_the_ship_at_two_metres_a_second(seed):
    import numpy as np

    from usvstation.bench.live import episode_scenario

    sc = episode_scenario(np.random.default_rng(1000 + seed), 2.0)
    plan = plan_scenario(sc, seed=seed).to_document()
    assert_valid(plan, sc)


@pytest.mark.parametrize("heading", [0.0, 90.0, 135.0])
@pytest.mark.parametrize(("current", "direction_deg"), [(1.5, 0.0), (2.0, 0.0), (2.0, 90.0),
                                                        (1.0, 180.0)])
def test_a_boat_pointing_away_in_a_strong_current_turns_within_the_limit(
        heading, current, direction_deg):
    # the run-out turns the hull by at most turn_max on its first leg and the course over
    # ground by at most turn_max at every waypoint, its speeds through the water in limits.
    # Static obstacles only: the slow run-out against 2 m/s (about 85 s) would meet the
    # moving one of OBSTACLES where it is then.
    h, c = math.radians(heading), math.radians(direction_deg)
    over_ground = math.hypot(1.5 * math.cos(h) + current * math.cos(c),
                             1.5 * math.sin(h) + current * math.sin(c))  # 1.5 through the water
    sc = recovery(current, direction_deg, speed=round(over_ground, 6), heading=heading,
                  obstacles=OBSTACLES[:2])
    plan = plan_scenario(sc, seed=1).to_document()
    assert_valid(plan, sc)
