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
