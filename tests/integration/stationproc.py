"""`usv-station serve` as a real subprocess on ephemeral ports, for end-to-end tests."""

from __future__ import annotations

import signal
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import httpx

from usvstation.serveproc import ServeProcess

TOKEN = "e2e-token-0123456789abcdef"


class StationProcess(ServeProcess):
    """A running station with an authenticated HTTP client and polling helpers."""

    def __init__(self, data_dir: Path, *args: str, token: str = TOKEN,
                 env: dict[str, str] | None = None) -> None:
        super().__init__(data_dir, *args, token=token, env=env)
        self.client = httpx.Client(base_url=self.url, timeout=30,
                                   headers={"Authorization": f"Bearer {token}"})

    def stop(self, sig: int = signal.SIGTERM, timeout: float = 10.0) -> float:
        client = getattr(self, "client", None)  # None when start-up failed before it was made
        if client is not None:
            client.close()
        return super().stop(sig, timeout)

    def wait_plan(self, plan_id: str, timeout: float = 30.0) -> dict:
        return self.wait(f"/api/plans/{plan_id}", "status", ("queued", "running"), timeout)

    def wait_link_up(self, timeout: float = 60.0, first_frame: bool = True) -> dict:
        """GET /api/boat once the boat's first report put the link up and (`first_frame`)
        its first telemetry frame arrived (startup prints the URLs before the simulated
        boat's first HEARTBEAT; the first position follows on the boat's telemetry grid)."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            boat = self.client.get("/api/boat").json()
            flowing = boat["link"]["frames"] > 0 or not first_frame
            if boat["link"]["up"] and boat["boat"] is not None and flowing:
                return boat
            time.sleep(0.05)
        self.stop()  # the fixture that called this never reaches its own stop()
        raise AssertionError(f"the boat link is not up after {timeout} s: {boat['link']}")

    def wait(self, path: str, key: str, pending: tuple, timeout: float) -> dict:
        """GET `path` until its `key` is no longer one of `pending`."""
        return self.wait_until(path, lambda body: body[key] not in pending, timeout,
                               f"{path} {key} other than {pending}")

    def wait_until(self, path: str, cond: Callable[[Any], bool], timeout: float,
                   what: str) -> Any:
        """GET `path` until cond(body) holds; the body. AssertionError after `timeout` s."""
        deadline = time.monotonic() + timeout
        while True:
            body = self.client.get(path).json()
            if cond(body):
                return body
            assert time.monotonic() < deadline, f"{what} not seen in {timeout} s: {body}"
            time.sleep(0.05)
