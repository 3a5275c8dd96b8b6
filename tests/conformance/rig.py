"""A station (BoatLink) on a boat process's pty, with a radio in between the test controls:
loss per direction, the station's transmitter off, the boat's frames echoed back to it,
frames of other senders injected, and a recording of what the station sent."""

from __future__ import annotations

import asyncio
import contextlib
import math
import random
import time
from typing import Any

from usvstation.geo import RampFrame
from usvstation.link import wire
from usvstation.link.mavlink import usv_recovery as mav
from usvstation.link.mission import Mission, mission_from_plan
from usvstation.link.protocol import LinkConfig, StatusTextReceived
from usvstation.link.station import BoatLink
from usvstation.link.transport import SerialStream

FRAME = RampFrame(30.5135, 114.4182, 90.0)  # case1's origin
USV_MISSION_ACK = mav.MAVLINK_MSG_ID_USV_MISSION_ACK


def msg_id(frame: bytes) -> int:
    return frame[7] | frame[8] << 8 | frame[9] << 16 if len(frame) >= 10 else -1


class Radio:
    """A ByteStream around the station's serial port (see the module doc)."""

    def __init__(self, inner: SerialStream, seed: int = 0) -> None:
        self.inner = inner
        self.rng = random.Random(seed)
        self.up_loss = self.down_loss = 0.0
        self.silent = False  # the station's transmitter is off
        self.echo = False  # the boat hears its own frames
        self.drop_down: Any = None  # predicate on a boat frame: drop it
        self.tap: list[bytes] = []  # the station's frames, as it sent them
        self._buf = bytearray()

    async def read(self) -> bytes:
        while True:
            data = await self.inner.read()
            if not data:
                return b""
            if self.echo:
                await self.inner.write(data)
            self._buf += data
            frames, keep = [], 0
            i = 0
            for size in wire.frame_lengths(self._buf):
                chunk = bytes(self._buf[i:i + size])
                if chunk[0] == mav.PROTOCOL_MARKER_V2 and (len(chunk) < 3 or len(chunk) < (
                        12 + chunk[1] + (13 if chunk[2] & 1 else 0))):
                    break  # incomplete (a serial line splits frames anywhere): wait for the rest
                i += size
                keep = i
                if self.rng.random() < self.down_loss:
                    continue
                if self.drop_down is not None and self.drop_down(chunk):
                    continue
                frames.append(chunk)
            del self._buf[:keep]
            if frames:
                return b"".join(frames)

    async def write(self, data: bytes) -> None:
        self.tap.append(data)
        if self.silent:
            return
        kept = [f for f in wire.split_frames(data) if self.rng.random() >= self.up_loss]
        if kept:
            await self.inner.write(b"".join(kept))

    async def inject(self, data: bytes) -> None:
        """Bytes to the boat from a third party (another sender, an attacker)."""
        await self.inner.write(data)

    async def close(self) -> None:
        await self.inner.close()


WALL_FACTOR = 20  # how much slower than the boat's clock the wall clock may run


class Rig:
    """The station side of a conformance test; `device()` gives the boat's current pty."""

    def __init__(self, boat: Any, *, session: int | None = None, seed: int = 0) -> None:
        self.boat = boat
        self.key = wire.read_key(boat.key_path)
        self.seed = seed
        self.radio: Radio | None = None
        self.events: list[tuple[float, Any]] = []
        self.link = BoatLink(stream_factory=self._open, reconnect_s=0.2, key=self.key,
                             session=session, config=LinkConfig())
        self.link.add_listener(lambda ev: self.events.append((time.monotonic(), ev)))

    async def _open(self) -> Radio:
        old = self.radio
        inner = await SerialStream.open(self.boat.device, 57600)
        self.radio = Radio(inner, self.seed)
        if old is not None:  # the test's radio settings survive a reconnect
            for k in ("up_loss", "down_loss", "silent", "echo", "drop_down"):
                setattr(self.radio, k, getattr(old, k))
            self.radio.tap = old.tap
        return self.radio

    async def __aenter__(self) -> Rig:
        await self.link.start()
        await self.until(lambda: self.link.link_up and self.report is not None
                         and self.link.telemetry is not None, 10.0)
        return self

    async def __aexit__(self, *exc: object) -> None:
        await self.link.close()

    @property
    def report(self):
        return self.link.report

    @property
    def proto(self):
        return self.link.protocol

    def texts(self) -> list[str]:
        return [e.text for _, e in self.events if isinstance(e, StatusTextReceived)]

    def _uptime_s(self) -> float | None:
        report = self.report
        return None if report is None else report.uptime_ms / 1000.0

    async def until(self, cond, timeout: float) -> None:
        """Wait for cond() up to `timeout` seconds of the boat's own clock (its reported
        uptime: the firmware in QEMU on a busy machine runs several times slower than the
        wall clock), and at most WALL_FACTOR times that of wall time."""
        wall_end = time.monotonic() + WALL_FACTOR * timeout
        start = self._uptime_s()
        while not cond():
            now = self._uptime_s()
            boat_s = 0.0 if start is None or now is None else now - start
            if start is None:
                start = now
            if boat_s > timeout or time.monotonic() > wall_end:
                raise AssertionError(f"timed out after {timeout} s of boat time ({boat_s:.1f} s"
                                     f" passed on the boat); boat report: {self.report}")
            await asyncio.sleep(0.02)

    def position(self) -> tuple[float, float]:
        t = self.link.telemetry
        x, y = FRAME.to_ramp(t.lat, t.lon)
        return float(x), float(y)

    def mission_here(self, mission_id: int, n: int = 8, speed: float = 1.0,
                     dy: float = 0.0) -> Mission:
        """A mission from the boat's reported position towards the ramp."""
        x0, y0 = self.position()
        wps, t = [], 0.0
        for i in range(n):
            f = i / (n - 1)
            x, y = x0 * (1 - f), y0 * (1 - f) + (dy * math.sin(math.pi * f))
            if wps:
                t += max(0.5, math.hypot(x - wps[-1]["x"], y - wps[-1]["y"]) / speed)
            wps.append({"x": x, "y": y, "t": t, "speed": speed, "heading_deg": 180.0})
        return mission_from_plan(wps, FRAME, mission_id)

    async def run_mission(self, mission: Mission) -> None:
        """Upload, then START; returns once the boat reports RUNNING it."""
        assert (await self.link.upload_mission(mission)).ok
        await self.until(lambda: self.report.active_id == mission.mission_id, 5.0)
        out = await self.link.command("start", mission.mission_id, mission.crc)
        assert out.accepted, out
        await self.until(lambda: self.report.state == "RUNNING", 5.0)


def foreign_codec(system_id: int, key: bytes | None, component: int = 190) -> wire.Codec:
    """An encoder for frames of another sender (unsigned with key None)."""
    return wire.Codec(system_id, component, key, timestamp=wire.signing_time(time.time()))


async def settle(seconds: float) -> None:
    with contextlib.suppress(asyncio.CancelledError):
        await asyncio.sleep(seconds)
