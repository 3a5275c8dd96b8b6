"""Scenario model: valid files load, invalid ones are refused naming the field and the reason."""

import copy
import json

import pytest

from usvstation.geometry import inflated_radius
from usvstation.scenario import (
    ScenarioError,
    bundled_scenario_dir,
    bundled_scenario_names,
    load_scenario,
    parse_scenario,
)

BASE = json.loads((bundled_scenario_dir() / "case1.json").read_text())


def with_change(path: str, value):
    data = copy.deepcopy(BASE)
    node = data
    keys = path.split(".")
    for key in keys[:-1]:
        node = node[int(key)] if key.isdigit() else node[key]
    last = keys[-1]
    if value is DELETE:
        del node[last]
    else:
        node[int(last) if last.isdigit() else last] = value
    return data


DELETE = object()


def error_of(data) -> str:
    with pytest.raises(ScenarioError) as info:
        parse_scenario(data)
    return str(info.value)


def test_public_scenarios_load():
    assert bundled_scenario_names() == ["case1", "case2", "case3", "case4"]
    for name in bundled_scenario_names():
        s = load_scenario(name)
        assert s.name == name and s.kind == "recovery" and s.origin is not None


def test_defaults_fill_optional_sections():
    s = parse_scenario({"name": "min", "start": {"x": 50.0, "y": 5.0},
                        "obstacles": [{"x": 20, "y": 0, "radius": 2}]})
    assert (s.goal.x, s.goal.y) == (0.0, 0.0)
    assert s.vessel.turn_max_deg == 60.0 and s.obstacles[0].vx == 0.0
    o, v = s.obstacles[0], s.vessel
    assert inflated_radius(o.radius, v.length, v.compensation_radius) == pytest.approx(4.2)  # eq. 7


@pytest.mark.parametrize(
    ("path", "value", "expected"),
    [
        ("start.x", "85", "start.x: Input should be a valid number (got '85')"),
        ("start.speed", True, "start.speed: Input should be a valid number (got True)"),
        ("obstacles.2.radius", -1, "obstacles[2].radius: Input should be greater than 0 (got -1)"),
        ("obstacles.0.radius", 0, "obstacles[0].radius: Input should be greater than 0 (got 0)"),
        ("vessel.length", 0, "vessel.length: Input should be greater than 0 (got 0)"),
        ("vessel.speed_min", -0.5, "vessel.speed_min: Input should be greater than 0"),
        ("vessel.accel_max", 0, "vessel.accel_max: Input should be greater than 0"),
        ("vessel.turn_max_deg", 270, "vessel.turn_max_deg: Input should be less than or equal"),
        ("kind", "docking", "kind: Input should be 'recovery' or 'transit' (got 'docking')"),
        ("name", "", "name: String should have at least 1 character"),
        ("start.colour", "red", "start.colour: unknown field"),
        ("speed_limit", 3, "speed_limit: unknown field"),
        ("start", DELETE, "start: required field is missing"),
        ("origin.lat", 95.0, "origin.lat: Input should be less than or equal to 90"),
    ],
)
def test_invalid_fields_are_named(path, value, expected):
    assert expected in error_of(with_change(path, value))


def test_speed_min_must_be_below_speed_max():
    data = with_change("vessel.speed_min", 3.0)
    assert "vessel.speed_min: must be below speed_max (got speed_min=3.0, speed_max=3.0)" in \
        error_of(data)


def test_start_inside_an_inflated_obstacle():
    # obstacle 0 of case1 is at (60, 8) radius 3: inflated to 5.2 m
    data = with_change("start.x", 62.0)
    data["start"]["y"] = 9.0
    assert error_of(data) == (
        "start: (62, 9) lies inside obstacles[0] inflated to R_l = 5.2 m (eq. 7) at t = 0"
    )


def test_goal_inside_an_inflated_obstacle():
    data = copy.deepcopy(BASE)
    data["obstacles"].append({"x": 2.0, "y": 1.0, "radius": 1.0, "vx": 0.0, "vy": 0.0})
    assert "goal: (0, 0) lies inside obstacles[4] inflated to R_l = 3.2 m" in error_of(data)


def test_recovery_goal_is_the_ramp_end_and_start_may_lie_anywhere_else():
    assert "goal: a recovery ends at the ramp end (0, 0)" in error_of(with_change("goal.x", 5.0))
    assert parse_scenario(with_change("start.x", -3.0)).start.x == -3.0  # behind the ramp
    data = with_change("start.x", 0.5)
    data["start"]["y"] = 0.0
    data["obstacles"] = []
    assert "goal: must lie at least 1 m from the start" in error_of(data)


def test_nan_is_refused():
    assert "start.y" in error_of(with_change("start.y", float("nan")))


def test_several_errors_in_one_line():
    data = with_change("start.x", "a")
    data["obstacles"][0]["radius"] = -2
    message = error_of(data)
    assert "\n" not in message
    assert message.index("start.x") < message.index("obstacles[0].radius")


def test_load_errors(tmp_path):
    with pytest.raises(ScenarioError, match=r"nope.json: no such scenario file"):
        load_scenario(tmp_path / "nope.json")
    bad = tmp_path / "bad.json"
    bad.write_text('{"name": "x",\n "start": }')
    with pytest.raises(ScenarioError, match=r"not valid JSON at line 2 column 11"):
        load_scenario(bad)
    top = tmp_path / "list.json"
    top.write_text("[1, 2]")
    with pytest.raises(ScenarioError, match="valid dictionary"):
        load_scenario(top)


def test_planner_options_in_the_scenario_are_validated():
    data = copy.deepcopy(BASE)
    data["planner"] = {"seed": 7, "population": 2}
    assert "planner.population: Input should be greater than or equal to 4" in error_of(data)
    data["planner"] = {"seed": 7, "mutation": 0.1}
    assert "planner.mutation: unknown field" in error_of(data)
    data["planner"] = {"seed": 7}
    assert parse_scenario(data).planner_options().seed == 7
