"""The live loop with the mother ship under way, through the HTTP API alone: the station
streams the ramp pose (USV_RAMP_POSE), the simulated boat tracks its plan in the moving
ramp frame over still water, a target turns onto the boat's path, the monitor warns, a
re-plan is proposed, confirmed, swapped, and the boat is recovered on the moving ramp with
no contact. Everything asserted comes from the boat's telemetry and the stored records."""

from __future__ import annotations

import math

import pytest
from stationproc import StationProcess
from test_live_loop import poll

from usvstation.geo import RampFrame
from usvstation.scenario import load_scenario
from usvstation.world.model import enu_to_compass

TARGET = "ais:211000301"
PARK = (35.0, 4.0)  # where the target keeps station on the ship, on the run to the ramp
SHIP = 1.0  # m/s over ground, course 270: along -x of the ramp frame (+x east, +y north)


def leg(rvx: float, rvy: float) -> tuple[float, float]:
    """Course and speed over ground of a velocity relative to the ship (ramp frame)."""
    speed, course = enu_to_compass(rvx - SHIP, rvy)
    return round(course, 4), round(speed, 4)


def scenario() -> dict:
    base = load_scenario("case1").model_dump(mode="json")
    (c1, s1), (c2, s2), (c3, s3) = leg(3.0, 0.0), leg(0.0, 3.0), leg(0.0, 0.0)
    return {
        **base, "name": "turning-target-under-way", "obstacles": [],
        "start": {"x": 85.0, "y": 10.0, "heading_deg": 180.0, "speed": 1.0},
        # the simulated Otter (2 m); planned at relative speeds it makes good against the
        # ship's way (at most 2.5 m/s through the water, of its 3.09)
        "vessel": {**base["vessel"], "length": 2.0, "compensation_radius": 1.5,
                   "speed_max": 1.5},
        "mother_ship": {"speed": SHIP, "course_deg": 270.0, "lever_arm": {"forward": -20.0}},
        # relative to the ship: along +x off the path, turns onto it at 5 s, and from 15 s
        # keeps station on the ship at PARK (over ground: the ship's course and speed)
        "traffic": [{
            "mmsi": 211000301, "name": "TURNER", "start": {"x": 20.0, "y": -26.0},
            "course_deg": c1, "speed": s1, "length": 8.0,
            "manoeuvres": [{"t": 5.0, "course_deg": c2, "speed": s2},
                           {"t": 15.0, "course_deg": c3, "speed": s3}],
        }],
    }


@pytest.fixture
def station(tmp_path):
    st = StationProcess(tmp_path / "data", "--sim-speed", "5", "--replan", "confirm")
    st.wait_link_up()
    try:
        yield st
    finally:
        st.stop()


def test_under_way_the_boat_tracks_the_moving_ramp_and_a_confirmed_replan_recovers_it(
        station) -> None:
    c = station.client
    assert c.put("/api/scenario", json=scenario()).status_code == 200
    world = poll(lambda: (w := c.get("/api/world").json())["own_ship"] and w["ramp"]
                 and w["ramp"]["speed"] > 0.9 and w, 30, "the moving ship in /api/world")
    assert world["ramp"]["source"] == "own_ship"
    assert world["ramp"]["vx"] == pytest.approx(-SHIP, abs=0.05)  # the ship makes way to -x
    # the target parks on the ship: still relative to the ramp, moving over ground
    poll(lambda: any(t["id"] == TARGET and math.hypot(t["rvx"], t["rvy"]) < 0.1
                     and t["speed"] > 0.9 and math.hypot(t["x"] - PARK[0], t["y"] - PARK[1]) < 2
                     for t in c.get("/api/world").json()["targets"]), 60,
         "the target keeping station on the path")
    # the boat keeps station on the moving ramp at its start (telemetry in the ramp frame)
    poll(lambda: (r := c.get("/api/boat").json()["telemetry"]) and
         math.hypot(r["x"] - 85.0, r["y"] - 10.0) < 4.0 and r["speed"] > 0.7, 60,
         "the boat keeping station astern of the moving ship")

    job = station.wait_plan(c.post("/api/plans", json={"seed": 1}).json()["id"], 120)
    assert job["status"] == "done"
    r = c.post("/api/missions", json={"plan_id": job["id"]})
    mission = station.wait(f"/api/missions/{r.json()['id']}", "state", ("uploading",), 20)
    assert mission["state"] == "verified"
    start = c.post("/api/boat/command", json={"command": "start", "mission_id": mission["id"]})
    assert start.status_code == 200, start.text

    warning = poll(lambda: next((a for a in c.get("/api/alerts").json()
                                 if a["level"] == "warning" and a["target_id"] == TARGET),
                                None), 60, "a warning on the turning target")
    assert warning["kind"] in ("clearance", "collision_course")
    replan = poll(lambda: next((p for p in c.get("/api/replans").json()
                                if p["state"] in ("proposed", "failed")), None),
                  120, "a proposed re-plan")
    assert replan["state"] == "proposed", replan["error"]
    new = c.get(f"/api/plans/{replan['plan_id']}").json()
    # the re-plan: the ship's way as an apparent current, the target where it keeps station
    env = new["scenario"]["environment"]
    assert env["current_speed"] == pytest.approx(SHIP, abs=0.05)
    assert env["current_dir_deg"] == pytest.approx(0.0, abs=3.0)
    (obstacle,) = new["scenario"]["obstacles"]
    assert math.hypot(obstacle["x"] - PARK[0], obstacle["y"] - PARK[1]) < 2.5

    confirm = c.post(f"/api/replans/{replan['id']}/confirm")
    assert confirm.status_code == 200 and confirm.json()["state"] == "applied", confirm.text
    swapped = confirm.json()["mission_id"]
    old = station.wait(f"/api/missions/{mission['id']}", "state", ("active",), 120)
    assert old["state"] == "gone"
    final = station.wait(f"/api/missions/{swapped}", "state",
                         ("uploading", "verified", "active"), 180)
    assert final["state"] == "completed"

    rows = [r for r in c.get("/api/telemetry", params={"limit": 100_000}).json()
            if r["run"] is not None]
    assert rows
    # over ground the boat made the ship's way; in the ramp frame it ended on the ramp
    last = rows[-1]
    assert math.hypot(last["x"], last["y"]) < 3.0
    o = scenario()["origin"]
    east, _ = RampFrame(o["lat"], o["lon"], o["ramp_bearing_deg"]).to_ramp(last["lat"],
                                                                         last["lon"])
    assert east < -50.0  # the ramp (and the boat on it) sailed west with the ship
    clearance = min(math.hypot(r["x"] - PARK[0], r["y"] - PARK[1]) for r in rows) - 4.0 - 1.0
    print(f"telemetry clearance to the target keeping station {clearance:.2f} m")
    assert clearance > 0.0
    texts = [s["text"] for s in c.get("/api/boat").json()["status"]]
    assert not any("ramp pose stale" in t for t in texts), texts
