"""`usv-station bench server`: live fan-out latency and API latency under planning load.

Runs a real `usv-station serve` subprocess with the simulated boat on loopback:

- `websocket`: 20 clients on /ws/live while the boat sends telemetry at 50 Hz;
  latency = a client's receive time minus the row's ingest time (`time`,
  stamped by the station when the frame arrived; same clock, 1 ms steps).
- `health_under_planning`: GET /api/health every 20 ms while the station runs
  4 plans at once (4 plan workers, kept busy with random 400 m transits).
- `abuse`: GET /api/health every 20 ms while (1) 50 MB bodies are sent without a
  token (time to the 401/413 answer) and (2) 1000 half-open connections are held;
  then the worst event-loop lag the station saw over the whole run.
"""

from __future__ import annotations

import asyncio
import datetime as dt
import socket
import statistics
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


class Station(ServeProcess):
    """`usv-station serve` on ephemeral ports in a temporary data dir."""

    def __init__(self, env: dict[str, str]) -> None:
        self.tmp = tempfile.TemporaryDirectory(prefix="usv-bench-")
        super().__init__(Path(self.tmp.name) / "data", token=TOKEN, env=env)

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


def run_server_bench(quick: bool = False,
                     progress: Callable[[str], None] = lambda _m: None) -> dict[str, Any]:
    seconds = 5.0 if quick else 30.0
    out: dict[str, Any] = {"command": "usv-station bench server --json" +
                           (" --quick" if quick else ""), "machine": machine_info()}
    progress("station with telemetry at 50 Hz, 20 websocket clients")
    station = Station({"USV_STATION_TELEMETRY_HZ": "50"})
    try:
        pause(2.0)  # link up, telemetry flowing
        out["websocket"] = asyncio.run(websocket_latency(station.url, 20, seconds))
        out["loop_lag_worst_ms_websocket"] = httpx.get(
            station.url + "/api/health", timeout=30).json()["loop_lag_ms"]["worst_since_start"]
    finally:
        station.close()
    progress("station with 4 plan workers, health probed while 4 plans run")
    station = Station({"USV_STATION_PLAN_WORKERS": "4"})
    try:
        out["health_under_planning"] = asyncio.run(health_under_planning(station.url, 4,
                                                                         seconds))
        out["loop_lag_worst_ms_planning"] = httpx.get(
            station.url + "/api/health", timeout=30).json()["loop_lag_ms"]["worst_since_start"]
    finally:
        station.close()
    progress("station under abuse: 50 MB bodies without a token, 1000 half-open connections")
    station = Station({})
    try:
        out["abuse"] = abuse(station.url, 1000, seconds)
    finally:
        station.close()
    # each station's worst since its start (start-up included): the whole bench's worst
    out["loop_lag_worst_ms"] = max(out["loop_lag_worst_ms_websocket"],
                                   out["loop_lag_worst_ms_planning"],
                                   out["abuse"]["loop_lag_worst_ms"])
    return out
