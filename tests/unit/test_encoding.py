"""Eq. 10-11: binary genes, decode-and-map, eq. 11 times; widths that grow with the scenario."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from usvstation.bench.scenarios import random_transit
from usvstation.planning.encoding import GeneLayout, InfeasibleProblem, timed_paths
from usvstation.planning.problem import Problem
from usvstation.scenario import load_scenario, parse_scenario
from usvstation.scenario.options import IGAOptions


def layout_of(scenario, **opts):
    return GeneLayout.build(Problem.from_scenario(scenario), IGAOptions(**opts))


CASE1 = layout_of(load_scenario("case1"))
TRANSIT = layout_of(random_transit(3))
LAYOUTS = [CASE1, layout_of(load_scenario("case4")), TRANSIT]


def test_paper_defaults_reproduce_3_7_4_bits_and_8_m_blocks():
    lay = CASE1
    assert (lay.gene_bits[0], lay.gene_bits[1], lay.gene_bits[2]) == (3, 7, 4)
    assert lay.x_res == 1.0 and lay.y_res == 1.0 and lay.v_res == pytest.approx(0.2)
    assert lay.n_mid == 10 and set(lay.x_count.tolist()) == {8}  # D_SL = 8 m
    assert lay.y_lo == -64.0 and lay.y_count == 128  # y in [-64, 63] as eq. 10's "+ 64"
    assert lay.v_count == 15  # 0.2 .. 3.0 m/s
    assert lay.n_genes == 3 * 10 + 1 and lay.n_bits == 14 * 10 + 4


def test_widths_grow_for_a_400_m_transit():
    lay, problem = TRANSIT, Problem.from_scenario(random_transit(3))
    f = problem.obstacles
    islands = f.static
    # the y search range covers every island's inflated circle with room to pass it (ships
    # far off the route at t = 0 only matter where they cross it)
    assert lay.y_lo <= (f.centre[islands, 1] - f.inflated[islands]).min()
    top = lay.y_lo + (lay.y_count - 1) * lay.y_res
    assert top >= (f.centre[islands, 1] + f.inflated[islands]).max()
    assert 2 ** lay.gene_bits[1] >= lay.y_count > 2 ** 7  # more than the paper's 7 bits
    assert lay.x_count.max() > 8 and 2 ** lay.gene_bits[0] >= lay.x_count.max()
    assert 2 ** lay.gene_bits[0] >= lay.x_count.max()
    assert lay.n_mid <= IGAOptions().max_waypoints


def test_start_too_close_to_the_run_in_is_infeasible():
    s = parse_scenario({"name": "near", "start": {"x": 4.0, "y": 20.0}})
    with pytest.raises(InfeasibleProblem, match="approach_length"):
        layout_of(s)


def random_levels(lay: GeneLayout, data) -> np.ndarray:
    """Admissible levels for every gene, the cone gene within its x-dependent range."""
    row = [data.draw(st.integers(0, int(c) - 1)) for c in lay.gene_count]
    levels = np.array([row])
    if lay.cone_tan is not None:
        g = lay.cone_gene
        m = int(lay.cone_half_levels(levels[:, g - 1])[0])
        levels[0, g] = data.draw(st.integers(0, 2 * m))
    return levels


@settings(max_examples=300, deadline=None)
@given(st.sampled_from(LAYOUTS), st.data())
def test_levels_codes_round_trip(lay, data):
    levels = random_levels(lay, data)
    codes = lay.levels_to_codes(levels)
    assert (codes >= 0).all() and (codes < (1 << lay.gene_bits)).all()
    np.testing.assert_array_equal(lay.codes_to_levels(codes), levels)


@settings(max_examples=200, deadline=None)
@given(st.sampled_from(LAYOUTS), st.data())
def test_bits_round_trip(lay, data):
    levels = random_levels(lay, data)
    bits = lay.encode(levels)
    assert bits.shape == (1, lay.n_bits) and set(np.unique(bits)) <= {0, 1}
    np.testing.assert_array_equal(lay.bits_to_codes(bits), lay.levels_to_codes(levels))
    got, want = lay.decode(bits), lay.levels_to_paths(levels)
    np.testing.assert_array_equal(got.x, want.x)
    np.testing.assert_array_equal(got.y, want.y)
    np.testing.assert_array_equal(got.v, want.v)


@settings(max_examples=200, deadline=None)
@given(st.sampled_from(LAYOUTS), st.data())
def test_any_bit_string_decodes_to_an_admissible_path(lay, data):
    """Decode-and-map: no bit pattern overflows its variable's range."""
    bits = np.array([data.draw(st.lists(st.integers(0, 1), min_size=lay.n_bits,
                                        max_size=lay.n_bits))], dtype=np.uint8)
    p = lay.decode(bits)
    x, y, v = p.x[0], p.y[0], p.v[0]
    assert (x[0], y[0]) == tuple(lay.start) and (x[-1], y[-1]) == tuple(lay.goal)
    assert (np.diff(x) < 0).all()  # stepped along x towards the goal
    for k in range(lay.n_mid):
        lo = lay.x_min + lay.x_base[k] * lay.x_res
        assert lo <= x[k + 1] <= lo + (lay.x_count[k] - 1) * lay.x_res
    assert (y[1:-1] >= lay.y_lo).all() and (y[1:-1] <= lay.y_lo + (lay.y_count - 1)).all()
    v_hi = lay.v_lo + (lay.v_count - 1) * lay.v_res
    assert (v >= lay.v_lo - 1e-12).all() and (v <= v_hi + 1e-9).all()
    if lay.cone_tan is not None:  # the arrival segment lies within 10 degrees of the axis
        assert abs(math.degrees(math.atan2(y[-2], x[-2]))) <= 10.0 + 1e-9


def test_eq11_segment_times():
    x = np.array([[30.0, 20.0, 0.0]])
    y = np.array([[0.0, 0.0, 0.0]])
    v = np.array([[1.0, 3.0, 1.0]])
    p = timed_paths(x, y, v)
    # dT = 2 L / (v_i + v_i+1): 2*10/4 = 5 s, then 2*20/4 = 10 s
    np.testing.assert_allclose(p.seg_dt, [[5.0, 10.0]])
    np.testing.assert_allclose(p.t, [[0.0, 5.0, 15.0]])
    np.testing.assert_allclose(p.seg_len, [[10.0, 20.0]])
