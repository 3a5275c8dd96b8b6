"""An in-memory, simulated-clock link between StationProtocol and BoatProtocol for tests."""

from __future__ import annotations

import random

from usvstation.geo import RampFrame
from usvstation.link import messages as m
from usvstation.link.mission import Mission, mission_from_plan
from usvstation.link.protocol import LinkConfig, StationProtocol
from usvstation.sim.boat import BoatConfig, BoatProtocol
from usvstation.sim.sensors import GpsNoise
from usvstation.sim.vehicle import KinematicVehicle

FRAME = RampFrame(30.5135, 114.4182, 90.0)


def plan_waypoints(n: int = 32, speed: float = 1.5) -> list[dict]:
    """A zig-zag approach to the ramp, n waypoints, position linear in time."""
    wps, t = [], 0.0
    for i in range(n):
        x, y = 90.0 - i * 90.0 / (n - 1), (6.0 if i % 2 else -6.0) * (1 - i / n)
        if wps:
            t += ((x - wps[-1]["x"]) ** 2 + (y - wps[-1]["y"]) ** 2) ** 0.5 / speed
        wps.append({"x": x, "y": y, "t": t, "speed": speed, "heading_deg": 180.0})
    return wps


def make_mission(mission_id: int = 7, n: int = 32) -> Mission:
    return mission_from_plan(plan_waypoints(n), FRAME, mission_id)


class Harness:
    """Station and boat joined by two lossy byte pipes on a shared simulated clock."""

    def __init__(self, *, loss: float = 0.0, seed: int = 1, boat_cfg: BoatConfig | None = None,
                 link_cfg: LinkConfig | None = None) -> None:
        self.t = 0.0
        self.rng = random.Random(seed)
        self.loss = loss
        self.up = True  # False: the radio is off in both directions
        self.vehicle = KinematicVehicle(85.0, 10.0, 3.14159)
        self.boat = BoatProtocol(self.vehicle, FRAME, boat_cfg or BoatConfig(),
                                 gps=GpsNoise(seed=seed), now=0.0)
        self.station = StationProtocol(link_cfg or LinkConfig(), 0.0)
        self.events: list = []
        self.to_boat: list[bytes] = []  # frames sent by the station, as delivered

    def _carry(self, data: bytes) -> bytes:
        if not self.up:
            return b""
        frames = [f for f in data.split(b"\x00") if f]
        return b"".join(b"\x00" + f + b"\x00" for f in frames if self.rng.random() >= self.loss)

    def step(self, dt: float = 0.01) -> None:
        self.t += dt
        self.boat.update(self.t)
        down = self._carry(self.boat.data_to_send())
        self.events += self.station.receive_data(down, self.t) if down else \
            self.station.poll(self.t)
        up = self._carry(self.station.data_to_send())
        if up:
            self.to_boat.append(up)
            self.boat.receive_data(up, self.t)

    def run(self, seconds: float, dt: float = 0.01, until=None) -> bool:
        end = self.t + seconds
        while self.t < end:
            self.step(dt)
            if until is not None and until():
                return True
        return until is None

    def of(self, cls: type) -> list:
        return [e for e in self.events if isinstance(e, cls)]

    def connect(self) -> None:
        assert self.run(2.0, until=lambda: self.station.link_up and self.boat.linked)


def telemetry_count(h: Harness) -> int:
    from usvstation.link.protocol import TelemetryReceived

    return len(h.of(TelemetryReceived))


__all__ = ["FRAME", "Harness", "m", "make_mission", "plan_waypoints", "telemetry_count"]
