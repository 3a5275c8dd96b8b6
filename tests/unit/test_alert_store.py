"""Alerts and re-plans survive in the station database; acknowledgement is stored."""

from __future__ import annotations

from usvstation.store.alerts import AlertStore
from usvstation.store.db import Store


def alert(i: int, run: int | None) -> dict:
    return {"id": f"a{i}", "time": f"2026-11-23T20:00:0{i}.000Z", "level": "warning",
            "kind": "clearance", "message": f"m{i}", "target_id": "ais:1", "run_id": run,
            "acknowledged": False}


def test_alerts_round_trip_newest_first_by_run_and_ack(tmp_path) -> None:
    store = Store(tmp_path)
    alerts = AlertStore(store)
    for i, run in ((1, 1), (2, 2), (3, 1)):
        alerts.add(alert(i, run))
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
