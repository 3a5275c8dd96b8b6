"""Issue 14: static-only planners and swept corridors, the APF traps, hidden families."""

import math

import numpy as np
import pytest

from usvstation.bench.compare import (
    colregs_cases,
    colregs_hidden,
    family_scenarios,
    transit_hidden,
    trap_cases,
    trap_hidden,
)
from usvstation.planning.registry import describe_planners, plan_with
from usvstation.planning.seeds.common import World
from usvstation.planning.validate import plan_violations


def _crossing_world() -> World:
    """One mover crossing the x axis at x = 100 westwards at 2 m/s, there at t = 50 s."""
    return World(np.array([100.0]), np.array([100.0]), np.array([0.0]), np.array([-2.0]),
                 np.array([4.0]), np.array([7.0]))


def test_swept_window_keeps_only_the_stretch_where_the_boat_could_meet_the_mover():
    world = _crossing_world()
    swept = world.swept_window(np.array([0.0, 0.0]), 2.0, 200.0, slow=1.3, fast=1.1)
    assert not swept.moving.any()
    assert swept.count > 3
    # every piece is on the mover's track, at a distance the boat could be at that time
    assert np.allclose(swept.cx, 100.0)
    s = (100.0 - swept.cy) / 2.0
    d = np.hypot(swept.cx, swept.cy)
    assert (d >= s * 2.0 / 1.3 - 7.0 - 1e-9).all() and (d <= s * 2.0 * 1.1 + 7.0 + 1e-9).all()
    # the meeting point (100, 0) at t = 50 s is covered; the track before the boat could
    # get there (y > 20 m, the first 40 s) is open water
    covered = np.hypot(swept.cx - 100.0, swept.cy - 0.0) < swept.inflated
    assert covered.any()
    assert swept.cy.max() < 20.0
    # consecutive pieces around the meeting point overlap: no gap a path could slip through
    near = np.sort(swept.cy[np.abs(swept.cy) <= 30.0])
    assert near.min() < -25.0 and near.max() > 10.0
    assert (np.diff(near) <= 0.7 * 7.0 + 1e-9).all()


def test_swept_window_keeps_static_circles_and_empty_worlds():
    still = World(np.array([5.0]), np.array([6.0]), np.zeros(1), np.zeros(1), np.ones(1),
                  np.full(1, 3.0))
    out = still.swept_window(np.zeros(2), 1.0, 100.0)
    assert (out.cx, out.cy, out.inflated) == (still.cx, still.cy, still.inflated)
    empty = World(*(np.zeros(0) for _ in range(6)))
    assert empty.swept_window(np.zeros(2), 1.0, 100.0).count == 0


def test_static_only_planners_say_they_plan_against_swept_corridors():
    caps = {p["name"]: p["capabilities"] for p in describe_planners()}
    for name in ("de-apf", "rrt-star", "bspline-rrt-star", "vpf-rrt-star"):
        assert "moving-obstacles-as-swept-corridors" in caps[name]
    for name in ("iga", "colregs-ga", "replan-ga"):
        assert "moving-obstacles-as-swept-corridors" not in caps[name]


@pytest.mark.parametrize("name", ["de-apf", "rrt-star"])
def test_static_only_planner_passes_a_crossing_target_on_its_corridor(name):
    sc = next(s for s in colregs_cases() if s.name == "colregs-crossing-give-way-b")
    plan = plan_with(sc, name, 1).to_document()
    assert plan_violations(plan, sc) == []
    assert plan["metrics"]["obstacle_model"] in ("swept", "timed")
    assert plan["metrics"]["min_clearance_m"] > 0.0


def test_de_apf_leaves_the_u_shape_by_following_its_edge():
    """003's U shape facing the start: the field alone stops inside it (the walker used to
    give up there); following the edge brings it round."""
    sc = next(s for s in trap_cases() if s.name == "trap-u-shape")
    for seed in (1, 2):
        plan = plan_with(sc, "de-apf", seed).to_document()
        assert plan_violations(plan, sc) == []
        assert plan["metrics"]["length_m"] > 105.0  # went round, not through


def test_colregs_ga_reaches_a_goal_beside_an_obstacle():
    sc = next(s for s in trap_cases() if s.name == "trap-goal-beside-obstacle")
    plan = plan_with(sc, "colregs-ga", 1).to_document()
    assert plan_violations(plan, sc) == []
    last = plan["waypoints"][-1]
    assert (last["x"], last["y"]) == (100.0, 0.0)


def test_hidden_scenarios_are_seeded_distinct_and_valid():
    for make in (transit_hidden, colregs_hidden, trap_hidden):
        a, b = make(1000), make(1001)
        assert make(1000) == a
        assert a.name != b.name and a != b
    for kind_seed in (1000, 1001, 1002):
        trap = trap_hidden(kind_seed)
        goal = math.hypot(trap.goal.x, trap.goal.y)
        assert 80.0 <= goal <= 150.0 + 1e-6
    names = [s.name for s in family_scenarios("colregs", hidden=3)]
    assert names[:8] == [s.name for s in colregs_cases()]
    assert all(n.startswith("colregs-hidden-") for n in names[8:]) and len(names) == 11
    assert [s.name for s in family_scenarios("traps", hidden=2, hidden_from=7)][3:] == [
        trap_hidden(7).name, trap_hidden(8).name]


def test_a_mover_crossing_the_run_in_at_arrival_is_passed_at_another_speed():
    """random-recovery-1001: a vessel reaches the ramp approach when the boat would at its
    start speed; a static-only planner cannot see that, its second attempt sails 1.3x faster."""
    from usvstation.bench.scenarios import random_recovery

    sc = random_recovery(1001)
    plan = plan_with(sc, "rrt-star", 1).to_document()
    assert plan_violations(plan, sc) == []
    assert plan["metrics"]["attempts"] == 2


def test_a_route_turning_too_far_from_the_start_heading_gets_a_lead_in():
    """random-recovery-1004 under way at 0.64 m/s: DE-APF's walk leaves 96 degrees off the
    heading; a lead-in along the heading keeps the first turn within the limit."""
    from usvstation.bench.scenarios import random_recovery
    from usvstation.planning.validate import first_turn_deg

    sc = random_recovery(1004)
    assert sc.start.speed >= 0.5
    plan = plan_with(sc, "de-apf", 2).to_document()
    assert plan_violations(plan, sc) == []
    assert first_turn_deg(plan, sc) <= sc.vessel.turn_max_deg
