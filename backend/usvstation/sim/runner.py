"""Run the simulated boat (BoatProtocol + a Vehicle) on a byte stream: `usv-station sim`."""

from __future__ import annotations

import asyncio
import contextlib
import json
import math
import os
from collections.abc import Awaitable, Callable
from dataclasses import dataclass
from pathlib import Path

from usvstation.clock import REAL_CLOCK, Clock
from usvstation.dynamics.params import HullMismatch
from usvstation.geo import RampFrame
from usvstation.link.transport import ByteStream, open_stream
from usvstation.scenario import Scenario
from usvstation.sim.boat import BoatConfig, BoatProtocol, NonVolatile
from usvstation.sim.sensors import GpsNoise, SensorProfile
from usvstation.sim.vehicle import KinematicVehicle, Vehicle

VEHICLES = ("dynamic", "kinematic")


def make_vehicle(kind: str, scenario: Scenario, sea_state: int = 0,
                 guidance: str = "avlos_comp", controller: str = "pid", *,
                 sensors: str | SensorProfile = "rtk", hull: HullMismatch | None = None,
                 seed: int = 0) -> Vehicle:
    """The simulated vehicle at the scenario's start pose.

    'dynamic' (default): the 3-DOF Otter with `guidance` (compensated AV-LOS
    by default) and `controller` (the PID autopilot by default) in the
    scenario's current and wind, plus waves of `sea_state` (0: none); it steers on
    `sensors` (a sim.sensors profile or its name: exact, rtk, gnss, rtk-moving-base)
    drawn from `seed`, and its real hull differs from its controllers' model by `hull`;
    on a recovery it flies the final approach with the scenario vessel's gates and goes
    around when one is missed, and every path it makes up itself (the drift-aware
    approach, the escape route) is checked against the scenario's obstacles first.
    'kinematic': follows the mission exactly (for protocol tests).
    """
    start = scenario.start
    heading = math.radians(start.heading_deg)
    if kind == "kinematic":
        return KinematicVehicle(start.x, start.y, heading)
    if kind != "dynamic":
        raise ValueError(f"vehicle: unknown kind {kind!r}; available: {', '.join(VEHICLES)}")
    from usvstation.dynamics import Environment, WaveField
    from usvstation.sim.dynamic import DynamicVehicle

    env = scenario.environment
    waves = WaveField.from_sea_state(sea_state, math.radians(env.wind_dir_deg)) \
        if sea_state > 0 else None
    from usvstation.guidance.approach import ArrivalLimits, obstacle_check

    recovery = scenario.kind == "recovery"
    half = 0.5 * max(scenario.vessel.length, 2.0)  # the Otter's 2 m hull at least
    return DynamicVehicle(start.x, start.y, heading, speed=start.speed,
                          env=Environment.from_scenario(env, waves=waves),
                          accel=scenario.vessel.accel_max, guidance=guidance,
                          controller=controller, sensors=sensors, hull=hull, seed=seed,
                          arrival=ArrivalLimits.from_vessel(scenario.vessel) if recovery
                          else None, path_check=obstacle_check(scenario.obstacles, half))


@dataclass
class SimulatedBoat:
    """The boat protocol engine on the event loop, fed from a stream and its clock."""

    boat: BoatProtocol
    log: Callable[[str], None] | None = None
    nv_path: Path | None = None  # the boat's "flash": its NonVolatile, written on change
    clock: Clock = REAL_CLOCK

    async def run(self, stream: ByteStream, stop: asyncio.Event | None = None) -> str:
        """Serve until the stream closes (returns why) or `stop` is set. With `nv_path` the
        floor in it is marked inexact at once (a crash from now on leaves the 2 s margin),
        kept up to date while running and written exact when the run ends cleanly."""
        nv = self.boat.nv
        self._saved_floor = nv.sign_floor
        if nv.exact:  # the boot used it; from now on only a clean end makes it exact again
            nv.exact = False
            if self.nv_path is not None:
                save_nv(self.nv_path, nv)
        stop = stop or asyncio.Event()
        reader = asyncio.get_running_loop().create_task(self._read(stream))
        try:
            while not reader.done() and not stop.is_set():
                self.boat.update(self.clock.now())
                await self._flush(stream)
                await self.clock.sleep(
                    min(max(self.boat.next_deadline() - self.clock.now(), 0.0005), 0.02))
        finally:
            reader.cancel()
            with contextlib.suppress(asyncio.CancelledError, Exception):
                await reader
            nv.sign_floor = max(nv.sign_floor, self.boat.newest_station_timestamp())
            if self.nv_path is not None and nv.sign_floor > 0:
                self._saved_floor = nv.sign_floor
                save_nv(self.nv_path, NonVolatile(nv.sign_floor, exact=True))
        return "stopped" if stop.is_set() else "stream closed"

    async def _read(self, stream: ByteStream) -> None:
        while True:
            try:
                data = await stream.read()
            except (ConnectionError, OSError):
                return
            if not data:
                return
            self.boat.receive_data(data, self.clock.now())
            await self._flush(stream)

    async def _flush(self, stream: ByteStream) -> None:
        if self.nv_path is not None and self.boat.nv.sign_floor != self._saved_floor:
            self._saved_floor = self.boat.nv.sign_floor
            save_nv(self.nv_path, self.boat.nv)
        if self.log is not None:
            for line in self.boat.log:
                self.log(line)
        self.boat.log.clear()
        data = self.boat.data_to_send(self.clock.now())
        if data:
            with contextlib.suppress(ConnectionError, OSError):
                await stream.write(data)


def default_nv_path(key_path: Path, boat_id: int) -> Path:
    """Where a boat keeps its signing floor by default: beside its key, one file per boat
    id (`link.key` -> `link.key.boat1.floor`); the C host boat uses the same name."""
    return key_path.with_name(f"{key_path.name}.boat{boat_id}.floor")


def load_nv(path: Path) -> NonVolatile:
    """The boat's non-volatile memory from its file (missing: a factory-new boat): the C
    boat's line `sign_floor N` (with ` exact` after a clean shutdown), or the JSON object
    earlier versions wrote."""
    try:
        text = path.read_text(encoding="utf-8").strip()
    except FileNotFoundError:
        return NonVolatile()
    except OSError as exc:
        raise ValueError(f"nv file {path}: {exc}") from None
    try:
        if text.startswith("{"):
            data = json.loads(text)
            return NonVolatile(sign_floor=int(data.get("sign_floor", 0)))
        words = text.split()
        if len(words) in (2, 3) and words[0] == "sign_floor":
            return NonVolatile(int(words[1]), exact=words[2:] == ["exact"])
    except (ValueError, AttributeError) as exc:
        raise ValueError(f"nv file {path}: {exc}") from None
    raise ValueError(f"nv file {path}: not a signing floor ('sign_floor N')")


def save_nv(path: Path, nv: NonVolatile) -> None:
    """Write the floor atomically (a crash leaves the old one, never a torn one)."""
    tmp = path.with_suffix(path.suffix + ".tmp")
    tmp.write_text(f"sign_floor {nv.sign_floor}{' exact' if nv.exact else ''}\n",
                   encoding="utf-8")
    os.replace(tmp, path)


def make_boat(frame: RampFrame, *, x: float = 85.0, y: float = 10.0, heading_deg: float = 180.0,
              config: BoatConfig | None = None, seed: int = 0, key: bytes | None = None,
              vehicle: Vehicle | None = None, nv: NonVolatile | None = None,
              gnss_error: bool = True, clock: Clock = REAL_CLOCK,
              boot_id: int | None = None) -> BoatProtocol:
    """A simulated boat at ramp-frame (x, y) with a KinematicVehicle unless one is given;
    signing with `key` (None: unsigned, --insecure-link), its time from `clock`;
    `gnss_error` False: a KinematicVehicle's fixes report its exact position (a vehicle
    with sensors, make_vehicle's 'dynamic', reports what its sensor profile measures)."""
    vehicle = vehicle or KinematicVehicle(x, y, math.radians(heading_deg))
    gps = GpsNoise(seed=seed) if gnss_error else GpsNoise(bias_std_m=0.0, white_std_m=0.0)
    return BoatProtocol(vehicle, frame, config or BoatConfig(), key=key, nv=nv,
                        gps=gps, now=clock.now(), unix_time=clock.unix(), boot_id=boot_id)


async def serve_on_url(boat: BoatProtocol, url: str, baud: int, *,
                       log: Callable[[str], None] = print, reconnect_s: float = 1.0,
                       stop: asyncio.Event | None = None, nv_path: Path | None = None,
                       opener: Callable[[str, int], Awaitable[ByteStream]] = open_stream,
                       clock: Clock = REAL_CLOCK) -> None:
    """Serve on a serial device or URL, reopening it when it closes or fails to open."""
    stop = stop or asyncio.Event()
    sim = SimulatedBoat(boat, log, nv_path, clock)
    while not stop.is_set():
        try:
            stream = await opener(url, baud)
        except (OSError, ConnectionError) as exc:
            log(f"cannot open {url}: {exc}; retrying")
            await clock.sleep(reconnect_s)
            continue
        reason = await sim.run(stream, stop)
        await stream.close()
        if not stop.is_set():
            log(f"{url}: {reason}; reopening")
            await clock.sleep(reconnect_s)
