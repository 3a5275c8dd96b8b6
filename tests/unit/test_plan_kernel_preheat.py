"""Preheating's compiled draw (planning/kernel_preheat.py) grows the same individuals as the
NumPy reference, bit for bit, and reports the same blocked waypoints and obstacle hits."""

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from usvstation.bench.scenarios import HIDDEN_FAMILIES, random_recovery, random_transit
from usvstation.planning import kernel_preheat
from usvstation.planning.encoding import GeneLayout, InfeasibleProblem
from usvstation.planning.preheat import preheat
from usvstation.planning.problem import Problem

FAMILIES = [random_recovery, random_transit,
            *(f for name, f in HIDDEN_FAMILIES.items() if name not in ("behind_ramp", "alongside"))]

pytestmark = pytest.mark.skipif(not kernel_preheat.AVAILABLE, reason="numba is not installed")


@settings(max_examples=40, deadline=None)
@given(family=st.sampled_from(FAMILIES), seed=st.integers(0, 10_000),
       obstacles=st.sampled_from([None, 40, 300]), candidates=st.sampled_from([3, 10, 40]),
       retries=st.integers(1, 4), count=st.sampled_from([5, 24, 120]))
def test_compiled_preheating_equals_the_numpy_reference(family, seed, obstacles, candidates,
                                                        retries, count):
    """Small and large draws (the large ones pruned by x-y-t boxes, paired per individual
    from 16 obstacles on), with and without currents, cones, moving and static obstacles."""
    if family is HIDDEN_FAMILIES["dense_field"]:
        sc = family(seed, obstacles or 120)
    else:
        sc = family(seed)
    opts = sc.planner_options(seed=seed, candidates=candidates, preheat_retries=retries)
    problem = Problem.from_scenario(sc)
    try:
        layout = GeneLayout.build(problem, opts)
    except InfeasibleProblem:  # a start behind the ramp: the IGA plans from a run-out
        assume(False)
    out = []
    for compiled in (True, False):
        rng = np.random.default_rng(seed)
        levels, ok, report = preheat(layout, problem, opts, rng, count, compiled=compiled)
        out.append((levels, ok, report, rng.random()))
    (levels, ok, report, after), (want_levels, want_ok, want, want_after) = out
    np.testing.assert_array_equal(ok, want_ok)
    np.testing.assert_array_equal(levels[ok], want_levels[want_ok])
    assert report.blocked_at == want.blocked_at
    assert report.produced == want.produced
    np.testing.assert_array_equal(report.obstacle_hits, want.obstacle_hits)
    assert after == want_after  # the same random numbers were drawn


def test_a_blocked_draw_reports_the_obstacles_that_blocked_it():
    """A wall across the corridor: nothing grows through it, and both routes name the same
    obstacles as those hit most."""
    sc = HIDDEN_FAMILIES["long_wall"](2)
    opts = sc.planner_options(candidates=6, preheat_retries=1, preheat_restarts=0)
    problem = Problem.from_scenario(sc)
    layout = GeneLayout.build(problem, opts)
    reports = [preheat(layout, problem, opts, np.random.default_rng(5), 40, compiled=c)[2]
               for c in (True, False)]
    assert reports[0].obstacle_hits.sum() > 0
    np.testing.assert_array_equal(reports[0].obstacle_hits, reports[1].obstacle_hits)
    assert reports[0].blocked_at == reports[1].blocked_at
