"""`usv-station serve --link socket://127.0.0.1:PORT` flies a whole planned mission against
the C boat's host build (protocol/c/boat): plan, upload, verify, START, DONE."""

from __future__ import annotations

import time

import pytest
from c_boat_support import CBoat, build_c_boat, c_compiler, conformance_argv
from stationproc import StationProcess

pytestmark = pytest.mark.skipif(c_compiler() is None,
                                reason="no C compiler (cc/gcc) to build protocol/c/boat")

SPEEDUP = 4.0  # the boat's clock runs 4x; the link's timeouts stay in wall time


def wait_mission(st: StationProcess, mission_id: str, states: set[str], timeout: float) -> dict:
    deadline = time.monotonic() + timeout
    while True:
        body = st.client.get(f"/api/missions/{mission_id}").json()
        if body["state"] in states:
            return body
        assert time.monotonic() < deadline, f"mission still {body['state']}: {body}"
        time.sleep(0.1)


def test_serve_flies_a_planned_mission_against_the_c_boat(tmp_path):
    from usvstation.link.wire import write_key

    key = tmp_path / "link.key"
    write_key(key)
    exe = build_c_boat(tmp_path / "build")
    place = conformance_argv()["c"][2:]  # case1's start pose: --lat .. --lon .. --heading-deg ..
    boat = CBoat.start(exe, key=key, speedup=SPEEDUP, extra=tuple(place[:6]))
    st = None
    try:
        st = StationProcess(tmp_path / "data", "--link", f"socket://127.0.0.1:{boat.port}",
                            "--link-key", str(key), "--boat-id", "1")
        deadline = time.monotonic() + 20
        while not st.client.get("/api/boat").json()["link"]["up"]:
            assert time.monotonic() < deadline, "the station never linked to the C boat"
            time.sleep(0.1)
        plan = st.wait_plan(st.client.post("/api/plans").json()["id"], 120)
        assert plan["status"] == "done", plan
        r = st.client.post("/api/missions", json={"plan_id": plan["id"]})
        assert r.status_code == 202, r.text
        mission = r.json()
        verified = wait_mission(st, mission["id"], {"verified", "failed"}, 60)
        assert verified["state"] == "verified", verified
        check = st.client.get(f"/api/missions/{mission['id']}/verify")
        assert check.status_code == 200 and check.json()["identical"], check.text
        r = st.client.post("/api/boat/command",
                           json={"command": "start", "mission_id": mission["id"]})
        assert r.status_code == 200, r.text
        done = wait_mission(st, mission["id"], {"completed", "aborted", "failed", "gone"}, 300)
        snapshot = st.client.get("/api/boat").json()
    finally:
        if st is not None:
            st.stop()
        boat.close()
    assert done["state"] == "completed", done
    assert snapshot["boat"]["state"] == "DONE", snapshot["boat"]
    assert (snapshot["boat"]["mission_id"], snapshot["boat"]["mission_crc32"]) == \
        (done["wire_id"], done["crc32"])
