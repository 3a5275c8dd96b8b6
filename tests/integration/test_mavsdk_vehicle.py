"""`usv-station serve --boat-protocol standard` recovers a vehicle made of MAVSDK's server
plugins (tests/integration/mavsdk_vehicle.py, pip `mavsdk`: code this project did not
write) over UDP: a 32-waypoint plan uploaded with the standard mission protocol and read
back identical, START (arm, OFFBOARD, the timed position targets), HOLD (MAVSDK's action
server refuses PX4's AUTO.LOITER: the station holds it in OFFBOARD where it is), RESUME
and ABORT (disarmed), each confirmed by what the MAVSDK side received; its telemetry in
/api/boat and the store. Under 10 % datagram loss an upload is whole or fails with a
clear error.
"""

from __future__ import annotations

import json
import math
import random
import select
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

from stationproc import StationProcess

from usvstation.geo import RampFrame
from usvstation.scenario import bundled_scenario_dir

VEHICLE = Path(__file__).with_name("mavsdk_vehicle.py")
CASE1 = json.loads((bundled_scenario_dir() / "case1.json").read_text())
FRAME = RampFrame(**{"lat": CASE1["origin"]["lat"], "lon": CASE1["origin"]["lon"],
                     "ramp_bearing_deg": CASE1["origin"]["ramp_bearing_deg"]})
# case1 with waypoints every 2.7 m: IGA gives 32 (seeded, a few generations)
SCENARIO = {**CASE1, "planner": {"seed": 1, "d_sl": 2.7, "max_waypoints": 30,
                                 "generations_max": 20}}


def free_udp_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class MavsdkVehicle:
    """The MAVSDK vehicle process; `events` are the JSON lines it printed."""

    def __init__(self, port: int, lat: float, lon: float) -> None:
        self.proc = subprocess.Popen(
            [sys.executable, str(VEHICLE), f"udpin://127.0.0.1:{port}", str(lat), str(lon),
             "300"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        self.events: list[dict] = []
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        for line in self.proc.stdout:
            if line.startswith("{"):
                self.events.append(json.loads(line))

    def of(self, event: str) -> list[dict]:
        return [e for e in list(self.events) if e["event"] == event]

    def wait(self, cond, timeout: float = 60.0, what: str = "") -> None:
        deadline = time.monotonic() + timeout
        while not cond():
            assert self.proc.poll() is None, "the MAVSDK vehicle exited"
            assert time.monotonic() < deadline, f"MAVSDK vehicle: no {what} after {timeout} s"
            time.sleep(0.05)

    def stop(self) -> None:
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(10)
        self._reader.join(5)
        self.proc.stdout.close()


class LossyRelay:
    """UDP between the station (it sends to `port`) and the vehicle at `vehicle_port`,
    dropping each datagram (one MAVLink frame) with probability `loss`, seeded."""

    def __init__(self, vehicle_port: int, loss: float, seed: int = 1) -> None:
        self.front = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.front.bind(("127.0.0.1", 0))
        self.port = self.front.getsockname()[1]
        self.back = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.back.connect(("127.0.0.1", vehicle_port))
        self.loss, self.rng = loss, random.Random(seed)
        self.station: tuple[str, int] | None = None
        self.dropped = self.passed = 0
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def _run(self) -> None:
        while not self._stop.is_set():
            ready, _, _ = select.select([self.front, self.back], [], [], 0.1)
            for s in ready:
                try:
                    data, addr = s.recvfrom(4096)
                except OSError:
                    continue  # the vehicle's port not open yet (ICMP unreachable)
                if s is self.front:
                    self.station = addr
                if self.rng.random() < self.loss:
                    self.dropped += 1
                    continue
                self.passed += 1
                try:
                    if s is self.front:
                        self.back.send(data)
                    elif self.station is not None:
                        self.front.sendto(data, self.station)
                except OSError:
                    pass

    def close(self) -> None:
        self._stop.set()
        self._thread.join(5)
        self.front.close()
        self.back.close()


def wait_state(st: StationProcess, path: str, states: set[str], timeout: float) -> dict:
    deadline = time.monotonic() + timeout
    while True:
        body = st.client.get(path).json()
        if body["state"] in states:
            return body
        assert time.monotonic() < deadline, f"{path} still {body['state']}: {body}"
        time.sleep(0.1)


def command(st: StationProcess, name: str, **kw: str) -> dict:
    r = st.client.post("/api/boat/command", json={"command": name, **kw})
    assert r.status_code == 200, r.text
    return r.json()


def plan_32(st: StationProcess) -> dict:
    r = st.client.post("/api/plans", json={"scenario": SCENARIO, "planner": "iga"})
    assert r.status_code == 202, r.text
    plan = st.wait_plan(r.json()["id"], 120)
    assert plan["status"] == "done", plan
    assert len(plan["plan"]["waypoints"]) == 32
    return plan


def start_position() -> tuple[float, float]:
    lat, lon = FRAME.to_geodetic(CASE1["start"]["x"], CASE1["start"]["y"])
    return float(lat), float(lon)


def serve(tmp_path: Path, port: int) -> StationProcess:
    st = StationProcess(tmp_path / "data", "--boat-protocol", "standard", "--vehicle-profile",
                        "px4", "--link", f"udp://127.0.0.1:{port}", "--insecure-link")
    st.wait_link_up(60)
    return st


def test_station_recovers_a_mavsdk_vehicle(tmp_path):
    port = free_udp_port()
    vehicle = MavsdkVehicle(port, *start_position())
    st = None
    try:
        vehicle.wait(lambda: vehicle.of("ready"), 60, "start")
        st = serve(tmp_path, port)
        link = st.client.get("/api/boat").json()["link"]
        assert (link["protocol"], link["profile"], link["signed"]) == ("standard", "px4", False)
        assert link["warning"].startswith("unsigned link")
        plan = plan_32(st)
        wps = plan["plan"]["waypoints"]

        r = st.client.post("/api/missions", json={"plan_id": plan["id"]})
        assert r.status_code == 202, r.text
        mission = wait_state(st, f"/api/missions/{r.json()['id']}", {"verified", "failed"}, 90)
        assert mission["state"] == "verified", mission
        # what MAVSDK's mission server took: every waypoint, every leg's speed
        vehicle.wait(lambda: vehicle.of("mission"), 10, "mission")
        items = vehicle.of("mission")[-1]["items"]
        assert [it["command"] for it in items] == [16, 178] * 31 + [16]
        lat, lon = FRAME.to_geodetic([w["x"] for w in wps], [w["y"] for w in wps])
        for i, it in enumerate(items[::2]):
            assert abs(it["x"] * 1e-7 - lat[i]) <= 1e-7 and abs(it["y"] * 1e-7 - lon[i]) <= 1e-7
        for i, it in enumerate(items[1::2]):
            a, b = wps[i], wps[i + 1]
            planned = math.hypot(b["x"] - a["x"], b["y"] - a["y"]) / (b["t"] - a["t"])
            assert abs(it["param2"] - planned) < 0.01
        check = st.client.get(f"/api/missions/{mission['id']}/verify")
        assert check.status_code == 200 and check.json()["identical"], check.text

        answer = command(st, "start", mission_id=mission["id"])
        assert answer["state"] == "RUNNING", answer
        vehicle.wait(lambda: any(e["arm"] and e["result"] == "SUCCESS"
                                 for e in vehicle.of("arm")), 10, "arm")
        vehicle.wait(lambda: any(e["mode"] == "OFFBOARD" and e["result"] == "SUCCESS"
                                 for e in vehicle.of("mode")), 10, "OFFBOARD")
        n = len(vehicle.of("target"))
        vehicle.wait(lambda: len(vehicle.of("target")) >= n + 10, 10, "position targets")
        moving = vehicle.of("target")[-5:]
        assert all(math.hypot(t["vx"], t["vy"]) > 0.1 for t in moving)
        assert all(t["frame"] == 6 for t in moving)  # MAV_FRAME_GLOBAL_RELATIVE_ALT_INT

        modes = len(vehicle.of("mode"))
        answer = command(st, "hold")
        assert answer["state"] == "HOLD", answer
        # the vehicle's own log of what it was asked (its events arrive on their own pipe)
        vehicle.wait(lambda: any(e["mode"] == "OFFBOARD" for e in vehicle.of("mode")[modes:]),
                     10, "the mode requests of HOLD")
        asked = vehicle.of("mode")[modes:]
        assert asked[0]["mode"] == "HOLD" and asked[0]["result"] == "COMMAND_DENIED"
        assert asked[-1]["mode"] == "OFFBOARD" and asked[-1]["result"] == "SUCCESS"
        n = len(vehicle.of("target"))
        vehicle.wait(lambda: len(vehicle.of("target")) >= n + 5, 10, "hold targets")
        held = vehicle.of("target")[n:]
        assert {(t["lat"], t["lon"]) for t in held} == {(held[0]["lat"], held[0]["lon"])}
        assert all(t["vx"] == 0 and t["vy"] == 0 for t in held)

        modes = len(vehicle.of("mode"))
        assert command(st, "resume")["state"] == "RUNNING"
        vehicle.wait(lambda: len(vehicle.of("mode")) > modes, 10, "the mode request of RESUME")
        assert vehicle.of("mode")[modes]["mode"] == "OFFBOARD"
        n = len(vehicle.of("target"))
        vehicle.wait(lambda: len(vehicle.of("target")) >= n + 5, 10, "targets after RESUME")
        assert any(math.hypot(t["vx"], t["vy"]) > 0.1 for t in vehicle.of("target")[n:])

        assert command(st, "abort")["state"] == "ABORTED"
        vehicle.wait(lambda: any(not e["arm"] and e["force"] and e["result"] == "SUCCESS"
                                 for e in vehicle.of("arm")), 10, "disarm")
        mission = wait_state(st, f"/api/missions/{mission['id']}", {"aborted"}, 10)

        boat = st.client.get("/api/boat").json()
        assert boat["telemetry"] is not None and boat["link"]["vehicle_mode"] is not None
        assert abs(boat["telemetry"]["lat"] - lat[0]) < 0.001
        assert boat["telemetry"]["satellites"] == 14 and boat["telemetry"]["battery_v"] == 12.6
        run = mission["run"]
        rows = st.client.get("/api/telemetry", params={"run": run, "limit": 10000}).json()
        assert len(rows) >= 5 and all(r["run"] == run for r in rows)  # stored in its run
    finally:
        if st is not None:
            st.stop()
        vehicle.stop()


def test_upload_under_10_percent_loss_is_whole_or_a_clear_error(tmp_path):
    port = free_udp_port()
    vehicle = MavsdkVehicle(port, *start_position())
    relay = st = None
    try:
        vehicle.wait(lambda: vehicle.of("ready"), 60, "start")
        relay = LossyRelay(port, loss=0.10, seed=3)
        st = serve(tmp_path, relay.port)
        plan = plan_32(st)
        r = st.client.post("/api/missions", json={"plan_id": plan["id"]})
        assert r.status_code == 202, r.text
        done = wait_state(st, f"/api/missions/{r.json()['id']}", {"verified", "failed"}, 180)
        if done["state"] == "failed":
            assert done["error"], done  # says why
            r = st.client.post("/api/boat/command",
                               json={"command": "start", "mission_id": done["id"]})
            assert r.status_code == 409, r.text  # never startable
        print("upload under 10 % loss:", (done["state"], done["error"]),
              f"datagrams dropped {relay.dropped}, passed {relay.passed}")
        assert relay.dropped > 0
        # MAVSDK's mission server takes a mission only whole: never a part of one
        for m in vehicle.of("mission"):
            assert len(m["items"]) == 63
        if done["state"] == "verified":
            items = vehicle.of("mission")[-1]["items"]
            sent = st.client.get(f"/api/missions/{done['id']}").json()
            assert sent["state"] == "verified" and items[0]["command"] == 16
    finally:
        if st is not None:
            st.stop()
        if relay is not None:
            relay.close()
        vehicle.stop()
