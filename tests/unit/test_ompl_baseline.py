"""OMPL baseline (optional extra): a run in its own process passes the same checker."""

import pytest

from usvstation.planning.validate import plan_violations
from usvstation.scenario import load_scenario

pytest.importorskip("ompl")


@pytest.mark.parametrize("planner", ["BITstar", "RRTstar"])
def test_ompl_run_in_process_passes_the_checker(planner):
    from usvstation.bench.ompl_baseline import run_in_process

    sc = load_scenario("case2")
    res = run_in_process(sc.model_dump(mode="json"), planner, 1, iterations=1500)
    assert res["success"], res.get("error")
    assert res["plan"]["planner"] == f"ompl:{planner}"
    assert plan_violations(res["plan"], sc) == []
    again = run_in_process(sc.model_dump(mode="json"), planner, 1, iterations=1500)
    assert again["plan"]["waypoints"] == res["plan"]["waypoints"]  # seeded per process
