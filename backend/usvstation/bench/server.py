"""`usv-station bench server`: live fan-out latency and API latency under planning load.

Runs a real `usv-station serve` subprocess with the simulated boat on loopback:

- `websocket`: 20 clients on /ws/live while the boat sends telemetry at 50 Hz;
  latency = a client's receive time minus the row's ingest time (`time`,
  stamped by the station when the frame arrived; same clock, 1 ms steps).
- `health_under_planning`: GET /api/health every 20 ms while the station runs
  4 plans at once (4 plan workers, kept busy with random 400 m transits).
"""

from __future__ import annotations

import asyncio
import datetime as dt
import statistics
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import httpx
import numpy as np

from usvstation.bench.planner import machine_info
from usvstation.bench.scenarios import random_transit
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
    stop = time.monotonic() + seconds

    async def client(i: int) -> None:
        async with connect(url.replace("http", "ws") + "/ws/live", max_size=None,
                           additional_headers={"Authorization": f"Bearer {TOKEN}"}) as ws:
            while time.monotonic() < stop:
                try:
                    text = await asyncio.wait_for(ws.recv(), timeout=1.0)
                except TimeoutError:
                    continue
                now = time.time()
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
    stop = time.monotonic() + seconds
    async with httpx.AsyncClient(base_url=url, timeout=30, headers=headers) as c:

        async def planner(k: int) -> int:
            done = 0
            while time.monotonic() < stop:
                job = (await c.post("/api/plans", headers=headers,
                                    json={"scenario": scenarios[(k + done) % 8]})).json()
                while (await c.get(f"/api/plans/{job['id']}")).json()["status"] in (
                        "queued", "running"):
                    await asyncio.sleep(0.02)
                done += 1
            return done

        async def prober() -> None:
            while time.monotonic() < stop:
                t0 = time.perf_counter()
                r = await c.get("/api/health")
                latencies.append(1000.0 * (time.perf_counter() - t0))
                running_seen.append(r.json()["plans"]["running"])
                await asyncio.sleep(0.02)

        results = await asyncio.gather(prober(), *(planner(k) for k in range(plans_at_once)))
    return {"plans_at_once": plans_at_once, "seconds": seconds,
            "plans_completed": sum(results[1:]),
            "running_median": statistics.median(running_seen) if running_seen else 0,
            **_percentiles(latencies)}


def run_server_bench(quick: bool = False,
                     progress: Callable[[str], None] = lambda _m: None) -> dict[str, Any]:
    seconds = 5.0 if quick else 30.0
    out: dict[str, Any] = {"command": "usv-station bench server --json" +
                           (" --quick" if quick else ""), "machine": machine_info()}
    progress("station with telemetry at 50 Hz, 20 websocket clients")
    station = Station({"USV_STATION_TELEMETRY_HZ": "50"})
    try:
        time.sleep(2.0)  # link up, telemetry flowing
        out["websocket"] = asyncio.run(websocket_latency(station.url, 20, seconds))
    finally:
        station.close()
    progress("station with 4 plan workers, health probed while 4 plans run")
    station = Station({"USV_STATION_PLAN_WORKERS": "4"})
    try:
        out["health_under_planning"] = asyncio.run(health_under_planning(station.url, 4,
                                                                         seconds))
    finally:
        station.close()
    return out
