"""`usv-station bench link`: usv-link 2 (signed MAVLink 2) figures.

- upload: a signed 32-waypoint mission over a real pty, the station (BoatLink on
  pyserial-asyncio, on the slave device) and the simulated boat (on the master) each
  writing through a FaultInjectingStream that paces the line at the baud (10 bits a
  byte) and drops whole frames with probability `loss`. `bound_s` is the line-rate
  bound: the upload's own frames (BEGIN, items, END and their ACKs, signed) both ways,
  x 10 / baud (the definition of issue 4's bench); `one_way_bound_s` the stricter
  full-duplex bound, the larger direction alone; `time_s` is from the upload call to its
  result; `identical`: the boat holds exactly the mission sent (read from the boat).
- failsafe: StationProtocol and BoatProtocol on a simulated clock, the boat RUNNING a
  long mission for 10 minutes of simulated time with `loss` of the station-to-boat
  frames; counts the boat's failsafes (any is spurious: the station never fell silent).
- decode: GLOBAL_POSITION_INT frames (signed) per second through the Python codec.
- standard_upload: the same 32 waypoints to a stock autopilot through the standard mission
  protocol (link/standard.py against sim/standard_vehicle.py), in simulated time on a
  modelled serial line (each direction paced at the baud, frames whole or lost, the
  vehicle's 1 Hz heartbeat and 5 Hz position sharing it). `time_s`: MISSION_COUNT to the
  vehicle's ACK; `verified_s`: to the end of the read-back the station does before it calls
  a mission verified; `bound_s`: the upload's own frames both ways x 10 / baud (the
  protocol is stop-and-wait: one item per round trip); `usv_link_time_s`: usv-link 2's
  windowed signed upload in the same line model.
"""

from __future__ import annotations

import asyncio
import platform
import random
from collections.abc import Callable
from typing import Any

from usvstation.clock import REAL_CLOCK, Stopwatch
from usvstation.geo import RampFrame
from usvstation.link import wire
from usvstation.link.mission import Mission, mission_from_plan
from usvstation.link.protocol import LinkConfig, StationProtocol, UploadResult
from usvstation.link.station import BoatLink
from usvstation.link.transport import FaultInjectingStream, PtyPair, SerialStream
from usvstation.sim.boat import BoatConfig, BoatProtocol
from usvstation.sim.runner import SimulatedBoat, make_boat
from usvstation.sim.sensors import GpsNoise
from usvstation.sim.vehicle import KinematicVehicle

FRAME = RampFrame(30.5135, 114.4182, 90.0)  # case1's origin
KEY = bytes(range(7, 39))


def bench_mission(n: int = 32, mission_id: int = 1, speed: float = 1.5) -> Mission:
    """A 32-waypoint zig-zag approach to the ramp from (85, 10), position linear in time."""
    wps: list[dict[str, float]] = []
    t = 0.0
    for i in range(n):
        f = i / (n - 1)
        x = 85.0 * (1 - f)
        y = 10.0 * (1 - f) + (0.0 if i in (0, n - 1) else (3.0 if i % 2 else -3.0))
        if wps:
            t += ((x - wps[-1]["x"]) ** 2 + (y - wps[-1]["y"]) ** 2) ** 0.5 / speed
        wps.append({"x": x, "y": y, "t": t, "speed": speed, "heading_deg": 180.0})
    return mission_from_plan(wps, FRAME, mission_id)


def upload_wire_bytes(mission: Mission) -> tuple[int, int]:
    """Bytes of a loss-free signed upload's own frames: (station to boat, boat to station)."""
    st = wire.Codec(wire.STATION_ID, wire.STATION_COMPONENT, KEY)
    bt = wire.Codec(wire.BOAT_ID, wire.BOAT_COMPONENT, KEY)
    e, b = st.mav, bt.mav
    up = len(st.encode(e.usv_mission_begin_encode(1, 1, mission.mission_id, mission.crc,
                                                  mission.count, 0)))
    up += len(st.encode(e.usv_mission_end_encode(1, 1, mission.mission_id, mission.crc,
                                                 mission.count)))
    for it in mission.items:
        up += len(st.encode(e.usv_mission_item_encode(
            1, 1, it.mission_id, it.seq, it.lat, it.lon, it.t_ms, it.speed_cms, it.course_cdeg,
            it.heading_cdeg)))
    down = sum(len(bt.encode(b.usv_mission_ack_encode(255, 190, mission.mission_id, seq, 0,
                                                      stage)))
               for seq, stage in [(0, 1), *((i + 1, 2) for i in range(mission.count)),
                                  (mission.count, 3)])
    return up, down


class _Rig:
    """Boat and station on one pty pair, each writing through a fault injector."""

    def __init__(self, baud: int, loss: float, seed: int) -> None:
        self.baud, self.loss, self.seed = baud, loss, seed
        self.pair = PtyPair()
        self.boat = make_boat(FRAME, config=BoatConfig(baud=baud), seed=seed, key=KEY)
        self.station_faults: FaultInjectingStream | None = None

    async def __aenter__(self) -> _Rig:
        self.boat_faults = FaultInjectingStream(self.pair.master_stream(), loss=self.loss,
                                                baud=self.baud, seed=self.seed)
        self.stop = asyncio.Event()
        self.boat_task = asyncio.get_running_loop().create_task(
            SimulatedBoat(self.boat).run(self.boat_faults, self.stop))

        async def factory() -> FaultInjectingStream:
            inner = await SerialStream.open(self.pair.slave_path, self.baud)
            self.station_faults = FaultInjectingStream(inner, loss=self.loss, baud=self.baud,
                                                       seed=self.seed + 1000)
            return self.station_faults

        self.link = BoatLink(stream_factory=factory, key=KEY, config=LinkConfig(baud=self.baud))
        await self.link.start()
        if not await self.link.wait_link_up(20.0):
            raise RuntimeError("the link did not come up")
        return self

    async def __aexit__(self, *exc: object) -> None:
        await self.link.close()
        self.stop.set()
        await self.boat_task
        await self.boat_faults.close()
        self.pair.close()


async def _upload_run(baud: int, loss: float, seed: int, bound_s: float,
                      one_way_s: float) -> dict[str, Any]:
    mission = bench_mission(mission_id=seed * 100 + int(loss * 100) + 1)
    async with _Rig(baud, loss, seed) as rig:
        await REAL_CLOCK.sleep(0.5)  # the handshake's frames and first telemetry drain
        watch = Stopwatch()
        result = await rig.link.upload_mission(mission)
        elapsed = watch.elapsed()
        active = rig.boat.active
        return {
            "baud": baud, "loss": loss, "seed": seed, "time_s": round(elapsed, 4),
            "bound_s": round(bound_s, 4), "ratio": round(elapsed / bound_s, 3),
            "one_way_bound_s": round(one_way_s, 4),
            "ratio_one_way": round(elapsed / one_way_s, 3),
            "completed": result.ok, "reason": result.reason,
            "identical": bool(active is not None and active.items == mission.items),
            "partial_activated": bool(active is not None and active.items != mission.items),
            "retransmissions": result.retransmissions,
        }


def spurious_failsafes(loss: float, minutes: float = 10.0, seed: int = 1,
                       dt: float = 0.01) -> dict[str, Any]:
    """The boat RUNNING for `minutes` of simulated time with `loss` of station frames."""
    rng = random.Random(seed)
    n = 64
    wps = [{"x": 85.0 - i * 0.5, "y": 10.0, "t": i * (minutes * 60 + 60) / (n - 1),
            "speed": 0.1, "heading_deg": 180.0} for i in range(n)]
    mission = mission_from_plan(wps, FRAME, 77)
    boat = BoatProtocol(KinematicVehicle(85.0, 10.0, 3.14159), FRAME, BoatConfig(), key=KEY,
                        gps=GpsNoise(seed=seed), now=0.0, unix_time=1.7e9)
    station = StationProtocol(LinkConfig(), 0.0, key=KEY, unix_time=1.7e9, session=5)
    t = 0.0
    uploaded = started = False
    running_s = 0.0
    while running_s < minutes * 60:
        t += dt
        boat.update(t)
        down = boat.data_to_send(t)
        events = station.receive_data(down, t) if down else station.poll(t)
        up = station.data_to_send()
        if up:
            kept = b"".join(f for f in wire.split_frames(up)
                            if not started or rng.random() >= loss)
            if kept:
                boat.receive_data(kept, t)
        if not uploaded and station.link_up:
            station.start_upload(mission, t)
            uploaded = True
        if uploaded and not started and any(isinstance(e, UploadResult) for e in events):
            station.send_command("start", t, mission.mission_id, mission.crc)
            started = True
        if boat.state == 2:  # RUNNING
            running_s += dt
        if t > minutes * 60 + 120:
            break
    return {"loss": loss, "simulated_running_s": round(running_s, 1),
            "failsafes": boat.failsafes, "boat_state": wire.BOAT_STATES[boat.state]}


def decode_rate(frames: int = 100_000, repeats: int = 3) -> tuple[float, float]:
    """Signed GLOBAL_POSITION_INT frames decoded through Codec.feed (4096-byte chunks), best
    of `repeats`: (per second of this process's CPU time, per second of wall time). The CPU
    figure is the codec's own rate on a shared machine; the wall figure includes waiting
    for a core."""
    enc = wire.Codec(1, 1, KEY, timestamp=wire.signing_time(1.7e9))
    e = enc.mav
    data = b"".join(enc.encode(e.global_position_int_encode(i, 305135000 + i, 1144182000, 0,
                                                            0, 150, -20, 0, 18000))
                    for i in range(frames))
    best_cpu = best_wall = 0.0
    for _ in range(repeats):
        dec = wire.Codec(255, 190, KEY, timestamp=0)
        watch = Stopwatch()
        n = 0
        for i in range(0, len(data), 4096):
            n += len(dec.feed(data[i : i + 4096])[0])
        cpu, wall = watch.cpu(), watch.elapsed()
        best_cpu, best_wall = max(best_cpu, n / max(cpu, 1e-9)), max(best_wall, n / wall)
        assert n == frames
    return best_cpu, best_wall


async def _uploads(quick: bool, progress: Callable[[str], None]) -> list[dict[str, Any]]:
    up, down = upload_wire_bytes(bench_mission())
    runs = []
    for baud, seeds in ((57600, [1] if quick else [1, 2, 3]), (9600, [1] if quick else [1, 2])):
        bound_s = (up + down) * 10 / baud
        one_way_s = max(up, down) * 10 / baud
        for loss in (0.0, 0.1, 0.2):
            batch = [await _upload_run(baud, loss, s, bound_s, one_way_s) for s in seeds]
            rows = [(r["time_s"], r["ratio"], r["ratio_one_way"], r["retransmissions"],
                     r["identical"]) for r in batch]
            progress(f"{baud} baud, loss {loss}: (time_s, ratio, one-way ratio, "
                     f"retransmissions, identical) {rows}")
            runs += batch
    return runs


class _SimLine:
    """A full-duplex serial line in simulated time: each direction sends whole frames one
    after another at the baud (10 bits a byte); a frame arrives when its last byte has,
    or (probability `loss`, seeded) never."""

    def __init__(self, baud: int, loss: float = 0.0, seed: int = 1) -> None:
        self.baud, self.loss, self.rng = baud, loss, random.Random(seed)
        self.free = [0.0, 0.0]
        self.queues: list[list[tuple[float, bytes]]] = [[], []]

    def send(self, direction: int, data: bytes, now: float) -> None:
        for frame in wire.split_frames(data):
            start = max(now, self.free[direction])
            self.free[direction] = start + len(frame) * 10 / self.baud
            if self.rng.random() >= self.loss:
                self.queues[direction].append((self.free[direction], frame))

    def receive(self, direction: int, now: float) -> bytes:
        q = self.queues[direction]
        n = 0
        while n < len(q) and q[n][0] <= now:
            n += 1
        out = b"".join(f for _, f in q[:n])
        del q[:n]
        return out


def standard_upload_bytes(mission: Mission, signed: bool) -> tuple[int, int]:
    """Bytes of a loss-free standard upload's own frames: (station to vehicle, back)."""
    from usvstation.link.standard_mission import standard_items

    key = KEY if signed else None
    st = wire.Codec(wire.STATION_ID, wire.STATION_COMPONENT, key)
    vh = wire.Codec(1, 1, key)
    items = standard_items(mission.items)
    up = len(st.encode(st.mav.mission_count_encode(1, 1, len(items), 0)))
    up += sum(len(st.encode(st.mav.mission_item_int_encode(
        1, 1, i.seq, i.frame, i.command, 0, 1, i.param1, i.param2, i.param3, i.param4, i.x,
        i.y, i.z, 0))) for i in items)
    down = sum(len(vh.encode(vh.mav.mission_request_int_encode(255, 190, i.seq, 0)))
               for i in items)
    down += len(vh.encode(vh.mav.mission_ack_encode(255, 190, 0, 0)))
    return up, down


def standard_upload_run(baud: int, signed: bool = False, loss: float = 0.0, seed: int = 1,
                        dt: float = 0.001) -> dict[str, Any]:
    """One 32-waypoint standard upload and read-back in simulated time (module doc)."""
    from usvstation.link.standard import PROFILES, StandardConfig, StandardProtocol
    from usvstation.link.standard_mission import standard_items
    from usvstation.sim.standard_vehicle import StandardVehicle

    mission = bench_mission()
    key = KEY if signed else None
    profile = PROFILES["px4"]  # no home item: the same 63 items as a boat serves
    vehicle = StandardVehicle(profile, key=key)
    if key is not None:
        vehicle.codec = wire.Codec(1, 1, key, timestamp=wire.signing_time(vehicle.unix0))
    station = StandardProtocol(StandardConfig(profile=profile, baud=baud), 0.0, key=key,
                               unix_time=vehicle.unix0, session=1)
    line = _SimLine(baud, loss, seed)
    t, started, uploaded_at, result = 0.0, None, None, None
    while t < 600.0 and result is None:
        t += dt
        vehicle.poll(t)
        line.send(1, vehicle.data_to_send(), t)
        up = line.receive(0, t)
        if up:
            vehicle.receive(up, t)
            line.send(1, vehicle.data_to_send(), t)
        down = line.receive(1, t)
        events = station.receive_data(down, t) if down else station.poll(t)
        line.send(0, station.data_to_send(), t)
        if started is None and station.link_up:
            started = t
            station.start_upload(mission, t)
            line.send(0, station.data_to_send(), t)
        if uploaded_at is None and station.upload is not None and station.upload.done:
            uploaded_at = t
        result = next((e for e in events if isinstance(e, UploadResult)), None)
    up_b, down_b = standard_upload_bytes(mission, signed)
    bound = (up_b + down_b) * 10 / baud
    assert started is not None and result is not None and uploaded_at is not None
    return {"baud": baud, "signed": signed, "loss": loss, "seed": seed,
            "time_s": round(uploaded_at - started, 4),
            "verified_s": round(t - started, 4), "bound_s": round(bound, 4),
            "ratio": round((uploaded_at - started) / bound, 3),
            "completed": result.ok, "reason": result.reason,
            "identical": vehicle.mission == list(standard_items(mission.items)),
            "retransmissions": result.retransmissions}


def usv_link_upload_sim(baud: int, dt: float = 0.001) -> float:
    """usv-link 2's signed 32-waypoint upload, in the same simulated line model."""
    mission = bench_mission()
    boat = BoatProtocol(KinematicVehicle(85.0, 10.0, 3.14159), FRAME, BoatConfig(baud=baud),
                        key=KEY, gps=GpsNoise(seed=1), now=0.0, unix_time=1.7e9)
    station = StationProtocol(LinkConfig(baud=baud), 0.0, key=KEY, unix_time=1.7e9,
                              session=5)
    line = _SimLine(baud)
    t, started = 0.0, None
    while t < 600.0:
        t += dt
        boat.update(t)
        up = line.receive(0, t)
        if up:
            boat.receive_data(up, t)
        line.send(1, boat.data_to_send(t), t)
        down = line.receive(1, t)
        events = station.receive_data(down, t) if down else station.poll(t)
        line.send(0, station.data_to_send(), t)
        if started is None and station.link_up:
            started = t
            station.start_upload(mission, t)
            line.send(0, station.data_to_send(), t)
        if any(isinstance(e, UploadResult) for e in events):
            assert started is not None
            return round(t - started, 4)
    raise RuntimeError("usv-link upload did not end")


def _standard_uploads(quick: bool, progress: Callable[[str], None]) -> list[dict[str, Any]]:
    up, down = upload_wire_bytes(bench_mission())
    rows = []
    for baud in (57600, 9600):
        usv_link = usv_link_upload_sim(baud)
        for signed in (False, True):
            for loss, seeds in ((0.0, [1]), (0.1, [1] if quick else [1, 2, 3])):
                for seed in seeds:
                    r = standard_upload_run(baud, signed, loss, seed)
                    r["usv_link_time_s"] = usv_link
                    r["usv_link_bound_s"] = round((up + down) * 10 / baud, 4)
                    rows.append(r)
                    progress(f"standard upload {baud} baud, signed {signed}, loss {loss}: "
                             f"{r['time_s']} s (bound {r['bound_s']} s, verified "
                             f"{r['verified_s']} s; usv-link 2 {usv_link} s)")
    return rows


def run_link_bench(quick: bool = False,
                   progress: Callable[[str], None] = lambda _: None) -> dict[str, Any]:
    up, down = upload_wire_bytes(bench_mission())
    uploads = asyncio.run(_uploads(quick, progress))
    minutes = 1.0 if quick else 10.0
    failsafe = [spurious_failsafes(loss, minutes) for loss in (0.2,)]
    progress(f"failsafe: {failsafe}")
    standard = _standard_uploads(quick, progress)
    decode_cpu, decode_wall = decode_rate(30_000 if quick else 100_000)
    progress(f"decode: {decode_cpu:.0f} frames per CPU second, {decode_wall:.0f} per wall s")

    def worst(baud: int, loss: float) -> float | None:
        r = [x["ratio"] for x in uploads if x["baud"] == baud and x["loss"] == loss]
        return max(r) if r else None

    return {
        "bench": "link", "protocol": "usv-link 2 (MAVLink 2, signed)", "waypoints": 32,
        "machine": f"{platform.machine()} {platform.system()} {platform.release()}, "
                   f"python {platform.python_version()}",
        "upload_bytes": {"station_to_boat": up, "boat_to_station": down},
        "upload": uploads,
        "worst_ratio_loss_free": {"57600": worst(57600, 0.0), "9600": worst(9600, 0.0)},
        "all_identical": all(r["identical"] for r in uploads),
        "partial_activations": sum(r["partial_activated"] for r in uploads),
        "failsafe": failsafe,
        "decode_frames_per_cpu_s": round(decode_cpu),
        "decode_frames_per_wall_s": round(decode_wall),
        "standard_upload": standard,
    }
