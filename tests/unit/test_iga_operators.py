"""The IGA's operators on packed genes: single-point crossover and bit-flip mutation act on
the paper's bit string exactly; the GA's fitness fast path equals the full evaluation."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from usvstation.planning import iga
from usvstation.planning.encoding import GeneLayout
from usvstation.planning.fitness import Evaluator
from usvstation.planning.preheat import preheat
from usvstation.planning.problem import Problem
from usvstation.scenario import load_scenario
from usvstation.scenario.options import IGAOptions

CASES = {name: Problem.from_scenario(load_scenario(name)) for name in ("case1", "case4")}
LAYOUTS = [GeneLayout.build(p, IGAOptions()) for p in CASES.values()]


def random_codes(lay: GeneLayout, rng: np.random.Generator, n: int) -> np.ndarray:
    return lay.bits_to_codes(rng.integers(0, 2, size=(n, lay.n_bits), dtype=np.uint8))


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(LAYOUTS), st.integers(0, 2**32 - 1))
def test_single_point_crossover_swaps_the_bit_strings_at_the_cut(lay, seed):
    rng = np.random.default_rng(seed)
    a, b = random_codes(lay, rng, 8), random_codes(lay, rng, 8)
    cut = rng.integers(1, lay.n_bits + 1, size=8)  # n_bits: no crossover
    c1, c2 = iga.single_point_crossover(lay, a, b, cut)
    bits = [lay.codes_to_bits(m) for m in (a, b, c1, c2)]
    for i, c in enumerate(cut):
        want1 = np.concatenate([bits[0][i, :c], bits[1][i, c:]])
        want2 = np.concatenate([bits[1][i, :c], bits[0][i, c:]])
        np.testing.assert_array_equal(bits[2][i], want1)
        np.testing.assert_array_equal(bits[3][i], want2)


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(LAYOUTS), st.integers(0, 2**32 - 1))
def test_the_crossover_mask_table_equals_the_masks_computed_per_cut(lay, seed):
    cut = np.random.default_rng(seed).integers(1, lay.n_bits + 1, size=64)
    assert lay._prefix_table is not None  # small layouts use the table
    np.testing.assert_array_equal(lay.prefix_masks(cut), lay._prefix_of(cut))


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(LAYOUTS), st.integers(0, 2**32 - 1))
def test_mutation_flips_bits_and_keeps_every_gene_in_its_width(lay, seed):
    rng = np.random.default_rng(seed)
    codes = random_codes(lay, rng, 40)
    out = iga.mutate(lay, codes, 0.05, rng)
    assert (out >= 0).all() and (out < (1 << lay.gene_bits)).all()
    flipped = (lay.codes_to_bits(out) != lay.codes_to_bits(codes)).sum()
    assert 0 < flipped < 40 * lay.n_bits  # about 5 % of the bits


@settings(max_examples=20, deadline=None)
@given(st.sampled_from(sorted(CASES)), st.integers(0, 2**32 - 1))
def test_the_ga_fitness_fast_path_equals_the_full_evaluation(name, seed):
    problem = CASES[name]
    opts = IGAOptions()
    lay = GeneLayout.build(problem, opts)
    rng = np.random.default_rng(seed)
    # preheated paths and local re-initialisations of them: feasible and infeasible rows
    grown, ok, _ = preheat(lay, problem, opts, rng, 20)
    levels = np.concatenate([grown[ok], iga.local_reinit(lay, rng, grown[ok], 40)])
    paths = lay.levels_to_paths(levels)
    for ranges in (None, lay.segment_x_range()):
        ev = Evaluator(problem, opts, ranges)
        full = ev(paths).fitness
        assert (full > 0).sum() >= ok.sum() > 0  # the preheated paths are feasible
        np.testing.assert_array_equal(ev.fitness(paths), full)
