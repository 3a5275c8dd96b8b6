"""SQLite storage: telemetry (batched, WAL), runs, plans and missions.

One writer thread owns the write connection and commits at most
`commit_interval_s` (200 ms) after a row arrives, so a crash loses at most
that much telemetry; WAL keeps committed rows through a kill -9. Readers use
their own connections from worker threads, so the event loop never blocks
on the database.
"""

from __future__ import annotations

import contextlib
import json
import queue
import sqlite3
import threading
from collections import deque
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from usvstation.clock import REAL_CLOCK, Clock, utc_iso

SCHEMA = """
CREATE TABLE IF NOT EXISTS runs (
    id INTEGER PRIMARY KEY,
    mission_id TEXT,
    plan_id TEXT,
    started_at TEXT NOT NULL,
    ended_at TEXT,
    state TEXT NOT NULL DEFAULT 'active'
);
CREATE TABLE IF NOT EXISTS telemetry (
    id INTEGER PRIMARY KEY,
    run INTEGER REFERENCES runs(id),
    time TEXT NOT NULL,
    boat_time REAL,
    lat REAL, lon REAL, x REAL, y REAL,
    heading_deg REAL, course_deg REAL, speed REAL, ramp_heading_deg REAL,
    yaw_rate_dps REAL, fix_type INTEGER, satellites INTEGER, hdop REAL,
    thrust_left REAL, thrust_right REAL, battery_v REAL,
    waypoint_index INTEGER, cross_track_m REAL, state TEXT
);
CREATE INDEX IF NOT EXISTS telemetry_run ON telemetry(run, id);
CREATE INDEX IF NOT EXISTS telemetry_time ON telemetry(time);
CREATE TABLE IF NOT EXISTS plans (
    id TEXT PRIMARY KEY,
    created_at TEXT NOT NULL,
    status TEXT NOT NULL,
    planner TEXT NOT NULL,
    seed INTEGER,
    scenario TEXT NOT NULL,
    plan TEXT,
    error TEXT,
    basis TEXT
);
CREATE TABLE IF NOT EXISTS missions (
    id TEXT PRIMARY KEY,
    plan_id TEXT NOT NULL REFERENCES plans(id),
    wire_id INTEGER NOT NULL,
    created_at TEXT NOT NULL,
    state TEXT NOT NULL,
    sent INTEGER NOT NULL DEFAULT 0,
    acked INTEGER NOT NULL DEFAULT 0,
    total INTEGER NOT NULL,
    error TEXT,
    run INTEGER,
    origin TEXT NOT NULL,
    items TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS settings (
    key TEXT PRIMARY KEY,
    value TEXT NOT NULL
);
"""

TELEMETRY_COLUMNS = (
    "run", "time", "boat_time", "lat", "lon", "x", "y", "heading_deg", "course_deg", "speed",
    "ramp_heading_deg", "yaw_rate_dps", "fix_type", "satellites", "hdop", "thrust_left",
    "thrust_right", "battery_v", "waypoint_index", "cross_track_m", "state",
)
_INSERT = (
    f"INSERT INTO telemetry ({', '.join(TELEMETRY_COLUMNS)}) "
    f"VALUES ({', '.join('?' for _ in TELEMETRY_COLUMNS)})"
)


def utc_now(clock: Clock = REAL_CLOCK) -> str:
    """The clock's time as ISO 8601 UTC with milliseconds, e.g. 2026-11-22T12:00:00.123Z."""
    return utc_iso(clock.unix())


def connect(path: Path, timeout: float = 30.0) -> sqlite3.Connection:
    conn = sqlite3.connect(path, check_same_thread=False, timeout=timeout)
    conn.row_factory = sqlite3.Row
    conn.execute("PRAGMA journal_mode=WAL")
    conn.execute("PRAGMA synchronous=NORMAL")
    conn.execute("PRAGMA foreign_keys=ON")
    return conn


@dataclass
class WriterStats:
    received: int = 0
    committed: int = 0
    commits: int = 0
    dropped: int = 0  # frames thrown away because the queue overflowed while failing
    retries: int = 0  # failed commits (each retried after a backoff)


QUEUE_MAX = 60_000  # 20 minutes at 50 Hz kept while the database refuses writes
BACKOFF_S = (0.25, 0.5, 1.0, 2.0, 4.0)  # waits between failed commits, the last repeated
WRITER_BUSY_TIMEOUT_S = 2.0
# reads and writes for requests wait this long for a lock another process holds, then fail
# (the API answers 503): a worker thread is not held for half a minute
REQUEST_BUSY_TIMEOUT_S = 5.0


class TelemetryWriter:
    """Background thread that batches telemetry rows into transactions.

    Its batching and retry pacing are I/O concerns and run on the real clock, whatever
    clock the station runs on. Any SQLite or OS error (disk full, a lock held by another process, a
    read-only file) is kept as `error` (health reports it) and the commit is
    retried after a growing backoff, on a fresh connection, until it
    succeeds; meanwhile rows wait in a queue of at most `queue_max` frames
    (the oldest dropped and counted beyond that). `error` clears on the first
    successful commit.
    """

    def __init__(self, path: Path, commit_interval_s: float = 0.2, batch_max: int = 2000,
                 queue_max: int = QUEUE_MAX) -> None:
        self.path, self.interval, self.batch_max = path, commit_interval_s, batch_max
        self.queue_max = queue_max
        self._queue: queue.SimpleQueue[tuple | threading.Event | None] = queue.SimpleQueue()
        self._thread = threading.Thread(target=self._run, name="telemetry-writer", daemon=True)
        self._pending: deque[tuple] = deque()
        self.stats = WriterStats()
        self.error: str | None = None

    @property
    def queued(self) -> int:
        """Rows received but not committed yet."""
        return self.stats.received - self.stats.committed - self.stats.dropped

    def start(self) -> None:
        self._thread.start()

    def put(self, row: dict[str, Any]) -> None:
        """Queue one telemetry row (keys of TELEMETRY_COLUMNS); never blocks."""
        self.stats.received += 1
        self._queue.put(tuple(row.get(c) for c in TELEMETRY_COLUMNS))

    def flush(self, timeout: float = 5.0) -> bool:
        """Block until every row queued so far is committed; False on timeout."""
        if not self._thread.is_alive():
            return False
        done = threading.Event()
        self._queue.put(done)
        return done.wait(timeout)

    def close(self, timeout: float = 5.0) -> None:
        """Commit what is queued (trying until `timeout`) and stop the thread."""
        if self._thread.is_alive():
            self._stop_by = REAL_CLOCK.now() + timeout
            self._queue.put(None)
            self._thread.join(timeout + 1.0)

    _stop_by: float | None = None

    def _take(self, item: tuple) -> None:
        self._pending.append(item)
        if len(self._pending) > self.queue_max:
            self._pending.popleft()
            self.stats.dropped += 1

    def _run(self) -> None:
        conn: sqlite3.Connection | None = None
        waiters: list[threading.Event] = []
        stopping, failures = False, 0
        commit_at: float | None = None  # monotonic time of the next commit (or retry)
        while True:
            now = REAL_CLOCK.now()
            wait = None if commit_at is None else max(0.0, commit_at - now)
            if stopping and self._stop_by is not None:
                wait = max(0.0, min(wait if wait is not None else 0.0, self._stop_by - now))
            try:
                item = self._queue.get(timeout=wait) if wait != 0.0 else self._queue.get_nowait()
            except queue.Empty:
                item = ()
            while item != ():  # take everything already queued
                if item is None:
                    stopping = True
                elif isinstance(item, threading.Event):
                    waiters.append(item)
                else:
                    self._take(item)
                try:
                    item = self._queue.get_nowait()
                except queue.Empty:
                    item = ()
            now = REAL_CLOCK.now()
            if not failures:
                if stopping or waiters or len(self._pending) >= self.batch_max:
                    commit_at = now
                elif self._pending and commit_at is None:
                    commit_at = now + self.interval
            if commit_at is None or now < commit_at:
                if stopping and not failures:
                    commit_at = now
                else:
                    continue
            try:
                if conn is None:
                    conn = connect(self.path, timeout=WRITER_BUSY_TIMEOUT_S)
                while self._pending:
                    batch = [self._pending[i]
                             for i in range(min(self.batch_max, len(self._pending)))]
                    self._commit(conn, batch)
                    for _ in batch:
                        self._pending.popleft()
            except (sqlite3.Error, OSError) as exc:
                self.error = f"{type(exc).__name__}: {exc}"
                self.stats.retries += 1
                failures += 1
                commit_at = REAL_CLOCK.now() + BACKOFF_S[min(failures, len(BACKOFF_S)) - 1]
                if conn is not None:
                    with contextlib.suppress(sqlite3.Error):
                        conn.close()
                    conn = None
                if stopping and (self._stop_by is None or REAL_CLOCK.now() >= self._stop_by):
                    return
                continue
            failures, commit_at, self.error = 0, None, None
            for w in waiters:
                w.set()
            waiters = []
            if stopping:
                conn.close()
                return

    def _commit(self, conn: sqlite3.Connection, rows: list[tuple]) -> None:
        if not rows:
            return
        with conn:
            conn.executemany(_INSERT, rows)
        self.stats.committed += len(rows)
        self.stats.commits += 1


SCHEMA_VERSION = 3  # PRAGMA user_version of a database this code wrote


def migrate(conn: sqlite3.Connection) -> None:
    """Bring a database of an earlier version up to SCHEMA_VERSION, in place.

    1 -> 2: the telemetry column `mode` held the boat's state: renamed `state`.
    2 -> 3: plans gain `basis` (the working scenario a plan was asked against, by field).
    """
    version = conn.execute("PRAGMA user_version").fetchone()[0]
    columns = {r[1] for r in conn.execute("PRAGMA table_info(telemetry)")}
    if "mode" in columns and "state" not in columns:
        conn.execute("ALTER TABLE telemetry RENAME COLUMN mode TO state")
    plan_columns = {r[1] for r in conn.execute("PRAGMA table_info(plans)")}
    if plan_columns and "basis" not in plan_columns:
        conn.execute("ALTER TABLE plans ADD COLUMN basis TEXT")
    if version < SCHEMA_VERSION:
        conn.execute(f"PRAGMA user_version = {SCHEMA_VERSION}")


class Store:
    """The station's database: schema, writer, and read helpers (call from worker threads)."""

    def __init__(self, data_dir: Path, clock: Clock = REAL_CLOCK) -> None:
        data_dir.mkdir(parents=True, exist_ok=True)
        self.clock = clock  # stamps runs, missions and plans
        self.path = data_dir / "station.sqlite3"
        self._local = threading.local()
        with connect(self.path) as conn:
            migrate(conn)
            conn.executescript(SCHEMA)
        self.writer = TelemetryWriter(self.path)

    def start(self) -> None:
        self.writer.start()

    def close(self) -> None:
        self.writer.close()

    @property
    def conn(self) -> sqlite3.Connection:
        """This thread's own connection."""
        conn = getattr(self._local, "conn", None)
        if conn is None:
            conn = self._local.conn = connect(self.path, timeout=REQUEST_BUSY_TIMEOUT_S)
        return conn

    # --- runs --------------------------------------------------------------
    def open_run(self, mission_id: str | None, plan_id: str | None) -> int:
        with self.conn as c:
            cur = c.execute(
                "INSERT INTO runs (mission_id, plan_id, started_at) VALUES (?, ?, ?)",
                (mission_id, plan_id, utc_now(self.clock)),
            )
            return int(cur.lastrowid)

    def close_run(self, run: int, state: str) -> None:
        with self.conn as c:
            c.execute("UPDATE runs SET ended_at = ?, state = ? WHERE id = ?",
                      (utc_now(self.clock), state, run))

    def close_stale_runs(self) -> None:
        """Runs left active by a previous station process end as 'interrupted'."""
        with self.conn as c:
            c.execute("UPDATE runs SET ended_at = ?, state = 'interrupted' WHERE state = 'active'",
                      (utc_now(self.clock),))

    def runs(self) -> list[dict[str, Any]]:
        rows = self.conn.execute(
            "SELECT r.*, (SELECT COUNT(*) FROM telemetry t WHERE t.run = r.id) AS points "
            "FROM runs r ORDER BY r.id"
        ).fetchall()
        return [dict(r) for r in rows]

    def run(self, run: int) -> dict[str, Any] | None:
        row = self.conn.execute("SELECT * FROM runs WHERE id = ?", (run,)).fetchone()
        return dict(row) if row else None

    # --- telemetry ---------------------------------------------------------
    def telemetry(self, run: int | None, since: str | None, until: str | None,
                  limit: int, after: int = 0) -> list[dict[str, Any]]:
        """At most `limit` rows with an id above `after` (the paging cursor), in id order."""
        sql, args = self._telemetry_query(run, since, until, after)
        rows = self.conn.execute(sql + " LIMIT ?", (*args, limit)).fetchall()
        return [dict(r) for r in rows]

    def telemetry_page(self, run: int | None, since: str | None, until: str | None,
                       limit: int, after: int = 0) -> tuple[int, int | None]:
        """(rows, id of the last) of the page of at most `limit` rows above `after`, as the
        table is now (rows stored later do not join it)."""
        sql, args = self._telemetry_query(run, since, until, after)
        page = "SELECT id" + sql[sql.index(" FROM telemetry"):] + " LIMIT ?"
        count, last = self.conn.execute(f"SELECT COUNT(*), MAX(id) FROM ({page})",
                                        (*args, limit)).fetchone()
        return int(count), None if last is None else int(last)

    def iter_telemetry(self, run: int | None, since: str | None = None,
                       until: str | None = None, chunk: int = 2000) -> Iterator[list[dict]]:
        """Telemetry in chunks, on a connection of its own (for streamed exports)."""
        conn = connect(self.path)
        try:
            sql, args = self._telemetry_query(run, since, until)
            cur = conn.execute(sql, args)
            while rows := cur.fetchmany(chunk):
                yield [dict(r) for r in rows]
        finally:
            conn.close()

    @staticmethod
    def _telemetry_query(run: int | None, since: str | None, until: str | None,
                         after: int = 0) -> tuple[str, tuple]:
        where, args = [], []
        if after:
            where.append("id > ?")
            args.append(after)
        if run is not None:
            where.append("run = ?")
            args.append(run)
        if since is not None:
            where.append("time >= ?")
            args.append(since)
        if until is not None:
            where.append("time <= ?")
            args.append(until)
        cols = ", ".join(("id", *TELEMETRY_COLUMNS))
        sql = f"SELECT {cols} FROM telemetry"
        if where:
            sql += " WHERE " + " AND ".join(where)
        return sql + " ORDER BY id", tuple(args)

    # --- plans ---------------------------------------------------------------
    def save_plan(self, job: dict[str, Any]) -> None:
        with self.conn as c:
            c.execute(
                "INSERT OR REPLACE INTO plans (id, created_at, status, planner, seed, scenario, "
                "plan, error, basis) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)",
                (job["id"], job["created_at"], job["status"], job["planner"], job.get("seed"),
                 json.dumps(job["scenario"]),
                 json.dumps(job["plan"]) if job.get("plan") is not None else None,
                 job.get("error"),
                 json.dumps(job["basis"]) if job.get("basis") is not None else None),
            )

    def plans(self) -> list[dict[str, Any]]:
        rows = self.conn.execute("SELECT * FROM plans ORDER BY created_at").fetchall()
        return [_plan_row(r) for r in rows]

    # --- missions ------------------------------------------------------------
    def save_mission(self, m: dict[str, Any]) -> None:
        with self.conn as c:
            c.execute(
                "INSERT OR REPLACE INTO missions (id, plan_id, wire_id, created_at, state, sent, "
                "acked, total, error, run, origin, items) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
                "?, ?)",
                (m["id"], m["plan_id"], m["wire_id"], m["created_at"], m["state"],
                 m["progress"]["sent"], m["progress"]["acked"], m["progress"]["total"],
                 m.get("error"), m.get("run"), json.dumps(m["origin"]), json.dumps(m["items"])),
            )

    def missions(self) -> list[dict[str, Any]]:
        rows = self.conn.execute("SELECT * FROM missions ORDER BY created_at").fetchall()
        out = []
        for r in rows:
            d = dict(r)
            d["items"] = json.loads(d["items"])
            d["origin"] = json.loads(d["origin"])
            d["progress"] = {"sent": d.pop("sent"), "acked": d.pop("acked"),
                             "total": d.pop("total")}
            out.append(d)
        return out

    # --- settings --------------------------------------------------------------
    def get_setting(self, key: str) -> Any:
        row = self.conn.execute("SELECT value FROM settings WHERE key = ?", (key,)).fetchone()
        return json.loads(row["value"]) if row else None

    def set_setting(self, key: str, value: Any) -> None:
        with self.conn as c:
            c.execute("INSERT OR REPLACE INTO settings (key, value) VALUES (?, ?)",
                      (key, json.dumps(value)))


def _plan_row(row: sqlite3.Row) -> dict[str, Any]:
    d = dict(row)
    d["scenario"] = json.loads(d["scenario"])
    d["plan"] = json.loads(d["plan"]) if d["plan"] else None
    d["basis"] = json.loads(d["basis"]) if d.get("basis") else None
    return d
