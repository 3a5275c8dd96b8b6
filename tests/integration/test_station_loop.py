"""The whole loop through the HTTP API alone, on `usv-station serve` with the simulated boat."""

import csv
import io
import itertools
import json
import math
import signal
import statistics
import threading
import time
import xml.etree.ElementTree as ET

import pytest
from stationproc import StationProcess
from websockets.sync.client import connect

from usvstation.planning.validate import plan_violations
from usvstation.scenario import load_scenario

GPX = "{http://www.topografix.com/GPX/1/1}"


@pytest.fixture(scope="module")
def station(tmp_path_factory):
    st = StationProcess(tmp_path_factory.mktemp("data"), "--sim-speed", "5")
    st.wait_link_up()
    yield st
    st.stop()


def _wait_until(condition, timeout_s):
    """Poll `condition` every 50 ms until it holds or `timeout_s` passes (a bound, not a
    timing check: the assertions after it say what must hold)."""
    deadline = time.monotonic() + timeout_s
    while not condition() and time.monotonic() < deadline:
        time.sleep(0.05)


def test_plan_upload_start_complete_and_export(station):
    c = station.client
    events: list[dict] = []
    ws_url = station.url.replace("http", "ws") + "/ws/live"
    done = threading.Event()

    def listen():
        with connect(ws_url, additional_headers={"Authorization":
                                                 f"Bearer {station.token}"}) as ws:
            while not done.is_set():
                try:
                    events.append(json.loads(ws.recv(timeout=0.5)))
                except TimeoutError:
                    continue

    listener = threading.Thread(target=listen, daemon=True)
    listener.start()

    boat = c.get("/api/boat").json()
    assert boat["link"]["up"] and boat["link"]["simulated"]
    # signed by default (a key generated into the data dir), paired with boat 1
    assert boat["link"]["signed"] and boat["link"]["warning"] is None
    assert (boat["link"]["boat_id"], boat["link"]["station_id"]) == (1, 255)
    # a pty loses and corrupts nothing: nothing refused, no other systems
    assert boat["link"]["frames"] > 0
    assert boat["link"]["frames_bad"] == 0 and boat["link"]["refused"] == {}
    assert boat["link"]["frames_lost"] == 0
    assert boat["link"]["other_systems"] == {}
    plan_job = station.wait_plan(c.post("/api/plans", json={"seed": 1}).json()["id"])
    assert plan_job["status"] == "done"
    plan = plan_job["plan"]
    assert plan_violations(plan, load_scenario("case1")) == []

    r = c.post("/api/missions", json={"plan_id": plan_job["id"]})
    assert r.status_code == 202
    mission = station.wait(f"/api/missions/{r.json()['id']}", "state", ("uploading",), 20)
    n = len(plan["waypoints"])
    assert mission["state"] == "verified"
    assert mission["progress"] == {"sent": n, "acked": n, "total": n}

    verify = c.get(f"/api/missions/{mission['id']}/verify")
    assert verify.status_code == 200 and verify.json()["identical"]
    ack = c.post("/api/boat/command", json={"command": "start", "mission_id": mission["id"]})
    assert ack.status_code == 200, ack.text
    assert ack.json()["result"] == "ACCEPTED" and ack.json()["mission"] == mission["id"]
    assert ack.json()["state"] == "RUNNING"
    mission = station.wait(f"/api/missions/{mission['id']}", "state", ("active",),
                           plan["metrics"]["duration_s"] / 5 + 30)
    assert mission["state"] == "completed"
    run = mission["run"]
    # the websocket delivers the same events, in order; on a loaded machine a little later
    _wait_until(lambda: any(e["type"] == "mission" and e["data"]["state"] == "completed"
                            for e in list(events)), 30)
    done.set()
    listener.join(5)

    rows = c.get("/api/telemetry", params={"run": run}).json()
    assert len(rows) > 50
    # the boat followed the plan to the ramp end
    assert min(math.hypot(r["x"], r["y"]) for r in rows) < 2.0
    last = rows[-1]  # the run ends on the boat's DONE heartbeat, at the ramp end
    assert math.hypot(last["x"], last["y"]) < 3.0 and last["state"] in ("RUNNING", "DONE")
    assert c.get("/api/boat").json()["boat"]["state"] == "DONE"
    # telemetry on its 5 Hz grid of boat time; a frame the radio had no room for is replaced
    # by the next (protocol/README.md: one queue entry per message), so a loaded machine at
    # sim speed 5 loses some, never most
    gaps = [b["boat_time"] - a["boat_time"] for a, b in itertools.pairwise(rows)]
    assert statistics.median(gaps) <= 0.2 + 1e-3
    span = rows[-1]["boat_time"] - rows[0]["boat_time"]
    assert (len(rows) - 1) / span >= 2.5
    runs = {x["id"]: x for x in c.get("/api/runs").json()}
    assert runs[run]["state"] == "completed" and runs[run]["points"] == len(rows)

    kinds = {e["type"] for e in events}
    assert {"hello", "telemetry", "mission", "run"} <= kinds
    states = [e["data"]["state"] for e in events if e["type"] == "mission"]
    assert "verified" in states and "active" in states and states[-1] == "completed"

    n_rows = len(rows)
    table = list(csv.DictReader(io.StringIO(
        c.get("/api/telemetry/export", params={"run": run, "format": "csv"}).text)))
    assert len(table) == n_rows
    lines = c.get("/api/telemetry/export", params={"run": run, "format": "jsonl"}).text
    assert len([json.loads(x) for x in lines.splitlines()]) == n_rows
    gj = c.get("/api/telemetry/export", params={"run": run, "format": "geojson"}).json()
    assert len(gj["features"][0]["geometry"]["coordinates"]) == n_rows
    assert len(gj["features"][1]["geometry"]["coordinates"]) == n
    root = ET.fromstring(c.get("/api/telemetry/export",
                               params={"run": run, "format": "gpx"}).content)
    assert len(root.findall(f"{GPX}trk/{GPX}trkseg/{GPX}trkpt")) == n_rows
    assert len(root.findall(f"{GPX}rte/{GPX}rtept")) == n


def test_command_rules(station):
    c = station.client
    # START names its mission; a completed one is no longer startable
    r = c.post("/api/boat/command", json={"command": "start"})
    assert r.status_code == 409 and "no verified mission" in r.json()["detail"]
    for done in [m for m in c.get("/api/missions").json() if m["state"] == "completed"]:
        r = c.post("/api/boat/command", json={"command": "start", "mission_id": done["id"]})
        assert r.status_code == 409 and "refused START: WRONG_STATE" in r.json()["detail"]
    r = c.post("/api/boat/command", json={"command": "fly"})
    assert r.status_code == 422
    assert c.post("/api/boat/command", json={"command": "hold"},
                  headers={"Authorization": "Bearer nope"}).status_code == 401
    assert c.post("/api/missions", json={"plan_id": "nope"}).status_code == 404


def test_sigterm_stops_gracefully(tmp_path):
    st = StationProcess(tmp_path / "data", "--sim-speed", "5")
    assert st.client.get("/api/health").json()["status"] == "ok"
    st.stop(signal.SIGTERM)
    # uvicorn shuts down gracefully, then re-raises the signal it caught
    assert st.proc.returncode in (0, -signal.SIGTERM)
    assert "Application shutdown complete" in st.log.read_text()
