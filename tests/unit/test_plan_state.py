"""Issue 12 rules, hand-made: true clearance, start heading, current, timing margin, geometry,
bounded inputs, re-planning from a boat under way."""

import math

import pytest

from usvstation.planning.plan import NoFeasiblePlan, plan_scenario, replan_from
from usvstation.planning.validate import (
    closest_distance,
    first_turn_deg,
    hull_clearance,
    plan_violations,
    water_speeds,
)
from usvstation.scenario import ScenarioError, load_scenario, parse_scenario

BASE = {"name": "t", "start": {"x": 85.0, "y": 10.0, "heading_deg": 180.0, "speed": 1.0}}


def scenario(**parts):
    return parse_scenario({**BASE, **parts})


def straight_plan(x0, y0, x1, y1, speed=1.0):
    d = math.hypot(x1 - x0, y1 - y0)
    h = math.degrees(math.atan2(y1 - y0, x1 - x0)) % 360
    return {"waypoints": [
        {"x": x0, "y": y0, "t": 0.0, "speed": speed, "heading_deg": h},
        {"x": x1, "y": y1, "t": d / speed, "speed": speed, "heading_deg": h},
    ]}


def test_tangent_hull_is_a_collision_and_clearance_is_water_between_hull_and_obstacle():
    # hull of 1.2 m (half 0.6) along y = 0; obstacle of radius 1 centred 1.6 m off: touching
    sc = scenario(start={"x": 60.0, "y": 0.0}, obstacles=[{"x": 30.0, "y": 1.6, "radius": 1.0}])
    plan = straight_plan(60.0, 0.0, 0.0, 0.0)
    assert hull_clearance(plan, sc) == pytest.approx(0.0, abs=1e-12)
    assert any("touching or inside" in v for v in plan_violations(plan, sc))
    sc2 = scenario(start={"x": 60.0, "y": 0.0}, obstacles=[{"x": 30.0, "y": 1.7, "radius": 1.0}])
    assert hull_clearance(plan, sc2) == pytest.approx(0.1)
    assert plan_violations(plan, sc2) == []


def test_returned_min_clearance_is_the_hull_water_clearance():
    sc = load_scenario("case2")
    plan = plan_scenario(sc, seed=1).to_document()
    assert plan["metrics"]["min_clearance_m"] == pytest.approx(hull_clearance(plan, sc), abs=1e-5)
    assert plan["metrics"]["margin_kept"] is True
    assert plan["metrics"]["min_clearance_m"] > 0.0
    smooth = plan["smoothed"]
    assert smooth["min_clearance_m"] > 0.0


@pytest.mark.parametrize("heading", [0.0, 90.0, 270.0, 45.0])
def test_boat_pointing_away_turns_within_the_limit(heading):
    sc = scenario(start={"x": 85.0, "y": 10.0, "heading_deg": heading, "speed": 2.0})
    plan = plan_scenario(sc, seed=1).to_document()
    assert plan_violations(plan, sc) == []
    assert first_turn_deg(plan, sc) <= sc.vessel.turn_max_deg + 1e-6


def test_a_plan_ignoring_the_start_heading_is_refused():
    sc = scenario(start={"x": 85.0, "y": 10.0, "heading_deg": 0.0, "speed": 2.0})
    plan = straight_plan(85.0, 10.0, 0.0, 0.0, speed=2.0)
    assert any("from the start heading" in v for v in plan_violations(plan, sc))


@pytest.mark.parametrize("direction", [0.0, 90.0, 180.0, 225.0])
def test_strong_current_keeps_speed_through_the_water_in_limits(direction):
    sc = scenario(environment={"current_speed": 1.0, "current_dir_deg": direction})
    plan = plan_scenario(sc, seed=1).to_document()
    assert plan_violations(plan, sc) == []
    for lo, hi, forward in water_speeds(plan, sc):
        assert sc.vessel.speed_min - 1e-4 <= lo and hi <= sc.vessel.speed_max + 1e-4 and forward
    # the hull crabs into a cross current: heading differs from course over ground
    if direction == 90.0:
        w = plan["waypoints"][1]
        assert abs(math.remainder(math.radians(w["heading_deg"] - w["course_deg"]),
                                  2 * math.pi)) > 0.05


def test_current_changes_the_plan():
    calm = plan_scenario(scenario(), seed=1).to_document()
    against = plan_scenario(scenario(environment={"current_speed": 0.8,
                                                  "current_dir_deg": 0.0}), seed=1).to_document()
    assert calm["waypoints"] != against["waypoints"]


def test_a_plan_too_fast_through_the_water_is_refused():
    sc = scenario(start={"x": 85.0, "y": 0.0}, environment={"current_speed": 0.5,
                                                             "current_dir_deg": 0.0})
    plan = straight_plan(85.0, 0.0, 0.0, 0.0, speed=3.0)  # 3.5 m/s through the water
    assert any("through the water" in v for v in plan_violations(plan, sc))


def crossing_ship():
    # a ship crossing the approach at 6 m/s (2x the boat's top speed)
    return scenario(start={"x": 85.0, "y": 0.0},
                    obstacles=[{"x": 45.0, "y": -150.0, "radius": 3.0, "vx": 0.0, "vy": 6.0}])


def test_timing_margin_keeps_the_hull_clear_when_early_or_late():
    sc = crossing_ship()
    plan = plan_scenario(sc, seed=1).to_document()
    assert plan_violations(plan, sc) == []
    ship = sc.obstacles[0]
    half = sc.vessel.length / 2
    for shift in [-3.0, -2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 2.0, 3.0]:
        for a, b in zip(plan["waypoints"], plan["waypoints"][1:], strict=False):
            late_a, late_b = {**a, "t": a["t"] + shift}, {**b, "t": b["t"] + shift}
            d = closest_distance(late_a, late_b, ship.x, ship.y, ship.vx, ship.vy)
            assert d - ship.radius - half > 0.0


def test_a_plan_that_only_works_on_time_is_refused():
    # the ship crosses the boat's track 4 s ahead of it: 2.3 m of water on time, a hit when
    # the boat runs 3 s early
    sc = parse_scenario({**BASE, "start": {"x": 50.0, "y": 0.0},
                         "vessel": {"time_margin_s": 3.0},
                         "obstacles": [{"x": 25.0, "y": 126.0,
                                        "radius": 1.0, "vx": 0.0, "vy": -6.0}]})
    plan = straight_plan(50.0, 0.0, 0.0, 0.0)
    out = plan_violations(plan, sc)
    assert any("early or late" in v for v in out)


@pytest.mark.parametrize("start", [{"x": -20.0, "y": 30.0}, {"x": 3.0, "y": 15.0},
                                   {"x": 2.0, "y": -8.0, "heading_deg": 90.0, "speed": 1.5}])
def test_starts_behind_or_beside_the_ramp(start):
    sc = scenario(start=start)
    plan = plan_scenario(sc, seed=1).to_document()
    assert plan_violations(plan, sc) == []
    assert abs(plan["waypoints"][-1]["course_deg"] - 180.0) <= 10.0


def test_replan_from_a_boat_under_way_propagates_obstacles():
    sc = crossing_ship()
    first = plan_scenario(sc, seed=1).to_document()
    w = first["waypoints"][3]
    again = replan_from(sc, w["x"], w["y"], w["heading_deg"], w["speed"], w["t"],
                        seed=1).to_document()
    assert again["waypoints"][0]["x"] == pytest.approx(w["x"])
    assert again["waypoints"][0]["t"] == 0.0
    ship = sc.obstacles[0]
    moved = sc.model_copy(update={"obstacles": []})
    assert moved.obstacles == []  # the original scenario is left alone
    assert ship.y == -150.0


def test_time_budget_is_respected_with_a_warning_or_no_plan():
    sc = load_scenario("case4")
    try:
        plan = plan_scenario(sc, seed=1, time_budget_s=0.001).to_document()
    except NoFeasiblePlan as exc:
        assert "time budget" in str(exc) or "no feasible plan" in str(exc)
    else:
        assert plan_violations(plan, sc) == []
        assert any("time budget" in w for w in plan["warnings"])


@pytest.mark.parametrize("path, value, expected", [
    (("start", "x"), 1e308, "start.x: Input should be less than or equal to 20000"),
    (("start", "speed"), 31.0, "start.speed: Input should be less than or equal to 30"),
    (("planner", "x_resolution"), 1e-9, "planner.x_resolution: Input should be greater"),
    (("planner", "population"), 5000, "planner.population: Input should be less"),
    (("planner", "generations_max"), 5001, "planner.generations_max: Input should be less"),
    (("planner", "time_budget_s"), 0.0, "planner.time_budget_s: Input should be greater"),
])
def test_out_of_range_inputs_are_refused_in_one_line(path, value, expected):
    data = {**BASE, "planner": {}}
    data = {k: (dict(v) if isinstance(v, dict) else v) for k, v in data.items()}
    data[path[0]][path[1]] = value
    with pytest.raises(ScenarioError) as info:
        parse_scenario(data)
    assert str(info.value).startswith(expected)
    assert "\n" not in str(info.value) and len(str(info.value)) < 300


def test_long_values_are_echoed_short(tmp_path):
    f = tmp_path / "s.json"
    f.write_text('{"name": "a", "start": {"x": ' + "9" * 5000 + ', "y": 0}}')
    with pytest.raises(ScenarioError) as info:
        load_scenario(f)
    assert len(str(info.value)) < 200 + len(str(f))
    data = {**BASE, "name": "n" * 300}
    with pytest.raises(ScenarioError) as info:
        parse_scenario(data)
    assert "name:" in str(info.value) and len(str(info.value)) < 200


def test_too_many_obstacles_are_refused():
    data = {**BASE, "obstacles": [{"x": 500.0, "y": float(i), "radius": 0.1}
                                  for i in range(2001)]}
    with pytest.raises(ScenarioError, match="obstacles: List should have at most 2000"):
        parse_scenario(data)
