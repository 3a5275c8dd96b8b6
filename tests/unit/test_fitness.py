"""Eq. 12 terms and gates on hand-made paths."""

import math

import numpy as np
import pytest

from usvstation.planning.encoding import timed_paths
from usvstation.planning.fitness import Evaluator, evaluate
from usvstation.planning.problem import Problem
from usvstation.scenario import parse_scenario
from usvstation.scenario.options import IGAOptions

OPTS = IGAOptions(terms="paper", weight_b=0.5, weight_d=0.5)  # eq. 12 in the paper's units


def problem(start=(40.0, 0.0), obstacles=(), kind="recovery", goal=(0.0, 0.0), **vessel):
    data = {
        "name": "hand", "kind": kind,
        "start": {"x": start[0], "y": start[1], "speed": 2.0},
        "goal": {"x": goal[0], "y": goal[1]},
        "obstacles": [dict(zip(("x", "y", "radius", "vx", "vy"), o, strict=True))
                      for o in obstacles],
        "vessel": {"speed_min": 0.2, "speed_max": 3.0, "accel_max": 0.5, "turn_max_deg": 60.0,
                   "time_margin_s": 0.0, **vessel},
    }
    return Problem.from_scenario(parse_scenario(data))


def paths(*rows):
    """rows of (x, y, v) waypoints, one path per argument."""
    arr = np.array(rows, dtype=float)
    return timed_paths(arr[:, :, 0], arr[:, :, 1], arr[:, :, 2])


def test_straight_run_in_terms():
    p = paths([(40, 0, 2), (30, 0, 2), (20, 0, 2), (10, 0, 2), (0, 0, 2)])
    ev = evaluate(p, problem(), OPTS)
    assert ev.fit_d[0] == pytest.approx(1.0)
    assert ev.fit_t[0] == pytest.approx(5.0)  # 4 segments of 10 m at 2 m/s
    assert ev.fit_ang[0] == pytest.approx(0.0)
    assert ev.fit_mal[0] == pytest.approx(0.0)
    assert ev.feasible[0]
    assert ev.fitness[0] == pytest.approx(10.0 / (4.0 * 1.0 + 0.5 * 5.0))


def test_right_angle_path_terms():
    # (20,10) -> (10,10) -> (10,0) -> (0,0): two 90 degree turns
    p = paths([(20, 10, 1), (10, 10, 1), (10, 0, 1), (0, 0, 1)])
    prob = problem(start=(20.0, 10.0), turn_max_deg=120.0)
    ev = evaluate(p, prob, OPTS)
    assert ev.fit_ang[0] == pytest.approx(1.0)  # (pi/2 + pi/2) / pi
    assert ev.fit_mal[0] == pytest.approx((10 + 10 + 0 + 0) / 4)
    assert ev.fit_d[0] == pytest.approx(30.0 / math.hypot(20, 10))
    assert ev.fit_t[0] == pytest.approx(10.0)
    denom = 4.0 * ev.fit_d[0] + 0.5 * 10.0 + 2.0 * 1.0 + 0.5 * 5.0
    assert ev.fitness[0] == pytest.approx(10.0 / denom)
    # with the default 60 degree turn limit the same path dies
    ev60 = evaluate(p, problem(start=(20.0, 10.0)), OPTS)
    assert not ev60.g_turn[0] and ev60.fitness[0] == 0.0


def test_acceleration_gate():
    # 1 -> 3 m/s over 4 m needs (9 - 1) / (2 * 4) = 1 m/s^2 > 0.5
    p = paths([(8, 0, 1), (4, 0, 3), (0, 0, 3)], [(8, 0, 1), (4, 0, 2), (0, 0, 2)])
    ev = evaluate(p, problem(start=(8.0, 0.0)), OPTS)
    assert ev.g_acc.tolist() == [False, True]
    assert ev.fitness[0] == 0.0 and ev.fitness[1] > 0.0


def test_velocity_gate():
    p = paths([(8, 0, 2), (4, 0, 2.5), (0, 0, 2.5)])
    ev = evaluate(p, problem(start=(8.0, 0.0), speed_max=2.2), OPTS)
    assert not ev.g_vel[0] and ev.fitness[0] == 0.0


def test_collision_gate_uses_the_inflated_radius():
    # obstacle radius 1 at (20, 3): eq. 7 inflates it to 1 + 1.2 + 1 = 3.2 > 3
    straight = [(40, 0, 2), (30, 0, 2), (20, 0, 2), (10, 0, 2), (0, 0, 2)]
    ev = evaluate(paths(straight), problem(obstacles=[(20, 3.3, 1, 0, 0)]), OPTS)
    assert ev.g_col[0]
    ev = evaluate(paths(straight), problem(obstacles=[(20, 3.1, 1, 0, 0)]), OPTS)
    assert not ev.g_col[0] and ev.fitness[0] == 0.0
    assert ev.violations[0] == 2  # the circle straddles the waypoint at x = 20: two segments


def test_moving_obstacle_collision_depends_on_timing():
    straight = [(40, 0, 2), (30, 0, 2), (20, 0, 2), (10, 0, 2), (0, 0, 2)]
    # crosses y = 0 at x = 20 at t = 10 s, when the boat is exactly there
    meets = problem(obstacles=[(20, -10, 1, 0, 1)])
    assert not evaluate(paths(straight), meets, OPTS).g_col[0]
    # crossing 5 s earlier: the boat is still 10 m away
    misses = problem(obstacles=[(20, -5, 1, 0, 1)])
    assert evaluate(paths(straight), misses, OPTS).g_col[0]


def test_sparse_pairs_agree_with_all_pairs():
    prob = problem(obstacles=[(20, 4, 1, 0, 0), (35, -20, 1, 0, 1)])
    p = paths([(40, 0, 2), (30, 2, 2), (20, 0, 2), (10, 0, 2), (0, 0, 2)],
              [(40, 0, 2), (30, -2, 2), (20, -1, 2), (10, 0, 2), (0, 0, 2)])
    lo = np.array([30.0, 20.0, 10.0, 0.0])
    hi = np.array([40.0, 30.0, 20.0, 10.0])
    a = evaluate(p, prob, OPTS)
    b = Evaluator(prob, OPTS, (lo, hi))(p)
    np.testing.assert_array_equal(a.fitness, b.fitness)
    np.testing.assert_array_equal(a.violations, b.violations)


def test_transit_has_no_malposition_term():
    # the same geometry as a recovery and a transit: only d * Fit_mal differs
    rows = [(40, 0, 2), (30, 5, 2), (20, 5, 2), (10, 0, 2), (0, 0, 2)]
    rec = evaluate(paths(rows), problem(), OPTS)
    tra = evaluate(paths(rows), problem(kind="transit"), OPTS)
    assert tra.fit_mal[0] == rec.fit_mal[0] == pytest.approx(2.0)
    assert 10.0 / tra.fitness[0] == pytest.approx(10.0 / rec.fitness[0] - 0.5 * 2.0)


def test_eg3_linear_penalty():
    opts = IGAOptions(fitness="linear")
    straight = [(40, 0, 2), (30, 0, 2), (20, 0, 2), (10, 0, 2), (0, 0, 2)]
    ok = evaluate(paths(straight), problem(), opts)
    assert ok.fitness[0] == pytest.approx(10.0)  # A (2 - Fit_d) with Fit_d = 1
    hit = evaluate(paths(straight), problem(obstacles=[(20, 3.1, 1, 0, 0)]), opts)
    assert hit.fitness[0] == pytest.approx(10.0 - 2 * 2.5)  # two violations, A/4 each


def test_normalised_terms_mean_the_same_at_every_scale():
    """Fit_T' = t_end v_max / D and Fit_mal' = Fit_mal / D: a path and the same path ten times
    larger get the same fitness (issue 12)."""
    opts = IGAOptions()
    assert opts.terms == "normalised"
    small = [(40, 0, 2), (30, 5, 2), (20, 5, 2), (10, 0, 2), (0, 0, 2)]
    big = [(10 * x, 10 * y, v) for x, y, v in small]
    ev_s = evaluate(paths(small), problem(start=(40.0, 0.0)), opts)
    ev_b = evaluate(paths(big), problem(start=(400.0, 0.0)), opts)
    assert ev_s.fit_t_norm[0] == pytest.approx(ev_b.fit_t_norm[0])
    assert ev_s.fit_mal_norm[0] == pytest.approx(ev_b.fit_mal_norm[0])
    assert ev_s.fitness[0] == pytest.approx(ev_b.fitness[0])
    assert ev_s.fit_t_norm[0] == pytest.approx(paths(small).t[0, -1] * 3.0 / 40.0)
    paper = IGAOptions(terms="paper", weight_b=0.5, weight_d=0.5)
    assert evaluate(paths(small), problem(start=(40.0, 0.0)), paper).fitness[0] != \
        pytest.approx(evaluate(paths(big), problem(start=(400.0, 0.0)), paper).fitness[0])
