"""The telemetry writer survives a locked database: it retries, keeps every row, recovers."""

import sqlite3
import time

from usvstation.station import LoopLagMonitor
from usvstation.store.db import Store


def row(i: int) -> dict:
    return {"run": None, "time": f"2026-11-22T10:00:00.{i:03d}Z", "boat_time": i * 0.1}


def wait_for(predicate, timeout: float) -> bool:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(0.02)
    return False


def test_writer_retries_while_locked_and_loses_nothing(tmp_path):
    store = Store(tmp_path)
    store.start()
    try:
        lock = sqlite3.connect(store.path, isolation_level=None)
        lock.execute("BEGIN EXCLUSIVE")
        for i in range(100):
            store.writer.put(row(i))
        assert wait_for(lambda: store.writer.error is not None, 30)
        assert "locked" in store.writer.error and store.writer.queued == 100
        lock.execute("ROLLBACK")
        lock.close()
        assert store.writer.flush(30)
        assert store.writer.error is None and store.writer.stats.dropped == 0
        assert store.writer.stats.retries >= 1
        assert len(store.telemetry(None, None, None, 1000)) == 100
    finally:
        store.close()


def test_writer_queue_is_bounded_and_counts_drops(tmp_path):
    store = Store(tmp_path)
    store.writer.queue_max = 50
    lock = sqlite3.connect(store.path, isolation_level=None)
    lock.execute("BEGIN EXCLUSIVE")
    store.start()
    try:
        for i in range(80):
            store.writer.put(row(i))
        assert wait_for(lambda: store.writer.stats.dropped == 30, 30)
        lock.execute("ROLLBACK")
        assert store.writer.flush(30)
        rows = store.telemetry(None, None, None, 1000)
        assert [r["boat_time"] for r in rows] == [i * 0.1 for i in range(30, 80)]  # newest kept
    finally:
        lock.close()
        store.close()


def test_loop_lag_window_keeps_the_worst_of_the_last_minute():
    m = LoopLagMonitor()
    m.record(0.0, 0.010)
    m.record(1.0, 0.200)
    m.record(2.0, 0.050)
    assert m.meter.worst_since(2.0) == 0.200 and m.worst_ever == 0.200
    m.record(62.0, 0.020)  # the 0.2 s stall is more than a minute old
    assert m.meter.worst_since(62.0) == 0.050
    assert m.worst_ever == 0.200
