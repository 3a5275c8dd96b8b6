"""The live loop through the HTTP API alone, in simulated time: the whole station with the
simulated boat and the simulated sea; a target turns onto the boat's path after the plan was
made, the monitor warns, a re-plan is proposed, the operator confirms it, and it is
swapped; under `auto` it is swapped at once, under `off` never."""

from __future__ import annotations

import csv
import io
import json
import math

import pytest
from simstation import SimStation, run_station

from usvstation.scenario import load_scenario
from usvstation.world.model import enu_to_compass

TARGET = "ais:211000201"
PARK = (35.0, 4.0)  # where the target stops, on the straight run to the ramp
RADIUS = 4.0


def scenario() -> dict:
    base = load_scenario("case1").model_dump(mode="json")
    return {
        **base, "name": "turning-target", "obstacles": [],
        # where the embedded boat lies (case1's start)
        "start": {"x": 85.0, "y": 10.0, "heading_deg": 180.0, "speed": 1.0},
        # the boat that sails it: the simulated Otter (2 m), with room for its tracking error
        "vessel": {**base["vessel"], "length": 2.0, "compensation_radius": 1.5,
                   "speed_max": 1.5},
        "mother_ship": {"speed": 0.0, "course_deg": 270.0, "lever_arm": {"forward": -20.0}},
        "traffic": [{
            "mmsi": 211000201, "name": "TURNER", "start": {"x": 20.0, "y": -26.0},
            "course_deg": 90.0, "speed": 3.0, "length": 8.0,  # east: along +x, off the path
            "manoeuvres": [{"t": 5.0, "course_deg": 0.0},  # turns north, onto the path
                           {"t": 15.0, "speed": 0.0}],  # and stops on it at (35, 4)
        }],
    }


async def put_scenario_and_wait_parked(sim: SimStation, doc: dict, target: str, park: tuple,
                                       relative: bool = False) -> dict:
    """The working scenario; once /api/world shows the target stopped where it parks (still
    over ground, or with `relative` still relative to the moving ramp)."""
    r = await sim.client.put("/api/scenario", json=doc)
    assert r.status_code == 200, r.text

    async def parked() -> dict | None:
        w = await sim.get("/api/world")
        for t in w["targets"]:
            speed = math.hypot(t["rvx"], t["rvy"]) if relative else t["speed"]
            if t["id"] == target and speed < 0.1 and \
                    math.hypot(t["x"] - park[0], t["y"] - park[1]) < 2.0:
                return w
        return None

    return await sim.poll(parked, 60, "the target stopped on the path")


def one_alert_per_cause(alerts: list[dict]) -> None:
    """One alert per cause (kind, target) of a recovery, changed in place (issue 25): the
    runs a hot swap opens continue the recovery and its alerts."""
    causes = [(a["kind"], a["target_id"]) for a in alerts if a["run_id"] is not None]
    assert len(causes) == len(set(causes)), sorted(causes, key=str)


async def first(sim: SimStation, path: str, pick, timeout: float, what: str):
    async def found():
        return next((x for x in await sim.get(path) if pick(x)), None)

    return await sim.poll(found, timeout, what)


def test_turning_target_warns_proposes_a_replan_and_confirm_swaps_it(tmp_path) -> None:
    async def body(sim: SimStation) -> None:
        c = sim.client
        world = await put_scenario_and_wait_parked(sim, scenario(), TARGET, PARK)
        assert world["ramp"]["source"] == "own_ship" and world["own_ship"]
        assert math.hypot(world["ramp"]["vx"], world["ramp"]["vy"]) < 0.05
        # The plan is made once the target has turned and stopped on the path (the working
        # scenario knows nothing of it): the monitor must find it, and the re-plan avoid it.
        job = await sim.wait_plan((await c.post("/api/plans", json={"seed": 1})).json()["id"])
        assert job["status"] == "done"
        mission = await sim.fly(job["id"])

        warning = await first(sim, "/api/alerts", lambda a: a["level"] in ("warning", "alarm")
                              and a["target_id"] == TARGET, 60, "a warning on the target")
        # parked on the path: a static target's predicted clearance, never a collision course
        assert warning["kind"] == "clearance"
        assert warning["run_id"] is not None and warning["acknowledged"] is False
        monitor = (await sim.get("/api/monitor"))["assessment"]
        row = next(t for t in monitor["targets"] if t["id"] == TARGET)
        assert row["encounter"] and "dcpa_m" in row and "tcpa_s" in row

        replan = await first(sim, "/api/replans", lambda p: p["state"] in ("proposed",
                                                                           "failed"),
                             120, "a proposed re-plan")
        assert replan["state"] == "proposed", replan["error"]
        warnings = {a["id"]: a for a in await sim.get("/api/alerts")
                    if a["level"] in ("warning", "alarm")}
        assert replan["alert_id"] in warnings and replan["policy"] == "confirm"
        # the first warning of the run started it (the target's, or a schedule slip)
        assert warnings[replan["alert_id"]]["kind"] in ("clearance", "collision_course",
                                                        "slip")
        new = await sim.get(f"/api/plans/{replan['plan_id']}")
        assert new["status"] == "done" and new["plan"]["metrics"]["collision_free"]
        (obstacle,) = new["scenario"]["obstacles"]
        assert math.hypot(obstacle["x"] - PARK[0], obstacle["y"] - PARK[1]) < 2.0

        confirm = await c.post(f"/api/replans/{replan['id']}/confirm")
        assert confirm.status_code == 200 and confirm.json()["state"] == "applied"
        swapped = confirm.json()["mission_id"]
        # the boat swaps at the announced instant: the old mission is replaced ("gone"),
        # the new one runs to the ramp
        old = await sim.wait(f"/api/missions/{mission['id']}", "state", ("active",), 120)
        assert old["state"] == "gone"
        final = await sim.sail(swapped, 300)
        assert final["state"] == "completed"
        rows = await sim.get("/api/telemetry", limit=100_000)
        clearance = min(math.hypot(r["x"] - PARK[0], r["y"] - PARK[1]) for r in rows) \
            - RADIUS - 1.0
        assert clearance > 0.0

        ack = await c.post(f"/api/alerts/{warning['id']}/ack")
        assert ack.status_code == 200 and ack.json()["acknowledged"] is True
        assert (await c.post("/api/alerts/nope/ack")).status_code == 404
        assert (await c.post(f"/api/alerts/{warning['id']}/ack",
                             headers={"Authorization": ""})).status_code == 401
        stored = await sim.get("/api/alerts", run=warning["run_id"])
        assert any(a["id"] == warning["id"] and a["acknowledged"] for a in stored)
        export = await c.get("/api/alerts/export", params={"run": warning["run_id"]})
        csv_rows = list(csv.DictReader(io.StringIO(export.text)))
        assert [r["id"] for r in csv_rows] == [a["id"] for a in reversed(stored)]
        lines = [json.loads(x) for x in (await c.get("/api/alerts/export", params={
            "run": warning["run_id"], "format": "jsonl"})).text.splitlines()]
        assert [x["record"] for x in lines] == ["alert"] * len(stored) + ["replan"]
        assert lines[-1]["id"] == replan["id"]
        kinds = {e["type"] for e in sim.events}
        assert {"world", "alert", "monitor", "replan"} <= kinds
        alerts = await sim.get("/api/alerts")
        one_alert_per_cause(alerts)
        assert not [a for a in alerts if a["kind"] == "collision_course"]  # all static
        # the run is over: its alerts ended with it, and no re-plan is left proposed
        assert not [a for a in await sim.get("/api/alerts") if a["active"]
                    and a["run_id"] is not None]
        assert not [p for p in await sim.get("/api/replans") if p["state"] == "proposed"]
        assert any(e["data"]["id"] == warning["id"] for e in sim.events
                   if e["type"] == "alert")

    run_station(tmp_path / "data", body, replan="confirm")


@pytest.mark.parametrize("policy", ["auto", "off"])
def test_replan_policies_auto_and_off(tmp_path, policy: str) -> None:
    async def body(sim: SimStation) -> None:
        c = sim.client
        await put_scenario_and_wait_parked(sim, scenario(), TARGET, PARK)
        job = await sim.wait_plan((await c.post("/api/plans", json={"seed": 1})).json()["id"])
        await sim.fly(job["id"])
        await first(sim, "/api/alerts", lambda a: a["level"] in ("warning", "alarm")
                    and a["target_id"] == TARGET, 60, "a warning")
        assert (await sim.get("/api/monitor"))["policy"] == policy
        if policy == "off":
            await sim.clock.sleep(10.0)
            assert await sim.get("/api/replans") == []
        else:
            done = await first(sim, "/api/replans", lambda p: p["state"] != "planning", 120,
                               "the re-plan")
            assert done["state"] == "applied" and done["latency_ms"] >= 0, done["error"]
        await c.post("/api/boat/command", json={"command": "abort"})

    run_station(tmp_path / "data", body, replan=policy)


SHIP = 1.0  # m/s over ground, course 270: along -x of the ramp frame (+x east, +y north)
MOVING_TARGET = "ais:211000301"


def leg(rvx: float, rvy: float) -> tuple[float, float]:
    """Course and speed over ground of a velocity relative to the ship (ramp frame)."""
    speed, course = enu_to_compass(rvx - SHIP, rvy)
    return round(course, 4), round(speed, 4)


def moving_scenario() -> dict:
    doc = scenario()
    (c1, s1), (c2, s2), (c3, s3) = leg(3.0, 0.0), leg(0.0, 3.0), leg(0.0, 0.0)
    doc.update(name="turning-target-under-way", mother_ship={
        "speed": SHIP, "course_deg": 270.0, "lever_arm": {"forward": -20.0}})
    # relative to the ship: along +x off the path, turns onto it at 5 s, and from 15 s
    # keeps station on the ship at PARK (over ground: the ship's course and speed)
    doc["traffic"] = [{
        "mmsi": 211000301, "name": "TURNER", "start": {"x": 20.0, "y": -26.0},
        "course_deg": c1, "speed": s1, "length": 8.0,
        "manoeuvres": [{"t": 5.0, "course_deg": c2, "speed": s2},
                       {"t": 15.0, "course_deg": c3, "speed": s3}]}]
    return doc


def test_under_way_the_boat_tracks_the_moving_ramp_and_a_confirmed_replan_recovers_it(
        tmp_path) -> None:
    """The mother ship under way: the station streams the ramp pose, the boat keeps station
    and tracks its plan in the moving ramp frame, a target keeping station on the ship turns
    onto the path, a confirmed re-plan avoids it, and the boat is recovered on the moving
    ramp. Everything asserted comes from the boat's telemetry and the stored records."""
    from usvstation.geo import RampFrame

    async def body(sim: SimStation) -> None:
        c = sim.client
        world = await put_scenario_and_wait_parked(sim, moving_scenario(), MOVING_TARGET,
                                                   PARK, relative=True)
        assert world["ramp"]["source"] == "own_ship"
        assert world["ramp"]["vx"] == pytest.approx(-SHIP, abs=0.05)  # the ship makes way
        assert next(t for t in world["targets"] if t["id"] == MOVING_TARGET)["speed"] > 0.9

        async def keeping_station() -> bool:
            r = (await sim.get("/api/boat"))["telemetry"]
            return math.hypot(r["x"] - 85.0, r["y"] - 10.0) < 4.0 and r["speed"] > 0.7

        await sim.poll(keeping_station, 60, "the boat keeping station astern of the ship")
        job = await sim.wait_plan((await c.post("/api/plans", json={"seed": 1})).json()["id"])
        assert job["status"] == "done"
        mission = await sim.fly(job["id"])
        warning = await first(sim, "/api/alerts", lambda a: a["level"] in ("warning", "alarm")
                              and a["target_id"] == MOVING_TARGET, 60, "a warning")
        assert warning["kind"] in ("clearance", "collision_course")
        replan = await first(sim, "/api/replans", lambda p: p["state"] in ("proposed",
                                                                           "failed"),
                             120, "a proposed re-plan")
        assert replan["state"] == "proposed", replan["error"]
        new = await sim.get(f"/api/plans/{replan['plan_id']}")
        # the re-plan: the ship's way as an apparent current, the target where it keeps station
        env = new["scenario"]["environment"]
        assert env["current_speed"] == pytest.approx(SHIP, abs=0.05)
        assert env["current_dir_deg"] == pytest.approx(0.0, abs=3.0)
        (obstacle,) = new["scenario"]["obstacles"]
        assert math.hypot(obstacle["x"] - PARK[0], obstacle["y"] - PARK[1]) < 2.5

        confirm = await c.post(f"/api/replans/{replan['id']}/confirm")
        assert confirm.status_code == 200 and confirm.json()["state"] == "applied"
        swapped = confirm.json()["mission_id"]
        old = await sim.wait(f"/api/missions/{mission['id']}", "state", ("active",), 120)
        assert old["state"] == "gone"
        # the ship makes 1 m/s and the boat 1.5 m/s through the water: it gains 0.5 m/s
        final = await sim.sail(swapped, 600)
        assert final["state"] == "completed"
        alerts = await sim.get("/api/alerts")
        one_alert_per_cause(alerts)
        assert not [a for a in alerts if a["active"] and a["run_id"] is not None]
        # a target keeping station on the ship makes way over ground: it may be on a
        # collision course; the re-plan was the only one (no flood of slip re-plans)
        assert [p["state"] for p in await sim.get("/api/replans")] == ["applied"]
        rows = [r for r in await sim.get("/api/telemetry", limit=100_000)
                if r["run"] is not None]
        last = rows[-1]
        assert math.hypot(last["x"], last["y"]) < 3.0  # on the ramp, in the ramp frame
        o = moving_scenario()["origin"]
        east, _ = RampFrame(o["lat"], o["lon"], o["ramp_bearing_deg"]).to_ramp(last["lat"],
                                                                             last["lon"])
        assert east < -50.0  # over ground, the ramp and the boat on it sailed west
        clearance = min(math.hypot(r["x"] - PARK[0], r["y"] - PARK[1]) for r in rows) \
            - RADIUS - 1.0
        assert clearance > 0.0
        texts = [s["text"] for s in (await sim.get("/api/boat"))["status"]]
        assert not any("ramp pose stale" in t for t in texts), texts

    run_station(tmp_path / "data", body, replan="confirm")
