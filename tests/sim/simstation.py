"""The whole station in one process on a simulated clock, driven through its HTTP API (httpx's
ASGI transport, on the same loop): what an integration test of the live loop needs, with
no real waits (docs/design.md "Clock")."""

from __future__ import annotations

import inspect
import random
from collections.abc import Awaitable, Callable
from pathlib import Path
from typing import Any, TypeVar

import httpx

from usvstation.api.app import create_app
from usvstation.clock import SimClock, run_simulated
from usvstation.config import Settings
from usvstation.scenario import Scenario
from usvstation.station import Station
from usvstation.trial.episode import new_approach

TOKEN = "sim-token-0123456789abcdef"
T = TypeVar("T")


class SimStation:
    """The station, its HTTP client (operator token) and its clock; waits in simulated time."""

    def __init__(self, station: Station, client: httpx.AsyncClient, clock: SimClock) -> None:
        self.station, self.client, self.clock = station, client, clock
        self.events: list[dict[str, Any]] = []  # what /ws/live would push: {type, data}
        self.new_approaches: list[str] = []  # missions (or why not) given at standby: `sail`
        station.hub.observers.append(
            lambda kind, data: self.events.append({"type": kind, "data": data}))

    async def poll(self, fn: Callable[[], Any], timeout: float, what: str,
                   every: float = 0.1) -> Any:
        """The first truthy value of `fn()` (a coroutine function or a plain one), polled
        every `every` s of simulated time; AssertionError after `timeout` simulated s."""
        until = self.clock.now() + timeout
        while self.clock.now() < until:
            value = fn()
            if inspect.isawaitable(value):
                value = await value
            if value:
                return value
            await self.clock.sleep(every)
        raise AssertionError(f"timed out after {timeout} s (simulated) waiting for {what}")

    async def get(self, path: str, **params: Any) -> Any:
        r = await self.client.get(path, params=params or None)
        assert r.status_code == 200, (path, r.status_code, r.text)
        return r.json()

    async def wait(self, path: str, key: str, pending: tuple, timeout: float) -> dict:
        async def settled() -> dict | None:
            body = await self.get(path)
            return body if body[key] not in pending else None

        return await self.poll(settled, timeout, f"{path} to leave {pending}")

    async def wait_plan(self, plan_id: str, timeout: float = 120.0) -> dict:
        return await self.wait(f"/api/plans/{plan_id}", "status", ("queued", "running"),
                               timeout)

    async def wait_link_up(self, timeout: float = 30.0) -> dict:
        async def up() -> dict | None:
            boat = await self.get("/api/boat")
            return boat if boat["link"]["up"] and boat["telemetry"] is not None else None

        return await self.poll(up, timeout, "the boat link")

    async def sail(self, mission_id: str, timeout: float) -> dict:
        """Until the mission flown ends (completed, aborted, gone...): as the mate does, a
        boat that went around and waits at its standby point is given the station's new
        approach (a plan from there against the live world, hot-swapped in:
        trial/episode.py `new_approach`), which is then the mission followed; the boat's
        own (RESUME) only when the station has none. `new_approaches` lists them."""
        seen: set[tuple[str, str]] = set()
        flying = mission_id

        async def ended() -> dict | None:
            nonlocal flying
            boat = await self.get("/api/boat")
            standby = {(s["time"], s["text"]) for s in boat["status"]
                       if "at standby" in s["text"]}
            if boat["boat"] and boat["boat"]["state"] == "GO_AROUND" and standby - seen:
                seen.update(standby)
                ok, new = await new_approach(self.client, self.clock)
                self.new_approaches.append(new)
                if ok:
                    flying = new
                else:
                    r = await self.client.post("/api/boat/command", json={"command": "resume"})
                    assert r.status_code == 200, r.text
            m = await self.get(f"/api/missions/{flying}")
            return m if m["state"] not in ("uploading", "verified", "active") else None

        return await self.poll(ended, timeout, f"mission {mission_id} to end", every=0.5)

    async def fly(self, plan_id: str) -> dict:
        """Upload a done plan, wait until verified and START it; the mission."""
        r = await self.client.post("/api/missions", json={"plan_id": plan_id})
        assert r.status_code == 202, r.text
        mission = await self.wait(f"/api/missions/{r.json()['id']}", "state", ("uploading",),
                                  30)
        assert mission["state"] == "verified", mission
        start = await self.client.post("/api/boat/command", json={
            "command": "start", "mission_id": mission["id"]})
        assert start.status_code == 200, start.text
        return mission


def run_station(data_dir: Path, body: Callable[[SimStation], Awaitable[T]], *,
                scenario: Scenario | None = None, **settings: Any) -> T:
    """Start a station in simulated time (settings: Settings fields), run `body`, stop it."""

    async def main(clock: SimClock) -> T:
        station = Station(Settings(data_dir=data_dir, token=TOKEN, link="sim", nmea=[],
                                   **settings), clock, in_process=True, scenario=scenario,
                          entropy=random.Random(0))
        await station.start()
        try:
            transport = httpx.ASGITransport(app=create_app(station))
            async with httpx.AsyncClient(transport=transport, base_url="http://127.0.0.1:8000",
                                         headers={"Authorization": f"Bearer {TOKEN}"},
                                         timeout=None) as client:
                sim = SimStation(station, client, clock)
                await sim.wait_link_up()
                return await body(sim)
        finally:
            await station.stop()

    return run_simulated(main)
