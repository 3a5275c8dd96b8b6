"""An in-memory, simulated-clock link between StationProtocol and BoatProtocol for tests.

Frames cross whole or not at all (per-frame loss, seeded); `echo` loops the boat's own
frames back to it; `tap` records what the station sent, for replay attacks.
"""

from __future__ import annotations

import math
import random

from usvstation.geo import RampFrame
from usvstation.link import wire
from usvstation.link.mission import Mission, mission_from_plan
from usvstation.link.protocol import LinkConfig, StationProtocol
from usvstation.sim.boat import BoatConfig, BoatProtocol, NonVolatile
from usvstation.sim.sensors import GpsNoise
from usvstation.sim.vehicle import KinematicVehicle

FRAME = RampFrame(30.5135, 114.4182, 90.0)
KEY = bytes(range(1, 33))
UNIX0 = 1.7e9  # wall clock at sim time 0


def plan_waypoints(n: int = 32, speed: float = 1.5, x0: float = 85.0, y0: float = 10.0
                   ) -> list[dict]:
    """A zig-zag approach to the ramp from (x0, y0), n waypoints, position linear in time."""
    wps, t = [], 0.0
    for i in range(n):
        f = i / (n - 1)
        x = x0 * (1 - f)
        y = y0 * (1 - f) + (0 if i in (0, n - 1) else (3.0 if i % 2 else -3.0))
        if wps:
            t += math.hypot(x - wps[-1]["x"], y - wps[-1]["y"]) / speed
        wps.append({"x": x, "y": y, "t": t, "speed": speed, "heading_deg": 180.0})
    return wps


def make_mission(mission_id: int = 7, n: int = 32, **kw) -> Mission:
    return mission_from_plan(plan_waypoints(n, **kw), FRAME, mission_id)


class Harness:
    """Station and boat joined by two lossy byte pipes on a shared simulated clock."""

    def __init__(self, *, loss: float = 0.0, up_loss: float | None = None, seed: int = 1,
                 boat_cfg: BoatConfig | None = None, link_cfg: LinkConfig | None = None,
                 key: bytes | None = KEY, station_key: bytes | None = None,
                 x: float = 85.0, y: float = 10.0) -> None:
        self.t = 0.0
        self.rng = random.Random(seed)
        self.seed = seed
        self.down_loss = loss
        self.up_loss = loss if up_loss is None else up_loss
        self.up = True  # False: the radio is off in both directions
        self.station_silent = False  # True: the station's transmitter is off
        self.echo = False  # the boat hears its own frames
        self.key = key
        self.boat_cfg = boat_cfg or BoatConfig()
        self.link_cfg = link_cfg or LinkConfig()
        self.nv = NonVolatile()
        self.boat = self._new_boat(x, y)
        self.station = StationProtocol(self.link_cfg, 0.0,
                                       key=key if station_key is None else station_key,
                                       unix_time=UNIX0, session=1000 + seed)
        self.events: list = []
        self.tap: list[tuple[float, bytes]] = []  # station frames as sent, with time
        self.extra_to_boat: list[bytes] = []  # injected into the boat's receiver
        self.extra_to_station: list[bytes] = []

    def _new_boat(self, x: float, y: float, boot_id: int = 1) -> BoatProtocol:
        vehicle = KinematicVehicle(x, y, math.pi)
        return BoatProtocol(vehicle, FRAME, self.boat_cfg, key=self.key, nv=self.nv,
                            gps=GpsNoise(seed=self.seed, bias_std_m=0, white_std_m=0),
                            now=self.t, unix_time=UNIX0 + self.t, boot_id=boot_id)

    def reboot_boat(self) -> None:
        s = self.boat.vehicle.state
        self.boat = self._new_boat(s.x, s.y, boot_id=self.boat.boot_id + 1)

    def restart_station(self, session: int) -> None:
        self.station = StationProtocol(self.link_cfg, self.t, key=self.station.key,
                                       unix_time=UNIX0 + self.t, session=session)

    def _carry(self, data: bytes, loss: float) -> bytes:
        if not self.up or not data:
            return b""
        return b"".join(f for f in wire.split_frames(data) if self.rng.random() >= loss)

    def step(self, dt: float = 0.01) -> None:
        self.t += dt
        self.boat.update(self.t)
        raw_down = self.boat.data_to_send(self.t)
        down = self._carry(raw_down, self.down_loss)
        down += b"".join(self.extra_to_station)
        self.extra_to_station.clear()
        self.events += self.station.receive_data(down, self.t) if down else \
            self.station.poll(self.t)
        sent = self.station.data_to_send()
        if sent and not self.station_silent:
            self.tap.append((self.t, sent))
        up = b"" if self.station_silent else self._carry(sent, self.up_loss)
        if self.echo and self.up:
            up += raw_down
        up += b"".join(self.extra_to_boat)
        self.extra_to_boat.clear()
        if up:
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
        assert self.run(3.0, until=lambda: self.station.link_up and self.boat.linked
                        and self.station.report is not None)
