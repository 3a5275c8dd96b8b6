"""`usv-station bench server`: live fan-out latency and API latency under load, and what a
web client can do to the boat link.

Runs real `usv-station serve` subprocesses with the simulated boat on loopback (ephemeral
ports, or `--base-port N`: the station on N, its 3D view on N + 1):

- `websocket`: 20 clients on /ws/live while the boat sends telemetry at 50 Hz;
  latency = a client's receive time minus the row's ingest time (`time`,
  stamped by the station when the frame arrived; same clock, 1 ms steps).
- `health_under_planning`: GET /api/health every 20 ms while the station runs
  4 plans at once (4 plan workers, kept busy with random 400 m transits).
- `abuse`: GET /api/health every 20 ms while (1) 50 MB bodies are sent without a
  token (time to the 401/413 answer) and (2) 1000 half-open connections are held;
  then the worst event-loop lag the station saw over the whole run.
- the floods of issue 26, each for the bench's duration on a station flying a mission:
  `open_path_flood` (16 clients sending 1 MiB JSON bodies to open paths: /nope, /,
  /docs, /api/health), `viewer_pages` (6 clients fetching 100,000-row telemetry pages
  with the viewer token, the database filled beforehand) and `half_open` (2100
  half-open connections, renewed as the station closes them). Each reports the boat's
  states seen (it must stay RUNNING), the link's worst heartbeat gap
  (`link_heartbeat_gap_ms`, measured by the link on its own loop), health latency and the
  station's memory (RSS: before, peak, after).
- `link_start`: an external boat on a pty (`serve --link /dev/pts/N`): the time from
  starting `serve` to its first HEARTBEAT on the boat's port, and the boat's silence
  across a restart of `serve` (the boat fails safe after 3 s of it).
"""

from __future__ import annotations

import asyncio
import contextlib
import datetime as dt
import functools
import os
import socket
import statistics
import sys
import tempfile
import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any

import httpx
import numpy as np

from usvstation.bench.planner import machine_info
from usvstation.bench.scenarios import random_transit
from usvstation.clock import REAL_CLOCK, Stopwatch, pause
from usvstation.serveproc import ServeProcess

TOKEN = "bench-token-0123456789abcdef"


def _percentiles(values: list[float]) -> dict[str, float]:
    arr = np.asarray(values)
    return {"count": int(arr.size), "p50_ms": round(float(np.percentile(arr, 50)), 2),
            "p99_ms": round(float(np.percentile(arr, 99)), 2),
            "max_ms": round(float(arr.max()), 2)}


VIEWER = "bench-viewer-0123456789abcdef"
BASE_PORT: int | None = None  # --base-port: the station on it, its 3D view on the next


def _port_args() -> tuple[str, ...]:
    if BASE_PORT is None:
        return ()
    return ("--port", str(BASE_PORT), "--viser-port", str(BASE_PORT + 1))


class Station(ServeProcess):
    """`usv-station serve` on ephemeral (or --base-port) ports in a temporary data dir."""

    def __init__(self, env: dict[str, str], *args: str,
                 prepare: Callable[[Path], None] | None = None) -> None:
        self.tmp = tempfile.TemporaryDirectory(prefix="usv-bench-")
        data = Path(self.tmp.name) / "data"
        if prepare is not None:
            prepare(data)
        super().__init__(data, *_port_args(), "--viewer-token", VIEWER, *args, token=TOKEN,
                         env=env)

    def close(self) -> None:
        self.stop()
        self.tmp.cleanup()


def _ingest_time(iso: str) -> float:
    return dt.datetime.fromisoformat(iso.replace("Z", "+00:00")).timestamp()


async def websocket_latency(url: str, clients: int, seconds: float) -> dict[str, Any]:
    """Telemetry ingest-to-delivery latency over `clients` websocket clients."""
    from websockets.asyncio.client import connect

    latencies: list[float] = []
    received = [0] * clients
    stop = REAL_CLOCK.now() + seconds

    async def client(i: int) -> None:
        async with connect(url.replace("http", "ws") + "/ws/live", max_size=None,
                           additional_headers={"Authorization": f"Bearer {TOKEN}"}) as ws:
            while REAL_CLOCK.now() < stop:
                try:
                    text = await asyncio.wait_for(ws.recv(), timeout=1.0)
                except TimeoutError:
                    continue
                now = REAL_CLOCK.unix()
                if text.startswith('{"type":"telemetry"'):
                    import json

                    row = json.loads(text)["data"]
                    latencies.append(1000.0 * (now - _ingest_time(row["time"])))
                    received[i] += 1

    await asyncio.gather(*(client(i) for i in range(clients)))
    rates = [n / seconds for n in received]
    return {"clients": clients, "seconds": seconds,
            "messages_per_client_per_s": round(statistics.median(rates), 2),
            **_percentiles(latencies)}


async def health_under_planning(url: str, plans_at_once: int, seconds: float) -> dict[str, Any]:
    """GET /api/health latency while `plans_at_once` plans keep the workers busy."""
    headers = {"Authorization": f"Bearer {TOKEN}"}
    scenarios = [random_transit(i).model_dump(mode="json") for i in range(8)]
    latencies: list[float] = []
    running_seen: list[int] = []
    stop = REAL_CLOCK.now() + seconds
    async with httpx.AsyncClient(base_url=url, timeout=30, headers=headers) as c:

        async def planner(k: int) -> int:
            done = 0
            while REAL_CLOCK.now() < stop:
                job = (await c.post("/api/plans", headers=headers,
                                    json={"scenario": scenarios[(k + done) % 8]})).json()
                while (await c.get(f"/api/plans/{job['id']}")).json()["status"] in (
                        "queued", "running"):
                    await REAL_CLOCK.sleep(0.02)
                done += 1
            return done

        async def prober() -> None:
            while REAL_CLOCK.now() < stop:
                watch = Stopwatch()
                r = await c.get("/api/health")
                latencies.append(1000.0 * watch.elapsed())
                running_seen.append(r.json()["plans"]["running"])
                await REAL_CLOCK.sleep(0.02)

        results = await asyncio.gather(prober(), *(planner(k) for k in range(plans_at_once)))
    return {"plans_at_once": plans_at_once, "seconds": seconds,
            "plans_completed": sum(results[1:]),
            "running_median": statistics.median(running_seen) if running_seen else 0,
            "running_max": max(running_seen, default=0),
            **_percentiles(latencies)}


class _Prober(threading.Thread):
    """GET /api/health every 20 ms on a keep-alive connection, latencies in ms."""

    def __init__(self, url: str) -> None:
        super().__init__(daemon=True)
        self.url, self.latencies, self.errors = url, [], 0
        self.stop = threading.Event()

    def run(self) -> None:
        with httpx.Client(base_url=self.url, timeout=30) as c:
            while not self.stop.is_set():
                watch = Stopwatch()
                try:
                    ok = c.get("/api/health").status_code == 200
                except httpx.HTTPError:
                    ok = False
                if ok:
                    self.latencies.append(1000.0 * watch.elapsed())
                else:
                    self.errors += 1
                pause(0.02)

    def take(self) -> list[float]:
        out, self.latencies = self.latencies, []
        return out


def _big_body_without_token(host: str, port: int, size: int) -> tuple[int, float]:
    """PUT a `size`-byte body with no token; (status, ms until the answer's first byte)."""
    head = (f"PUT /api/scenario HTTP/1.1\r\nHost: {host}:{port}\r\n"
            f"Content-Type: application/json\r\nContent-Length: {size}\r\n\r\n").encode()
    chunk = b"\0" * 65536
    with socket.create_connection((host, port), timeout=30) as s:
        watch = Stopwatch()
        s.sendall(head)
        s.setblocking(False)
        sent, data = 0, b""
        while b"\r\n" not in data and watch.elapsed() < 30:
            if sent < size:
                try:
                    sent += s.send(chunk[: size - sent])
                except BlockingIOError:
                    pause(0.001)
                except OSError:
                    sent = size
            try:
                piece = s.recv(4096)
            except BlockingIOError:
                continue
            if not piece:
                break
            data += piece
        elapsed = 1000.0 * watch.elapsed()
    status = int(data.split()[1]) if data.startswith(b"HTTP/") else 0
    return status, round(elapsed, 2)


def abuse(url: str, half_open: int, seconds: float) -> dict[str, Any]:
    host, port = url.split("//")[1].split(":")
    port_n = int(port)
    prober = _Prober(url)
    prober.start()
    pause(1.0)
    prober.take()
    bodies = [_big_body_without_token(host, port_n, 50 << 20) for _ in range(5)]
    during_bodies = prober.take()
    conns = []
    for i in range(half_open):
        sock = socket.create_connection((host, port_n), timeout=30)
        if i % 2:
            sock.sendall(b"GET /api/health HTTP/1.1\r\nHost: x")
        conns.append(sock)
    prober.take()
    pause(seconds)
    during_half_open = prober.take()
    for sock in conns:
        sock.close()
    prober.stop.set()
    prober.join()
    health = httpx.get(url + "/api/health", timeout=30).json()
    return {
        "link_heartbeat_gap_ms": health["link_heartbeat_gap_ms"],
        "body_50mb_no_token": {"statuses": sorted({b[0] for b in bodies}),
                               "answer_ms": [b[1] for b in bodies],
                               "max_ms": max(b[1] for b in bodies)},
        "health_during_bodies": _percentiles(during_bodies) if during_bodies else {"count": 0},
        "half_open_connections": half_open,
        "health_during_half_open": (_percentiles(during_half_open) if during_half_open
                                    else {"count": 0}),
        "health_errors": prober.errors,
        "loop_lag_worst_ms": health["loop_lag_ms"]["worst_since_start"],
    }


# --- issue 26: what web clients can do to the boat link ------------------------------------

OPEN_PATHS = ("/nope", "/", "/docs", "/api/health")
PAGE_ROWS = 100_000
SETTLE_S = 5.0  # after a flood, memory is read this long after it stopped


def rss_mb(pid: int) -> float:
    """Resident memory of a process, MB (Linux /proc)."""
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return round(int(line.split()[1]) / 1024, 1)
    return 0.0


def long_scenario() -> dict[str, Any]:
    """case1 from 300 m out at 1.5 m/s at most: a mission of a few minutes to flood during."""
    from usvstation.scenario import load_scenario

    doc = load_scenario("case1").model_dump(mode="json")
    doc.update(name="bench-long-approach", start={**doc["start"], "x": 300.0})
    doc["vessel"] = {**doc["vessel"], "speed_max": 1.5}
    return doc


def prepare_data(rows: int = 0) -> Callable[[Path], None]:
    """A data dir with the long scenario as the working one and `rows` telemetry rows."""

    def prepare(data: Path) -> None:
        from usvstation.store.db import Store

        store = Store(data)
        store.set_setting("scenario", long_scenario())
        store.start()
        for i in range(rows):
            store.writer.put({"run": None, "time": f"2026-01-01T00:00:{i % 60:02d}.000Z",
                              "boat_time": i * 0.2, "lat": 30.5 + i * 1e-7, "lon": 114.4,
                              "x": 85.0 - i * 1e-3, "y": 10.0, "heading_deg": 180.0,
                              "course_deg": 180.0, "speed": 1.0, "ramp_heading_deg": 180.0,
                              "yaw_rate_dps": 0.0, "fix_type": 3, "satellites": 12,
                              "hdop": 0.8, "thrust_left": 0.3, "thrust_right": 0.3,
                              "battery_v": 14.8, "waypoint_index": 1,
                              "cross_track_m": 0.05, "state": "RUNNING"})
        store.close()

    return prepare


def fly_mission(url: str) -> str:
    """Plan the working scenario, upload it and START it; the mission's id."""
    with httpx.Client(base_url=url, timeout=60,
                      headers={"Authorization": f"Bearer {TOKEN}"}) as c:
        deadline = REAL_CLOCK.now() + 120
        while not c.get("/api/boat").json()["link"]["up"]:
            if REAL_CLOCK.now() > deadline:
                raise RuntimeError("bench server: the boat link never came up")
            pause(0.1)
        job = c.post("/api/plans", json={"seed": 1}).json()
        while (job := c.get(f"/api/plans/{job['id']}").json())["status"] in ("queued",
                                                                             "running"):
            pause(0.1)
        if job["status"] != "done":
            raise RuntimeError(f"bench server: no plan: {job.get('error')}")
        mission = c.post("/api/missions", json={"plan_id": job["id"]}).json()
        while (mission := c.get(f"/api/missions/{mission['id']}").json())["state"] == \
                "uploading":
            pause(0.1)
        r = c.post("/api/boat/command", json={"command": "start", "mission_id": mission["id"]})
        if r.status_code != 200:
            raise RuntimeError(f"bench server: START refused: {r.text}")
        return mission["id"]


class _Watch(threading.Thread):
    """The boat's state (GET /api/boat every 200 ms) and the station's memory."""

    def __init__(self, url: str, pid: int) -> None:
        super().__init__(daemon=True)
        self.url, self.pid = url, pid
        self.states: dict[str, int] = {}
        self.peak_mb = 0.0
        self.stop = threading.Event()
        self.ready = threading.Event()  # its connection is open (before any flood starts)

    def run(self) -> None:
        with httpx.Client(base_url=self.url, timeout=30,
                          headers={"Authorization": f"Bearer {TOKEN}"}) as c:
            c.get("/api/health")
            self.ready.set()
            while not self.stop.is_set():
                self.peak_mb = max(self.peak_mb, rss_mb(self.pid))
                try:
                    boat = c.get("/api/boat").json()["boat"]
                    state = boat["state"] if boat else "none"
                except (httpx.HTTPError, ValueError):
                    state = "no answer"
                self.states[state] = self.states.get(state, 0) + 1
                pause(0.2)


def _open_path_load(url: str, stop: threading.Event, out: list[int]) -> None:
    body = b"[" + b",".join(b'{"x": 0.5, "y": [1, 2, 3], "s": "abcdef"}'
                            for _ in range((1 << 20) // 42)) + b"]"
    i = 0
    with httpx.Client(base_url=url, timeout=60) as c:
        while not stop.is_set():
            try:
                r = c.post(OPEN_PATHS[i % len(OPEN_PATHS)], content=body,
                           headers={"Content-Type": "application/json"})
                out.append(r.status_code)
            except httpx.HTTPError:
                out.append(0)
            i += 1


def _viewer_page_load(url: str, stop: threading.Event, out: list[int],
                      rows: int = PAGE_ROWS) -> None:
    with httpx.Client(base_url=url, timeout=120,
                      headers={"Authorization": f"Bearer {VIEWER}"}) as c:
        while not stop.is_set():
            try:
                with c.stream("GET", "/api/telemetry", params={"limit": rows}) as r:
                    size = sum(len(piece) for piece in r.iter_bytes())
                out.append(r.status_code if size > 0 else 0)
            except httpx.HTTPError:
                out.append(0)


def _half_open_load(url: str, count: int, stop: threading.Event, out: list[int]) -> None:
    """`count` half-open connections, each renewed (at most once a second) when the station
    closes it; `out` counts the connections made."""
    import select

    host, port = url.split("//")[1].split(":")
    addr = (host, int(port))
    socks: list[socket.socket | None] = [None] * count

    def open_one(i: int) -> None:
        try:
            s = socket.create_connection(addr, timeout=5)
            if i % 2:
                s.sendall(b"GET /api/health HTTP/1.1\r\nHost: x")
            s.setblocking(False)
            socks[i] = s
            out.append(1)
        except OSError:
            socks[i] = None

    for i in range(count):
        if stop.is_set():
            break
        open_one(i)
    while not stop.is_set():
        poll = select.poll()  # select() stops at fd 1024
        slot = {}
        for i, s in enumerate(socks):
            if s is not None:
                poll.register(s, select.POLLIN)
                slot[s.fileno()] = i
        for fd, _ in poll.poll(0):  # closed by the station (header timeout, per-client cap)
            i = slot[fd]
            s = socks[i]
            assert s is not None
            try:
                gone = s.recv(4096) == b""
            except OSError:
                gone = True
            if gone:
                socks[i] = None
                s.close()
        for i, s in enumerate(socks):
            if s is None and not stop.is_set():
                open_one(i)
        stop.wait(1.0)
    for s in socks:
        if s is not None:
            s.close()


Load = Callable[[str, threading.Event, list[int]], None]


def flood(name: str, seconds: float, clients: int, load: Load, *,
          prepare: Callable[[Path], None], what: str,
          settle_s: float = SETTLE_S) -> dict[str, Any]:
    """One flood on a station of its own flying a mission: the boat's states, the link's
    heartbeat gap, health latency and the station's memory."""
    station = Station({}, prepare=prepare)
    try:
        fly_mission(station.url)
        return measure_flood(station, seconds, clients, load, what=what, settle_s=settle_s)
    finally:
        station.close()


def measure_flood(station: Station, seconds: float, clients: int, load: Load, *, what: str,
                  settle_s: float = SETTLE_S) -> dict[str, Any]:
    """One flood on a station already flying a mission (`flood`, or the quick bench's one
    station for all three)."""
    pid = station.proc.pid
    prober = _Prober(station.url)
    prober.start()
    pause(1.0)
    prober.take()
    baseline = rss_mb(pid)
    watch = _Watch(station.url, pid)
    watch.start()
    watch.ready.wait(60)  # like the operator's console: connected before the flood
    stop, out = threading.Event(), []
    threads = [threading.Thread(target=load, args=(station.url, stop, out), daemon=True)
               for _ in range(clients)]
    began = REAL_CLOCK.unix()
    for t in threads:
        t.start()
    pause(seconds)
    stop.set()
    for t in threads:
        t.join(120)
    ended = REAL_CLOCK.unix()
    during = prober.take()
    pause(settle_s)
    after = rss_mb(pid)
    watch.stop.set()
    watch.join()
    prober.stop.set()
    prober.join()
    health = httpx.get(station.url + "/api/health", timeout=30).json()
    statuses: dict[str, int] = {}
    for code in out:
        statuses[str(code)] = statuses.get(str(code), 0) + 1
    return {
        "what": what, "clients": clients, "seconds": seconds, "requests": len(out),
        "statuses": statuses, "boat_states_seen": watch.states,
        "boat_left_running": sorted(set(watch.states) - {"RUNNING"}),
        "link_heartbeat_gap_ms": health["link_heartbeat_gap_ms"],
        "link_heartbeat_late_during_flood_ms": _late_within(
            health["link_heartbeat_gap_ms"]["late"], began, ended),
        "health": _percentiles(during) if during else {"count": 0},
        "health_errors": prober.errors,
        "memory_mb": {"baseline": baseline, "peak": watch.peak_mb, "after": after,
                      "after_minus_baseline": round(after - baseline, 1)},
        "loop_lag_worst_ms": health["loop_lag_ms"]["worst_since_start"],
    }


def _late_within(late: list[tuple[str, float]], began: float, ended: float) -> list[float]:
    """The late heartbeat intervals (ms, over 375 ms) that ended within [began, ended]:
    none means every interval of the flood was under 375 ms."""
    return [ms for when, ms in late if began <= _ingest_time(when) <= ended]


def link_start(restarts: int = 3) -> dict[str, Any]:
    """An external boat's port (a pty with the station's key): time from starting `serve` to
    its first HEARTBEAT there, and the silence on it across SIGTERM and a new `serve`."""
    import os
    import select
    import signal
    import subprocess

    from usvstation.link import wire
    from usvstation.link.transport import PtyPair
    from usvstation.serveproc import SCRIPT

    tmp = tempfile.TemporaryDirectory(prefix="usv-bench-link-")
    key = Path(tmp.name) / "boat.key"
    wire.write_key(key)
    boat = wire.Codec(1, wire.BOAT_COMPONENT, wire.read_key(key))
    pair = PtyPair()
    first_ms: list[float] = []
    silence_ms: list[float] = []
    last_frame: float | None = None

    def heartbeat_within(timeout: float) -> float | None:
        """Read the port until a station HEARTBEAT; the stopwatch time it came (None)."""
        nonlocal last_frame
        end = REAL_CLOCK.now() + timeout
        while REAL_CLOCK.now() < end:
            if select.select([pair.master_fd], [], [], 0.05)[0]:
                msgs, _ = boat.feed(os.read(pair.master_fd, 65536))
                if any(m.get_srcSystem() == 255 for m in msgs):
                    last_frame = REAL_CLOCK.now()
                    if any(m.get_type() == "HEARTBEAT" for m in msgs):
                        return last_frame
        return None

    def start() -> subprocess.Popen:
        return subprocess.Popen(
            [str(SCRIPT), "serve", "--port", "0", "--viser-port", "0", "--data-dir",
             str(Path(tmp.name) / "data"), "--token", TOKEN, "--link", pair.slave_path,
             "--link-key", str(key)], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            start_new_session=True)

    procs: list[subprocess.Popen] = []
    try:
        for _ in range(restarts):
            began = REAL_CLOCK.now()
            procs.append(start())
            heard = heartbeat_within(60.0)
            if heard is None:
                raise RuntimeError("bench server: serve never reached the boat's port")
            first_ms.append(round(1000 * (heard - began), 1))
            heartbeat_within(3.0)  # running for a while
            before = last_frame
            procs[-1].send_signal(signal.SIGTERM)
            procs[-1].wait(30)
            # the same port, a new station at once: the boat hears nothing between
            procs.append(start())
            heard = heartbeat_within(60.0)
            if heard is not None and before is not None:
                silence_ms.append(round(1000 * (heard - before), 1))
            procs[-1].send_signal(signal.SIGTERM)
            procs[-1].wait(30)
    finally:
        for proc in procs:
            if proc.poll() is None:
                proc.kill()
                proc.wait()
            with contextlib.suppress(ProcessLookupError, PermissionError):
                os.killpg(proc.pid, signal.SIGKILL)
        pair.close()
        tmp.cleanup()
    return {"bytecode_cache": not sys.dont_write_bytecode,  # PYTHONDONTWRITEBYTECODE: slower
            "first_heartbeat_ms": first_ms, "first_heartbeat_max_ms": max(first_ms),
            "restart_silence_ms": silence_ms,
            "restart_silence_max_ms": max(silence_ms) if silence_ms else None,
            "failsafe_after_ms": 3000}


def _websocket_phase(station: Station, out: dict[str, Any], seconds: float) -> None:
    pause(2.0)  # link up, telemetry flowing
    out["websocket"] = asyncio.run(websocket_latency(station.url, 20, seconds))
    health = httpx.get(station.url + "/api/health", timeout=30).json()
    out["loop_lag_worst_ms_websocket"] = health["loop_lag_ms"]["worst_since_start"]
    out["websocket"]["link_heartbeat_gap_ms"] = health["link_heartbeat_gap_ms"]


def _planning_phase(station: Station, out: dict[str, Any], seconds: float) -> None:
    out["health_under_planning"] = asyncio.run(health_under_planning(station.url, 4, seconds))
    health = httpx.get(station.url + "/api/health", timeout=30).json()
    out["loop_lag_worst_ms_planning"] = health["loop_lag_ms"]["worst_since_start"]
    out["health_under_planning"]["link_heartbeat_gap_ms"] = health["link_heartbeat_gap_ms"]


def _abuse_phase(station: Station, out: dict[str, Any], seconds: float, half_open: int) -> None:
    out["abuse"] = abuse(station.url, half_open, seconds)


def run_server_bench(quick: bool = False,
                     progress: Callable[[str], None] = lambda _m: None,
                     base_port: int | None = None) -> dict[str, Any]:
    global BASE_PORT
    BASE_PORT = base_port
    # quick: a smoke test of every measure (2 s phases, fewer connections), not figures
    seconds = 2.0 if quick else 30.0
    half_open = 300 if quick else 1000
    half_open_flood = 400 if quick else 2100
    page_rows = 10_000 if quick else PAGE_ROWS
    settle_s = 1.0 if quick else SETTLE_S
    command = "usv-station bench server --json" + (" --quick" if quick else "") + \
        (f" --base-port {base_port}" if base_port is not None else "")
    out: dict[str, Any] = {"command": command, "machine": machine_info(),
                           "load_average": [round(x, 2) for x in os.getloadavg()]}
    floods = {
        "open_path_flood": (16, _open_path_load, "1 MiB JSON bodies, open paths"),
        "viewer_pages": (6, functools.partial(_viewer_page_load, rows=page_rows),
                         f"GET /api/telemetry?limit={page_rows}, viewer token"),
        "half_open": (1, lambda url, stop, o: _half_open_load(url, half_open_flood, stop, o),
                      f"{half_open_flood} half-open connections"),
    }
    # each phase: what it measures, the station settings it needs, the measure; each records
    # the station's worst loop lag since its start (and its heartbeat gaps)
    phases = (
        ("telemetry at 50 Hz, 20 websocket clients", {"USV_STATION_TELEMETRY_HZ": "50"},
         _websocket_phase),
        ("4 plan workers, health probed while 4 plans run", {"USV_STATION_PLAN_WORKERS": "4"},
         _planning_phase),
        (f"abuse: 50 MB bodies without a token, {half_open} half-open connections", {},
         functools.partial(_abuse_phase, half_open=half_open)),
    )
    if quick:  # one station takes every phase in turn, its worst figures since its start
        station = Station({k: v for _, env, _ in phases for k, v in env.items()},
                          prepare=prepare_data(page_rows + 10_000))
        try:
            for what, _, phase in phases:
                progress(what)
                phase(station, out, seconds)
            progress("floods: open paths, viewer pages, half-open, on the same station")
            fly_mission(station.url)
            for name, (clients, load, what) in floods.items():
                out[name] = measure_flood(station, seconds, clients, load, what=what,
                                          settle_s=settle_s)
        finally:
            station.close()
    else:
        for what, env, phase in phases:
            progress(f"station with {what}")
            station = Station(env)
            try:
                phase(station, out, seconds)
            finally:
                station.close()
        for name, (clients, load, what) in floods.items():
            progress(f"{name}: {what}, {clients} client(s)")
            rows = page_rows + 10_000 if name == "viewer_pages" else 0
            out[name] = flood(name, seconds, clients, load, prepare=prepare_data(rows),
                              what=what, settle_s=settle_s)
    progress("link start: serve on an external boat's port, first heartbeat and restarts")
    out["link_start"] = link_start(1 if quick else 5)
    # each station's worst since its start (start-up included): the whole bench's worst
    out["loop_lag_worst_ms"] = max(out["loop_lag_worst_ms_websocket"],
                                   out["loop_lag_worst_ms_planning"],
                                   out["abuse"]["loop_lag_worst_ms"])
    out["link_heartbeat_gap_worst_ms"] = max(
        out[k]["link_heartbeat_gap_ms"]["worst_last_minute"]
        for k in ("open_path_flood", "viewer_pages", "half_open"))
    # the worst interval within a flood's own 30 s (375 ms when none was late)
    out["link_heartbeat_gap_worst_during_floods_ms"] = max(
        max(out[k]["link_heartbeat_late_during_flood_ms"], default=375.0)
        for k in ("open_path_flood", "viewer_pages", "half_open"))
    return out
