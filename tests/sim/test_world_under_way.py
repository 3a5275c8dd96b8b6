"""Under way, the world keeps the scenario's charted obstacles where they are over ground,
also after a plan of the live world starts (its obstacles carry velocities relative to the
moving ramp), and a ship on AIS is one track, not a second `manual` one."""

from __future__ import annotations

import math

from simstation import SimStation, run_station

from usvstation.scenario import load_scenario
from usvstation.world.model import enu_to_compass

SHIP = 1.0  # m/s, course 270: the ramp frame moves along -x


def scenario() -> dict:
    base = load_scenario("case1").model_dump(mode="json")
    speed, course = enu_to_compass(-SHIP, 0.0)  # the AIS ship keeps pace with the mother ship
    return {**base, "name": "under-way",
            "obstacles": [{"x": 60.0, "y": 20.0, "radius": 2.0, "vx": 0.0, "vy": 0.0}],
            "mother_ship": {"speed": SHIP, "course_deg": 270.0,
                            "lever_arm": {"forward": -20.0}},
            "traffic": [{"mmsi": 211000401, "name": "PACER", "start": {"x": 40.0, "y": -25.0},
                         "course_deg": course, "speed": speed, "length": 8.0}]}


def test_charted_obstacles_stay_put_over_ground_and_ais_ships_are_not_doubled(tmp_path):
    async def body(sim: SimStation) -> None:
        c = sim.client
        assert (await c.put("/api/scenario", json=scenario())).status_code == 200

        async def sea_in_world() -> bool:
            w = await sim.get("/api/world")
            return bool(w["ramp"] and w["ramp"]["speed"] > 0.9
                        and any(t["id"] == "ais:211000401" for t in w["targets"]))

        await sim.poll(sea_in_world, 30, "the sea in /api/world")
        world = (await sim.get("/api/world/scenario"))["scenario"]
        assert any(math.hypot(o["x"] - 40.0, o["y"] + 25.0) < 2.0 for o in world["obstacles"])
        job = await sim.wait_plan((await c.post("/api/plans", json={
            "seed": 1, "scenario": world})).json()["id"])
        assert job["status"] == "done", job["error"]
        await sim.fly(job["id"])  # a plan of the live world uploads (its basis is unchanged)
        await sim.clock.sleep(10.0)
        targets = (await sim.get("/api/world"))["targets"]
        manual = [t for t in targets if t["source"] == "manual"]
        assert len(manual) == 1, manual  # the charted obstacle; PACER is tracked by its AIS
        assert manual[0]["speed"] < 0.05  # still over ground ...
        # ... and moves astern relative to the ramp, which makes way along -x
        assert math.hypot(manual[0]["rvx"] - SHIP, manual[0]["rvy"]) < 0.05
        ais = next(t for t in targets if t["id"] == "ais:211000401")
        assert math.hypot(ais["rvx"], ais["rvy"]) < 0.1  # keeping pace with the ship

    run_station(tmp_path / "data", body, replan="off")


def test_the_mother_ship_moves_and_turns_the_ramp_in_api_world(tmp_path):
    """The simulated sea's ship under way (NMEA own-ship sentences) moves the ramp in
    /api/world by speed x time along its course; when it turns, the stern ramp swings with
    its heading at the ship's turn rate."""
    import datetime as dt

    import pytest

    from usvstation.geo import RampFrame

    base = load_scenario("case1").model_dump(mode="json")
    doc = {**base, "mother_ship": {"speed": 1.5, "course_deg": 270.0, "turn_rate_deg_s": 2.0,
                                   "lever_arm": {"forward": -30.0},
                                   "manoeuvres": [{"t": 30.0, "course_deg": 250.0}]}}

    async def body(sim: SimStation) -> None:
        assert (await sim.client.put("/api/scenario", json=doc)).status_code == 200

        async def under_way() -> dict | None:
            w = await sim.get("/api/world")
            return w if w["own_ship"] and w["own_ship"]["speed"] else None

        w1 = await sim.poll(under_way, 30, "the own ship under way")
        await sim.clock.sleep(10.0)
        w2 = await sim.get("/api/world")
        r1, r2 = w1["ramp"], w2["ramp"]
        assert r1["source"] == "own_ship"
        assert r2["ramp_bearing_deg"] == pytest.approx(90.0, abs=0.05)  # a stern ramp
        assert r2["speed"] == pytest.approx(1.5, abs=0.01)  # (VTG: 0.01 kn)
        assert r2["course_deg"] == pytest.approx(270.0, abs=0.1)
        assert (r2["vx"], r2["vy"]) == pytest.approx((-1.5, 0.0), abs=0.01)
        x, y = RampFrame(r1["lat"], r1["lon"], 90.0).to_ramp(r2["lat"], r2["lon"])
        elapsed = (dt.datetime.fromisoformat(w2["time"]) -
                   dt.datetime.fromisoformat(w1["time"])).total_seconds()
        assert float(y) == pytest.approx(0.0, abs=0.5)
        assert float(x) == pytest.approx(-1.5 * elapsed, abs=1.0)
        assert w2["stats"]["bad"] == 0
        await sim.clock.sleep(45.0 - sim.clock.now())  # the turn (t 30 s, 2 deg/s) is done
        w3 = await sim.get("/api/world")
        assert w3["own_ship"]["heading_deg"] == pytest.approx(250.0, abs=0.15)  # HDT 0.1
        assert w3["ramp"]["ramp_bearing_deg"] == pytest.approx(70.0, abs=0.15)

    run_station(tmp_path / "data", body)
