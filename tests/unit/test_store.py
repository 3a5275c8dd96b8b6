"""The store: batched telemetry commits, flush barrier, and what a restart makes of missions."""

import time

from usvstation.services.boat import recover_missions
from usvstation.store.db import Store


def mission(mid, state):
    return {"id": mid, "plan_id": "p1", "wire_id": 3, "created_at": "2026-11-22T10:00:00.000Z",
            "state": state, "progress": {"sent": 2, "acked": 1, "total": 4}, "error": None,
            "run": None, "origin": {"lat": 30.5, "lon": 114.4, "ramp_bearing_deg": 90.0},
            "items": []}


def test_restart_fails_interrupted_uploads_and_leaves_the_rest_to_the_boat(tmp_path):
    store = Store(tmp_path)
    with store.conn as c:
        c.execute("INSERT INTO plans (id, created_at, status, planner, scenario) "
                  "VALUES ('p1', 't', 'done', 'iga', '{}')")
    for mid, state in (("a", "uploading"), ("b", "active"), ("c", "verified"), ("d", "completed")):
        store.save_mission(mission(mid, state))
    got = recover_missions(store)
    assert got["a"]["state"] == "failed" and "during the upload" in got["a"]["error"]
    # an active mission stays active until the boat's first report says what it holds
    assert got["b"]["state"] == "active"
    assert got["c"]["state"] == "verified" and got["d"]["state"] == "completed"
    again = {m["id"]: m["state"] for m in Store(tmp_path).missions()}  # persisted
    assert again == {"a": "failed", "b": "active", "c": "verified", "d": "completed"}


def test_writer_commits_within_the_window_and_flushes_on_demand(tmp_path):
    store = Store(tmp_path)
    store.start()
    try:
        store.writer.put({"time": "2026-11-22T10:00:00.000Z", "lat": 1.0, "lon": 2.0})
        assert store.writer.stats.committed == 0  # batched, not written at once
        deadline = time.monotonic() + 5.0  # the 200 ms window is measured by the kill -9 test
        while store.writer.stats.committed < 1:  # committed on its own, without a flush
            assert time.monotonic() < deadline
            time.sleep(0.005)
        for i in range(10):
            store.writer.put({"time": f"2026-11-22T10:00:0{i}.000Z", "lat": 1.0, "lon": 2.0})
        assert store.writer.flush()
        assert len(store.telemetry(None, None, None, 100)) == 11
    finally:
        store.close()
