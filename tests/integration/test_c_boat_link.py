"""The C boat (protocol/c/boat) on a loopback socket, driven with pymavlink as the station.

Every test starts the host build on an ephemeral 127.0.0.1 port; times are the boat's own
(USV_MISSION_STATE.uptime_ms, TIMESYNC), never this machine's wall clock.
"""

from __future__ import annotations

import contextlib
import re
import time

import pytest
from c_boat_support import (
    ABORTED,
    BOAT_ID,
    CMD_ABORT,
    CMD_HOLD,
    CMD_RESUME,
    CMD_START,
    DONE,
    FAILSAFE,
    GO_AROUND,
    HOLD,
    IDLE,
    READY,
    RUNNING,
    CBoat,
    Item,
    MavClient,
    build_c_boat,
    c_compiler,
    heartbeats,
    line_north,
    load_dialect,
    mission_crc32,
    u32,
)
from hypothesis import strategies as st

pytestmark = pytest.mark.skipif(c_compiler() is None,
                                reason="no C compiler (cc/gcc) to build protocol/c/boat")

ACCEPTED, DENIED, UNSUPPORTED = 0, 2, 3
M_ACCEPTED, M_BAD_COUNT, M_UNKNOWN, M_OUT_OF_RANGE, M_DENIED, M_EXPIRED = 0, 2, 3, 5, 8, 9
REASON_MISMATCH, REASON_TOO_FAR = 2, 4


@pytest.fixture(scope="module")
def exe(tmp_path_factory):
    return build_c_boat(tmp_path_factory.mktemp("cboat"))


@pytest.fixture(scope="module")
def d():
    return load_dialect()


@pytest.fixture
def key_path(tmp_path):
    from usvstation.link.wire import write_key

    path = tmp_path / "link.key"
    write_key(path)
    return path


@contextlib.contextmanager
def boat_and_station(exe, d, key_path, **kw):
    boat = CBoat.start(exe, key=key_path, **kw)
    client = None
    try:
        client = MavClient(d, port=boat.port, key=bytes.fromhex(key_path.read_text()))
        yield boat, client
    finally:
        if client is not None:
            client.close()
        boat.close()


def upload_and_start(c, mission_id, items, seq=1, session=4242):
    assert c.upload(mission_id, items).result == M_ACCEPTED
    ack = c.command(CMD_START, seq, session, mission_id, mission_crc32(mission_id, items))
    assert ack.result == ACCEPTED
    return c.wait_state(RUNNING, 10)


def boat_uptime_now(c) -> int:
    """The boat's uptime (ms) at the instant it received our TIMESYNC (a station frame)."""
    ts1 = time.monotonic_ns()
    start = c.mark()
    c.send(c.d.MAVLink_timesync_message(0, ts1))
    reply = c.wait_for(lambda m: m.get_type() == "TIMESYNC" and m.ts1 == ts1, 10, start)
    return reply.tc1 // 1_000_000


def test_telemetry_signed_and_complete(exe, d, key_path):
    with boat_and_station(exe, d, key_path) as (_, c), heartbeats(c):
        c.wait_for(lambda m: m.get_type() == "USV_MISSION_STATE")
        c.wait_for(lambda m: m.get_type() == "USV_THRUST", start=c.mark())
        kinds = {m.get_type() for m in c.msgs}
        hb = c.of_type("HEARTBEAT")[0]
    assert {"HEARTBEAT", "GLOBAL_POSITION_INT", "ATTITUDE", "VFR_HUD", "GPS_RAW_INT",
            "SYS_STATUS", "USV_THRUST", "USV_MISSION_STATE"} <= kinds
    assert hb.type == d.MAV_TYPE_SURFACE_BOAT and hb.custom_mode == 4  # IDLE: Rover HOLD
    assert hb.get_srcSystem() == BOAT_ID
    assert all(m.get_signed() for m in c.msgs)  # every boat frame carries a signature
    # USV_MISSION_STATE follows every HEARTBEAT
    order = [m.get_type() for m in c.msgs]
    for i, kind in enumerate(order[:-3]):
        if kind == "HEARTBEAT":
            assert "USV_MISSION_STATE" in order[i + 1:i + 4]


def test_mavutil_sees_a_surface_boat(exe, key_path):
    from pymavlink import mavutil

    boat = CBoat.start(exe, key=key_path)
    conn = None
    try:
        conn = mavutil.mavlink_connection(f"tcp:127.0.0.1:{boat.port}", source_system=255)
        hb = conn.recv_match(type="HEARTBEAT", blocking=True, timeout=15)
        pos = conn.recv_match(type="GLOBAL_POSITION_INT", blocking=True, timeout=15)
    finally:
        if conn is not None:
            conn.close()
        boat.close()
    assert hb is not None and hb.type == mavutil.mavlink.MAV_TYPE_SURFACE_BOAT
    assert pos is not None and abs(pos.lat / 1e7 - 59.9) < 1e-4


def test_whole_mission_then_readback(exe, d, key_path):
    items = line_north(4, step_m=20, leg_s=10)
    with boat_and_station(exe, d, key_path, speedup=10) as (_, c), heartbeats(c):
        upload_and_start(c, 7, items)
        st = c.wait_state(DONE, 60)
        assert (st.active_id, st.active_count) == (7, 4)
        assert st.uptime_ms >= items[-1].t_ms
        for seq, it in enumerate(items):
            start = c.mark()
            c.send(d.MAVLink_usv_mission_read_message(BOAT_ID, 1, 7, seq))
            back = c.wait_for(lambda m: m.get_type() == "USV_MISSION_ITEM", 10, start)
            assert (back.seq, back.lat, back.lon, back.t_ms, back.speed_cms) == \
                (seq, it.lat, it.lon, it.t_ms, it.speed_cms)
        gp = c.of_type("GLOBAL_POSITION_INT")[-1]
    assert abs(gp.lat - items[-1].lat) < 60  # within ~6 m of the last waypoint


def test_start_must_name_the_held_mission_and_be_near_waypoint_0(exe, d, key_path):
    far = line_north(3, lat=59.9005)  # waypoint 0 about 56 m north of the boat
    far_m = 0.0005 * 6378137.0 * 3.141592653589793 / 180
    with boat_and_station(exe, d, key_path) as (_, c), heartbeats(c):
        assert c.upload(5, far).result == M_ACCEPTED
        crc = mission_crc32(5, far)
        wrong = c.command(CMD_START, 1, 9, 6, crc)
        assert (wrong.result, wrong.progress) == (DENIED, REASON_MISMATCH)
        start = c.mark()
        too_far = c.command(CMD_START, 2, 9, 5, crc)
        assert (too_far.result, too_far.progress) == (DENIED, REASON_TOO_FAR)
        text = c.wait_for(lambda m: m.get_type() == "STATUSTEXT"
                          and "from waypoint 0" in m.text, 5, start)
        assert text.text == f"START refused: {far_m:.1f} m from waypoint 0 > 10.0 m"
        assert c.state().state == READY


def test_unsigned_and_forged_frames_refused_and_reported(exe, d, key_path):
    items = line_north(3)
    with boat_and_station(exe, d, key_path) as (_, c), heartbeats(c):
        assert c.upload(3, items).result == M_ACCEPTED
        # unsigned START and guidance on the same connection
        raw = d.MAVLink(None, srcSystem=255, srcComponent=190)
        crc = mission_crc32(3, items)
        start = c.mark()
        c.write(bytes(d.MAVLink_command_int_message(
            BOAT_ID, 1, 0, CMD_START, 0, 0, 1.0, 5.0, 0, 0, 3, crc - (1 << 32)
            if crc >= 1 << 31 else crc, 0).pack(raw)))
        c.write(bytes(d.MAVLink_usv_guidance_message(BOAT_ID, 1, 9000, 200, 5000).pack(raw)))
        c.write(bytes(d.MAVLink_usv_mission_begin_message(BOAT_ID, 1, 99, 1, 2, 0).pack(raw)))
        # forged: signed with another key
        forger = d.MAVLink(None, srcSystem=255, srcComponent=190)
        forger.signing.secret_key = bytes(32)
        forger.signing.sign_outgoing = True
        forger.signing.timestamp = int((time.time() - 1420070400) * 100_000)
        c.write(bytes(d.MAVLink_command_int_message(
            BOAT_ID, 1, 0, CMD_ABORT, 0, 0, 2.0, 5.0, 0, 0, 0, 0, 0).pack(forger)))
        text = c.wait_for(lambda m: m.get_type() == "STATUSTEXT" and "refused" in m.text, 5,
                          start)
        st = c.wait_for(lambda m: m.get_type() == "USV_MISSION_STATE" and m.rejected >= 4,
                        10, start)
    # one text per rate-limit slot, naming the latest refusal and the count so far: the
    # unsigned frames, or (when all four arrived before the slot) the forged one after them
    assert re.match(r"refused (unsigned|bad signature) frame from 255", text.text), text.text
    assert st.state == READY and st.active_id == 3 and st.staging == 0  # nothing acted
    assert not [m for m in c.msgs[start:] if m.get_type() == "COMMAND_ACK"]


def test_wrong_sender_refused_and_does_not_refresh_failsafe(exe, d, key_path):
    key = bytes.fromhex(key_path.read_text())
    with boat_and_station(exe, d, key_path) as (_, c):
        with heartbeats(c):
            upload_and_start(c, 11, line_north(3, leg_s=60))
        t_last = boat_uptime_now(c)  # the station's last frame
        # a second boat (id 2, same key) keeps talking, including commands
        second = d.MAVLink(None, srcSystem=2, srcComponent=1)
        second.signing.secret_key = key
        second.signing.sign_outgoing = True
        second.signing.timestamp = int((time.time() - 1420070400) * 100_000)
        start = c.mark()
        deadline = time.monotonic() + 15
        while time.monotonic() < deadline:
            c.write(bytes(d.MAVLink_heartbeat_message(11, 8, 0, 0, 4, 3).pack(second)))
            c.write(bytes(d.MAVLink_command_int_message(
                BOAT_ID, 1, 0, CMD_HOLD, 0, 0, 1.0, 7.0, 0, 0, 0, 0, 0).pack(second)))
            if [m for m in c.msgs[start:] if m.get_type() == "USV_MISSION_STATE"
                    and m.state == FAILSAFE]:
                break
            time.sleep(0.1)
        fs = c.wait_for(lambda m: m.get_type() == "USV_MISSION_STATE" and m.state == FAILSAFE,
                        5, start)
        texts = [m.text for m in c.of_type("STATUSTEXT", start)]
    assert 3000 <= fs.uptime_ms - t_last <= 3500
    assert fs.rejected >= 1 and any("wrong sender frame from 2" in t for t in texts)
    assert not [m for m in c.msgs[start:] if m.get_type() == "COMMAND_ACK"]


def test_own_echo_does_not_keep_the_link(exe, d, key_path):
    with boat_and_station(exe, d, key_path) as (_, c):
        with heartbeats(c):
            upload_and_start(c, 12, line_north(3, leg_s=60))
        t_last = boat_uptime_now(c)  # the station's last frame
        start = c.mark()
        echoed = len(c.raw_in)
        deadline = time.monotonic() + 15
        while time.monotonic() < deadline:  # everything the boat says goes straight back
            data = bytes(c.raw_in[echoed:])
            echoed += len(data)
            if data:
                c.write(data)
            if [m for m in c.msgs[start:] if m.get_type() == "USV_MISSION_STATE"
                    and m.state == FAILSAFE]:
                break
            time.sleep(0.02)
        fs = c.wait_for(lambda m: m.get_type() == "USV_MISSION_STATE" and m.state == FAILSAFE,
                        5, start)
    assert echoed > 0
    assert 3000 <= fs.uptime_ms - t_last <= 3500


def test_replayed_session_after_reboot_changes_nothing(exe, d, key_path, tmp_path):
    items = line_north(3)
    nv = tmp_path / "nv"
    with boat_and_station(exe, d, key_path, nv=nv) as (_, c), heartbeats(c):
        upload_and_start(c, 21, items)
        recorded = b"".join(c.sent)
    time.sleep(1.2)  # nothing special: the boat writes its floor each second and at exit
    with boat_and_station(exe, d, key_path, nv=nv) as (_, c2):
        first = c2.state()
        assert first.state == IDLE
        start = c2.mark()
        c2.write(recorded)
        st = c2.wait_for(lambda m: m.get_type() == "USV_MISSION_STATE" and m.rejected > 0, 10,
                         start)
        later = c2.state()
    assert first.boot_id != 0
    assert (later.state, later.active_id, later.staging) == (IDLE, 0, 0)
    assert st.rejected >= len([f for f in recorded.split(b"\xfd") if f]) // 2
    assert not [m for m in c2.msgs[start:] if m.get_type() in ("COMMAND_ACK", "USV_MISSION_ACK")]


def test_station_restart_mid_run_hold_then_abort(exe, d, key_path):
    items = line_north(4, step_m=40, leg_s=15)
    boat = CBoat.start(exe, key=key_path)
    key = bytes.fromhex(key_path.read_text())
    try:
        a = MavClient(d, port=boat.port, key=key)
        with heartbeats(a):
            upload_and_start(a, 31, items, seq=1, session=1111)
            a.wait_for(lambda m: m.get_type() == "VFR_HUD" and m.groundspeed > 1.0, 20)
        a.close()
        # the restarted station: new session, command ids from 1 again
        boat_b = MavClient(d, port=boat.port, key=key)
        try:
            with heartbeats(boat_b):
                hold = boat_b.command(CMD_HOLD, 1, 2222)
                assert hold.result == ACCEPTED
                st = boat_b.wait_state(HOLD, 5)
                assert st.station_session == 2222
                slow = boat_b.wait_for(lambda m: m.get_type() == "VFR_HUD"
                                       and m.groundspeed < 0.5, 20, boat_b.mark())
                assert slow.groundspeed < 0.5
                assert boat_b.command(CMD_ABORT, 2, 2222).result == ACCEPTED
                st = boat_b.wait_state(ABORTED, 5)
                thrust = boat_b.wait_for(lambda m: m.get_type() == "USV_THRUST", 5,
                                         boat_b.mark())
        finally:
            boat_b.close()
    finally:
        boat.close()
    assert (st.active_id, st.staging) == (0, 0)
    assert (thrust.left_pm, thrust.right_pm) == (0, 0)


def test_duplicate_start_answered_not_redone_hold_always_acts(exe, d, key_path):
    items = line_north(3, leg_s=60)
    with boat_and_station(exe, d, key_path) as (_, c), heartbeats(c):
        crc = mission_crc32(41, items)
        upload_and_start(c, 41, items, seq=5, session=77)
        assert c.command(CMD_HOLD, 6, 77).result == ACCEPTED
        c.wait_state(HOLD, 5)
        again = c.command(CMD_START, 5, 77, 41, crc)  # a retry of the old START
        assert again.result == ACCEPTED
        assert c.state().state == HOLD  # answered from memory, not executed
        assert c.command(CMD_RESUME, 7, 77).result == ACCEPTED
        c.wait_state(RUNNING, 5)
        assert c.command(CMD_HOLD, 6, 77).result == ACCEPTED  # same id: HOLD acts again
        c.wait_state(HOLD, 5)
        # the same START id in a new session is a new command (refused: not READY)
        fresh = c.command(CMD_START, 5, 78, 41, crc)
        assert fresh.result == DENIED and c.state().station_session == 78


def test_mission_lifecycle_limits(exe, d, key_path):
    with boat_and_station(exe, d, key_path, extra=("--staging-expiry-s", "1.5")) as (_, c), \
            heartbeats(c):
        one = c.mission_msg(d.MAVLink_usv_mission_begin_message(BOAT_ID, 1, 50, 0, 1, 0), 1, 50)
        assert one.result == M_BAD_COUNT
        items = line_north(3)
        crc = mission_crc32(51, items)
        assert c.mission_msg(d.MAVLink_usv_mission_begin_message(BOAT_ID, 1, 51, crc, 3, 0), 1,
                             51).result == M_ACCEPTED
        start = c.mark()
        bad = c.mission_msg(d.MAVLink_usv_mission_item_message(
            BOAT_ID, 1, 51, 1, items[1].lat, items[1].lon, 10000, 3001, 0, 0), 2, 51)
        assert (bad.result, bad.seq) == (M_OUT_OF_RANGE, 1)
        assert c.wait_for(lambda m: m.get_type() == "STATUSTEXT" and "speed_cms" in m.text, 5,
                          start)
        # ABORT clears staging: the next item of that mission is EXPIRED
        assert c.command(CMD_ABORT, 1, 3).result == ACCEPTED
        it = items[0]
        late = c.mission_msg(d.MAVLink_usv_mission_item_message(
            BOAT_ID, 1, 51, 0, it.lat, it.lon, 0, 100, 0, 0), 2, 51)
        assert late.result == M_EXPIRED
        # staging expires without progress (here 1.5 s)
        assert c.mission_msg(d.MAVLink_usv_mission_begin_message(BOAT_ID, 1, 52, crc, 3, 0), 1,
                             52).result == M_ACCEPTED
        c.wait_for(lambda m: m.get_type() == "STATUSTEXT" and "expired" in m.text, 10)
        end = c.mission_msg(d.MAVLink_usv_mission_end_message(BOAT_ID, 1, 52, crc, 3), 3, 52)
        assert end.result == M_EXPIRED
        assert c.state().staging == 0


def test_hot_swap_at_the_instant(exe, d, key_path):
    first = line_north(4, step_m=20, leg_s=20)
    second = line_north(3, step_m=10, leg_s=20, lat=59.9002)
    with boat_and_station(exe, d, key_path) as (_, c), heartbeats(c):
        upload_and_start(c, 61, first)
        since = c.mark()
        now = boat_uptime_now(c)
        swap_at = int(now) + 4000
        assert c.upload(62, second, swap_at_ms=swap_at).result == M_ACCEPTED
        st = c.state()
        assert (st.active_id, st.staged_id, st.staging, st.swap_at_ms) == (61, 62, 2, swap_at)
        swapped = c.wait_for(lambda m: m.get_type() == "USV_MISSION_STATE"
                             and m.active_id == 62, 15)
        c.state()
        states = c.of_type("USV_MISSION_STATE", since)
    assert swapped.state == RUNNING and swapped.staging == 0
    assert swapped.uptime_ms >= swap_at
    for s in states:  # old before the instant, new after it, never anything else
        assert s.active_id in (61, 62)
        assert (s.active_id == 62) == (s.uptime_ms >= swap_at)
        if s.active_id == 62:
            assert s.active_crc32 == u32(mission_crc32(62, second))


def test_telemetry_paced_to_the_line_replies_first(exe, d, key_path):
    """At 9600 baud and 50 Hz telemetry (more than the line carries) the boat sends at most
    the line rate, drops telemetry (counted in SYS_STATUS.errors_count2), never a reply."""
    with boat_and_station(exe, d, key_path, extra=("--baud", "9600", "--telemetry-hz",
                                                   "50")) as (_, c), heartbeats(c):
        first = c.state()
        with c._cv:
            start_bytes = len(c.raw_in)
        acks = [c.command(CMD_HOLD, seq, 5) for seq in range(1, 21)]
        last = c.state()
        while last.uptime_ms - first.uptime_ms < 2000:
            last = c.state()
        with c._cv:
            sent = len(c.raw_in) - start_bytes
        status = c.wait_for(lambda m: m.get_type() == "SYS_STATUS", 5, c.mark())
    assert all(a.result == ACCEPTED for a in acks)
    boat_s = (last.uptime_ms - first.uptime_ms) / 1000
    assert sent <= 960 * boat_s + 300  # the line's 960 bytes/s, plus the frame on the line
    assert status.errors_count2 > 0


_item = st.tuples(st.integers(-900_000_000, 900_000_000),
                  st.integers(-1_800_000_000, 1_800_000_000), st.integers(1, 600_000),
                  st.integers(0, 3000), st.integers(0, 35999), st.integers(0, 35999))


def test_any_valid_mission_verifies_with_the_python_crc32(exe, d, key_path):
    """Random in-range missions: the C boat's CRC-32 equals wire.item_crc32 and it
    activates them; one value out of range is refused at that item."""
    from hypothesis import given, settings

    from usvstation.link import wire
    from usvstation.link.mission import MissionItem

    with boat_and_station(exe, d, key_path) as (_, c), heartbeats(c):
        seq = iter(range(1, 10_000))

        @settings(max_examples=15, deadline=None, database=None)
        @given(st.integers(1, 2**32 - 1), st.lists(_item, min_size=2, max_size=12),
               st.integers(0, 5))
        def check(mission_id, raw, bad_field):
            t, items = 0, []
            for k, (lat, lon, dt, speed, course, heading) in enumerate(raw):
                t = 0 if k == 0 else t + dt
                items.append(Item(lat, lon, t, speed, course, heading))
            wire_items = [MissionItem(mission_id, k, it.lat, it.lon, it.t_ms, it.speed_cms,
                                      it.course_cdeg, it.heading_cdeg)
                          for k, it in enumerate(items)]
            assert mission_crc32(mission_id, items) == wire.item_crc32(wire_items)
            assert c.command(CMD_ABORT, next(seq), 1).result == ACCEPTED
            end = c.upload(mission_id, items)
            assert (end.result, end.stage) == (M_ACCEPTED, 3)
            held = c.state()
            assert (held.active_id, held.active_crc32, held.state) == \
                (mission_id, wire.item_crc32(wire_items), READY)
            # the same mission with one value out of range: refused at that item
            broken = list(items)
            k = len(items) - 1
            it = broken[k]
            broken[k] = [Item(910_000_000, it.lon, it.t_ms, it.speed_cms, 0, 0),
                         Item(it.lat, 1_810_000_000, it.t_ms, it.speed_cms, 0, 0),
                         Item(it.lat, it.lon, it.t_ms, 3001, 0, 0),
                         Item(it.lat, it.lon, it.t_ms, 100, 36000, 0),
                         Item(it.lat, it.lon, it.t_ms, 100, 0, 36000),
                         Item(it.lat, it.lon, it.t_ms, 100, 0, 0)][bad_field]
            if bad_field == 5:  # times not increasing: refused at END
                broken[k] = Item(it.lat, it.lon, broken[k - 1].t_ms, 100, 0, 0)
            nak = c.upload(u32(mission_id + 1) or 1, broken)
            assert nak.result == M_OUT_OF_RANGE and nak.seq == k

        check()


@pytest.mark.parametrize(("sensors", "fix_type"), [("exact", 3), ("rtk", 6), ("gnss", 3)])
def test_the_boat_reports_what_its_sensors_measure(exe, d, key_path, sensors, fix_type):
    """The host build navigates on its sensor model (issue 23): at rest on its start point,
    exact sensors read the start, RTK centimetres off it, plain GNSS decimetres to metres."""
    with boat_and_station(exe, d, key_path, extra=("--sensors", sensors, "--seed", "3")) \
            as (_, c), heartbeats(c):
        c.wait_for(lambda m: len(c.of_type("GLOBAL_POSITION_INT")) >= 8, 20)
        fixes = c.of_type("GLOBAL_POSITION_INT")
        raw = c.wait_for(lambda m: m.get_type() == "GPS_RAW_INT")
    north = [(f.lat - 599_000_000) * 0.0111 for f in fixes]  # 1e-7 deg of latitude ~ 0.0111 m
    worst = max(abs(n) for n in north)
    if sensors == "exact":
        assert worst < 0.02
    elif sensors == "rtk":
        assert worst < 0.15
    else:
        assert 0.05 < worst < 6.0
    assert raw.fix_type == fix_type


def test_an_unknown_sensor_profile_is_refused(exe):
    import subprocess

    out = subprocess.run([str(exe), "pty", "--insecure-link", "--sensors", "dgps"],
                         capture_output=True, text=True, timeout=30)
    assert out.returncode == 2
    assert "--sensors dgps: unknown profile (exact, rtk, gnss, rtk-moving-base)" in out.stderr


def test_a_missed_gate_goes_around_to_standby_and_resume_approaches_again(exe, d, key_path):
    """Plain GNSS (no RTK-class fix): the 30 m gate is missed; the C boat reports GO_AROUND,
    stands by at the first item 50 m back and RESUME re-flies the approach from there."""
    items = line_north(3, step_m=60, leg_s=30)  # a 60 m final leg: every gate on it
    with boat_and_station(exe, d, key_path, speedup=10,
                          extra=("--sensors", "gnss", "--seed", "2")) as (_, c), heartbeats(c):
        start = c.mark()
        upload_and_start(c, 8, items)
        c.wait_state(GO_AROUND, 60)
        why = c.wait_for(lambda m: m.get_type() == "STATUSTEXT"
                         and m.text.startswith("go-around:"), 10, start)
        assert why.text == "go-around: gate 30 m: no RTK-class fix"
        c.wait_for(lambda m: m.get_type() == "STATUSTEXT"
                   and m.text == "go-around: at standby, RESUME to approach", 60, start)
        ack = c.command(CMD_RESUME, 9, 4242)
        assert ack.result == ACCEPTED
        st = c.wait_state(RUNNING, 10)
        assert st.current_seq == 1  # the approach again from the standby item, 60 m back
        assert c.wait_state(GO_AROUND, 60).active_id == 8  # and again no RTK: around


def test_the_new_approach_is_a_hot_swap_the_c_boat_takes_at_its_standby_item_only(
        exe, d, key_path):
    """GO_AROUND: a swap whose END comes before the boat stands by is refused; at the
    standby item the station's new approach (a mission from there) is swapped in: RUNNING
    with it."""
    items = line_north(3, step_m=60, leg_s=30)  # a 60 m final leg: every gate on it
    standby = items[1]  # the first item at least 50 m back from the last
    with boat_and_station(exe, d, key_path, speedup=3,
                          extra=("--sensors", "gnss", "--seed", "2")) as (_, c), heartbeats(c):
        start = c.mark()
        upload_and_start(c, 31, items)
        c.wait_state(GO_AROUND, 60)
        early = line_north(2, step_m=60, leg_s=30, lat=standby.lat * 1e-7)
        ack = c.upload(32, early, swap_at_ms=boat_uptime_now(c) + 20000)
        assert ack.result == M_DENIED  # at END
        assert c.wait_for(lambda m: m.get_type() == "STATUSTEXT" and m.text ==
                          "swap of 32 refused: go-around not at standby yet", 10, start)
        c.wait_for(lambda m: m.get_type() == "STATUSTEXT"
                   and m.text == "go-around: at standby, RESUME to approach", 60, start)
        since = c.mark()
        swap_at = boat_uptime_now(c) + 3000
        assert c.upload(33, early, swap_at_ms=swap_at).result == M_ACCEPTED
        swapped = c.wait_for(lambda m: m.get_type() == "USV_MISSION_STATE"
                             and m.active_id == 33, 20, since)
        assert swapped.state == RUNNING and swapped.uptime_ms >= swap_at
        assert c.wait_for(lambda m: m.get_type() == "STATUSTEXT" and m.text.startswith(
            "new approach: mission 33 at "), 10, since)


def test_a_hot_swap_on_the_final_leg_inside_the_first_gate_is_dropped(exe, d, key_path):
    """Committed to the final approach: the gates decide, a swap is not taken there."""
    items = line_north(3, step_m=60, leg_s=30)
    with boat_and_station(exe, d, key_path, speedup=5) as (_, c), heartbeats(c):
        upload_and_start(c, 41, items)
        c.wait_for(lambda m: m.get_type() == "USV_MISSION_STATE" and m.current_seq >= 1
                   and m.uptime_ms >= 46000, 60)  # past 90 m of 120: inside the 30 m gate
        since = c.mark()
        ack = c.upload(42, line_north(2, step_m=20, leg_s=10),
                       swap_at_ms=boat_uptime_now(c) + 3000)
        assert ack.result == M_DENIED
        assert c.wait_for(lambda m: m.get_type() == "STATUSTEXT" and m.text ==
                          "swap of 42 refused: on the final approach", 10, since)
        assert c.state().active_id == 41
