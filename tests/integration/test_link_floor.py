"""A signed session recorded before a boat reboots starts nothing after it, with every boat's
defaults: the boat inside `serve` (EmbeddedSim), `usv-station sim` and the C host boat keep
their signing floor beside their key without being told (docs/link.md "Replay").

Real time over ptys: a station (BoatLink) uploads a mission and STARTs it while its bytes are
recorded; the boat stops and boots again; the recording is written to it; a fresh station
then reads the boat's own report: IDLE, no mission, the replayed frames counted as refused.
The Python boats' clock refuses frames older than 60 s on its own (MAVLink), so a replay
within the minute is what only the floor stops.
"""

from __future__ import annotations

import asyncio
import contextlib
import os
import re
import subprocess
import sys
import time
from pathlib import Path

import pytest

from usvstation.config import Settings
from usvstation.link import wire
from usvstation.link.mission import mission_from_plan
from usvstation.link.protocol import LinkConfig, MissionState
from usvstation.link.station import BoatLink
from usvstation.link.transport import SerialStream
from usvstation.scenario import load_scenario
from usvstation.services.simboat import EmbeddedSim
from usvstation.sim.runner import default_nv_path, load_nv

EXE = os.path.join(os.path.dirname(sys.executable), "usv-station")
CASE1 = load_scenario("case1")


class Recording(SerialStream):
    """A serial port that keeps a copy of everything written to it."""

    def __init__(self, inner: SerialStream, log: bytearray) -> None:
        super().__init__(inner._reader, inner._writer)
        self.log = log

    async def write(self, data: bytes) -> None:
        self.log += data
        await super().write(data)


def _mission(mission_id: int = 77):
    o = CASE1.origin
    assert o is not None
    from usvstation.geo import RampFrame

    frame = RampFrame(o.lat, o.lon, o.ramp_bearing_deg)
    s = CASE1.start
    wps = [{"x": s.x - 3.0 * i, "y": s.y, "t": 3.0 * i, "speed": 1.0, "heading_deg": 180.0}
           for i in range(4)]
    return mission_from_plan(wps, frame, mission_id)


async def _until(cond, timeout: float = 30.0) -> None:
    end = time.monotonic() + timeout
    while not cond():
        assert time.monotonic() < end, "timed out"
        await asyncio.sleep(0.02)


async def record_upload_and_start(device: str, key: bytes) -> bytes:
    """A station flies a mission to the boat on `device`; every byte it wrote."""
    log = bytearray()

    async def factory() -> SerialStream:
        return Recording(await SerialStream.open(device), log)

    link = BoatLink(stream_factory=factory, key=key, config=LinkConfig(), reconnect_s=0.2)
    await link.start()
    try:
        assert await link.wait_link_up(30.0)
        m = _mission()
        assert (await link.upload_mission(m)).ok
        assert (await link.command("start", m.mission_id, m.crc)).accepted
        await _until(lambda: link.report is not None and link.report.state == "RUNNING")
    finally:
        await link.close()
    return bytes(log)


async def replay_then_read(device: str, key: bytes, recorded: bytes) -> MissionState:
    """Write `recorded` to the boat, then what a fresh station hears it report."""
    raw = await SerialStream.open(device)
    try:
        for i in range(0, len(recorded), 512):
            await raw.write(recorded[i:i + 512])
    finally:
        await raw.close()
    link = BoatLink(stream_factory=lambda: SerialStream.open(device), key=key,
                    config=LinkConfig(), reconnect_s=0.2)
    await link.start()
    try:
        assert await link.wait_link_up(30.0)
        await _until(lambda: link.report is not None and link.report.rejected > 0)
        return link.report
    finally:
        await link.close()


def test_the_boat_inside_serve_refuses_a_replay_after_a_restart(tmp_path):
    settings = Settings(data_dir=tmp_path, link="sim", nmea=[])
    key_path = tmp_path / "link.key"
    wire.write_key(key_path)
    key = wire.read_key(key_path)
    floor = default_nv_path(key_path, 1)
    assert floor == tmp_path / "link.key.boat1.floor" and not floor.exists()

    boat = EmbeddedSim(CASE1, settings, key)
    boat.start()
    try:
        recorded = asyncio.run(record_upload_and_start(boat.device, key))
    finally:
        boat.stop()
    saved = load_nv(floor)  # created on first use, exact after the clean stop
    assert saved.sign_floor > 0 and saved.exact

    rebooted = EmbeddedSim(CASE1, settings, key)
    rebooted.start()
    try:
        report = asyncio.run(replay_then_read(rebooted.device, key, recorded))
    finally:
        rebooted.stop()
    assert (report.state, report.active_id, report.staging) == ("IDLE", 0, 0)
    assert report.rejected >= 3


def _start_sim(key_path: Path, *extra: str) -> tuple[subprocess.Popen, str]:
    proc = subprocess.Popen([EXE, "sim", "--link", "pty", "--link-key", str(key_path),
                             "--vehicle", "kinematic", *extra],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    assert proc.stdout is not None
    first = proc.stdout.readline()
    found = re.search(r"boat on (/dev/\S+) \(.*signing floor (\S+),", first)
    if found is None:
        proc.kill()
        proc.wait()
        raise AssertionError(f"usv-station sim did not start: {first!r}")
    return proc, found.group(1) + "|" + found.group(2)


def _stop(proc: subprocess.Popen) -> None:
    if proc.poll() is None:
        proc.terminate()
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
    if proc.stdout is not None:
        proc.stdout.close()


def test_usv_station_sim_keeps_its_floor_beside_its_key(tmp_path):
    key_path = tmp_path / "boat.key"
    wire.write_key(key_path)
    key = wire.read_key(key_path)
    proc, where = _start_sim(key_path)
    device, floor = where.split("|")
    try:
        assert Path(floor) == default_nv_path(key_path, 1)
        recorded = asyncio.run(record_upload_and_start(device, key))
    finally:
        _stop(proc)
    assert load_nv(Path(floor)).exact

    proc, where = _start_sim(key_path)
    try:
        report = asyncio.run(replay_then_read(where.split("|")[0], key, recorded))
    finally:
        _stop(proc)
    assert (report.state, report.active_id) == ("IDLE", 0) and report.rejected >= 3


def test_an_unsigned_sim_keeps_no_floor(tmp_path):
    proc = subprocess.Popen([EXE, "sim", "--link", "pty", "--insecure-link", "--duration", "0"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            cwd=tmp_path)
    try:
        out = proc.communicate(timeout=60)[0]
    finally:
        with contextlib.suppress(ProcessLookupError):
            proc.kill()
    assert "signing floor none" in out and list(tmp_path.iterdir()) == []


@pytest.fixture(scope="module")
def c_boat(tmp_path_factory):
    from c_boat_support import build_c_boat, c_compiler

    if c_compiler() is None:
        pytest.skip("no C compiler (cc/gcc) to build protocol/c/boat")
    return build_c_boat(tmp_path_factory.mktemp("cboat"))


def test_the_c_host_boat_keeps_its_floor_beside_its_key(c_boat, tmp_path):
    from c_boat_support import CBoat, MavClient, line_north, load_dialect, mission_crc32

    key_path = tmp_path / "link.key"
    wire.write_key(key_path)
    key = wire.read_key(key_path)
    d = load_dialect()
    items = line_north(3)
    boat = CBoat.start(c_boat, key=key_path)
    try:
        c = MavClient(d, port=boat.port, key=key)
        try:
            assert c.upload(31, items).result == 0
            assert c.command(44100, 1, 4242, 31, mission_crc32(31, items)).result == 0
            c.wait_state(2, 10)  # RUNNING
            recorded = b"".join(c.sent)
        finally:
            c.close()
    finally:
        boat.close()
    floor = default_nv_path(key_path, 1)
    words = floor.read_text().split()
    assert words[0] == "sign_floor" and int(words[1]) > 0 and words[2:] == ["exact"]
    assert load_nv(floor).exact  # the Python boats read the C boat's file

    boat = CBoat.start(c_boat, key=key_path)
    try:
        c = MavClient(d, port=boat.port, key=key)
        try:
            start = c.mark()
            c.write(recorded)
            st = c.wait_for(lambda m: m.get_type() == "USV_MISSION_STATE" and m.rejected > 0,
                            10, start)
            later = c.state()
        finally:
            c.close()
    finally:
        boat.close()
    assert st.rejected > 0 and (later.state, later.active_id) == (0, 0)
    assert floor.read_text().split()[2:] == ["exact"]
