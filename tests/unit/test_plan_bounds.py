"""Issue 12 bounds: the time budget stops a run within one batch, a plan that would exceed the
memory bound is refused in one line, chunked passes count what one pass counts."""

import itertools
import json
import subprocess
import sys

import numpy as np
import pytest

from usvstation.planning import fitness as fitness_mod
from usvstation.planning.budget import Budget
from usvstation.planning.encoding import GeneLayout
from usvstation.planning.fitness import Evaluator
from usvstation.planning.iga import EVAL_CHUNK, run_iga
from usvstation.planning.limits import (
    PLAN_BYTES_MAX,
    PlanTooLarge,
    circle_count,
    estimate_bytes,
)
from usvstation.planning.plan import plan_scenario
from usvstation.planning.preheat import random_levels
from usvstation.planning.problem import Problem
from usvstation.scenario import ScenarioError, load_scenario, parse_scenario


def _ticking(budget_ticks, ticks, max_evaluations=None):
    """A budget whose clock advances one tick per reading: the deadline in ticks."""
    return Budget(max_evaluations, float(budget_ticks), clock=lambda: float(next(ticks)),
                  started=0.0)


def _run(budget_ticks, opts, problem, layout):
    """A run whose clock advances one tick per reading: the budget in ticks, no wall time."""
    return run_iga(problem, opts, layout, _ticking(budget_ticks, itertools.count()))


def test_time_budget_stops_within_one_batch_of_evaluations():
    sc = load_scenario("case1")
    opts = sc.planner_options(seed=3, population=300, generations_max=6, stall_generations=50)
    problem = Problem.from_scenario(sc)
    layout = GeneLayout.build(problem, opts)
    full = _run(10**9, opts, problem, layout)
    assert full.stop_reason == "generations_max"
    ticks = itertools.count()
    run_iga(problem, opts, layout, _ticking(1e18, ticks))
    total = next(ticks)  # clock readings of a whole run
    budgets = sorted({int(b) for b in np.linspace(0, total - 2, 14)})
    previous = None
    for b in budgets:
        cut, more = _run(b, opts, problem, layout), _run(b + 1, opts, problem, layout)
        assert cut.stop_reason == "time_budget"
        # one more tick of budget buys at most one batch of evaluations
        assert 0 <= more.evaluations - cut.evaluations <= EVAL_CHUNK
        assert cut.evaluations <= full.evaluations
        if previous is not None:
            assert cut.evaluations >= previous
        previous = cut.evaluations


def test_budget_spent_in_preheating_evaluates_one_batch_and_stops():
    sc = load_scenario("case4")
    opts = sc.planner_options(seed=1, population=400)
    problem = Problem.from_scenario(sc)
    result = _run(0, opts, problem, GeneLayout.build(problem, opts))
    assert result.stop_reason == "time_budget"
    assert result.generations == 0
    assert result.evaluations == EVAL_CHUNK


def _fast_ships(count, speed, margin):
    return parse_scenario({
        "name": "fast-ships", "start": {"x": 85.0, "y": 10.0},
        "vessel": {"time_margin_s": margin},
        "obstacles": [{"x": 40.0 + i, "y": -300.0, "radius": 0.5, "vx": 0.0, "vy": speed}
                      for i in range(count)],
    })


def test_a_plan_above_the_memory_bound_is_refused_in_one_line():
    sc = _fast_ships(200, 10.0, 10.0)  # each ship swept into 150 circles over +-10 s
    assert circle_count(sc) == Problem.from_scenario(sc).obstacles.count == 30000
    assert estimate_bytes(sc, sc.planner_options()) > PLAN_BYTES_MAX
    with pytest.raises(PlanTooLarge) as info:
        plan_scenario(sc, seed=1).to_document()
    msg = str(info.value)
    assert isinstance(info.value, ScenarioError)
    assert msg.startswith("planner: this plan would need about ")
    assert "200 obstacles swept into 30000 circles" in msg and "\n" not in msg
    # the same ships with a smaller timing margin fit
    small = _fast_ships(200, 10.0, 0.5)
    assert estimate_bytes(small, small.planner_options()) <= PLAN_BYTES_MAX


def test_cli_refuses_a_plan_above_the_memory_bound_with_exit_2(tmp_path):
    sc = _fast_ships(200, 10.0, 10.0)
    f = tmp_path / "big.json"
    f.write_text(json.dumps(sc.model_dump(mode="json")))
    out = subprocess.run([sys.executable, "-m", "usvstation.cli", "plan", str(f)],
                         capture_output=True, text=True, timeout=120, check=False)
    assert out.returncode == 2
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and "planner: this plan would need about" in lines[0]


@pytest.mark.parametrize("name", ["case1", "case2", "case3", "case4"])
def test_public_scenarios_fit_the_memory_bound(name):
    sc = load_scenario(name)
    assert estimate_bytes(sc, sc.planner_options()) <= PLAN_BYTES_MAX
    large = sc.planner_options(population=1000, candidates=32, max_waypoints=200)
    assert estimate_bytes(sc, large) <= PLAN_BYTES_MAX
    worst = sc.planner_options(population=1000, candidates=64, max_waypoints=200)
    assert estimate_bytes(sc, worst) > PLAN_BYTES_MAX  # refused, not risked


def test_chunked_collision_passes_count_what_one_pass_counts(monkeypatch):
    sc = load_scenario("case4")
    problem = Problem.from_scenario(sc)
    opts = sc.planner_options()
    layout = GeneLayout.build(problem, opts)
    paths = layout.levels_to_paths(random_levels(layout, np.random.default_rng(5), 300))
    whole = [Evaluator(problem, opts).collisions(paths),
             Evaluator(problem, opts, layout.segment_x_range()).collisions(paths)]
    monkeypatch.setattr(fitness_mod, "BRUTE_CHUNK", 64)
    parts = [Evaluator(problem, opts).collisions(paths),
             Evaluator(problem, opts, layout.segment_x_range()).collisions(paths)]
    np.testing.assert_array_equal(whole[0], whole[1])
    np.testing.assert_array_equal(whole[0], parts[0])
    np.testing.assert_array_equal(whole[0], parts[1])
    assert whole[0].sum() > 0
