"""The link over a real pseudo-terminal pair, in real time: the station (BoatLink on
pyserial-asyncio, opening the pty's slave device) and the simulated boat (on the master),
plus the `usv-station sim` and `link-key` commands."""

from __future__ import annotations

import asyncio
import itertools
import os
import subprocess
import sys
import time

import pytest

from usvstation.geo import RampFrame
from usvstation.link import wire
from usvstation.link.mission import mission_from_plan
from usvstation.link.protocol import LinkConfig, StatusTextReceived, TelemetryReceived
from usvstation.link.station import BoatLink, LinkError
from usvstation.link.transport import PtyPair, SerialStream
from usvstation.sim.boat import BoatConfig
from usvstation.sim.runner import SimulatedBoat, make_boat

FRAME = RampFrame(30.5135, 114.4182, 90.0)
KEY = bytes(range(3, 35))
EXE = os.path.join(os.path.dirname(sys.executable), "usv-station")


def mission(n: int = 8, mission_id: int = 3):
    wps = [{"x": 85.0 - 2.5 * i, "y": 10.0 + (0 if i == 0 else (-1) ** i), "t": 2.0 * i,
            "speed": 1.3, "heading_deg": 180.0} for i in range(n)]
    return mission_from_plan(wps, FRAME, mission_id)


class Rig:
    def __init__(self, *, boat_cfg: BoatConfig | None = None) -> None:
        self.pair = PtyPair()
        self.boat = make_boat(FRAME, config=boat_cfg or BoatConfig(), seed=3, key=KEY)
        self.events: list = []

    async def __aenter__(self) -> Rig:
        self.stop = asyncio.Event()
        self.task = asyncio.get_running_loop().create_task(
            SimulatedBoat(self.boat).run(self.pair.master_stream(), self.stop))
        self.link = BoatLink(stream_factory=lambda: SerialStream.open(self.pair.slave_path),
                             reconnect_s=0.2, key=KEY, config=LinkConfig())
        self.link.add_listener(lambda ev: self.events.append((time.monotonic(), ev)))
        await self.link.start()
        assert await self.link.wait_link_up(5.0)
        return self

    async def __aexit__(self, *exc) -> None:
        await self.link.close()
        self.stop.set()
        await self.task
        self.pair.close()

    def of(self, cls):
        return [e for _, e in self.events if isinstance(e, cls)]

    async def until(self, cond, timeout: float) -> None:
        end = time.monotonic() + timeout
        while not cond():
            assert time.monotonic() < end, "timed out"
            await asyncio.sleep(0.01)


def test_upload_start_and_telemetry_over_a_pty():
    async def main():
        async with Rig(boat_cfg=BoatConfig(sim_speed=5.0)) as rig:
            ms = mission()
            progress = []
            res = await rig.link.upload_mission(ms, progress_cb=progress.append)
            assert res.ok and rig.boat.active.items == ms.items
            assert progress[-1].acked == ms.count
            out = await rig.link.command("start", ms.mission_id, ms.crc)
            assert out.accepted
            n0 = len(rig.of(TelemetryReceived))
            await rig.until(lambda: len(rig.of(TelemetryReceived)) - n0 >= 15, 10.0)
            tel = [e.telemetry for e in rig.of(TelemetryReceived)[n0:]]
            gaps = {round((b.time_s - a.time_s) * 1000) for a, b in itertools.pairwise(tel)}
            assert gaps == {200}  # 5 Hz on the boat's own clock, a fixed grid
            assert tel[-1].state == "RUNNING" and tel[-1].speed > 0
            assert rig.link.report.active_id == ms.mission_id
            assert rig.link.protocol.refused == {}

    asyncio.run(main())


def test_station_port_closed_boat_fails_safe_and_reconnect_resumes():
    async def main():
        async with Rig() as rig:
            ms = mission(6)
            assert (await rig.link.upload_mission(ms)).ok
            assert (await rig.link.command("start", ms.mission_id, ms.crc)).accepted
            rig.link.reconnect_s = 5.0  # stay away long enough for the failsafe
            await rig.link.disconnect()
            assert not rig.link.link_up  # the station knows at once: its port is closed
            with pytest.raises(LinkError, match="link is down"):
                await rig.link.command("hold")
            await rig.until(lambda: rig.boat.state == 6, 5.0)  # FAILSAFE
            assert await rig.link.wait_link_up(8.0)  # reopened: same boat, no restart
            await rig.until(lambda: rig.link.report.state == "FAILSAFE", 3.0)
            texts = [e.text for e in rig.of(StatusTextReceived)]
            assert any("RESUME or ABORT" in t for t in texts)
            assert (await rig.link.command("resume")).accepted
            await rig.until(lambda: rig.link.report.state == "RUNNING", 3.0)

    asyncio.run(main())


def test_link_key_new_and_the_sim_cli_on_a_pty(tmp_path):
    key = tmp_path / "k"
    out = subprocess.run([EXE, "link-key", "new", str(key)], capture_output=True, text=True)
    assert out.returncode == 0 and len(wire.read_key(key)) == 32
    again = subprocess.run([EXE, "link-key", "new", str(key)], capture_output=True, text=True)
    assert again.returncode == 2 and "refusing to overwrite" in again.stderr
    bare = subprocess.run([EXE, "sim", "--link", "pty", "--duration", "1"],
                          capture_output=True, text=True)
    assert bare.returncode == 2 and "--link-key PATH" in bare.stderr
    proc = subprocess.Popen([EXE, "sim", "--link", "pty", "--telemetry-hz", "20",
                             "--link-key", str(key), "--duration", "20"],
                            stdout=subprocess.PIPE, text=True)
    try:
        line = proc.stdout.readline()
        assert "boat on /dev/" in line and "signed" in line, line
        path = line.split("boat on ")[1].split()[0]

        async def main():
            link = BoatLink(path, baud=57600, key=wire.read_key(key))
            async with link:
                assert await link.wait_link_up(5.0)
                tel = []
                async for t in link.telemetry_stream():
                    tel.append(t)
                    if len(tel) == 10:
                        break
                assert link.report.state == "IDLE"
                assert all(abs(t.lat - 30.5135) < 0.01 for t in tel)

        asyncio.run(main())
    finally:
        proc.terminate()
        proc.wait(10)
        proc.stdout.close()


def test_serve_refuses_a_real_link_without_a_key(tmp_path):
    out = subprocess.run([EXE, "serve", "--link", "/dev/null", "--data-dir", str(tmp_path)],
                         capture_output=True, text=True, timeout=60)
    assert out.returncode == 2 and "--link-key PATH" in out.stderr
