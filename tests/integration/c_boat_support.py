"""Build and drive the C boat (protocol/c/boat) from Python tests.

`build_c_boat` runs `make -C protocol/c/boat` into a temporary directory; `CBoat` starts the
host program on an ephemeral 127.0.0.1 port (or a pty) and `MavClient` speaks MAVLink 2 to
it with pymavlink's generated usv_recovery codec, signing with a 32-byte key. The boat's
clock is its uptime; tests wait on what the boat reports (USV_MISSION_STATE), never on
the wall clock of this machine.
"""

from __future__ import annotations

import contextlib
import functools
import os
import re
import shutil
import socket
import subprocess
import threading
import time
import zlib
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[2]
BOAT_DIR = ROOT / "protocol" / "c" / "boat"
SIGNING_EPOCH = 1420070400  # MAVLink signing timestamps: 10 us units since 2015-01-01
STATION_ID = 255
STATION_COMP = 190
BOAT_ID = 1
START_LAT, START_LON = 59.9, 10.7

# USV_BOAT_STATE / USV_STAGING_STATE / USV_MISSION_RESULT / MAV_CMD values (dialect)
IDLE, READY, RUNNING, HOLD, DONE, ABORTED, FAILSAFE, GO_AROUND = range(8)
CMD_START, CMD_HOLD, CMD_RESUME, CMD_ABORT = 44100, 44101, 44102, 44103


def c_compiler() -> str | None:
    return shutil.which(os.environ.get("CC", "cc")) or shutil.which("gcc")


def build_c_boat(build_dir: Path, target: str = "all") -> Path:
    """`make -C protocol/c/boat BUILD=build_dir target`; returns the program built."""
    subprocess.run(["make", "-s", "-C", str(BOAT_DIR), f"BUILD={build_dir}", target],
                   check=True, capture_output=True, text=True)
    name = {"all": "usv_boat_host", "fuzz": "usv_boat_fuzz"}[target]
    return build_dir / name


@functools.cache
def conformance_argv() -> dict[str, list[str]]:
    """The C boat's entry for tests/conformance BOATS: the host program built once into a
    temporary directory (removed at exit), on a new pty, placed at case1's start; {} when no
    C compiler is installed (test_c_boat_build.py then says so as its skip reason)."""
    import atexit
    import math
    import tempfile

    from usvstation.geo import RampFrame
    from usvstation.scenario import load_scenario

    if c_compiler() is None:
        return {}
    build = Path(tempfile.mkdtemp(prefix="usv-c-boat-"))
    atexit.register(shutil.rmtree, build, True)
    exe = build_c_boat(build)
    case1 = load_scenario("case1")
    o = case1.origin
    frame = RampFrame(o.lat, o.lon, o.ramp_bearing_deg)
    lat, lon = frame.to_geodetic(case1.start.x, case1.start.y)
    compass = float(frame.ramp_bearing_deg - case1.start.heading_deg) % 360.0
    assert math.isfinite(compass)
    # exact sensors, like the Python boat of the rig: the boats are compared on the protocol
    return {"c": [str(exe), "pty", "--lat", f"{float(lat):.9f}", "--lon", f"{float(lon):.9f}",
                  "--heading-deg", f"{compass:g}", "--telemetry-hz", "5",
                  "--sensors", "exact"]}


def load_dialect() -> Any:
    """pymavlink's generated Python codec of protocol/usv_recovery.xml (the project's copy)."""
    from usvstation.link.mavlink import usv_recovery

    return usv_recovery


def signing_now() -> int:
    return int((time.time() - SIGNING_EPOCH) * 100_000)


@dataclass(frozen=True)
class Item:
    lat: int
    lon: int
    t_ms: int
    speed_cms: int = 100
    course_cdeg: int = 0
    heading_cdeg: int = 0


def mission_crc32(mission_id: int, items: list[Item]) -> int:
    """CRC-32 over each item's wire payload from mission_id on, without the target bytes."""
    import struct

    crc = 0
    for seq, it in enumerate(items):
        crc = zlib.crc32(struct.pack("<IiiIHHHH", mission_id, it.lat, it.lon, it.t_ms, seq,
                                     it.speed_cms, it.course_cdeg, it.heading_cdeg), crc)
    return crc


def line_north(n: int, *, step_m: float = 20.0, leg_s: float = 10.0,
               lat: float = START_LAT, lon: float = START_LON) -> list[Item]:
    """n waypoints due north from (lat, lon), step_m apart, leg_s apart in time."""
    dlat = step_m / 6378137.0 * 180.0 / 3.141592653589793
    speed = round(step_m / leg_s * 100)
    return [Item(round((lat + i * dlat) * 1e7), round(lon * 1e7), round(i * leg_s * 1000),
                 speed, 0, 0) for i in range(n)]


@dataclass
class CBoat:
    """The host C boat as a child process; always stopped by `close`."""

    proc: subprocess.Popen
    port: int | None
    lines: list[str] = field(default_factory=list)

    @classmethod
    def start(cls, exe: Path, *, key: Path | None, where: str = "0", boat_id: int = BOAT_ID,
              station_id: int = STATION_ID, speedup: float = 1.0, nv: Path | None = None,
              extra: tuple[str, ...] = ()) -> CBoat:
        args = [str(exe), where, "--boat-id", str(boat_id), "--station-id", str(station_id),
                "--speedup", str(speedup), "--lat", str(START_LAT), "--lon", str(START_LON),
                *extra]
        if nv is not None:
            args += ["--nv-file", str(nv)]
        args += ["--link-key", str(key)] if key is not None else ["--insecure-link"]
        proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                text=True)
        assert proc.stdout is not None
        first = proc.stdout.readline()
        m = re.search(r"listening on 127\.0\.0\.1:(\d+)", first)
        if m is None and " on " not in first:
            proc.kill()
            proc.wait()
            raise RuntimeError(f"C boat did not start: {first!r}")
        boat = cls(proc, int(m.group(1)) if m else None, [first])
        threading.Thread(target=boat._drain, daemon=True).start()
        return boat

    def _drain(self) -> None:
        assert self.proc.stdout is not None
        for line in self.proc.stdout:
            self.lines.append(line)

    def close(self) -> None:
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()


class MavClient:
    """A station (or an attacker) on the boat's TCP port or a pty master fd."""

    def __init__(self, dialect: Any, *, port: int | None = None, fd: int | None = None,
                 key: bytes | None = None, sysid: int = STATION_ID,
                 compid: int = STATION_COMP, sign: bool = True) -> None:
        self.d = dialect
        self.sock: socket.socket | None = None
        self.fd = fd
        if port is not None:
            self.sock = socket.create_connection(("127.0.0.1", port), timeout=10)
            self.sock.settimeout(0.2)
        self.mav = dialect.MAVLink(None, srcSystem=sysid, srcComponent=compid)
        self.mav.robust_parsing = True
        self.rx_mav = dialect.MAVLink(None, srcSystem=sysid, srcComponent=compid)
        self.rx_mav.robust_parsing = True
        if key is not None:
            for m in (self.mav, self.rx_mav):
                m.signing.secret_key = key
                m.signing.timestamp = signing_now()
            self.mav.signing.sign_outgoing = sign
        self.key = key
        self.msgs: list[Any] = []
        self.raw_in = bytearray()
        self.sent: list[bytes] = []
        self._cv = threading.Condition()
        self._tx_lock = threading.Lock()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._read, daemon=True)
        self._thread.start()

    # ---- I/O
    def _read(self) -> None:
        while not self._stop.is_set():
            try:
                if self.sock is not None:
                    data = self.sock.recv(4096)
                    if not data:
                        return
                else:
                    import select

                    assert self.fd is not None
                    r, _, _ = select.select([self.fd], [], [], 0.2)
                    if not r:
                        continue
                    data = os.read(self.fd, 4096)
            except TimeoutError:
                continue
            except OSError:
                return
            msgs = self.rx_mav.parse_buffer(data) or []
            with self._cv:
                self.raw_in += data
                for m in msgs:
                    if m.get_type() != "BAD_DATA":
                        self.msgs.append(m)
                self._cv.notify_all()

    def write(self, data: bytes) -> None:
        if self.sock is not None:
            self.sock.sendall(data)
        else:
            assert self.fd is not None
            os.write(self.fd, data)

    def send(self, msg: Any) -> bytes:
        with self._tx_lock:
            if self.key is not None and self.mav.signing.sign_outgoing:
                self.mav.signing.timestamp = max(self.mav.signing.timestamp + 1, signing_now())
            frame = bytes(msg.pack(self.mav))
            self.sent.append(frame)
            self.write(frame)
        return frame

    def close(self) -> None:
        self._stop.set()
        if self.sock is not None:
            with contextlib.suppress(OSError):
                self.sock.close()
        self._thread.join(timeout=5)

    # ---- waiting on what the boat says
    def wait_for(self, pred: Callable[[Any], bool], timeout: float = 20.0,
                 start: int = 0) -> Any:
        """The first message (from index start) satisfying pred; AssertionError on timeout."""
        deadline = time.monotonic() + timeout
        i = start
        with self._cv:
            while True:
                while i < len(self.msgs):
                    if pred(self.msgs[i]):
                        return self.msgs[i]
                    i += 1
                left = deadline - time.monotonic()
                if left <= 0:
                    raise AssertionError("no matching message from the boat in time")
                self._cv.wait(left)

    def mark(self) -> int:
        with self._cv:
            return len(self.msgs)

    def of_type(self, name: str, start: int = 0) -> list[Any]:
        with self._cv:
            return [m for m in self.msgs[start:] if m.get_type() == name]

    def state(self, timeout: float = 20.0) -> Any:
        """The next USV_MISSION_STATE."""
        return self.wait_for(lambda m: m.get_type() == "USV_MISSION_STATE", timeout,
                             self.mark())

    def wait_state(self, state: int, timeout: float = 30.0) -> Any:
        return self.wait_for(lambda m: m.get_type() == "USV_MISSION_STATE"
                             and m.state == state, timeout, self.mark())

    # ---- station actions
    def heartbeat(self) -> None:
        self.send(self.d.MAVLink_heartbeat_message(6, 8, 0, 0, 4, 3))  # GCS, INVALID

    def command(self, cmd: int, seq: int, session: int, x: int = 0, y: int = 0,
                target: int = BOAT_ID) -> Any:
        """Send a COMMAND_INT and return its COMMAND_ACK (matched on command and seq)."""
        start = self.mark()
        xi = x - (1 << 32) if x >= 1 << 31 else x
        yi = y - (1 << 32) if y >= 1 << 31 else y
        self.send(self.d.MAVLink_command_int_message(target, 1, 0, cmd, 0, 0, float(seq),
                                                     float(session), 0, 0, xi, yi, 0))
        return self.wait_for(lambda m: m.get_type() == "COMMAND_ACK" and m.command == cmd
                             and m.result_param2 == seq, 10, start)

    def mission_msg(self, msg: Any, stage: int, mission_id: int) -> Any:
        start = self.mark()
        self.send(msg)
        return self.wait_for(lambda m: m.get_type() == "USV_MISSION_ACK" and m.stage == stage
                             and m.mission_id == mission_id, 10, start)

    def upload(self, mission_id: int, items: list[Item], *, swap_at_ms: int = 0,
               target: int = BOAT_ID) -> Any:
        """BEGIN, every ITEM, END, each waiting for its ACK; returns END's ACK."""
        crc = mission_crc32(mission_id, items)
        d = self.d
        ack = self.mission_msg(d.MAVLink_usv_mission_begin_message(
            target, 1, mission_id, crc, len(items), swap_at_ms), 1, mission_id)
        if ack.result != 0:
            return ack
        for seq, it in enumerate(items):
            ack = self.mission_msg(d.MAVLink_usv_mission_item_message(
                target, 1, mission_id, seq, it.lat, it.lon, it.t_ms, it.speed_cms,
                it.course_cdeg, it.heading_cdeg), 2, mission_id)
            if ack.result != 0:
                return ack
        return self.mission_msg(d.MAVLink_usv_mission_end_message(
            target, 1, mission_id, crc, len(items)), 3, mission_id)


@contextlib.contextmanager
def heartbeats(client: MavClient, period_s: float = 0.25) -> Iterator[threading.Event]:
    """Station heartbeats on a fixed schedule until the block ends (or the event is set)."""
    stop = threading.Event()

    def run() -> None:
        while not stop.is_set():
            with contextlib.suppress(OSError):
                client.heartbeat()
            stop.wait(period_s)

    t = threading.Thread(target=run, daemon=True)
    t.start()
    try:
        yield stop
    finally:
        stop.set()
        t.join(timeout=5)


def u32(v: int) -> int:
    return v & 0xFFFFFFFF
