"""Any ground station can watch a recovery (docs/link.md "Standard MAVLink"): every boat
answers the standard mission protocol for reading and sends the standard telemetry a
ground station shows; a ground station with the link's key reads but cannot command, one
without it (or with another key) gets nothing.

The second ground station is pymavlink's common dialect (the codec MAVProxy is built on)
with MAVLink 2 signing set up as MAVProxy's `signing setup KEY` sets it, and pymavlink's
`mavwp.MAVWPLoader` collecting the items: code this project did not write. It shares the
boat's radio with the station (the conformance rig): its frames go to the boat beside the
station's, and it hears every boat frame.
"""

from __future__ import annotations

import asyncio
import math
import time

from pymavlink import mavutil, mavwp
from pymavlink.dialects.v20 import common
from rig import FRAME, Rig

from usvstation.link.mission import Mission, mission_from_plan

GCS_ID = 250
EPOCH_2015 = 1420070400


class Gcs:
    """A second ground station on the rig's radio (see the module doc)."""

    def __init__(self, rig: Rig, key: bytes | None, system_id: int = GCS_ID) -> None:
        self.rig = rig
        self.mav = common.MAVLink(None, srcSystem=system_id, srcComponent=190)
        self.mav.robust_parsing = True
        if key is not None:  # what mavutil's setup_signing (MAVProxy `signing setup`) does
            self.mav.signing.secret_key = key
            self.mav.signing.sign_outgoing = True
            self.mav.signing.link_id = 1
            self.mav.signing.timestamp = int((time.time() - EPOCH_2015) * 100_000)
        self.heard: list = []
        self.sent = 0  # frames injected (ask repeats its request)
        rig.radio.drop_down = self._hear  # hears every boat frame, drops none

    def _hear(self, frame: bytes) -> bool:
        for m in self.mav.parse_buffer(frame) or ():
            if m.get_type() not in ("BAD_DATA", "UNKNOWN") and \
                    getattr(m, "target_system", GCS_ID) in (0, GCS_ID):
                self.heard.append(m)
        return False

    async def send(self, msg) -> None:
        data = msg.pack(self.mav)
        self.mav.seq = (self.mav.seq + 1) % 256
        self.sent += 1
        await self.rig.radio.inject(data)

    def latest(self, kind: str):
        return next((m for m in reversed(self.heard) if m.get_type() == kind), None)

    async def ask(self, msg, kinds: tuple[str, ...], timeout: float = 5.0):
        """Send `msg` (again every 0.5 s) until a message of `kinds` arrives; None if not."""
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            start = len(self.heard)
            await self.send(msg)
            for _ in range(25):
                await asyncio.sleep(0.02)
                got = next((m for m in self.heard[start:] if m.get_type() in kinds), None)
                if got is not None:
                    return got
        return None

    async def download(self) -> mavwp.MAVWPLoader:
        """The mission, as MAVProxy's `wp list` gets it: count, then each item."""
        count = await self.ask(self.mav.mission_request_list_encode(1, 1, 0), ("MISSION_COUNT",))
        assert count is not None, "no MISSION_COUNT"
        loader = mavwp.MAVWPLoader(target_system=1, target_component=1)
        for seq in range(count.count):
            item = await self.ask(self.mav.mission_request_int_encode(1, 1, seq, 0),
                                  ("MISSION_ITEM_INT",))
            assert item is not None and item.seq == seq, f"no item {seq}"
            loader.add(item)
        await self.send(self.mav.mission_ack_encode(1, 1, 0, 0))
        return loader


def _mode(gcs: Gcs) -> str | None:
    """The boat's mode as pymavlink (and so MAVProxy) names it from its last HEARTBEAT."""
    hb = gcs.latest("HEARTBEAT")
    return None if hb is None else mavutil.mode_string_v10(hb)


def _plan(rig: Rig, n: int = 12, speed: float = 0.9) -> tuple[list[dict], Mission]:
    """A timed plan from the boat's position towards the ramp, its speed changing from
    waypoint to waypoint, timed as the planners time theirs (paper 000 eq. 11)."""
    x0, y0 = rig.position()
    wps, t = [], 0.0
    for i in range(n):
        f = i / (n - 1)
        x, y = x0 * (1 - f), y0 * (1 - f) + 2.0 * math.sin(math.pi * f)
        v = speed * (1 + 0.2 * (i % 3))
        if wps:
            a = wps[-1]
            t += 2 * math.hypot(x - a["x"], y - a["y"]) / (a["speed"] + v)
        wps.append({"x": x, "y": y, "t": t, "speed": v, "heading_deg": 180.0})
    return wps, mission_from_plan(wps, FRAME, 4242)


def test_keyed_gcs_downloads_the_mission_and_sees_the_recovery(boat):
    async def main():
        async with Rig(boat) as rig:
            gcs = Gcs(rig, rig.key)
            wps, mission = _plan(rig)
            await rig.run_mission(mission)
            loader = await gcs.download()
            items = [loader.wp(i) for i in range(loader.count())]
            nav = [it for it in items if it.command == common.MAV_CMD_NAV_WAYPOINT]
            speeds = [it for it in items if it.command == common.MAV_CMD_DO_CHANGE_SPEED]
            assert len(nav) == len(wps) and len(speeds) == len(wps) - 1
            lat, lon = FRAME.to_geodetic([w["x"] for w in wps], [w["y"] for w in wps])
            for i, it in enumerate(nav):
                assert abs(it.x * 1e-7 - lat[i]) <= 1e-7 and abs(it.y * 1e-7 - lon[i]) <= 1e-7
            for i, it in enumerate(speeds):
                a, b = wps[i], wps[i + 1]
                planned = math.hypot(b["x"] - a["x"], b["y"] - a["y"]) / (b["t"] - a["t"])
                assert abs(it.param2 - planned) < 0.01, (i, it.param2, planned)
            def running() -> bool:  # as a ground station sees RUNNING
                cur = gcs.latest("MISSION_CURRENT")
                return _mode(gcs) == "AUTO" and cur is not None and cur.total == len(items) \
                    and cur.mission_state == common.MISSION_STATE_ACTIVE \
                    and gcs.latest("MISSION_ITEM_REACHED") is not None

            await rig.until(running, 10.0)
            assert gcs.latest("HEARTBEAT").base_mode & common.MAV_MODE_FLAG_SAFETY_ARMED
            assert gcs.latest("MISSION_CURRENT").seq % 2 == 0  # a NAV_WAYPOINT
            for kind in ("GLOBAL_POSITION_INT", "VFR_HUD", "SYS_STATUS", "ATTITUDE",
                         "GPS_RAW_INT"):
                await rig.until(lambda k=kind: gcs.latest(k) is not None, 5.0)
            pos = gcs.latest("GLOBAL_POSITION_INT")
            assert abs(pos.lat * 1e-7 - lat[0]) < 0.001
            await rig.link.command("hold")
            await rig.until(lambda: _mode(gcs) == "LOITER" and gcs.latest(
                "MISSION_CURRENT").mission_state == common.MISSION_STATE_PAUSED, 5.0)

    asyncio.run(main())


def test_keyed_gcs_reads_but_cannot_command(boat):
    async def main():
        async with Rig(boat) as rig:
            gcs = Gcs(rig, rig.key)
            _, mission = _plan(rig, n=6)
            await rig.run_mission(mission)
            before = rig.report.rejected
            m = gcs.mav
            for msg in (m.command_long_encode(1, 1, common.MAV_CMD_DO_SET_MODE, 0, 1, 4, 0, 0,
                                              0, 0, 0),
                        m.command_int_encode(1, 1, 0, 44103, 0, 0, 1, 99, 0, 0, 0, 0, 0),
                        m.mission_count_encode(1, 1, 3, 0),
                        m.mission_clear_all_encode(1, 1, 0),
                        m.set_mode_encode(1, 1, 4),
                        m.set_position_target_global_int_encode(
                            0, 1, 1, 6, 3520, 305135000, 1144182000, 0, 0, 0, 0, 0, 0, 0, 0, 0)):
                await gcs.send(msg)
            await rig.until(lambda: rig.report.rejected - before >= 6, 15.0)
            assert rig.report.state == "RUNNING" and rig.report.active_id == mission.mission_id
            assert not any(h.get_type() in ("COMMAND_ACK", "MISSION_REQUEST_INT",
                                            "MISSION_REQUEST") for h in gcs.heard)
            count = await gcs.ask(m.mission_request_list_encode(1, 1, 0), ("MISSION_COUNT",))
            assert count is not None and count.count == 2 * mission.count - 1  # still reads

    asyncio.run(main())


def test_gcs_without_the_key_or_with_another_gets_nothing(boat):
    async def main():
        async with Rig(boat) as rig:
            _, mission = _plan(rig, n=6)
            assert (await rig.link.upload_mission(mission)).ok
            await rig.until(lambda: rig.report.state == "READY", 5.0)
            before, sent = rig.report.rejected, 0
            for key in (None, bytes(range(32))):
                gcs = Gcs(rig, key, system_id=GCS_ID)
                m = gcs.mav
                assert await gcs.ask(m.mission_request_list_encode(1, 1, 0), ("MISSION_COUNT",),
                                     timeout=2.0) is None
                await gcs.send(m.command_int_encode(1, 1, 0, 44103, 0, 0, 1, 99, 0, 0, 0, 0, 0))
                sent += gcs.sent
            # every frame is refused (the asks repeat theirs: fewer on a busy machine)
            await rig.until(lambda: rig.report.rejected - before >= sent, 15.0)
            assert rig.report.state == "READY" and rig.report.active_id == mission.mission_id

    asyncio.run(main())
