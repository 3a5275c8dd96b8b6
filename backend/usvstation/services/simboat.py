"""The simulated boat's lifetime inside the station.

`EmbeddedSim` (`usv-station serve`): a thread with its own event loop, on the wall clock,
serving BoatProtocol on the master side of a pty; the station opens the slave.
`InProcessSim` (simulated time): the same boat on the station's own loop and clock, over an
in-memory pipe behind a radio model (FaultInjectingStream: airtime at the link's baud, loss,
silence)."""

from __future__ import annotations

import asyncio
import contextlib
import threading
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from usvstation.clock import REAL_CLOCK, Clock
from usvstation.config import Settings
from usvstation.geo import RampFrame
from usvstation.link.transport import (
    ByteStream,
    FaultInjectingStream,
    MemoryPipe,
    PtyPair,
)
from usvstation.scenario import Scenario
from usvstation.sim.boat import BoatConfig, BoatProtocol, NonVolatile
from usvstation.sim.runner import (
    SimulatedBoat,
    default_nv_path,
    load_nv,
    make_boat,
    make_vehicle,
)
from usvstation.sim.vehicle import Vehicle


@dataclass
class EmbeddedSim:
    """The simulated boat on the far end of a pty, paired with this station and signing
    with the station's key (None only with --insecure-link), its signing floor kept beside
    the key like any boat's (sim/runner.py `default_nv_path`): a session recorded before a
    restart of `serve` is refused after it."""

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

    @property
    def nv_path(self) -> Path | None:
        """The boat's signing floor file (None for an unsigned link)."""
        if self.key is None:
            return None
        s = self.settings
        return default_nv_path(s.link_key or s.data_dir / "link.key", s.boat_id)

    async def _main(self) -> None:
        self._loop, self._stop = asyncio.get_running_loop(), asyncio.Event()
        try:
            nv_path = self.nv_path
            nv = load_nv(nv_path) if nv_path is not None else None
            boat = build_boat(self.scenario, self.settings, self.key, REAL_CLOCK, nv=nv)
        finally:
            self._ready.set()
        await SimulatedBoat(boat, nv_path=nv_path).run(self.pair.master_stream(), self._stop)


def build_boat(scenario: Scenario, settings: Settings, key: bytes | None, clock: Clock,
               vehicle: Vehicle | None = None, boot_id: int | None = None,
               nv: NonVolatile | None = None) -> BoatProtocol:
    """The simulated boat of the station's settings at the scenario's start, on `clock`;
    `vehicle` default: the dynamic Otter of sim/runner.py `make_vehicle`; `boot_id`
    default: drawn at random by the boat."""
    o = scenario.origin
    assert o is not None, "the station gives the working scenario an origin first"
    frame = RampFrame(o.lat, o.lon, o.ramp_bearing_deg)
    s = settings
    config = BoatConfig(boat_id=s.boat_id, station_id=s.station_id,
                        telemetry_hz=s.telemetry_hz, failsafe_timeout_s=s.heartbeat_timeout_s,
                        sim_speed=s.sim_speed, baud=s.baud)
    return make_boat(frame, config=config, key=key, gnss_error=s.sim_gnss_error,
                     vehicle=vehicle or make_vehicle(
                         "dynamic", scenario, sensors="rtk" if s.sim_gnss_error else "exact"),
                     x=scenario.start.x, y=scenario.start.y, clock=clock, boot_id=boot_id,
                     nv=nv)


class InProcessSim:
    """The simulated boat on the station's loop and clock (simulated time), joined to the
    station by a MemoryPipe; `radio` is the boat's transmitter (turn it off with
    `radio.enabled = False` for a link-loss burst), `uplink` the station's."""

    def __init__(self, scenario: Scenario, settings: Settings, key: bytes | None, clock: Clock,
                 vehicle: Callable[[Scenario], Vehicle] | None = None,
                 boot_id: int | None = None) -> None:
        self.clock = clock
        self.boat = build_boat(scenario, settings, key, clock,
                               vehicle(scenario) if vehicle is not None else None, boot_id)
        self.pipe = MemoryPipe()
        self._stop = asyncio.Event()
        self._task: asyncio.Task | None = None
        self.radio: FaultInjectingStream | None = None
        self.uplink: FaultInjectingStream | None = None
        self._baud = settings.baud

    def start(self) -> None:
        self.radio = FaultInjectingStream(self.pipe.boat, baud=self._baud, clock=self.clock)
        self.uplink = FaultInjectingStream(self.pipe.station, baud=self._baud, clock=self.clock)
        self._task = asyncio.get_running_loop().create_task(
            SimulatedBoat(self.boat, clock=self.clock).run(self.radio, self._stop),
            name="simulated-boat")

    async def station_stream(self) -> ByteStream:
        """The station's end of the pipe (BoatLink's stream factory)."""
        assert self.uplink is not None, "start() first"
        return self.uplink

    async def stop(self) -> None:
        self._stop.set()
        if self._task is not None:
            with contextlib.suppress(asyncio.CancelledError, Exception):
                await self._task
