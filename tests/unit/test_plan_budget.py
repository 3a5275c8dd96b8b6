"""One budget for every planner (issues 23 and 27): a deterministic evaluation count decides
the plan; the wall clock is only a safety net, and says so in `warnings` when it fires."""

import itertools

import pytest

from usvstation.bench.scenarios import dense_field
from usvstation.planning.budget import Budget, BudgetExhausted
from usvstation.planning.errors import NoFeasiblePlan
from usvstation.planning.registry import plan_with, planner_names
from usvstation.scenario import load_scenario


def _without_timings(doc: dict) -> dict:
    return {**doc, "metrics": {k: v for k, v in doc["metrics"].items() if k != "elapsed_s"}}


def _crawling_clock(step_s: float):
    """A clock that advances `step_s` per reading: a very slow (or very busy) machine."""
    ticks = itertools.count()
    return lambda: next(ticks) * step_s


def test_dense_plan_does_not_depend_on_elapsed_time():
    """The same dense 320-obstacle plan on a quick clock and on one 1000 x slower
    (each reading 10 ms later) that stays within the safety net."""
    sc = dense_field(1, 320)
    quick = plan_with(sc, "iga", 1).to_document()
    slow = plan_with(sc, "iga", 1, clock=_crawling_clock(0.01), time_budget_s=600.0)
    assert _without_timings(slow.to_document()) == _without_timings(quick)
    assert quick["warnings"] == [] and slow.metrics["stop_reason"] == "converged"


@pytest.mark.parametrize("name", ["rrt-star", "de-apf"])
def test_seed_plan_does_not_depend_on_elapsed_time(name):
    sc = load_scenario("case1")
    quick = plan_with(sc, name, 1).to_document()
    slow = plan_with(sc, name, 1, clock=_crawling_clock(0.001), time_budget_s=600.0)
    assert _without_timings(slow.to_document()) == _without_timings(quick)


def test_the_safety_net_fires_with_a_warning_or_no_plan():
    """Past the wall deadline the IGA returns its best plan so far, saying so."""
    sc = load_scenario("case1")
    plan = plan_with(sc, "iga", 1, clock=_crawling_clock(0.1), time_budget_s=3.0)
    assert plan.metrics["stop_reason"] == "time_budget"
    assert any("safety net" in w for w in plan.warnings)
    with pytest.raises(NoFeasiblePlan, match=r"within the time budget of 0\.001 s"):
        plan_with(sc, "colregs-ga", 1, clock=_crawling_clock(0.01), time_budget_s=0.001)


@pytest.mark.parametrize("name", planner_names())
def test_every_planner_honours_max_evaluations(name):
    """A small evaluation budget stops every planner (a plan within it, or none),
    the same way twice."""
    sc = load_scenario("case1")
    limit = 40 if name in ("rrt-star", "bspline-rrt-star", "vpf-rrt-star") else 200
    outcomes = []
    for _ in range(2):
        try:
            plan = plan_with(sc, name, 1, max_evaluations=limit)
        except NoFeasiblePlan as exc:
            assert f"within {limit} evaluations" in str(exc) or "no feasible plan" in str(exc)
            outcomes.append(str(exc))
        else:
            doc = plan.to_document()
            batch = 128 if name == "iga" else 60  # one evaluation batch past the limit at most
            assert doc["metrics"]["evaluations"] <= limit + batch
            outcomes.append(_without_timings(doc))
    assert outcomes[0] == outcomes[1]


def test_the_scenario_budget_binds_every_planner():
    """`planner.max_evaluations` in the scenario is honoured by a seed planner too."""
    data = load_scenario("case1").model_dump()
    data["planner"] = {"max_evaluations": 300}
    from usvstation.scenario import parse_scenario

    plan = plan_with(parse_scenario(data), "rrt-star", 1, attempts=1)
    assert plan.metrics["evaluations"] <= 300


def test_budget_counts_and_raises_only_past_the_limit():
    b = Budget(10, 5.0, clock=lambda: 0.0, started=0.0)
    b.spend(10)
    assert b.exhausted() and b.stop_reason() == "max_evaluations"
    b.check()  # at the limit: a loop that stops at exhausted() never raises
    b.spend(1)
    with pytest.raises(BudgetExhausted):
        b.check()
    late = Budget(None, 1.0, clock=lambda: 2.0, started=0.0)
    assert late.exhausted() and late.stop_reason() == "time_budget"
    assert "1 s" in late.failure() and "safety net" in late.warning()


def test_the_api_and_campaigns_hand_the_budget_to_every_planner():
    from usvstation.campaign.spec import CampaignSpec

    sc = load_scenario("case1").with_budget(time_budget_s=2.0, max_evaluations=900)
    assert sc.planner.time_budget_s == 2.0 and sc.planner.max_evaluations == 900
    assert sc.with_budget() is sc
    spec = CampaignSpec(planners=["iga", "rrt-star"], families=["recovery"], seeds=1,
                        max_evaluations=500, options={"rrt-star": {"max_evaluations": 50}})
    assert spec.planner_options("iga") == {"max_evaluations": 500}
    assert spec.planner_options("rrt-star") == {"max_evaluations": 50}


def test_a_plan_request_carries_the_budget_and_refuses_a_bad_one():
    from pydantic import ValidationError

    from usvstation.api.models import PlanRequest

    req = PlanRequest(planner="rrt-star", time_budget_s=2.0, max_evaluations=500)
    assert (req.time_budget_s, req.max_evaluations) == (2.0, 500)
    with pytest.raises(ValidationError, match="max_evaluations"):
        PlanRequest(max_evaluations=0)
