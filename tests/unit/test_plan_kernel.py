"""The compiled eq. 12 kernel (planning/kernel.py) agrees bit for bit with the NumPy
reference (`Evaluator.fitness_numpy`) on random problems and random paths."""

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from usvstation.bench.scenarios import HIDDEN_FAMILIES, random_recovery, random_transit
from usvstation.planning import kernel
from usvstation.planning.encoding import GeneLayout, InfeasibleProblem
from usvstation.planning.fitness import Evaluator
from usvstation.planning.iga import local_reinit
from usvstation.planning.preheat import preheat, random_levels
from usvstation.planning.problem import Problem

FAMILIES = [random_recovery, random_transit,
            *(f for name, f in HIDDEN_FAMILIES.items() if name not in ("behind_ramp", "alongside"))]

pytestmark = pytest.mark.skipif(not kernel.AVAILABLE, reason="numba is not installed")


@settings(max_examples=30, deadline=None)
@given(family=st.sampled_from(FAMILIES), seed=st.integers(0, 10_000),
       terms=st.sampled_from(["normalised", "paper"]))
def test_kernel_equals_the_numpy_reference(family, seed, terms):
    sc = family(seed) if family is not HIDDEN_FAMILIES["dense_field"] else family(seed, 120)
    opts = sc.planner_options(seed=seed, population=24, terms=terms)
    problem = Problem.from_scenario(sc)
    try:
        layout = GeneLayout.build(problem, opts)
    except InfeasibleProblem:  # a start behind the ramp: the IGA plans from a run-out
        assume(False)
    rng = np.random.default_rng(seed)
    grown, ok, _ = preheat(layout, problem, opts, rng, 24)
    levels = np.concatenate([grown, random_levels(layout, rng, 24)])
    if ok.any():  # small changes of feasible paths: near the gates' edges
        levels = np.concatenate([levels, local_reinit(layout, rng, grown[ok], 48)])
    paths = layout.levels_to_paths(levels)
    ev = Evaluator(problem, opts, layout.segment_x_range())
    reference = ev.fitness_numpy(paths)
    assert np.array_equal(ev.fitness(paths), reference)
    assert np.array_equal(reference, ev(paths).fitness)


def test_kernel_sees_collisions_and_gates_the_reference_sees():
    """A batch with feasible, colliding and gate-failing paths gives the same verdicts."""
    sc = HIDDEN_FAMILIES["crossing_ships"](3)
    opts = sc.planner_options()
    problem = Problem.from_scenario(sc)
    layout = GeneLayout.build(problem, opts)
    rng = np.random.default_rng(1)
    grown, _, _ = preheat(layout, problem, opts, rng, 60)
    paths = layout.levels_to_paths(np.concatenate([grown, random_levels(layout, rng, 60)]))
    ev = Evaluator(problem, opts, layout.segment_x_range())
    full = ev(paths)
    fit = ev.fitness(paths)
    assert (fit > 0).sum() > 0 and (~full.g_col).sum() > 0 and (~full.g_turn).sum() > 0
    assert np.array_equal(fit > 0, full.feasible)
