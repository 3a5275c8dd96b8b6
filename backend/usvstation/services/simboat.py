"""The simulated boat's lifetime inside `usv-station serve`: a thread with its own event
loop serving BoatProtocol on the master side of a pty; the station opens the slave."""

from __future__ import annotations

import asyncio
import contextlib
import threading
from dataclasses import dataclass

from usvstation.config import Settings
from usvstation.geo import RampFrame
from usvstation.link.transport import PtyPair
from usvstation.scenario import Scenario


@dataclass
class EmbeddedSim:
    """The simulated boat on the far end of a pty, paired with this station and signing
    with the station's key (None only with --insecure-link)."""

    scenario: Scenario
    settings: Settings
    key: bytes | None

    def __post_init__(self) -> None:
        self.pair = PtyPair()
        self.device = self.pair.slave_path
        self._loop: asyncio.AbstractEventLoop | None = None
        self._stop: asyncio.Event | None = None
        self._ready = threading.Event()
        self._thread = threading.Thread(target=self._run, name="simulated-boat", daemon=True)

    def start(self) -> None:
        self._thread.start()
        self._ready.wait(10)

    def stop(self) -> None:
        if self._loop is not None and self._stop is not None:
            with contextlib.suppress(RuntimeError):
                self._loop.call_soon_threadsafe(self._stop.set)
        self._thread.join(3)
        self.pair.close()

    def _run(self) -> None:
        asyncio.run(self._main())

    async def _main(self) -> None:
        from usvstation.sim.boat import BoatConfig
        from usvstation.sim.runner import SimulatedBoat, make_boat, make_vehicle

        self._loop, self._stop = asyncio.get_running_loop(), asyncio.Event()
        o = self.scenario.origin
        frame = RampFrame(o.lat, o.lon, o.ramp_bearing_deg)
        s = self.settings
        config = BoatConfig(boat_id=s.boat_id, station_id=s.station_id,
                            telemetry_hz=s.telemetry_hz, failsafe_timeout_s=s.heartbeat_timeout_s,
                            sim_speed=s.sim_speed, baud=s.baud)
        boat = make_boat(frame, config=config, key=self.key, gnss_error=s.sim_gnss_error,
                         vehicle=make_vehicle("dynamic", self.scenario, sensors="rtk"
                                              if s.sim_gnss_error else "exact"),
                         x=self.scenario.start.x, y=self.scenario.start.y)
        self._ready.set()
        await SimulatedBoat(boat).run(self.pair.master_stream(), self._stop)
