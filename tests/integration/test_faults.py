"""Faults on a real `usv-station serve`: they are reported, they heal, nothing is lost.

The waits below are deadlines for something to happen (the boat clock and the
retry backoff set the pace), not performance assertions.
"""

from __future__ import annotations

import contextlib
import json
import os
import random
import signal
import socket
import sqlite3
import subprocess
import time
from pathlib import Path

import pytest
from stationproc import TOKEN, StationProcess
from websockets.sync.client import connect

from usvstation.scenario import load_scenario
from usvstation.serveproc import SCRIPT


def _long_plan() -> dict:
    """case1 at the largest population and generation count, with 1000 small islands beside
    the corridor that pruning keeps: about a minute of CPU with the compiled kernels (500
    generations took 5.8 s on a quiet machine), three times the 20 s limit."""
    base = load_scenario("case1").model_dump(mode="json")
    rng = random.Random(3)
    islands = [{"x": rng.uniform(15, 80), "y": rng.uniform(-60, -25) if i % 2
                else rng.uniform(30, 60), "radius": 0.5, "vx": 0.0, "vy": 0.0}
               for i in range(1000)]
    return {**base, "obstacles": base["obstacles"] + islands,
            "planner": {"population": 1000, "generations_max": 5000,
                        "stall_generations": 5000, "time_budget_s": 600.0,
                        "max_evaluations": 50_000_000}}


LONG_PLAN = _long_plan()


def wait_for(predicate, timeout: float, what: str):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = predicate()
        if value:
            return value
        time.sleep(0.1)
    raise AssertionError(f"{what} not within {timeout} s")


def health(st: StationProcess) -> dict:
    return st.client.get("/api/health").json()


def descendants(pid: int) -> set[int]:
    children: dict[int, list[int]] = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            with contextlib.suppress(OSError, IndexError, ValueError):
                stat = (entry / "stat").read_text()
                ppid = int(stat.rsplit(")", 1)[1].split()[1])
                children.setdefault(ppid, []).append(int(entry.name))
    out, todo = set(), [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            out.add(child)
            todo.append(child)
    return out


def alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


def test_database_locked_for_40_s_loses_nothing_and_heals(tmp_path):
    st = StationProcess(tmp_path / "data", env={"USV_STATION_TELEMETRY_HZ": "20"})
    try:
        wait_for(lambda: health(st)["telemetry_writer"]["committed"] > 0, 30, "telemetry")
        lock = sqlite3.connect(tmp_path / "data" / "station.sqlite3", isolation_level=None)
        lock.execute("BEGIN EXCLUSIVE")
        try:
            h = wait_for(lambda: (h := health(st))["status"] == "degraded" and h, 30,
                         "degraded health")
            assert "telemetry writer" in h["reasons"][0] and "locked" in h["reasons"][0]
            time.sleep(40)
            during = health(st)["telemetry_writer"]
            assert during["queued"] > 0 and during["error"]
        finally:
            lock.execute("ROLLBACK")
            lock.close()
        received = during["received"]
        w = wait_for(lambda: (w := health(st)["telemetry_writer"])["committed"] >= received
                     and w, 10, "telemetry rows resuming")
        assert w["dropped"] == 0
        assert wait_for(lambda: health(st)["status"] == "ok", 10, "ok health")
        with sqlite3.connect(tmp_path / "data" / "station.sqlite3") as db:
            assert db.execute("SELECT COUNT(*) FROM telemetry").fetchone()[0] >= received
    finally:
        st.stop()


@pytest.fixture
def small_fs(tmp_path):
    mnt = tmp_path / "fs"
    mnt.mkdir()
    r = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=4m", "tmpfs", str(mnt)],
                       capture_output=True, text=True)
    if r.returncode != 0:
        pytest.skip(f"cannot mount a small tmpfs here (needs root): {r.stderr.strip()}")
    try:
        yield mnt
    finally:
        subprocess.run(["umount", "-l", str(mnt)], check=False)


def test_full_filesystem_degrades_then_resumes(small_fs):
    st = StationProcess(small_fs / "data", env={"USV_STATION_TELEMETRY_HZ": "20"})
    filler = small_fs / "filler"
    try:
        wait_for(lambda: health(st)["telemetry_writer"]["committed"] > 0, 30, "telemetry")
        with contextlib.suppress(OSError), filler.open("wb") as f:
            while True:
                f.write(b"\0" * 65536)
                f.flush()
        h = wait_for(lambda: (h := health(st))["status"] == "degraded" and h, 60,
                     "degraded health")
        assert "full" in h["telemetry_writer"]["error"]
        # a live client that connects now hears it too
        with connect(st.url.replace("http", "ws") + "/ws/live", open_timeout=30,
                     additional_headers={"Authorization": f"Bearer {TOKEN}"}) as ws:
            deadline = time.monotonic() + 30
            while time.monotonic() < deadline:
                event = json.loads(ws.recv(timeout=30))
                said = event["data"].get("health") if event["type"] == "hello" else \
                    event["data"] if event["type"] == "health" else None
                if said and said["status"] == "degraded":
                    break
            else:
                raise AssertionError("no degraded health on the websocket")
            assert "full" in said["reasons"][0]
        filler.unlink()
        received = health(st)["telemetry_writer"]["received"]
        wait_for(lambda: health(st)["telemetry_writer"]["committed"] >= received, 20,
                 "telemetry rows resuming")
        assert wait_for(lambda: health(st)["status"] == "ok", 20, "ok health")
        assert health(st)["telemetry_writer"]["dropped"] == 0
    finally:
        st.stop()
        with contextlib.suppress(OSError):
            filler.unlink()


@pytest.fixture(scope="module")
def planner_station(tmp_path_factory):
    st = StationProcess(tmp_path_factory.mktemp("data"), "--plan-timeout-s", "20",
                        "--plan-queue", "3", env={"USV_STATION_PLAN_WORKERS": "1"})
    yield st
    st.stop()


def submit(st: StationProcess, scenario: dict | None = None) -> str:
    r = st.client.post("/api/plans", json={"scenario": scenario} if scenario else {"seed": 1})
    assert r.status_code == 202, r.text
    return r.json()["id"]


def test_a_killed_plan_worker_fails_its_job_and_is_replaced(planner_station):
    st = planner_station
    job = submit(st, LONG_PLAN)
    wait_for(lambda: st.client.get(f"/api/plans/{job}").json()["status"] == "running", 30,
             "running plan")
    (pid,) = health(st)["plans"]["worker_pids"]
    os.kill(pid, signal.SIGKILL)
    failed = st.wait_plan(job, 30)
    assert failed["status"] == "failed" and "killed by signal 9" in failed["error"]
    assert st.wait_plan(submit(st), 120)["status"] == "done"
    plans = health(st)["plans"]
    assert plans["workers_alive"] == 1 and plans["worker_pids"] != [pid]


def test_cancel_queue_limit_and_time_limit(planner_station):
    st = planner_station
    jobs = [submit(st, LONG_PLAN) for _ in range(3)]
    r = st.client.post("/api/plans", json={})
    assert r.status_code == 429 and r.headers["retry-after"].isdigit()
    for job in jobs[1:]:
        r = st.client.delete(f"/api/plans/{job}")
        assert r.status_code == 200 and r.json()["status"] == "cancelled"
    assert st.client.delete(f"/api/plans/{jobs[1]}").status_code == 409
    assert st.client.delete("/api/plans/nope").status_code == 404
    timed_out = st.wait_plan(jobs[0], 60)
    assert timed_out["status"] == "failed" and "20 s limit" in timed_out["error"]
    assert st.wait_plan(submit(st), 120)["status"] == "done"


def test_kill_9_of_the_station_leaves_no_worker(tmp_path):
    st = StationProcess(tmp_path / "data")
    try:
        workers = set(health(st)["plans"]["worker_pids"])
        family = descendants(st.proc.pid)
        assert workers and workers <= family
        st.proc.kill()
        st.proc.wait()
        wait_for(lambda: not any(alive(p) for p in family), 3, "every worker gone")
    finally:
        st.stop()


def serve_fails(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([str(SCRIPT), "serve", "--port", "0", "--viser-port", "0",
                           "--token", TOKEN, *args], capture_output=True, text=True,
                          timeout=120, cwd=cwd)


def one_line_exit_2(r: subprocess.CompletedProcess) -> str:
    assert r.returncode == 2, r.stderr
    assert "Traceback" not in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr
    return r.stderr


def test_start_failures_are_one_line_and_exit_2(tmp_path, small_fs_ro):
    assert "data dir" in one_line_exit_2(serve_fails("--data-dir", str(small_fs_ro),
                                                     cwd=tmp_path))
    with socket.socket() as busy:
        busy.bind(("127.0.0.1", 0))
        busy.listen()
        port = str(busy.getsockname()[1])
        r = subprocess.run([str(SCRIPT), "serve", "--port", port, "--viser-port", "0",
                            "--data-dir", str(tmp_path / "d1"), "--token", TOKEN],
                           capture_output=True, text=True, timeout=120)
        assert "cannot listen" in one_line_exit_2(r)
    r = serve_fails("--data-dir", str(tmp_path / "d2"), "--link", "/dev/ttyUSB-none",
                    cwd=tmp_path)
    assert "serial device /dev/ttyUSB-none not found" in one_line_exit_2(r)
    assert "port" in one_line_exit_2(serve_fails("--data-dir", str(tmp_path / "d3"),
                                                 "--port", "99999", cwd=tmp_path))


@pytest.fixture
def small_fs_ro(tmp_path):
    mnt = tmp_path / "ro"
    mnt.mkdir()
    r = subprocess.run(["mount", "-t", "tmpfs", "-o", "ro,size=1m", "tmpfs", str(mnt)],
                       capture_output=True, text=True)
    if r.returncode != 0:
        pytest.skip(f"cannot mount a read-only tmpfs here (needs root): {r.stderr.strip()}")
    try:
        yield mnt
    finally:
        subprocess.run(["umount", "-l", str(mnt)], check=False)


def test_a_working_scenario_without_origin_starts_with_a_warning(tmp_path):
    scenario = load_scenario("case2").model_dump(mode="json")
    scenario.pop("origin", None)
    st = StationProcess(tmp_path / "data")
    try:
        assert st.client.put("/api/scenario", json=scenario).status_code == 200
    finally:
        st.stop()
    st = StationProcess(tmp_path / "data")
    try:
        assert health(st)["link_up"] in (True, False)
        assert "has no origin" in st.log.read_text()
        assert st.client.get("/api/scenario").json().get("origin") is None
    finally:
        st.stop()
