"""Station parts behind the console (issue 16): alerts, the outdated-plan check, MBTiles."""

from __future__ import annotations

import sqlite3

from hypothesis import given
from hypothesis import strategies as st

from usvstation.api.charts import read_package, read_tile
from usvstation.link.protocol import LinkDown, LinkUp
from usvstation.scenario import load_scenario
from usvstation.services.alerts import LinkAlerts
from usvstation.services.plans import outdated_by, scenario_digest
from usvstation.world.monitor import AlertEvent


def test_link_lost_raises_one_warning_that_ends_when_the_link_is_back():
    raised: list[AlertEvent] = []
    alerts = LinkAlerts(raised.append)
    alerts.on_link_event(LinkDown("no frame from the boat for 3.0 s"))
    alerts.on_link_event(LinkDown("no frame from the boat for 3.0 s"))  # still down: no repeat
    alerts.on_link_event(LinkUp(1))
    alerts.on_link_event(LinkUp(1))
    assert raised == [
        AlertEvent("warning", "link_lost",
                   "link to the boat lost: no frame from the boat for 3.0 s"),
        AlertEvent(None, "link_lost", "link to the boat restored", announce=False, rose=False)]


def test_outdated_by_names_the_changed_fields_of_the_same_scenario():
    case1 = load_scenario("case1")
    moved = case1.model_copy(update={"start": case1.start.model_copy(update={"x": 80.0})})
    # a job stored before bases were kept: its own scenario against the working one
    old = {"scenario": case1.model_dump(mode="json"), "basis": None}
    assert outdated_by(old, case1) == []
    assert outdated_by(old, moved) == ["start"]
    assert outdated_by({"scenario": load_scenario("case2").model_dump(mode="json"),
                        "basis": None}, moved) == []


def test_a_plan_made_from_the_working_scenario_stays_uploadable_until_it_changes():
    """A plan from the boat (or the live world) has another start (obstacles, current)
    than the working scenario it was made from: not outdated by that, only by a change of
    the working scenario itself."""
    case1 = load_scenario("case1")
    from_boat = case1.model_copy(update={"start": case1.start.model_copy(update={"x": 60.0})})
    job = {"scenario": from_boat.model_dump(mode="json"), "basis": scenario_digest(case1)}
    assert outdated_by(job, case1) == []
    edited = case1.model_copy(update={"vessel": case1.vessel.model_copy(
        update={"length": 2.0})})
    assert outdated_by(job, edited) == ["vessel"]


def test_plan_from_a_boat_inside_the_ship_is_refused_in_one_sentence():
    import pytest

    from usvstation.scenario import parse_scenario
    from usvstation.services.errors import Conflict
    from usvstation.services.plans import scenario_from_boat

    doc = load_scenario("case1").model_dump(mode="json")
    doc["mother_ship"] = {"speed": 0.0, "course_deg": 270.0, "length": 40.0, "beam": 10.0,
                          "ramp_width": 3.0}
    row = {"x": -10.0, "y": 1.0, "ramp_heading_deg": 0.0, "speed": 0.5, "boat_time": 3.0,
           "run": None}
    with pytest.raises(Conflict) as refused:
        scenario_from_boat(parse_scenario(doc), row, None)
    assert str(refused.value) == (
        "cannot plan from the boat: start: (-10, 1) lies inside the mother ship's hull (x in "
        "[-40, 0], |y| <= 5 m of the ramp frame), behind the ramp; a recovery starts in the "
        "water")


def _mbtiles(path, tiles):
    db = sqlite3.connect(path)
    db.execute("CREATE TABLE metadata (name TEXT, value TEXT)")
    db.execute("CREATE TABLE tiles (zoom_level INTEGER, tile_column INTEGER, tile_row INTEGER, "
               "tile_data BLOB)")
    db.executemany("INSERT INTO metadata VALUES (?, ?)", [
        ("name", "Harbour"), ("format", "png"), ("minzoom", "3"), ("maxzoom", "5"),
        ("bounds", "114.4,30.5,114.5,30.6")])
    db.executemany("INSERT INTO tiles VALUES (?, ?, ?, ?)", tiles)
    db.commit()
    db.close()


def test_mbtiles_metadata(tmp_path):
    path = tmp_path / "harbour.mbtiles"
    _mbtiles(path, [])
    pkg = read_package(path)
    assert (pkg.name, pkg.title, pkg.format, pkg.minzoom, pkg.maxzoom) == (
        "harbour", "Harbour", "png", 3, 5)
    assert pkg.bounds == [114.4, 30.5, 114.5, 30.6]
    assert pkg.tiles == "/api/charts/harbour/{z}/{x}/{y}"


@given(z=st.integers(0, 20), data=st.data())
def test_mbtiles_rows_are_tms_and_tiles_are_xyz(tmp_path_factory, z, data):
    n = 1 << z
    x = data.draw(st.integers(0, n - 1))
    y = data.draw(st.integers(0, n - 1))
    path = tmp_path_factory.mktemp("charts") / "c.mbtiles"
    _mbtiles(path, [(z, x, n - 1 - y, b"tile")])
    assert read_tile(path, z, x, y) == b"tile"
    if n > 1:
        assert read_tile(path, z, x, n - 1 - y) in (None, b"tile")
        assert (read_tile(path, z, x, n - 1 - y) is None) == (n - 1 - y != y)
