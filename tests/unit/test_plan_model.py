"""The typed plan and the stable plan format it is written as: exact inverses."""

import json
import pickle

import pytest

from usvstation.planning.model import Plan, PlanMetrics, Waypoint
from usvstation.planning.registry import plan_with
from usvstation.scenario import load_scenario


@pytest.mark.parametrize("planner", ["iga", "rrt-star"])
def test_a_planners_plan_reads_back_from_its_document_the_same(planner):
    plan = plan_with(load_scenario("case1"), planner, 1)
    doc = plan.to_document()
    assert Plan.from_document(doc) == plan
    assert json.dumps(Plan.from_document(doc).to_document()) == json.dumps(doc)  # same bytes
    assert pickle.loads(pickle.dumps(plan)) == plan  # it crosses the process pool
    assert plan.metrics.length_m == doc["metrics"]["length_m"]
    assert plan.waypoints[0].x == doc["waypoints"][0]["x"]


def test_the_iga_plan_keeps_its_smoothed_path_sections_and_course():
    plan = plan_with(load_scenario("case1"), "iga", 1)
    assert plan.smoothed is not None and plan.smoothed.degree in (2, 3)
    assert list(plan.sections) == ["encoding", "history"]
    assert all(w.course_deg is not None for w in plan.waypoints)


def test_a_minimal_document_and_the_copies_that_change_a_plan():
    doc = {"planner": "p", "scenario": "s", "seed": 3,
           "waypoints": [{"x": 1.0, "y": 2.0, "t": 0.0, "speed": 1.0, "heading_deg": 180.0},
                         {"x": 0.0, "y": 0.0, "t": 2.0, "speed": 1.0, "heading_deg": 180.0}],
           "metrics": {"fitness": None, "length_m": 2.2, "duration_s": 2.0,
                       "min_clearance_m": None, "collision_free": True, "generations": 0,
                       "elapsed_s": 0.1}}
    plan = Plan.from_document(doc)
    assert plan.warnings == () and plan.smoothed is None and plan.sections == {}
    assert plan.to_document() == {**doc, "warnings": []}
    assert plan.waypoints[1] == Waypoint(0.0, 0.0, 2.0, 1.0, 180.0)
    assert "course_deg" not in plan.to_document()["waypoints"][0]
    later = plan.warned("a").warned("b").with_metrics(generations=7, extra=1)
    assert later.warnings == ("a", "b") and plan.warnings == ()
    assert list(later.metrics)[-1] == "extra" and later.metrics.generations == 7
    assert plan.metrics.generations == 0
    assert isinstance(later.metrics, PlanMetrics) and later.metrics["extra"] == 1
