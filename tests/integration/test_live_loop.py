"""The live loop through the HTTP API alone, on `usv-station serve` with the simulated boat
and the simulated sea: a target turns onto the boat's path after the plan was made, the
monitor warns, a re-plan is proposed, the operator confirms it, and it is swapped."""

from __future__ import annotations

import csv
import io
import json
import math
import threading
import time

import pytest
from stationproc import StationProcess
from websockets.sync.client import connect

from usvstation.scenario import load_scenario
from usvstation.services.boat import BoatService
from usvstation.services.monitor import NO_HOT_SWAP

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


def poll(fn, timeout: float, what: str):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = fn()
        if value:
            return value
        time.sleep(0.1)
    raise AssertionError(f"timed out waiting for {what}")


def wait_parked(c) -> None:
    """Until /api/world shows the target stopped where it parks, on the boat's path."""
    poll(lambda: any(t["id"] == TARGET and t["speed"] < 0.1
                     and math.hypot(t["x"] - PARK[0], t["y"] - PARK[1]) < 2.0
                     for t in c.get("/api/world").json()["targets"]), 60,
         "the target stopped on the path")


@pytest.fixture
def station(tmp_path):
    st = StationProcess(tmp_path / "data", "--sim-speed", "5", "--replan", "confirm")
    st.wait_link_up()
    try:
        yield st
    finally:
        st.stop()


def test_turning_target_warns_proposes_a_replan_and_confirm_swaps_it(station) -> None:
    c = station.client
    events: list[dict] = []
    done = threading.Event()

    def listen() -> None:
        with connect(station.url.replace("http", "ws") + "/ws/live",
                     additional_headers={"Authorization": f"Bearer {station.token}"}) as ws:
            while not done.is_set():
                try:
                    events.append(json.loads(ws.recv(timeout=0.5)))
                except TimeoutError:
                    continue

    listener = threading.Thread(target=listen, daemon=True)
    listener.start()
    try:
        assert c.put("/api/scenario", json=scenario()).status_code == 200
        world = poll(lambda: (w := c.get("/api/world").json())["own_ship"] and any(
            t["id"] == TARGET for t in w["targets"]) and w, 30, "the sea in /api/world")
        assert world["ramp"]["source"] == "own_ship"
        assert math.hypot(world["ramp"]["vx"], world["ramp"]["vy"]) < 0.05
        # The plan is made once the target has turned and stopped on the path (the working
        # scenario knows nothing of it): the monitor must find it, and the re-plan avoid it
        # where it lies (started earlier, the warning can come while it still moves).
        wait_parked(c)

        job = station.wait_plan(c.post("/api/plans", json={"seed": 1}).json()["id"], 120)
        assert job["status"] == "done"
        r = c.post("/api/missions", json={"plan_id": job["id"]})
        mission = station.wait(f"/api/missions/{r.json()['id']}", "state", ("uploading",), 20)
        assert mission["state"] == "verified"
        assert c.post("/api/boat/command", json={"command": "start",
                                                 "mission_id": mission["id"]}).status_code == 200

        warning = poll(lambda: next((a for a in c.get("/api/alerts").json()
                                     if a["level"] == "warning" and a["target_id"] == TARGET),
                                    None), 60, "a warning on the turning target")
        assert warning["kind"] in ("clearance", "collision_course")
        assert warning["run_id"] is not None and warning["acknowledged"] is False
        monitor = c.get("/api/monitor").json()["assessment"]
        row = next(t for t in monitor["targets"] if t["id"] == TARGET)
        assert row["encounter"] and "dcpa_m" in row and "tcpa_s" in row

        replan = poll(lambda: next((p for p in c.get("/api/replans").json()
                                    if p["state"] in ("proposed", "failed")), None),
                      120, "a proposed re-plan")
        assert replan["state"] == "proposed", replan["error"]
        warnings = {a["id"]: a for a in c.get("/api/alerts").json() if a["level"] == "warning"}
        assert replan["alert_id"] in warnings and replan["policy"] == "confirm"
        # the first warning of the run started it (the target's, or a schedule slip)
        assert warnings[replan["alert_id"]]["kind"] in ("clearance", "collision_course", "slip")
        new = c.get(f"/api/plans/{replan['plan_id']}").json()
        assert new["status"] == "done" and new["plan"]["metrics"]["collision_free"]
        (obstacle,) = new["scenario"]["obstacles"]
        assert math.hypot(obstacle["x"] - PARK[0], obstacle["y"] - PARK[1]) < 2.0

        confirm = c.post(f"/api/replans/{replan['id']}/confirm")
        if not hasattr(BoatService, "swap_mission"):
            # usv-link 2's hot swap is not on this branch: the re-plan is kept as a plan
            assert confirm.status_code == 409
            assert confirm.json()["detail"] == f"re-plan {replan['id']}: {NO_HOT_SWAP}"
            replans = c.get("/api/replans").json()
            assert [p["state"] for p in replans] == ["planned"]
            assert c.post("/api/boat/command", json={"command": "abort"}).status_code == 200
        else:
            assert confirm.status_code == 200 and confirm.json()["state"] == "applied"
            swapped = confirm.json()["mission_id"]
            # the boat swaps at the announced instant: the old mission is replaced ("gone"),
            # the new one runs to the ramp
            old = station.wait(f"/api/missions/{mission['id']}", "state", ("active",), 120)
            assert old["state"] == "gone"
            final = station.wait(f"/api/missions/{swapped}", "state",
                                 ("uploading", "verified", "active"), 120)
            assert final["state"] == "completed"
            rows = c.get("/api/telemetry", params={"limit": 100_000}).json()
            clearance = min(math.hypot(r["x"] - PARK[0], r["y"] - PARK[1]) for r in rows) \
                - RADIUS - 1.0
            print(f"true clearance to the parked target {clearance:.2f} m")
            assert clearance > 0.0

        ack = c.post(f"/api/alerts/{warning['id']}/ack")
        assert ack.status_code == 200 and ack.json()["acknowledged"] is True
        assert c.post("/api/alerts/nope/ack").status_code == 404
        assert c.post(f"/api/alerts/{warning['id']}/ack", headers={"Authorization": ""}
                      ).status_code == 401
        stored = c.get("/api/alerts", params={"run": warning["run_id"]}).json()
        assert any(a["id"] == warning["id"] and a["acknowledged"] for a in stored)
        csv_rows = list(csv.DictReader(io.StringIO(c.get(
            "/api/alerts/export", params={"run": warning["run_id"]}).text)))
        assert [r["id"] for r in csv_rows] == [a["id"] for a in reversed(stored)]
        lines = [json.loads(x) for x in c.get("/api/alerts/export", params={
            "run": warning["run_id"], "format": "jsonl"}).text.splitlines()]
        assert [x["record"] for x in lines] == ["alert"] * len(stored) + ["replan"]
        assert lines[-1]["id"] == replan["id"]
    finally:
        done.set()
        listener.join(5)
    kinds = {e["type"] for e in events}
    assert {"world", "alert", "monitor", "replan"} <= kinds
    pushed = [e["data"] for e in events if e["type"] == "alert"]
    assert any(a["id"] == warning["id"] for a in pushed)


@pytest.mark.parametrize("policy", ["auto", "off"])
def test_replan_policies_auto_and_off(tmp_path, policy: str) -> None:
    st = StationProcess(tmp_path / "data", "--sim-speed", "5", "--replan", policy)
    st.wait_link_up()
    c = st.client
    try:
        assert c.put("/api/scenario", json=scenario()).status_code == 200
        poll(lambda: any(t["id"] == TARGET for t in c.get("/api/world").json()["targets"]),
             30, "the target")
        wait_parked(c)
        job = st.wait_plan(c.post("/api/plans", json={"seed": 1}).json()["id"], 120)
        r = c.post("/api/missions", json={"plan_id": job["id"]})
        mission = st.wait(f"/api/missions/{r.json()['id']}", "state", ("uploading",), 20)
        assert c.post("/api/boat/command", json={"command": "start",
                                                 "mission_id": mission["id"]}).status_code == 200
        poll(lambda: any(a["level"] == "warning" and a["target_id"] == TARGET
                         for a in c.get("/api/alerts").json()), 60, "a warning")
        assert c.get("/api/monitor").json()["policy"] == policy
        if policy == "off":
            time.sleep(1.0)
            assert c.get("/api/replans").json() == []
        else:
            done = poll(lambda: next((p for p in c.get("/api/replans").json()
                                      if p["state"] != "planning"), None),
                        120, "the re-plan")
            if hasattr(BoatService, "swap_mission"):
                assert done["state"] == "applied" and done["latency_ms"] > 0, done["error"]
            else:
                assert done["state"] == "planned" and done["error"] == NO_HOT_SWAP
                assert c.get(f"/api/plans/{done['plan_id']}").json()["status"] == "done"
        c.post("/api/boat/command", json={"command": "abort"})
    finally:
        st.stop()
