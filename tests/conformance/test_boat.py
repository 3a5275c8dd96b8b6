"""usv-link 2 conformance: what every boat must do, checked on the boat process's pty.

Times are the boat's own (its uptime in USV_MISSION_STATE), never the wall clock.
"""

from __future__ import annotations

import asyncio
import time

from rig import USV_MISSION_ACK, WALL_FACTOR, Rig, foreign_codec, msg_id, settle

from usvstation.link import wire
from usvstation.link.mavlink import usv_recovery as mav
from usvstation.link.protocol import BoatReport, ReadbackResult
from usvstation.services.missions import MissionRecord, MissionStatus


def _run(coro) -> None:
    asyncio.run(coro)


def _record(mission) -> MissionRecord:
    return MissionRecord("m", "p", mission.mission_id, "t",
                         {"lat": 30.5135, "lon": 114.4182, "ramp_bearing_deg": 90.0},
                         [it.as_dict() for it in mission.items])


def _reports(rig: Rig) -> list:
    return [e.report for _, e in rig.events if isinstance(e, BoatReport)]


def test_mavutil_sees_a_surface_boat_and_its_position(boat):
    """pymavlink's own mavutil, a client this project did not write, on the boat's pty."""
    from pymavlink import mavutil

    conn = mavutil.mavlink_connection(boat.device, baud=57600, dialect="common")
    try:
        hb = conn.recv_match(type="HEARTBEAT", blocking=True, timeout=10)
        assert hb is not None and hb.type == mavutil.mavlink.MAV_TYPE_SURFACE_BOAT
        assert hb.get_srcSystem() == 1
        pos = conn.recv_match(type="GLOBAL_POSITION_INT", blocking=True, timeout=10)
        assert pos is not None and abs(pos.lat / 1e7 - 30.5135) < 0.01
    finally:
        conn.close()


def test_echo_after_silence_fails_safe_within_3_5_s(boat):
    async def main():
        async with Rig(boat) as rig:
            m = rig.mission_here(11, n=6, speed=0.8)
            await rig.run_mission(m)
            silent_at = rig.proto.boat_uptime_ms(rig.proto.now)
            rig.radio.echo = True  # the boat hears its own frames from now on
            rig.radio.silent = True
            await rig.until(lambda: rig.report.state == "FAILSAFE", 6.0)
            first = next(r for r in _reports(rig) if r.state == "FAILSAFE")
            assert first.uptime_ms - silent_at <= 3500
            assert any("failsafe" in t for t in rig.texts())

    _run(main())


def test_a_second_boat_is_counted_not_stored_and_failsafe_stays(boat):
    async def main():
        async with Rig(boat) as rig:
            other = foreign_codec(2, rig.key, component=1)
            m = rig.mission_here(12, n=6, speed=0.8)
            await rig.run_mission(m)
            rig.radio.silent = True
            silent_at = rig.proto.boat_uptime_ms(rig.proto.now)
            fake = other.mav
            # another boat, same key, 5 Hz, on both sides of the radio, for up to 5 s of the
            # boat's own time (the firmware in QEMU on a busy machine runs slower than ours)
            wall_end = time.monotonic() + 5.0 * WALL_FACTOR
            while rig.report.uptime_ms - silent_at < 5000 and time.monotonic() < wall_end:
                frames = other.encode(fake.heartbeat_encode(
                    mav.MAV_TYPE_SURFACE_BOAT, mav.MAV_AUTOPILOT_GENERIC, 0, 2, 4))
                frames += other.encode(fake.global_position_int_encode(
                    1, 10 * 10**7, 10 * 10**7, 0, 0, 0, 0, 0, 0))
                await rig.radio.inject(frames)  # to the boat
                rig.link._dispatch(rig.proto.receive_data(frames, rig.proto.now))  # station
                await settle(0.2)
                if rig.report.state == "FAILSAFE":
                    break
            assert rig.report.state == "FAILSAFE"
            first = next(r for r in _reports(rig) if r.state == "FAILSAFE")
            assert first.uptime_ms - silent_at <= 3500
            assert rig.proto.other_systems[2] >= 2
            assert abs(rig.link.telemetry.lat - 30.5135) < 0.01  # never the other boat's

    _run(main())


def test_replayed_signed_session_to_a_rebooted_boat_does_nothing(boat):
    async def main():
        async with Rig(boat) as rig:
            m = rig.mission_here(13, n=6, speed=0.8)
            await rig.run_mission(m)
            recorded = b"".join(rig.radio.tap)
        boat.restart()  # reboot: same non-volatile memory
        observer = wire.Codec(254, 190, wire.read_key(boat.key_path))
        from usvstation.link.transport import SerialStream

        port = await SerialStream.open(boat.device, 57600)
        try:
            reports = []

            async def listen():
                while True:
                    msgs, _ = observer.feed(await port.read())
                    reports.extend(x for x in msgs if x.get_type() == "USV_MISSION_STATE")

            task = asyncio.get_running_loop().create_task(listen())
            for i in range(0, len(recorded), 256):  # the whole session, at line speed
                await port.write(recorded[i:i + 256])
                await asyncio.sleep(256 * 10 / 57600)
            # 2.5 s of the boat's own time for the last frames to be judged
            wall_end = time.monotonic() + 2.5 * WALL_FACTOR
            seen = None
            while time.monotonic() < wall_end:
                await settle(0.1)
                if reports and seen is None:
                    seen = reports[-1].uptime_ms
                if seen is not None and reports[-1].uptime_ms - seen >= 2500:
                    break
            task.cancel()
            assert reports, "the rebooted boat reports"
            last = reports[-1]
            assert last.active_id == 0 and last.state == 0  # IDLE, nothing activated
            assert last.rejected > 0 and last.station_session == 0
        finally:
            await port.close()

    _run(main())


def test_unsigned_and_forged_start_mission_and_guidance_are_refused(boat):
    async def main():
        async with Rig(boat) as rig:
            m = rig.mission_here(14, n=6, speed=0.8)
            assert (await rig.link.upload_mission(m)).ok
            await rig.until(lambda: rig.report.state == "READY", 5.0)
            before = rig.report.rejected
            for key in (None, bytes(32)):  # unsigned; signed with the wrong key
                bad = foreign_codec(255, key)
                e = bad.mav
                await rig.radio.inject(
                    bad.encode(e.command_int_encode(1, 1, 0, mav.MAV_CMD_USV_START, 0, 0, 1.0,
                                                    77.0, 0, 0, wire.to_i32(m.mission_id),
                                                    wire.to_i32(m.crc), 0))
                    + bad.encode(e.usv_mission_begin_encode(1, 1, 99, 1, 2, 0))
                    + bad.encode(e.usv_guidance_encode(1, 1, 9000, 300, 5000)))
            # the boat counts each refusal in its next report (about 1 Hz of its time)
            await rig.until(lambda: rig.report.rejected - before >= 6, 15.0)
            assert rig.report.state == "READY" and rig.report.active_id == m.mission_id
            assert rig.report.staged_id == 0
            assert any("refused" in t for t in rig.texts())

    _run(main())


def test_station_restart_mid_run_then_hold_and_abort_act(boat):
    async def main():
        async with Rig(boat, session=111) as rig:
            m = rig.mission_here(15, n=6, speed=1.0)
            await rig.run_mission(m)
            start_seq = rig.proto.commands._next_seq - 1
        # a new station process: another session whose first command reuses the old seq
        async with Rig(boat, session=222) as rig:
            rig.proto.commands._next_seq = start_seq
            assert rig.report.state == "RUNNING"
            out = await rig.link.command("hold")
            assert out.accepted and out.seq == start_seq
            await rig.until(lambda: rig.report.state == "HOLD", 3.0)
            await rig.until(lambda: rig.link.telemetry.speed < 0.5, 15.0)  # it slows down ...
            assert rig.report.state == "HOLD"
            out = await rig.link.command("abort")
            assert out.accepted
            await rig.until(lambda: rig.report.state == "ABORTED", 3.0)
            assert rig.report.active_id == 0
            await rig.until(lambda: rig.link.telemetry.speed < 0.05, 15.0)  # ... and stops

    _run(main())


def test_lost_mission_end_ack_station_state_equals_the_boats(boat):
    async def main():
        async with Rig(boat) as rig:
            m = rig.mission_here(16, n=6)
            # every USV_MISSION_ACK for END (stage 3) is lost on the way back
            rig.radio.drop_down = lambda f: msg_id(f) == USV_MISSION_ACK and len(f) > 19 \
                and f[19] == 3
            result = await rig.link.upload_mission(m)
            assert not result.ok and "USV_MISSION_END" in result.reason
            rec = _record(m)
            rec.state = MissionStatus.FAILED
            rec.apply(rig.report)
            assert rig.report.active_id == m.mission_id and rig.report.state == "READY"
            assert rec.state == MissionStatus.VERIFIED

    _run(main())


def test_boat_reboot_after_verify_mission_gone_within_two_heartbeats(boat):
    async def main():
        async with Rig(boat) as rig:
            m = rig.mission_here(17, n=6)
            assert (await rig.link.upload_mission(m)).ok
            await rig.until(lambda: rig.report.active_id == m.mission_id, 5.0)
            rec = _record(m)
            rec.apply(rig.report)
            assert rec.state == MissionStatus.VERIFIED
            old_boot = rig.report.boot_id
            boat.restart()
            await rig.until(lambda: rig.report.boot_id != old_boot, 15.0)
            first = next(r for r in _reports(rig) if r.boot_id != old_boot)
            assert first.uptime_ms <= 2000  # within two boat heartbeats of the boot
            rec.apply(first)
            assert rec.state == MissionStatus.GONE

    _run(main())


def test_hot_swap_under_20_percent_loss_old_then_new_never_a_mixture(boat):
    async def main():
        async with Rig(boat, seed=5) as rig:
            old = rig.mission_here(18, n=8, speed=0.6)
            await rig.run_mission(old)
            rig.radio.up_loss = rig.radio.down_loss = 0.2
            new = rig.mission_here(19, n=8, speed=0.6, dy=6.0)
            swap_at = rig.proto.boat_uptime_ms(rig.proto.now) + 8000
            result = await rig.link.upload_mission(new, swap_at_ms=swap_at)
            assert result.ok, result
            await rig.until(lambda: rig.report.active_id == new.mission_id, 15.0)
            ids = [r.active_id for r in _reports(rig) if r.active_id]
            first_new = ids.index(new.mission_id)
            assert set(ids[:first_new]) == {old.mission_id}
            assert set(ids[first_new:]) == {new.mission_id}
            swapped = next(r for r in _reports(rig) if r.active_id == new.mission_id)
            assert swapped.uptime_ms >= swap_at and swapped.state == "RUNNING"
            assert swapped.active_crc32 == new.crc
            rb = await rig.link.read_mission(new.mission_id, new.count)
            assert isinstance(rb, ReadbackResult) and rb.items == new.items

    _run(main())


def test_commands_end_within_bounded_time_when_the_boat_is_silent(boat):
    async def main():
        async with Rig(boat) as rig:
            rig.radio.drop_down = lambda f: True  # the boat's answers never arrive
            out = await rig.link.command("hold")  # returns: retries and link loss are bounded
            assert out.result is None and out.error

    _run(main())
