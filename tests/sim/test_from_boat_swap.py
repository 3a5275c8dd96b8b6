"""Plans made from the boat upload like any other, idle or under way, and a hot swap shows only
once the boat reports it done: the whole station in simulated time through its HTTP API."""

from __future__ import annotations

from simstation import SimStation, run_station

from usvstation.scenario import load_scenario


async def _from_boat_plan(sim: SimStation, seed: int) -> dict:
    r = await sim.client.post("/api/plans", json={"from_boat": True, "seed": seed})
    assert r.status_code == 202, r.text
    job = await sim.wait_plan(r.json()["id"])
    assert job["status"] == "done", job["error"]
    return job


def test_from_boat_plans_upload_and_a_hot_swap_shows_when_the_boat_swapped(tmp_path) -> None:
    async def body(sim: SimStation) -> None:
        c = sim.client
        r = await c.put("/api/scenario", json=load_scenario("case1").model_dump(mode="json"))
        assert r.status_code == 200
        await sim.clock.sleep(2.0)  # telemetry placed in the working scenario's frame

        # idle: a plan from the boat's own position uploads and verifies
        first = await _from_boat_plan(sim, 1)
        mission = await sim.fly(first["id"])

        # under way: a second plan from the boat is a hot swap
        await sim.clock.sleep(5.0)
        second = await _from_boat_plan(sim, 2)
        r = await c.post("/api/missions", json={"plan_id": second["id"]})
        assert r.status_code == 202, r.text
        swapped = r.json()
        seen_before_swap = set()
        while True:
            boat = await sim.get("/api/boat")
            new = await sim.get(f"/api/missions/{swapped['id']}")
            if boat["boat"]["mission_id"] == swapped["wire_id"]:
                break
            # until the boat reports flying it, the station shows the old mission in hand
            seen_before_swap.add(new["state"])
            assert boat["mission"]["id"] == mission["id"], boat["mission"]
            assert new["state"] in ("uploading", "failed"), new
            await sim.clock.sleep(0.1)
        assert seen_before_swap == {"uploading"}
        done = await sim.wait(f"/api/missions/{swapped['id']}", "state", ("uploading",), 10)
        assert done["state"] == "active"
        old = await sim.get(f"/api/missions/{mission['id']}")
        assert old["state"] == "gone"
        assert (await c.post("/api/boat/command", json={"command": "abort"})).status_code == 200

    run_station(tmp_path / "data", body)
