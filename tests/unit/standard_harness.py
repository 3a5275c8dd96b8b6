"""StandardProtocol joined to a minimal stock-autopilot stand-in
(sim/standard_vehicle.py) on a simulated clock with seeded frame loss, for the state
machines' unit tests."""

from __future__ import annotations

import random
from typing import Any

from usvstation.link import wire
from usvstation.link.standard import PROFILES, StandardConfig, StandardProtocol
from usvstation.sim.standard_vehicle import StandardVehicle

UNIX0 = 1.7e9


class StandardHarness:
    """StandardProtocol and a StandardVehicle joined by lossy frame pipes, simulated time."""

    def __init__(self, *, profile: str = "ardupilot-rover", loss: float = 0.0, seed: int = 1,
                 key: bytes | None = None, guided: bool = True, baud: int = 57600) -> None:
        p = PROFILES[profile]
        self.t = 0.0
        self.rng = random.Random(seed)
        self.loss = loss
        self.vehicle = StandardVehicle(p, unix0=UNIX0)
        self.station = StandardProtocol(StandardConfig(profile=p, guided=guided, baud=baud),
                                        0.0, key=key, unix_time=UNIX0, session=7)
        self.events: list = []
        self.drop_down: Any = None  # predicate on a vehicle frame (decoded): drop it

    def _carry(self, data: bytes, down: bool = False) -> bytes:
        kept = []
        for f in wire.split_frames(data):
            if self.rng.random() < self.loss:
                continue
            if down and self.drop_down is not None:
                msgs, _ = wire.Codec(99, 1, None).feed(f)
                if msgs and self.drop_down(msgs[0]):
                    continue
            kept.append(f)
        return b"".join(kept)

    def step(self, dt: float = 0.01) -> None:
        self.t += dt
        self.vehicle.poll(self.t)
        self.events += self.station.poll(self.t)
        up = self._carry(self.station.data_to_send())
        if up:
            self.vehicle.receive(up, self.t)
        down = self._carry(self.vehicle.data_to_send(), down=True)
        if down:
            self.events += self.station.receive_data(down, self.t)

    def until(self, cond: Any, limit_s: float = 60.0) -> bool:
        end = self.t + limit_s
        while self.t < end:
            if cond():
                return True
            self.step()
        return bool(cond())

    def of(self, kind: type) -> list:
        return [e for e in self.events if isinstance(e, kind)]
