"""A go-around at sea with a ship parked beside the ramp axis (issue 24), the whole station in
simulated time: the plan (against the live world) goes round the ship; on the final approach
the boat's RTK corrections drop out, it misses a gate and goes around, back along its plan
to its standby point; the station's new approach (planned from there against the live
world and hot-swapped in at the standby point) goes round the ship again and the boat
arrives. The straight line from the standby point to the ramp, the boat's own new approach
before issue 24's follow-up, runs through the ship."""

from __future__ import annotations

import math
from dataclasses import replace

from simstation import SimStation, run_station

from usvstation.scenario import Scenario, load_scenario
from usvstation.trial.episode import with_final_straight

TARGET = "ais:211000401"
PARK = (40.0, 1.0)  # the ship lies still across the ramp axis
RADIUS = 4.0  # half its 8 m length
HALF_HULL = 1.0  # the simulated Otter


def scenario() -> dict:
    base = load_scenario("case1").model_dump(mode="json")
    return {
        **base, "name": "parked-beside-the-axis", "obstacles": [],
        "start": {"x": 85.0, "y": 10.0, "heading_deg": 180.0, "speed": 1.0},
        "vessel": {**base["vessel"], "length": 2.0, "compensation_radius": 1.5,
                   "speed_max": 1.5},
        "mother_ship": {"speed": 0.0, "course_deg": 270.0, "lever_arm": {"forward": -20.0}},
        "traffic": [{"mmsi": 211000401, "name": "PARKED", "start": {"x": PARK[0], "y": PARK[1]},
                     "course_deg": 0.0, "speed": 0.0, "length": 8.0}],
    }


def line_clearance(a: tuple[float, float], b: tuple[float, float]) -> float:
    """Hull clearance to the parked ship of a boat sailing straight from a to b."""
    (ax, ay), (bx, by) = a, b
    dx, dy = bx - ax, by - ay
    w = max(0.0, min(1.0, ((PARK[0] - ax) * dx + (PARK[1] - ay) * dy) / (dx * dx + dy * dy)))
    return math.hypot(ax + w * dx - PARK[0], ay + w * dy - PARK[1]) - RADIUS - HALF_HULL


def test_a_go_around_flies_back_round_a_parked_ship_and_the_new_approach_avoids_it(tmp_path):
    async def body(sim: SimStation) -> None:
        c = sim.client

        async def seen() -> dict | None:
            w = await sim.get("/api/world")
            return w if any(t["id"] == TARGET for t in w["targets"]) else None

        await sim.poll(seen, 60, "the parked ship on AIS")
        world = with_final_straight((await sim.get("/api/world/scenario"))["scenario"])
        job = await sim.wait_plan((await c.post("/api/plans", json={
            "seed": 1, "scenario": world})).json()["id"])
        assert job["status"] == "done", job["error"]
        mission = await sim.fly(job["id"])
        vehicle = sim.station.sim.boat.vehicle
        good = vehicle.sensors.profile
        # on the final approach the RTK corrections drop out: the next gate is missed
        await sim.poll(lambda: vehicle.approach is not None, 300, "the final approach")
        vehicle.sensors.profile = replace(good, gnss=replace(good.gnss, fix_type=5))
        await sim.poll(lambda: vehicle.go_around is not None, 120, "the go-around")
        assert "no RTK-class fix" in vehicle.go_around
        vehicle.sensors.profile = good  # the corrections are back
        final = await sim.sail(mission["id"], 900)
        assert final["state"] == "completed", final
        texts = [s["text"] for s in (await sim.get("/api/boat"))["status"]]
        assert len(sim.new_approaches) == 1, (sim.new_approaches, texts)
        (new,) = sim.new_approaches  # the station's new approach, hot-swapped in
        assert new == final["id"] != mission["id"]
        rows = [r for r in await sim.get("/api/telemetry", limit=100_000)
                if r["run"] is not None]
        clearance = min(math.hypot(r["x"] - PARK[0], r["y"] - PARK[1]) for r in rows) \
            - RADIUS - HALF_HULL
        assert clearance > 0.0
        assert math.hypot(rows[-1]["x"], rows[-1]["y"]) < 1.0  # on the ramp
        standby = vehicle.standby
        assert math.hypot(*standby) > 45.0
        assert line_clearance(standby, (0.0, 0.0)) < 0.0  # straight in would have hit it
        texts = [s["text"] for s in (await sim.get("/api/boat"))["status"]]
        assert any(t.startswith("new approach: mission") for t in texts), texts
        alerts = await sim.get("/api/alerts")
        assert any(a["kind"] == "go_around" for a in alerts)

    # the simulated boat knows the scenario's obstacles (none), not the ship on AIS
    run_station(tmp_path / "data", body, scenario=Scenario(**scenario()), replan="off")
