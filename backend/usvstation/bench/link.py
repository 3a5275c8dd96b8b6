"""`usv-station bench link`: mission upload over a real pty at 57600 baud with injected
faults, sustained telemetry rate, and the Python codec's telemetry decode rate.

Upload runs: the station (BoatLink over pyserial-asyncio on the pty's slave device) and
the simulated boat (on the pty master) each write through a FaultInjectingStream that
paces the line at 57600 baud (10 bits a byte), drops whole frames with probability
`loss` and flips bits at `ber`. `bound_s` is the loss-free upload's bytes on the wire in
both directions x 10 / baud; `time_s` is from the upload call to its result.
"""

from __future__ import annotations

import asyncio
import platform
import time
from collections.abc import Callable
from typing import Any

from usvstation.geo import RampFrame
from usvstation.link import messages as m
from usvstation.link.codec import Encoder, FrameDecoder
from usvstation.link.mission import Mission, mission_from_plan
from usvstation.link.protocol import TelemetryReceived
from usvstation.link.station import BoatLink
from usvstation.link.transport import FaultInjectingStream, PtyPair, SerialStream
from usvstation.sim.boat import BoatConfig
from usvstation.sim.runner import SimulatedBoat, make_boat

BAUD = 57600
FRAME = RampFrame(30.5135, 114.4182, 90.0)  # case1's origin


def bench_mission(n: int = 32, mission_id: int = 1) -> Mission:
    """A 32-waypoint zig-zag approach to the ramp (ramp frame, position linear in time)."""
    wps: list[dict[str, float]] = []
    t = 0.0
    for i in range(n):
        x, y = 90.0 - i * 90.0 / (n - 1), (8.0 if i % 2 else -8.0) * (1 - i / n)
        if wps:
            t += ((x - wps[-1]["x"]) ** 2 + (y - wps[-1]["y"]) ** 2) ** 0.5 / 1.5
        wps.append({"x": x, "y": y, "t": t, "speed": 1.5, "heading_deg": 180.0})
    return mission_from_plan(wps, FRAME, mission_id)


class _Rig:
    """Boat and station on one pty pair, each writing through a fault injector."""

    def __init__(self, loss: float, ber: float, seed: int, telemetry_hz: float = 5.0) -> None:
        self.loss, self.ber, self.seed = loss, ber, seed
        self.pair = PtyPair()
        self.boat = make_boat(FRAME, config=BoatConfig(telemetry_hz=telemetry_hz), seed=seed)
        self.station_faults: FaultInjectingStream | None = None

    async def __aenter__(self) -> _Rig:
        self.boat_faults = FaultInjectingStream(self.pair.master_stream(), loss=self.loss,
                                                ber=self.ber, baud=BAUD, seed=self.seed)
        self.stop = asyncio.Event()
        self.boat_task = asyncio.get_running_loop().create_task(
            SimulatedBoat(self.boat).run(self.boat_faults, self.stop))

        async def factory() -> FaultInjectingStream:
            inner = await SerialStream.open(self.pair.slave_path, BAUD)
            self.station_faults = FaultInjectingStream(inner, loss=self.loss, ber=self.ber,
                                                       baud=BAUD, seed=self.seed + 1000)
            return self.station_faults

        self.link = BoatLink(stream_factory=factory)
        await self.link.start()
        if not await self.link.wait_link_up(20.0):
            raise RuntimeError("the link did not come up")
        return self

    def wire_bytes(self) -> int:
        return self.boat_faults.bytes_on_wire + (self.station_faults.bytes_on_wire
                                                 if self.station_faults else 0)

    async def __aexit__(self, *exc: object) -> None:
        await self.link.close()
        self.stop.set()
        await self.boat_task
        await self.boat_faults.close()
        self.pair.close()


async def _upload_run(loss: float, ber: float, seed: int) -> dict[str, Any]:
    mission = bench_mission()
    async with _Rig(loss, ber, seed) as rig:
        await asyncio.sleep(0.3)  # let the handshake's frames drain from the queues
        b0 = rig.wire_bytes()
        t0 = time.perf_counter()
        result = await rig.link.upload_mission(mission)
        elapsed = time.perf_counter() - t0
        await asyncio.sleep(0.05)  # the END ACK's last bytes
        wire = rig.wire_bytes() - b0
        active = rig.boat.active
        return {
            "loss": loss, "ber": ber, "seed": seed, "time_s": round(elapsed, 4),
            "completed": result.ok, "reason": result.reason,
            "identical": bool(active is not None and active.items == mission.items),
            "partial_activated": bool(active is not None and active.items != mission.items),
            "retransmissions": result.retransmissions, "wire_bytes": wire,
        }


async def _telemetry_rate(hz: float, seconds: float) -> float:
    async with _Rig(0.0, 0.0, 0, telemetry_hz=hz) as rig:
        count = 0

        def on_event(ev: Any) -> None:
            nonlocal count
            if isinstance(ev, TelemetryReceived):
                count += 1

        await asyncio.sleep(0.5)
        rig.link.add_listener(on_event)
        t0 = time.perf_counter()
        await asyncio.sleep(seconds)
        return count / (time.perf_counter() - t0)


def decode_rate(frames: int = 100_000, repeats: int = 3) -> float:
    """Telemetry frames per second through FrameDecoder.feed (4096-byte chunks), best of N."""
    enc = Encoder()
    base = m.Telemetry(123456, 305135000, 1144182000, 3, 12, 90, 150, 18000, 17950, -120, 500,
                       480, 12100, 5, -35, 2, 1, 0)
    data = b"".join(enc.encode(base._replace(time_ms=i, lat_e7=305135000 + i))
                    for i in range(frames))
    best = 0.0
    for _ in range(repeats):
        dec = FrameDecoder()
        t0 = time.perf_counter()
        n = 0
        for i in range(0, len(data), 4096):
            n += len(dec.feed(data[i : i + 4096]))
        best = max(best, n / (time.perf_counter() - t0))
        assert n == frames
    return best


async def _run(quick: bool, progress: Callable[[str], None]) -> dict[str, Any]:
    seeds = [1] if quick else [1, 2, 3, 4, 5]
    runs = []
    clean = [await _upload_run(0.0, 0.0, s) for s in seeds]
    runs += clean
    progress(f"loss-free: {[r['time_s'] for r in clean]}")
    bound_bytes = max(r["wire_bytes"] for r in clean)
    bound_s = bound_bytes * 10 / BAUD
    for loss in (0.0, 0.1, 0.2):
        batch = [await _upload_run(loss, 1e-4, s) for s in seeds]
        progress(f"loss {loss} + ber 1e-4: {[(r['time_s'], r['completed']) for r in batch]}")
        runs += batch
    for r in runs:
        r["bound_s"] = round(bound_s, 4)
        r["ratio"] = round(r["time_s"] / bound_s, 3)
    tel_seconds = 2.0 if quick else 5.0
    tel_50 = await _telemetry_rate(50.0, tel_seconds)
    tel_5 = await _telemetry_rate(5.0, tel_seconds)
    progress(f"telemetry: {tel_50:.1f} Hz at 50 configured, {tel_5:.2f} Hz at 5")
    return {
        "bench": "link", "baud": BAUD, "waypoints": 32,
        "machine": f"{platform.machine()} {platform.system()} {platform.release()}, "
                   f"python {platform.python_version()}",
        "bound_bytes": bound_bytes,
        "upload": runs,
        "telemetry_hz": round(tel_50, 2), "telemetry_hz_configured": 50,
        "telemetry_hz_default": round(tel_5, 2),
        "decode_frames_per_s": round(decode_rate(30_000 if quick else 100_000)),
    }


def run_link_bench(quick: bool = False,
                   progress: Callable[[str], None] = lambda _: None) -> dict[str, Any]:
    return asyncio.run(_run(quick, progress))
