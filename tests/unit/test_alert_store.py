"""Alerts and re-plans survive in the station database; acknowledgement is stored."""

from __future__ import annotations

from usvstation.store.alerts import AlertStore
from usvstation.store.db import Store


def alert(i: int, run: int | None) -> dict:
    t = f"2026-11-23T20:00:0{i}.000Z"
    return {"id": f"a{i}", "time": t, "level": "warning",
            "kind": "clearance", "message": f"m{i}", "target_id": "ais:1", "run_id": run,
            "acknowledged": False, "active": True, "updated_at": t, "announced_at": t,
            "ended_at": None}


def test_alerts_round_trip_newest_first_by_run_and_ack(tmp_path) -> None:
    store = Store(tmp_path)
    alerts = AlertStore(store)
    for i, run in ((1, 1), (2, 2), (3, 1)):
        alerts.save(alert(i, run))
    assert [a["id"] for a in alerts.alerts()] == ["a3", "a2", "a1"]
    assert [a["id"] for a in alerts.alerts(run=1)] == ["a3", "a1"]
    assert alerts.alerts(limit=1) == [alert(3, 1)]
    acked = alerts.acknowledge("a1")
    assert acked == {**alert(1, 1), "acknowledged": True}
    assert alerts.acknowledge("a1") == acked and alerts.acknowledge("zz") is None
    # a second station process on the same data dir sees the same
    again = AlertStore(Store(tmp_path))
    assert again.alerts(run=1)[1]["acknowledged"] is True


def test_replans_are_kept_and_updated(tmp_path) -> None:
    alerts = AlertStore(Store(tmp_path))
    record = {"id": "r1", "created_at": "2026-11-23T20:00:00.000Z", "run_id": 3,
              "alert_id": "a1", "plan_id": None, "policy": "confirm", "state": "planning",
              "error": None, "latency_ms": None, "mission_id": None, "dropped_targets": []}
    alerts.save_replan(record)
    alerts.save_replan({**record, "state": "proposed", "plan_id": "p1"})
    (row,) = alerts.replans(run=3)
    assert (row["state"], row["plan_id"]) == ("proposed", "p1")
    assert alerts.replans(run=4) == []


def test_an_alert_changes_in_place_and_a_restart_ends_what_was_left_active(tmp_path) -> None:
    alerts = AlertStore(Store(tmp_path))
    alerts.save(alert(1, 1))
    alerts.save(alert(2, None))
    raised = {**alert(1, 1), "level": "alarm", "message": "worse"}
    alerts.save(raised)
    assert [a for a in alerts.alerts() if a["id"] == "a1"] == [raised]
    alerts.save({**alert(2, None), "active": False, "ended_at": "2026-11-23T20:00:09.000Z"})
    # the next station process ends what the last one left active: only a1 here
    assert AlertStore(Store(tmp_path)).end_active("2026-11-23T20:01:00.000Z") == 1
    (a1,) = [a for a in alerts.alerts() if a["id"] == "a1"]
    assert (a1["active"], a1["ended_at"]) == (False, "2026-11-23T20:01:00.000Z")


def test_a_database_of_the_first_version_gains_the_new_columns(tmp_path) -> None:
    import sqlite3

    store = Store(tmp_path)
    with store.conn as c:
        c.execute("CREATE TABLE alerts (id TEXT PRIMARY KEY, time TEXT NOT NULL, level TEXT "
                  "NOT NULL, kind TEXT NOT NULL, message TEXT NOT NULL, target_id TEXT, "
                  "run_id INTEGER, acknowledged INTEGER NOT NULL DEFAULT 0, "
                  "acknowledged_at TEXT)")
        c.execute("INSERT INTO alerts VALUES ('old', '2026-01-01T00:00:00.000Z', 'warning', "
                  "'link_lost', 'link lost', NULL, NULL, 0, NULL)")
    (old,) = AlertStore(store).alerts()
    assert (old["active"], old["updated_at"], old["ended_at"]) == (
        False, "2026-01-01T00:00:00.000Z", None)
    assert isinstance(store.conn, sqlite3.Connection)
