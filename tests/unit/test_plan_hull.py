"""Plans beside the mother ship (issue 27): the hull as a polygon obstacle with eq. 7's margin
outside the tapered approach corridor, starts inside the hull refused in one sentence."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from usvstation.bench.checker import STEP_M, _sampled_ship_clearance, check_plan
from usvstation.bench.scenarios import alongside, outline_astern_traffic
from usvstation.planning.hull import (
    corridor,
    distance_to_corridor,
    hull_ring,
    keepout_circles,
    outline_clearance,
)
from usvstation.planning.registry import plan_with
from usvstation.planning.validate import plan_violations
from usvstation.scenario import ScenarioError, load_scenario, parse_scenario
from usvstation.scenario.hull import inside

SHIP = {"length": 60.0, "beam": 12.0, "ramp_width": 3.0}


def _scenario(x, y, heading=180.0, speed=1.0, **ship):
    base = load_scenario("case1").model_dump(mode="json")
    return parse_scenario({**base, "name": "beside", "obstacles": [],
                           "start": {"x": x, "y": y, "heading_deg": heading, "speed": speed},
                           "mother_ship": {**SHIP, **ship}})


@pytest.mark.parametrize("x, y, words", [
    (-20.0, 3.0, "lies inside the mother ship's hull (x in [-60, 0], |y| <= 6 m"),
    (-3.0, 0.0, "behind the ramp"),
    (-20.0, 6.3, "touches the ship"),
])
def test_a_start_inside_or_against_the_hull_is_refused_in_one_sentence(x, y, words):
    with pytest.raises(ScenarioError, match=r"^start: ") as info:
        _scenario(x, y)
    assert words in str(info.value) and "\n" not in str(info.value)


def test_an_outline_replaces_the_box_and_a_bad_one_is_refused():
    bow = [[0.0, -5.0], [0.0, 5.0], [-30.0, 5.0], [-45.0, 0.0], [-30.0, -5.0]]
    sc = _scenario(-40.0, 4.0, outline=bow)  # outside the tapered bow, inside the box
    assert not inside(-40.0, 4.0, hull_ring(sc).tolist())
    with pytest.raises(ScenarioError, match=r"mother_ship\.outline"):
        _scenario(-20.0, 3.0, outline=bow)
    with pytest.raises(ScenarioError, match=r"mother_ship\.outline: the polygon encloses no"):
        _scenario(40.0, 0.0, outline=[[0.0, 0.0], [-10.0, 0.0], [-20.0, 0.0]])
    with pytest.raises(ScenarioError, match=r"ramp_width: must be narrower than the beam"):
        _scenario(40.0, 0.0, ramp_width=20.0)


def test_without_beam_or_outline_the_ship_has_no_shape():
    base = load_scenario("case1").model_dump(mode="json")
    sc = parse_scenario({**base, "start": {"x": -20.0, "y": 3.0},
                         "mother_ship": {"speed": 1.0, "course_deg": 270.0}})
    assert hull_ring(sc) is None and keepout_circles(sc, 2.2)[1].size == 0


def test_keepout_keeps_the_margin_along_the_hull_and_tapers_into_the_corridor():
    sc = _scenario(40.0, 0.0)
    centres, radii = keepout_circles(sc, 2.2)
    half, tan_a = corridor(sc)
    # no circle reaches into the corridor: the run-in along the axis is always open
    assert np.all(radii <= distance_to_corridor(centres, half, tan_a) + 1e-9)
    # every point of the band within 2.2 m of the side or the bow is covered
    band = np.column_stack([np.linspace(-59.0, -1.0, 300), np.full(300, 6.0 + 2.19)])
    d = np.hypot(band[:, None, 0] - centres[:, 0], band[:, None, 1] - centres[:, 1])
    assert np.all((d < radii).any(axis=1))
    # on the stern face the margin tapers to 0 at the ramp's edge (|y| = 1.5)
    stern = (np.abs(centres[:, 0]) < 1e-9) & (np.abs(centres[:, 1]) < 6.0)
    ys, rs = np.abs(centres[stern, 1]), radii[stern]
    assert rs[np.argmin(ys)] < 0.3 and rs[np.argmax(ys)] > 2.2
    assert ys.min() > 1.5


@settings(max_examples=60, deadline=None)
@given(x=st.floats(-5.0, 40.0), y=st.floats(-20.0, 20.0))
def test_distance_to_corridor_is_a_distance(x, y):
    """Zero inside W, else the least distance to points sampled densely in W."""
    sc = _scenario(40.0, 0.0)
    half, tan_a = corridor(sc)
    d = float(distance_to_corridor(np.array([[x, y]]), half, tan_a)[0])
    xs = np.linspace(0.0, 60.0, 1201)
    edge = np.concatenate([np.column_stack([xs, half + xs * tan_a]),
                           np.column_stack([xs, -half - xs * tan_a]),
                           np.column_stack([np.zeros(61), np.linspace(-half, half, 61)])])
    inside_w = x >= 0 and abs(y) <= half + x * tan_a
    expected = 0.0 if inside_w else float(np.min(np.hypot(edge[:, 0] - x, edge[:, 1] - y)))
    assert d == pytest.approx(expected, abs=0.03)


MM = st.floats(-70.0, 20.0).map(lambda v: round(v, 3))  # millimetres: no 1e-300 m slivers


@settings(max_examples=40, deadline=None)
@given(x0=MM, y0=MM.map(lambda v: v / 3.0), x1=MM, y1=MM.map(lambda v: v / 3.0))
def test_outline_clearance_agrees_with_the_independent_checker(x0, y0, x1, y1):
    """The validator's exact clearance against the checker's dense sampling (2 cm)."""
    sc = _scenario(40.0, 0.0)
    x, y = np.array([x0, x1]), np.array([y0, y1])
    exact = outline_clearance(sc, x, y)
    sampled = _sampled_ship_clearance(x, y, sc)
    if sampled is None:  # all of it inside the corridor
        assert exact is None
    elif sampled > STEP_M:
        assert exact == pytest.approx(sampled, abs=STEP_M)
    else:
        assert exact <= STEP_M


@pytest.mark.parametrize("name", ["iga", "rrt-star", "replan-ga"])
@pytest.mark.parametrize("start", [(-30.0, 14.0, 0.0, 1.0), (-40.0, -12.0, 180.0, 0.0),
                                   (10.0, 7.0, 180.0, 1.0)])
def test_planners_plan_beside_the_hull_and_keep_clear_of_it(name, start):
    sc = _scenario(*start)
    plan = plan_with(sc, name, 1).to_document()
    assert plan_violations(plan, sc) == []
    rep = check_plan(plan, sc)
    assert rep.ok, rep.problems
    assert rep.ship_clearance_m is None or rep.ship_clearance_m > 0.0


def test_a_route_through_the_hull_is_refused_by_the_validator_and_the_checker():
    sc = _scenario(-30.0, 14.0, heading=0.0)
    plan = plan_with(sc, "iga", 1).to_document()
    wps = plan["waypoints"]
    bad = {**plan, "waypoints": [wps[0], {**wps[1], "x": -10.0, "y": 0.0}, *wps[2:]]}
    assert any("mother ship's hull" in v for v in plan_violations(bad, sc))
    assert any("mother ship's hull" in p for p in check_plan(bad, sc).problems)


@pytest.mark.parametrize("family", [alongside, outline_astern_traffic])
def test_the_hull_families_plan_and_pass_the_checker(family):
    for i in range(3):
        sc = family(i)
        plan = plan_with(sc, "iga", 1).to_document()
        assert check_plan(plan, sc).ok
