"""The IGA's compiled generation (planning/kernel_ga.py) agrees bit for bit with the NumPy
operators it replaces, on random problems, populations and draws."""

from dataclasses import replace

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from usvstation.bench.scenarios import HIDDEN_FAMILIES, random_recovery, random_transit
from usvstation.planning import iga, kernel_ga
from usvstation.planning.encoding import GeneLayout, InfeasibleProblem
from usvstation.planning.fitness import Evaluator, first_turn, first_turn_of
from usvstation.planning.preheat import PreheatReport, preheat, random_levels
from usvstation.planning.problem import Problem
from usvstation.scenario import load_scenario
from usvstation.scenario.options import IGAOptions

FAMILIES = [random_recovery, random_transit,
            *(f for name, f in HIDDEN_FAMILIES.items() if name not in ("behind_ramp", "alongside"))]

pytestmark = pytest.mark.skipif(not kernel_ga.AVAILABLE, reason="numba is not installed")


def _setup(family, seed: int, **options):
    sc = family(seed) if family is not HIDDEN_FAMILIES["dense_field"] else family(seed, 120)
    opts = sc.planner_options(seed=seed, **options)
    problem = Problem.from_scenario(sc)
    try:
        layout = GeneLayout.build(problem, opts)
    except InfeasibleProblem:  # a start behind the ramp: the IGA plans from a run-out
        assume(False)
    return problem, opts, layout


def _population(layout, problem, opts, rng, n):
    """Preheated paths, their local re-initialisations and random ones (feasible and not)."""
    grown, ok, _ = preheat(layout, problem, opts, rng, n // 2)
    levels = np.concatenate([grown, random_levels(layout, rng, n - n // 2)])
    if ok.any():
        levels[n // 2:] = np.concatenate([
            iga.local_reinit(layout, rng, grown[ok], n - n // 2 - n // 4),
            levels[n - n // 4:]])
    return layout.levels_to_codes(levels)


@settings(max_examples=40, deadline=None)
@given(family=st.sampled_from(FAMILIES), seed=st.integers(0, 10_000))
def test_decode_equals_decode_and_map(family, seed):
    problem, _, layout = _setup(family, seed)
    rng = np.random.default_rng(seed)
    codes = layout.bits_to_codes(rng.integers(0, 2, size=(37, layout.n_bits), dtype=np.uint8))

    moving = replace(problem, start_heading=1.0)  # the first-turn gate, also for a boat at rest

    def first(dx, dy):
        return first_turn_of(np.arctan2(dy, dx), layout.start_speed, moving) > moving.turn_max

    tables = kernel_ga.LayoutTables.of(layout, first)
    assert tables.first_table.size or layout.gene_count[0] * layout.gene_count[1] > 1 << 16
    want = layout.decode_codes(codes)
    x, y, v, t, seg, dx, dy, first_bad = kernel_ga.decode(codes, *tables.mapping())
    for got, ref in ((x, want.x), (y, want.y), (v, want.v), (t, want.t), (seg, want.seg_len),
                     (dx, want.seg_dx), (dy, want.seg_dy)):
        np.testing.assert_array_equal(got, ref.T)
    if tables.first_table.size:
        np.testing.assert_array_equal(first_bad, first_turn(want, moving) > moving.turn_max)
    levels = layout.codes_to_levels(codes)
    np.testing.assert_array_equal(kernel_ga.codes_to_levels(codes, *tables.coding()), levels)
    np.testing.assert_array_equal(kernel_ga.levels_to_codes(levels, *tables.coding()),
                                  layout.levels_to_codes(levels))


@settings(max_examples=40, deadline=None)
@given(family=st.sampled_from(FAMILIES), seed=st.integers(0, 10_000),
       ssih=st.booleans(), preheated=st.booleans(), elitism=st.booleans(),
       fresh_left=st.integers(0, 20), parents=st.booleans())
def test_a_compiled_generation_equals_the_numpy_generation(
        family, seed, ssih, preheated, elitism, fresh_left, parents):
    problem, opts, layout = _setup(family, seed, population=24, ssih=ssih, preheat=preheated,
                                   elitism=elitism)
    rng = np.random.default_rng(seed)
    codes = _population(layout, problem, opts, rng, 24)
    evaluator = Evaluator(problem, opts, layout.segment_x_range())
    fit = evaluator.fitness(layout.decode_codes(codes))
    fresh = _population(layout, problem, opts, rng, 20)[:fresh_left]
    pop = iga._Population(codes, fit)
    n_parents = max(opts.elite_count, 1) if parents else 0
    pm = min(0.5, 1.5 / layout.n_bits)
    engine = iga._Compiled.of(layout, evaluator, problem, opts)
    results = []
    for run in (engine.generation, None):
        seen: list[np.ndarray] = []

        def fitness(batch, seen=seen):
            seen.append(batch)
            return evaluator.fitness_numpy(layout.decode_codes(batch)), True

        draws = np.random.default_rng(seed + 1)
        if run is None:
            out = iga._generation_numpy(layout, problem, opts, pop, n_parents, fresh, 11,
                                        PreheatReport(), draws, pm, fitness, None)
        else:
            out = run(pop, n_parents, fresh, 11, PreheatReport(), draws, pm, fitness, None)
        results.append((out, seen, draws.random()))
    (got, got_batches, got_next), (want, want_batches, want_next) = results
    np.testing.assert_array_equal(got_batches[0], want_batches[0])  # children and newborns
    np.testing.assert_array_equal(got[0].codes, want[0].codes)
    np.testing.assert_array_equal(got[0].fit, want[0].fit)
    assert got[1] == want[1]  # children that died
    np.testing.assert_array_equal(got[2], want[2])  # the fresh stock left
    assert got_next == want_next  # the same random numbers were drawn


@settings(max_examples=60, deadline=None)
@given(st.lists(st.sampled_from([0.0, 0.5, 1.0, 1.2, 2.0]), min_size=6, max_size=30),
       st.integers(0, 5), st.integers(1, 12), st.booleans())
def test_next_population_equals_elitism_and_sacrifice(batch_fit, n_elite, n_children, ssih):
    """Ties, deaths and newborns in every proportion: the elite group in rank order, the
    dead children replaced by the fittest living newborns, first of equals first."""
    n_children = min(n_children, len(batch_fit))
    rng = np.random.default_rng(len(batch_fit))
    batch_fit = np.array(batch_fit)
    batch = rng.integers(0, 1000, size=(batch_fit.size, 4))
    fit = rng.choice([0.0, 1.0, 1.5], size=8)
    codes = rng.integers(0, 1000, size=(8, 4))
    order = np.argsort(-fit, kind="stable")
    got_codes, got_fit, n_dead = kernel_ga.next_population(
        codes, fit, order, n_elite, batch, batch_fit, n_children, ssih)
    children, child_fit = batch[:n_children], batch_fit[:n_children]
    if ssih:
        children, child_fit = iga._sacrifice(children, child_fit, batch[n_children:],
                                             batch_fit[n_children:])
    np.testing.assert_array_equal(got_codes, np.concatenate([codes[order[:n_elite]], children]))
    np.testing.assert_array_equal(got_fit, np.concatenate([fit[order[:n_elite]], child_fit]))
    assert n_dead == int(np.count_nonzero(batch_fit[:n_children] <= 0.0))


@pytest.mark.parametrize("ablation", ["IGA", "EG1", "EG2", "EG3", "EG4"])
@pytest.mark.parametrize("case", ["case1", "case4"])
def test_a_compiled_run_equals_the_numpy_run(case, ablation):
    """Whole runs, with every ablation of section 4.2: the same generations and best path."""
    sc = load_scenario(case)
    opts = IGAOptions.ablation(ablation, seed=3, generations_max=40)
    problem = Problem.from_scenario(sc)
    layout = GeneLayout.build(problem, opts)
    a = iga.run_iga(problem, opts, layout, compiled=True)
    b = iga.run_iga(problem, opts, layout, compiled=False)
    assert (a.generations, a.stop_reason, a.evaluations) == (b.generations, b.stop_reason,
                                                             b.evaluations)
    assert a.history_best == b.history_best and a.history_elite_mean == b.history_elite_mean
    np.testing.assert_array_equal(a.best.x, b.best.x)
    np.testing.assert_array_equal(a.best.y, b.best.y)
    np.testing.assert_array_equal(a.best.v, b.best.v)
