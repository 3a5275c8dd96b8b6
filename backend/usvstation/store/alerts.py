"""Alerts and re-plans, kept with their run in the station's database (call from threads).

Two tables of their own, created next to store/db.py's schema on the same file:
`alerts` {id, time, level, kind, message, target_id, run_id, acknowledged, active,
updated_at, announced_at, ended_at} (an alert changes in place: `save` writes its whole
record) and `replans` {id, created_at, run_id, alert_id, plan_id, policy, state, error,
latency_ms, mission_id}. A database of an earlier version gains the new alert columns.
"""

from __future__ import annotations

import sqlite3
from typing import Any

from usvstation.store.db import Store, utc_now

SCHEMA = """
CREATE TABLE IF NOT EXISTS alerts (
    id TEXT PRIMARY KEY,
    time TEXT NOT NULL,
    level TEXT NOT NULL,
    kind TEXT NOT NULL,
    message TEXT NOT NULL,
    target_id TEXT,
    run_id INTEGER,
    acknowledged INTEGER NOT NULL DEFAULT 0,
    acknowledged_at TEXT,
    active INTEGER NOT NULL DEFAULT 0,
    updated_at TEXT,
    announced_at TEXT,
    ended_at TEXT
);
CREATE INDEX IF NOT EXISTS alerts_run ON alerts(run_id, time);
CREATE TABLE IF NOT EXISTS replans (
    id TEXT PRIMARY KEY,
    created_at TEXT NOT NULL,
    run_id INTEGER,
    alert_id TEXT,
    plan_id TEXT,
    policy TEXT NOT NULL,
    state TEXT NOT NULL,
    error TEXT,
    latency_ms REAL,
    mission_id TEXT
);
"""

ALERT_FIELDS = ("id", "time", "level", "kind", "message", "target_id", "run_id",
                "acknowledged", "active", "updated_at", "announced_at", "ended_at")
# columns added after the first version: (name, declaration) for ALTER TABLE
_ADDED = (("active", "INTEGER NOT NULL DEFAULT 0"), ("updated_at", "TEXT"),
          ("announced_at", "TEXT"), ("ended_at", "TEXT"))
_BOOLS = ("acknowledged", "active")
REPLAN_FIELDS = ("id", "created_at", "run_id", "alert_id", "plan_id", "policy", "state",
                 "error", "latency_ms", "mission_id")


class AlertStore:
    """Reads and writes alerts and re-plans through the Store's per-thread connections."""

    def __init__(self, store: Store) -> None:
        self.store = store
        with store.conn as c:
            c.executescript(SCHEMA)
            have = {row[1] for row in c.execute("PRAGMA table_info(alerts)")}
            for name, declaration in _ADDED:
                if name not in have:
                    c.execute(f"ALTER TABLE alerts ADD COLUMN {name} {declaration}")

    def save(self, alert: dict[str, Any]) -> None:
        """Write an alert as it is now (new, or changed in place: level, state, ack)."""
        values = {**alert, "updated_at": alert.get("updated_at") or alert["time"],
                  "announced_at": alert.get("announced_at") or alert["time"]}
        with self.store.conn as c:
            c.execute(f"INSERT OR REPLACE INTO alerts ({', '.join(ALERT_FIELDS)}) VALUES "
                      f"({', '.join('?' for _ in ALERT_FIELDS)})",
                      tuple(int(bool(values.get(k))) if k in _BOOLS else values.get(k)
                            for k in ALERT_FIELDS))

    def end_active(self, ended_at: str) -> int:
        """End every alert still active (left by a previous station process); how many."""
        with self.store.conn as c:
            return c.execute("UPDATE alerts SET active = 0, ended_at = ?, updated_at = ? "
                             "WHERE active = 1", (ended_at, ended_at)).rowcount

    def alerts(self, run: int | None = None, limit: int = 1000) -> list[dict[str, Any]]:
        """Newest first; of one run when `run` is given."""
        where, args = ("WHERE run_id = ?", (run,)) if run is not None else ("", ())
        rows = self.store.conn.execute(
            f"SELECT {', '.join(ALERT_FIELDS)} FROM alerts {where} "
            f"ORDER BY time DESC, rowid DESC LIMIT ?", (*args, limit)).fetchall()
        return [_alert(r) for r in rows]

    def acknowledge(self, alert_id: str) -> dict[str, Any] | None:
        with self.store.conn as c:
            c.execute("UPDATE alerts SET acknowledged = 1, acknowledged_at = ? "
                      "WHERE id = ? AND acknowledged = 0", (utc_now(self.store.clock), alert_id))
            row = c.execute(f"SELECT {', '.join(ALERT_FIELDS)} FROM alerts WHERE id = ?",
                            (alert_id,)).fetchone()
        return _alert(row) if row else None

    def save_replan(self, replan: dict[str, Any]) -> None:
        with self.store.conn as c:
            c.execute(f"INSERT OR REPLACE INTO replans ({', '.join(REPLAN_FIELDS)}) VALUES "
                      f"({', '.join('?' for _ in REPLAN_FIELDS)})",
                      tuple(replan.get(k) for k in REPLAN_FIELDS))

    def replans(self, run: int | None = None) -> list[dict[str, Any]]:
        where, args = ("WHERE run_id = ?", (run,)) if run is not None else ("", ())
        rows = self.store.conn.execute(
            f"SELECT {', '.join(REPLAN_FIELDS)} FROM replans {where} "
            f"ORDER BY created_at, rowid", args).fetchall()
        return [dict(r) for r in rows]


def _alert(row: sqlite3.Row) -> dict[str, Any]:
    out = dict(row)
    for key in _BOOLS:
        out[key] = bool(out[key])
    out["updated_at"] = out["updated_at"] or out["time"]
    out["announced_at"] = out["announced_at"] or out["time"]
    return out
