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


def test_an_old_database_keeps_its_telemetry_and_its_mode_column_becomes_state(tmp_path):
    """Schema 1 named the boat's state `mode`; opening it renames the column in place."""
    import sqlite3

    old = sqlite3.connect(tmp_path / "station.sqlite3")
    old.executescript("""
        CREATE TABLE runs (id INTEGER PRIMARY KEY, mission_id TEXT, plan_id TEXT,
            started_at TEXT NOT NULL, ended_at TEXT, state TEXT NOT NULL DEFAULT 'active');
        CREATE TABLE telemetry (id INTEGER PRIMARY KEY, run INTEGER REFERENCES runs(id),
            time TEXT NOT NULL, boat_time REAL, lat REAL, lon REAL, x REAL, y REAL,
            heading_deg REAL, course_deg REAL, speed REAL, ramp_heading_deg REAL,
            yaw_rate_dps REAL, fix_type INTEGER, satellites INTEGER, hdop REAL,
            thrust_left REAL, thrust_right REAL, battery_v REAL,
            waypoint_index INTEGER, cross_track_m REAL, mode TEXT);
        INSERT INTO telemetry (time, boat_time, x, y, mode)
            VALUES ('2026-11-22T10:00:00.000Z', 1.5, 10.0, 2.0, 'HOLD');
    """)
    old.commit()
    old.close()
    store = Store(tmp_path)
    (row,) = store.telemetry(None, None, None, 10)
    assert row["state"] == "HOLD" and "mode" not in row
    assert (row["boat_time"], row["x"], row["y"]) == (1.5, 10.0, 2.0)
    assert store.conn.execute("PRAGMA user_version").fetchone()[0] == 3
    Store(tmp_path)  # opening it again changes nothing
    assert store.telemetry(None, None, None, 10) == [row]


def test_a_schema_2_database_keeps_its_plans_and_gains_their_basis(tmp_path):
    """Schema 2 kept no basis: its plans load with basis None (compared by scenario)."""
    import sqlite3

    old = sqlite3.connect(tmp_path / "station.sqlite3")
    old.executescript("""
        CREATE TABLE plans (id TEXT PRIMARY KEY, created_at TEXT NOT NULL,
            status TEXT NOT NULL, planner TEXT NOT NULL, seed INTEGER,
            scenario TEXT NOT NULL, plan TEXT, error TEXT);
        INSERT INTO plans VALUES ('p1', '2026-11-22T10:00:00.000Z', 'failed', 'iga', 1,
            '{"name": "case1"}', NULL, 'no plan');
        PRAGMA user_version = 2;
    """)
    old.commit()
    old.close()
    store = Store(tmp_path)
    (job,) = store.plans()
    assert (job["id"], job["scenario"], job["basis"]) == ("p1", {"name": "case1"}, None)
    job["basis"] = {"start": "0123456789abcdef"}
    store.save_plan(job)
    assert store.plans()[0]["basis"] == {"start": "0123456789abcdef"}
