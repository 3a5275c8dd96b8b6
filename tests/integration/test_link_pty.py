"""The link over a real pseudo-terminal pair: station (BoatLink on pyserial-asyncio, opening
the pty's slave device) and the simulated boat (on the master), in real time."""

from __future__ import annotations

import asyncio
import itertools
import os
import statistics
import subprocess
import sys
import time

import pytest

from usvstation.geo import RampFrame
from usvstation.link import messages as m
from usvstation.link.mission import mission_from_plan
from usvstation.link.protocol import LinkDown, LinkUp, StatusTextReceived, TelemetryReceived
from usvstation.link.station import BoatLink, LinkError
from usvstation.link.transport import FaultInjectingStream, PtyPair, SerialStream
from usvstation.sim.boat import BoatConfig
from usvstation.sim.runner import SimulatedBoat, make_boat

FRAME = RampFrame(30.5135, 114.4182, 90.0)


def mission(n: int = 32, mission_id: int = 3):
    wps = [{"x": 80.0 - 2.5 * i, "y": (-1) ** i * 2.0, "t": 2.0 * i, "speed": 1.3,
            "heading_deg": 180.0} for i in range(n)]
    return mission_from_plan(wps, FRAME, mission_id)


class Rig:
    def __init__(self, *, boat_cfg: BoatConfig | None = None, radio: bool = False) -> None:
        self.pair = PtyPair()
        self.boat = make_boat(FRAME, config=boat_cfg or BoatConfig(), seed=3)
        self.radio = radio
        self.station_radio: FaultInjectingStream | None = None
        self.events: list = []

    async def __aenter__(self) -> Rig:
        stream = self.pair.master_stream()
        self.boat_stream = FaultInjectingStream(stream) if self.radio else stream
        self.stop = asyncio.Event()
        self.task = asyncio.get_running_loop().create_task(
            SimulatedBoat(self.boat).run(self.boat_stream, self.stop))

        async def factory():
            inner = await SerialStream.open(self.pair.slave_path, 57600)
            if not self.radio:
                return inner
            self.station_radio = FaultInjectingStream(inner)
            return self.station_radio

        self.link = BoatLink(stream_factory=factory, reconnect_s=0.2)
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
        return [(t, e) for t, e in self.events if isinstance(e, cls)]

    async def until(self, cond, timeout: float) -> float:
        t0 = time.monotonic()
        while not cond():
            if time.monotonic() - t0 > timeout:
                raise AssertionError("timed out")
            await asyncio.sleep(0.01)
        return time.monotonic() - t0


def test_upload_start_and_telemetry_over_a_pty():
    async def main():
        async with Rig(boat_cfg=BoatConfig(sim_speed=5.0)) as rig:
            ms = mission()
            progress = []
            res = await rig.link.upload_mission(ms, progress_cb=progress.append)
            assert res.ok and rig.boat.active.items == ms.items
            assert [p.acked for p in progress][-1] == 32
            ack = await rig.link.command("start", mission_id=ms.mission_id)
            assert ack.accepted and ack.state == m.State.RUNNING
            n0 = len(rig.of(TelemetryReceived))
            await asyncio.sleep(1.0)
            tel = [e.telemetry for _, e in rig.of(TelemetryReceived)[n0:]]
            # 5 Hz of boat time at sim speed 5: 25 frames a second on the link, 200 ms apart
            assert 20 <= len(tel) <= 27
            assert tel[-1].state == m.State.RUNNING and tel[-1].sog_cms > 0
            gaps = [b.time_ms - a.time_ms for a, b in itertools.pairwise(tel)]
            assert statistics.median(gaps) == pytest.approx(200, abs=20)
            lat, lon = tel[-1].lat_e7 / 1e7, tel[-1].lon_e7 / 1e7
            x, _ = FRAME.to_ramp(lat, lon)
            assert 40 < x < 85  # on its way along the mission
            assert rig.link.boat_state.mission_id == ms.mission_id

    asyncio.run(main())


def test_station_port_closed_boat_fails_safe_and_reconnect_resumes():
    async def main():
        async with Rig() as rig:
            ms = mission(6)
            assert (await rig.link.upload_mission(ms)).ok
            assert (await rig.link.command("start", ms.mission_id)).accepted
            rig.link.reconnect_s = 5.0  # stay away long enough for the failsafe
            t_close = time.monotonic()
            await rig.link.disconnect()
            assert not rig.link.link_up  # the station knows at once: its port is closed
            with pytest.raises(LinkError, match="link is down"):
                await rig.link.command("hold")
            waited = await rig.until(lambda: rig.boat.failsafe, 4.0)
            assert waited <= 3.5
            assert rig.boat.state == m.State.HOLD
            assert time.monotonic() - t_close >= 2.9
            assert await rig.link.wait_link_up(5.0)  # reopened: same boat, no restart
            n0 = len(rig.of(TelemetryReceived))
            await asyncio.sleep(1.0)
            assert len(rig.of(TelemetryReceived)) - n0 >= 4
            texts = [e.text for _, e in rig.of(StatusTextReceived)]
            assert any("RESUME" in t for t in texts)
            assert (await rig.link.command("resume")).state == m.State.RUNNING

    asyncio.run(main())


def test_silent_radio_detected_by_both_sides_within_3_5_s():
    async def main():
        async with Rig(radio=True) as rig:
            ms = mission(6)
            assert (await rig.link.upload_mission(ms)).ok
            assert (await rig.link.command("start", ms.mission_id)).accepted
            rig.boat_stream.enabled = rig.station_radio.enabled = False  # no bytes either way
            t_off = time.monotonic()
            await rig.until(lambda: rig.boat.failsafe and not rig.link.link_up, 4.0)
            t_down = rig.of(LinkDown)[-1][0] - t_off
            assert t_down <= 3.5 and time.monotonic() - t_off <= 3.6
            assert rig.boat.state == m.State.HOLD
            rig.boat_stream.enabled = rig.station_radio.enabled = True
            assert await rig.link.wait_link_up(3.0)
            n0 = len(rig.of(TelemetryReceived))
            await asyncio.sleep(0.7)
            assert len(rig.of(TelemetryReceived)) > n0
            assert [type(e) for _, e in rig.events if isinstance(e, LinkUp | LinkDown)] == \
                [LinkUp, LinkDown, LinkUp]

    asyncio.run(main())


def test_usv_station_sim_cli_on_a_pty():
    """`usv-station sim --link pty` prints its device; a station connects and gets telemetry."""
    exe = os.path.join(os.path.dirname(sys.executable), "usv-station")
    proc = subprocess.Popen([exe, "sim", "--link", "pty", "--telemetry-hz", "20",
                             "--sim-speed", "4", "--duration", "20"],
                            stdout=subprocess.PIPE, text=True)
    try:
        line = proc.stdout.readline()
        assert "boat on /dev/" in line, line
        path = line.split("boat on ")[1].split()[0]

        async def main():
            link = BoatLink(path, baud=57600)
            async with link:
                assert await link.wait_link_up(5.0)
                tel = []
                async for t in link.telemetry_stream():
                    tel.append(t)
                    if len(tel) == 10:
                        break
                assert all(t.fix_type == m.FixType.FIX_3D for t in tel)
                assert link.boat_state.sender == m.Sender.BOAT

        asyncio.run(main())
    finally:
        proc.terminate()
        proc.wait(10)
