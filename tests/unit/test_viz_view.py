"""The 3D (x, y, t) view: geometry helpers and the viser GUI controls on a real viser server."""

import math
import time

import numpy as np
import pytest

from usvstation.scenario import load_scenario
from usvstation.viz.view import (
    CIRCLE_SIDES,
    LAYERS,
    ThreeDView,
    oblique_cylinder,
    track_position_at,
)

WAYPOINTS = [{"x": 80.0, "y": 10.0, "t": 0.0}, {"x": 40.0, "y": 0.0, "t": 20.0},
             {"x": 0.0, "y": 0.0, "t": 30.0}]


def test_moving_obstacle_leans_along_its_velocity():
    v, f = oblique_cylinder(10.0, 5.0, 2.0, 0.5, -0.25, 40.0, 1.0)
    bottom, top = v[:CIRCLE_SIDES], v[CIRCLE_SIDES:2 * CIRCLE_SIDES]
    assert np.allclose(bottom[:, 2], 0.0) and np.allclose(top[:, 2], 40.0)
    # the top circle is the bottom one moved by v * t: eq. 8's centre (x + vx t, y + vy t)
    assert np.allclose(top[:, :2] - bottom[:, :2], [20.0, -10.0], atol=1e-5)
    assert np.allclose(np.hypot(*(bottom[:, :2] - [10.0, 5.0]).T), 2.0, atol=1e-5)
    assert f.max() < len(v) and len(f) == 4 * CIRCLE_SIDES


def test_real_position_is_the_last_report_at_or_before_t():
    track = [(80.0, 10.0, 0.0), (79.0, 9.5, 0.2), (78.0, 9.0, 0.4)]
    assert track_position_at([], 1.0) is None
    assert track_position_at(track, -0.1) is None
    assert track_position_at(track, 0.3) == (79.0, 9.5)
    assert track_position_at(track, 5.0) == (78.0, 9.0)


@pytest.fixture
def view():
    v = ThreeDView(port=0)
    v.start()
    yield v
    v.stop()


def test_layers_toggle_from_code_and_gui(view):
    assert set(view.layers) == set(LAYERS)
    view.set_layer("obstacles", False)
    assert view.layers["obstacles"].visible is False
    assert view.gui["layer:obstacles"].value is False
    view.gui["layer:plan"].value = False  # as when the operator unticks the box
    assert view.layers["plan"].visible is False and view.layers["track"].visible is True
    with pytest.raises(ValueError, match="unknown layer 'sea'"):
        view.set_layer("sea", True)


def test_plan_sets_the_horizon_and_scrubbing_moves_the_time_plane(view):
    scenario = load_scenario("case1")
    view.show_scenario(scenario)
    view.show_plan({"waypoints": WAYPOINTS})
    assert view.horizon_s == math.ceil(30.0 * 1.2)
    assert view.gui["time"].max == view.horizon_s
    view.gui["time"].value = 10.0  # the operator drags the slider
    assert view.time_s == 10.0 and view.follow_live is False
    assert view.gui["readout"].content.splitlines()[1].startswith("planned: x 60.0 m, y 5.0 m")
    moving = [i for i, o in enumerate(scenario.obstacles) if o.moving]
    disc, vx, vy = view._discs[moving[0]]
    assert tuple(disc.position) == pytest.approx((vx * 10.0, vy * 10.0, 10.0))
    assert view._plane.position[2] == pytest.approx(10.0)


def test_live_track_moves_the_time_when_following(view):
    view.show_scenario(load_scenario("case1"))
    view.show_plan({"waypoints": WAYPOINTS})
    view.gui["follow"].value = False  # left unticked after the last run
    view.clear_track()  # a new run follows again
    assert view.follow_live is True and view.gui["follow"].value is True
    for i in range(3):
        view.add_track_point(80.0 - i, 10.0, 2.0 * i)
        time.sleep(0.55)  # past the redraw interval: each point redraws
    assert view.time_s == pytest.approx(4.0)
    assert "real: x 78.0 m, y 10.0 m" in view.gui["readout"].content
    view.gui["follow"].value = False
    view.add_track_point(70.0, 10.0, 12.0)
    time.sleep(0.55)
    view.add_track_point(69.0, 10.0, 13.0)
    assert view.time_s == pytest.approx(4.0)


def test_a_run_longer_than_its_plan_extends_slider_and_obstacles(view):
    view.show_scenario(load_scenario("case1"))
    view.show_plan({"waypoints": WAYPOINTS})
    assert view.horizon_s == 36
    view.clear_track()
    view.add_track_point(80.0, 10.0, 0.0)
    time.sleep(0.55)
    view.add_track_point(79.0, 10.0, 50.0)  # the boat held: 50 s into a 30 s plan
    assert view.horizon_s == 60 and view.gui["time"].max == 60
    tops = [node.vertices[:, 2].max() for node in view._obstacle_nodes[::2]]
    assert tops and all(top == pytest.approx(60.0) for top in tops)


def test_feed_shows_a_runs_plan_and_its_own_track_from_hub_events(view):
    """The 3D view listens to the station's events: a run's plan when it opens, then only
    that run's fixes, timed from its first fix; nothing after the run ends."""
    from usvstation.services.hub import LiveHub
    from usvstation.viz.feed import ThreeDFeed

    plan = {"waypoints": [{**w, "speed": 1.0, "heading_deg": 180.0} for w in WAYPOINTS]}
    hub = LiveHub()
    hub.observers.append(ThreeDFeed(view, {"m1": plan}.get).on_event)

    def fix(run, x, t):
        return {"run": run, "x": x, "y": 0.0, "boat_time": t}

    hub.publish("telemetry", fix(None, 99.0, 1.0))  # no run yet: not drawn
    hub.publish("run", {"id": 7, "mission": "m1", "state": "active"})
    assert view.waypoints == plan["waypoints"]
    hub.publish("telemetry", fix(7, 80.0, 100.0))
    hub.publish("telemetry", fix(6, 50.0, 100.1))  # another run's fix
    hub.publish("telemetry", fix(7, 79.0, 100.2))
    hub.publish("run", {"id": 7, "mission": "m1", "state": "completed"})
    hub.publish("telemetry", fix(7, 78.0, 100.4))  # after the end
    assert view._track == [(80.0, 0.0, 0.0), (79.0, 0.0, pytest.approx(0.2 * view.time_scale))]


# --- issue 25: the hull, the targets and the palettes -----------------------------------------
def _with_ship(**ship):
    doc = load_scenario("case1").model_dump(mode="json")
    doc["mother_ship"] = {"speed": 1.0, "course_deg": 270.0, **ship}
    from usvstation.scenario import parse_scenario

    return parse_scenario(doc)


def test_hull_is_the_ships_box_or_outline_swept_over_time():
    from usvstation.viz.scene import hull_outline, hull_prism

    ship = _with_ship(length=40.0, beam=10.0).mother_ship
    v, f = hull_prism(ship, 30.0)
    assert v.shape == (8, 3) and f.max() < 8 and len(f) == 8
    assert {tuple(p) for p in v[:4, :2]} == {(0.0, -5.0), (0.0, 5.0), (-40.0, 5.0),
                                             (-40.0, -5.0)}
    assert np.allclose(v[4:, 2], 30.0) and np.allclose(v[4:, :2], v[:4, :2])
    segments = hull_outline(ship)
    assert segments.shape == (4, 2, 3) and np.allclose(segments[:, 1], np.roll(segments[:, 0],
                                                                                -1, axis=0))
    tri = _with_ship(outline=[[0, -4], [0, 4], [-30, 0]]).mother_ship
    assert hull_prism(tri, 1.0)[0].shape == (6, 3)
    # no beam nor outline: its length on the axis, and no prism
    bare = _with_ship(length=50.0).mother_ship
    assert hull_prism(bare, 1.0) is None
    assert hull_outline(bare).tolist() == [[[0.0, 0.0, 0.0], [-50.0, 0.0, 0.0]]]
    assert hull_outline(None) is None


def test_targets_sweep_along_their_relative_velocity_in_their_colour():
    from usvstation.viz.scene import PALETTES, target_sweeps

    day = PALETTES["day"]
    targets = [
        {"id": "ais:1", "name": "TURNER", "mmsi": 1, "x": 50.0, "y": -20.0, "rvx": -1.0,
         "rvy": 2.0, "lost": False},
        {"id": "arpa:2", "name": None, "mmsi": None, "x": 10.0, "y": 5.0, "rvx": 0.0,
         "rvy": 0.0, "lost": True}]
    a, b = target_sweeps(targets, 10.0, 40.0, 1.0, day, frozenset({"ais:1"}))
    assert a.position == (50.0, -20.0, 10.0) and a.color == day.danger and a.label == "TURNER"
    assert a.segments.tolist() == [[[50.0, -20.0, 10.0], [20.0, 40.0, 40.0]]]
    assert (b.color, b.label) == (day.lost, "arpa:2 (lost)")


def test_night_palette_has_nothing_brighter_than_the_consoles_red():
    from usvstation.viz.scene import PALETTES, palette

    for name, p in PALETTES.items():
        assert palette(name) is p
    night = [c for c in vars(PALETTES["night"]).values() if isinstance(c, tuple)]
    assert night and all(g <= 60 and b <= 30 and r <= 0xE0 for r, g, b in night)
    with pytest.raises(ValueError, match="unknown palette 'noon'; palettes: day, dusk, night"):
        palette("noon")


def test_view_draws_the_hull_and_targets_and_switches_palette(view):
    from usvstation.viz.scene import PALETTES

    view.show_scenario(_with_ship(length=40.0, beam=10.0))
    assert len(view._ship_nodes) == 2  # the outline and the prism
    targets = [{"id": "ais:1", "name": "TURNER", "mmsi": 1, "x": 50.0, "y": -20.0,
                "rvx": -1.0, "rvy": 2.0, "lost": False}]
    view.show_targets(targets, 0.0, frozenset({"ais:1"}))
    assert set(view._target_nodes) == {"ais:1"}
    view.gui["palette"].value = "night"  # as when the operator picks it
    assert view.palette is PALETTES["night"]
    assert [label.visible for label in view._axis_labels] == [False, False]
    assert set(view._target_nodes) == {"ais:1"} and len(view._ship_nodes) == 2
    view.show_targets([], 0.0)
    assert view._target_nodes == {}
    view.show_scenario(load_scenario("case1"))  # no mother ship: no hull
    assert view._ship_nodes == []


def test_feed_draws_the_worlds_targets_at_the_runs_time_dangerous_from_the_monitor(view):
    from usvstation.services.hub import LiveHub
    from usvstation.viz.feed import ThreeDFeed

    hub = LiveHub()
    plan = {"waypoints": [{**w, "speed": 1.0, "heading_deg": 180.0} for w in WAYPOINTS]}
    hub.observers.append(ThreeDFeed(view, {"m1": plan}.get).on_event)
    target = {"id": "ais:1", "name": "TURNER", "mmsi": 1, "x": 50.0, "y": -20.0, "rvx": -1.0,
              "rvy": 2.0, "lost": False}
    hub.publish("world", {"targets": [target]})
    assert view.targets == [target] and view._target_time == 0.0
    hub.publish("run", {"id": 7, "mission": "m1", "state": "active"})
    hub.publish("telemetry", {"run": 7, "x": 80.0, "y": 0.0, "boat_time": 100.0})
    hub.publish("telemetry", {"run": 7, "x": 79.0, "y": 0.0, "boat_time": 112.5})
    hub.publish("monitor", {"targets": [{"id": "ais:1", "min_clearance_m": 1.0}],
                            "margin_m": 1.6})
    hub.publish("world", {"targets": [target]})
    assert view._target_time == 12.5 and view._dangerous == {"ais:1"}
