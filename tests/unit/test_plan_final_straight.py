"""The planner's final straight along the ramp axis (planner option `final_straight`, issue 24;
an extension of paper 000): the last leg of a recovery along the axis from at least the
first approach gate in, so the boat's gates can all be met; the paper's run-in otherwise."""

from __future__ import annotations

import math

import pytest

from usvstation.planning.plan import final_straight_options, plan_scenario, straight_length
from usvstation.planning.validate import plan_violations
from usvstation.scenario import load_scenario, parse_scenario


def otter_case(name: str, **changes) -> object:
    data = load_scenario(name).model_dump()
    data["vessel"].update(length=2.0, speed_max=2.4)
    data.update(changes)
    return parse_scenario(data)


def last_leg(plan: dict) -> tuple[float, float]:
    """(length m, angle off the ramp axis deg) of the plan's last leg."""
    a, b = plan["waypoints"][-2], plan["waypoints"][-1]
    length = math.hypot(a["x"] - b["x"], a["y"] - b["y"])
    return length, abs(math.degrees(math.atan2(a["y"] - b["y"], a["x"] - b["x"])))


@pytest.mark.parametrize("name", ["case1", "case3"])
def test_the_last_leg_runs_along_the_axis_from_the_first_gate_in(name):
    scenario = otter_case(name)
    plan = plan_scenario(scenario, seed=21, final_straight=True).to_document()
    gate = scenario.vessel.gates_m[0]
    length, off = last_leg(plan)
    assert length >= gate and off <= 1.0
    assert plan["metrics"]["final_straight_m"] >= gate
    assert not plan_violations(plan, scenario)
    assert not plan.get("warnings")


def test_a_start_off_the_axis_and_close_in_runs_out_for_the_room():
    """case3 starts 40 m out and 35 m to the side: the straight needs a run-out first."""
    scenario = otter_case("case3")
    paper = plan_scenario(scenario, seed=21).to_document()
    straight = plan_scenario(scenario, seed=21, final_straight=True).to_document()
    assert paper["metrics"]["final_straight_m"] < 30.0 <= straight["metrics"]["final_straight_m"]
    assert straight["metrics"]["prefix_legs"] > 0
    assert straight["metrics"]["duration_s"] > paper["metrics"]["duration_s"]


def test_a_boat_already_coming_in_keeps_the_straight_it_has_room_for():
    """A new approach from 50 m out on the axis (a standby point): no run-out to sea."""
    scenario = otter_case("case1", start={"x": 50.0, "y": 0.0, "heading_deg": 180.0,
                                          "speed": 0.5}, obstacles=[])
    opts = final_straight_options(scenario, scenario.planner_options(final_straight=True))
    assert opts is not None and 5.0 < opts.approach_length < 30.0
    plan = plan_scenario(scenario, seed=1, final_straight=True).to_document()
    assert plan["metrics"]["prefix_legs"] == 0
    assert plan["metrics"]["final_straight_m"] == pytest.approx(50.0)
    close = otter_case("case1", start={"x": 20.0, "y": 0.5, "heading_deg": 180.0, "speed": 1.0})
    assert final_straight_options(close, close.planner_options(final_straight=True)) is None


def test_an_obstacle_on_the_axis_falls_back_to_the_papers_run_in_with_a_warning():
    obstacles = [{"x": 18.0, "y": 0.0, "radius": 2.0, "vx": 0.0, "vy": 0.0}]
    scenario = otter_case("case1", obstacles=obstacles)
    plan = plan_scenario(scenario, seed=21, final_straight=True).to_document()
    (warning,) = plan["warnings"]
    assert warning.startswith("no plan with a final straight of 30 m along the ramp axis")
    assert warning.endswith("planned with the 5 m run-in")
    assert not plan_violations(plan, scenario)


def test_off_by_default_and_not_for_a_transit():
    scenario = otter_case("case1")
    assert final_straight_options(scenario, scenario.planner_options()) is None
    default = plan_scenario(scenario, seed=21).to_document()
    explicit = plan_scenario(scenario, seed=21, final_straight=False).to_document()
    assert default["waypoints"] == explicit["waypoints"]
    transit = otter_case("case1", kind="transit", goal={"x": -30.0, "y": 0.0})
    assert final_straight_options(transit, transit.planner_options(final_straight=True)) \
        is None


def test_straight_length_counts_the_last_legs_on_the_axis():
    import numpy as np

    xs = np.array([80.0, 60.0, 40.0, 20.0, 0.0])
    ys = np.array([10.0, 4.0, 0.3, -0.2, 0.0])
    assert straight_length(xs, ys) == pytest.approx(math.hypot(20.0, 0.5) +
                                                    math.hypot(20.0, 0.2))
    assert straight_length(xs, np.array([10.0, 4.0, 2.0, 1.0, 0.0])) == 0.0
