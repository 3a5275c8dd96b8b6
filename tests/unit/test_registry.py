"""The planner registry: every planner's plans pass the independent checker."""

import json

import pytest

from usvstation.cli import main
from usvstation.planning.errors import NoFeasiblePlan
from usvstation.planning.registry import (
    PlannerOptionError,
    describe_planners,
    plan_with,
    planner_names,
)
from usvstation.planning.validate import plan_violations
from usvstation.scenario import load_scenario, parse_scenario

SEED_PLANNERS = ["colregs-ga", "replan-ga", "de-apf", "rrt-star", "bspline-rrt-star",
                 "vpf-rrt-star"]


def test_registry_lists_every_planner_with_paper_and_capabilities():
    got = describe_planners()
    assert [p["name"] for p in got] == ["iga", *SEED_PLANNERS]
    assert [p["paper"] for p in got] == ["000", "001", "002", "003", "004", "004", "004"]
    for p in got:
        assert set(p) == {"name", "paper", "title", "capabilities"}
        assert all(isinstance(c, str) for c in p["capabilities"])
    assert "colregs" in got[1]["capabilities"]
    assert "re-planning" in got[2]["capabilities"]


@pytest.mark.parametrize("name", SEED_PLANNERS)
def test_seed_planner_plans_pass_the_checker(name):
    sc = load_scenario("case2")
    plan = plan_with(sc, name, 1).to_document()
    assert plan["planner"] == name and plan["scenario"] == "case2"
    assert plan_violations(plan, sc) == []
    wps = plan["waypoints"]
    assert (wps[0]["x"], wps[0]["y"], wps[0]["t"]) == (78.0, -10.0, 0.0)
    assert (wps[-1]["x"], wps[-1]["y"]) == (0.0, 0.0)
    assert 175.0 <= wps[-1]["heading_deg"] <= 185.0   # the run-in along the ramp axis
    assert plan["metrics"]["min_clearance_m"] > 0.0


@pytest.mark.parametrize("name", ["iga", *SEED_PLANNERS])
def test_open_water_plans_have_no_clearance_and_match_the_plan_record(name):
    """No obstacle: every planner plans it, with `min_clearance_m` null (nothing to clear),
    and the plan has the shape the station stores and serves (records.PlanDocument)."""
    from pydantic import TypeAdapter

    from usvstation.records import PlanDocument

    sc = load_scenario("case1").model_copy(update={"obstacles": []})
    plan = plan_with(sc, name, 1).to_document()
    assert plan["metrics"]["min_clearance_m"] is None
    assert plan_violations(plan, sc) == []
    assert TypeAdapter(PlanDocument).validate_python(plan) == plan  # nothing lost or changed


@pytest.mark.parametrize("name", ["rrt-star", "vpf-rrt-star", "de-apf"])
def test_same_seed_same_plan(name):
    sc = load_scenario("case1")
    a, b = plan_with(sc, name, 3).to_document(), plan_with(sc, name, 3).to_document()
    assert a["waypoints"] == b["waypoints"]


def test_unknown_planner_and_bad_option_name_the_field():
    sc = load_scenario("case1")
    with pytest.raises(PlannerOptionError, match="planner: unknown planner 'nope'"):
        plan_with(sc, "nope").to_document()
    with pytest.raises(PlannerOptionError, match=r"planner\.iterations"):
        plan_with(sc, "rrt-star", 1, iterations=3).to_document()
    with pytest.raises(PlannerOptionError, match=r"planner\.bogus"):
        plan_with(sc, "de-apf", 1, bogus=1).to_document()


ENCLOSED = {
    "name": "enclosed", "kind": "transit", "start": {"x": 0.0, "y": 0.0, "speed": 1.0},
    "goal": {"x": 60.0, "y": 0.0},
    "obstacles": [{"x": 60.0 + 9.0 * c, "y": 9.0 * s, "radius": 3.5}
                  for c, s in ((1, 0), (0.7071, 0.7071), (0, 1), (-0.7071, 0.7071), (-1, 0),
                               (-0.7071, -0.7071), (0, -1), (0.7071, -0.7071))],
}


@pytest.mark.parametrize("name", ["rrt-star", "replan-ga"])
def test_enclosed_goal_is_no_feasible_plan(name):
    with pytest.raises(NoFeasiblePlan, match=name):
        plan_with(parse_scenario(ENCLOSED), name, 1, attempts=2, **(
            {"iterations": 300} if name == "rrt-star" else {})).to_document()


def test_cli_plan_with_planner(tmp_path, capsys):
    out = tmp_path / "plan.json"
    assert main(["plan", "case3", "--planner", "vpf-rrt-star", "--json", "--out", str(out)]) == 0
    plan = json.loads(out.read_text())
    assert plan["planner"] == "vpf-rrt-star"
    path = tmp_path / "enclosed.json"
    path.write_text(json.dumps(ENCLOSED))
    assert main(["plan", str(path), "--planner", "rrt-star", "--set", "iterations=200",
                 "--set", "attempts=1"]) == 3


def test_planner_names_match_issue_and_cli():
    from usvstation.cli import PLANNER_NAMES

    assert planner_names() == PLANNER_NAMES == ["iga", *SEED_PLANNERS]
