"""`usv-station hil` plus `serve --link socket://127.0.0.1:PORT`: the firmware binary in
QEMU's Cortex-M3 takes a planned mission (upload, verify, START), the vessel model driven by
its own thrust moves along the plan in telemetry, HOLD and ABORT act, and the run is stored.

The firmware's clock runs SIM_SPEED times the wall clock (its link timeouts stay in wall
time, so the station's link is unchanged); every wait is on what the station reports. The
speed is 4, not more: the HIL loop is not lockstep, so its wall-clock latency times the speed
is the navigation's age in boat time, and at 10 on a loaded 2-core machine the fixes came
half a second late and the boat weaved up to 11 m off the plan (1-2 m at 4)."""

from __future__ import annotations

import itertools
import math
import time

from hil_support import HilProcess, require_qemu, session_image, stack_high_water
from stationproc import StationProcess

SIM_SPEED = 4.0
MOVED_M = 10.0  # along the plan before HOLD
HOLD_SPEED = 0.6  # m/s: station keeping returns to the hold point at 0.4 m/s at most


def distance_to_path(x: float, y: float, wps: list[dict]) -> float:
    """Distance (m) from a point to the plan's polyline (ramp frame)."""
    best = math.inf
    for a, b in itertools.pairwise(wps):
        ax, ay, bx, by = a["x"], a["y"], b["x"], b["y"]
        dx, dy = bx - ax, by - ay
        f = min(1.0, max(0.0, ((x - ax) * dx + (y - ay) * dy) / max(dx * dx + dy * dy, 1e-9)))
        best = min(best, math.hypot(x - ax - f * dx, y - ay - f * dy))
    return best


def test_serve_flies_the_firmware_in_qemu_then_hold_and_abort_act_and_the_run_is_stored(
        tmp_path):
    require_qemu()
    from usvstation.link.wire import write_key

    key = tmp_path / "link.key"
    write_key(key)
    image = session_image()
    t0 = time.monotonic()
    hil = st = None
    try:
        monitor = tmp_path / "qemu-monitor.sock"
        hil = HilProcess("--port", "0", "--scenario", "case1", "--link-key", str(key),
                         "--sim-speed", str(SIM_SPEED), "--image", str(image),
                         "--qemu-monitor", str(monitor))
        st = StationProcess(tmp_path / "data", "--link", f"socket://127.0.0.1:{hil.port}",
                            "--link-key", str(key), "--boat-id", "1")
        boat = st.wait_link_up(120)
        assert boat["link"]["signed"] and boat["boat"]["state"] == "IDLE"
        plan = st.wait_plan(st.client.post("/api/plans").json()["id"], 120)
        assert plan["status"] == "done", plan
        wps = plan["plan"]["waypoints"]
        r = st.client.post("/api/missions", json={"plan_id": plan["id"]})
        assert r.status_code == 202, r.text
        mission = r.json()
        verified = st.wait_until(f"/api/missions/{mission['id']}",
                            lambda b: b["state"] in ("verified", "failed"), 60, "verified")
        assert verified["state"] == "verified", verified
        check = st.client.get(f"/api/missions/{mission['id']}/verify")
        assert check.status_code == 200 and check.json()["identical"], check.text
        r = st.client.post("/api/boat/command",
                           json={"command": "start", "mission_id": mission["id"]})
        assert r.status_code == 200 and r.json()["state"] == "RUNNING", r.text
        x0 = wps[0]["x"]
        running = st.wait_until("/api/boat", lambda b: b["telemetry"]["x"] < x0 - MOVED_M,
                           120, f"the boat {MOVED_M} m along the plan")
        assert running["boat"]["state"] == "RUNNING"
        assert running["boat"]["mission_crc32"] == verified["crc32"]

        r = st.client.post("/api/boat/command", json={"command": "hold"})
        assert r.status_code == 200 and r.json()["state"] == "HOLD", r.text
        held = st.wait_until("/api/boat", lambda b: b["telemetry"]["speed"] < HOLD_SPEED
                        and b["boat"]["state"] == "HOLD", 120, "the boat slowed in HOLD")
        t = held["telemetry"]
        assert math.hypot(t["x"] - running["telemetry"]["x"],
                          t["y"] - running["telemetry"]["y"]) < 30.0
        r = st.client.post("/api/boat/command", json={"command": "abort"})
        assert r.status_code == 200 and r.json()["state"] == "ABORTED", r.text
        st.wait_until("/api/boat", lambda b: b["telemetry"]["thrust_left"] == 0.0
                 and b["telemetry"]["thrust_right"] == 0.0, 60, "the propellers stopped")
        aborted = st.wait_until(f"/api/missions/{mission['id']}",
                           lambda b: b["state"] == "aborted", 60, "the mission aborted")
        run_id = aborted["run"]
        runs = st.client.get("/api/runs").json()
        rows = st.client.get("/api/telemetry", params={"run": run_id}).json()
        boat = st.client.get("/api/boat").json()
        used, spare = stack_high_water(monitor, image, tmp_path / "ram.bin")
    finally:
        if st is not None:
            st.stop()
        if hil is not None:
            hil.close()
    duration = time.monotonic() - t0
    print(f"HIL run against serve at sim speed {SIM_SPEED:g}: {duration:.1f} s wall")
    assert boat["boat"]["state"] == "ABORTED" and boat["boat"]["mission_id"] == 0
    run = next(r for r in runs if r["id"] == run_id)
    assert run["mission_id"] == mission["id"] and run["ended_at"] is not None
    moving = [r for r in rows if r["state"] == "RUNNING"]
    assert len(moving) >= 10
    # the firmware's own thrust drove the model along the plan (GPS noise ~1 m)
    assert max(abs(r["thrust_left"]) + abs(r["thrust_right"]) for r in moving) > 0.5
    off_path = max(distance_to_path(r["x"], r["y"], wps) for r in moving)
    print(f"largest distance from the planned path while RUNNING: {off_path:.1f} m")
    assert off_path < 8.0
    # the stored run went as far as the live view saw it go (the furthest row: with the GPS
    # noise of about 1 m a later row can read a few decimetres further back)
    assert min(r["x"] for r in moving) < x0 - MOVED_M
    # the 8 KB chip's stack after a whole session (upload, readback, commands, telemetry)
    print(f"QEMU firmware stack: {used} B used at most, {spare} B never touched")
    assert spare >= 256
