"""The standard MAVLink station side (link/standard*.py): the mission as standard items,
the mission and command protocols under loss, the recovery account, the GUIDED schedule,
vehicle profiles and signing; on a simulated clock against a minimal vehicle stand-in
(tests/unit/standard_harness.py). MAVSDK is the independent counterpart in
tests/integration/test_mavsdk_vehicle.py."""

from __future__ import annotations

import math
from dataclasses import replace

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from link_harness import FRAME, make_mission
from standard_harness import UNIX0, StandardHarness

from usvstation.link import wire
from usvstation.link.mavlink import usv_recovery as mav
from usvstation.link.mission import mission_from_plan, plan_from_mission
from usvstation.link.protocol import (
    BoatReport,
    CommandOutcome,
    ReadbackResult,
    StatusTextReceived,
    UploadResult,
)
from usvstation.link.standard import PROFILES, GuidedSchedule
from usvstation.link.standard_mission import (
    DO_CHANGE_SPEED,
    NAV_WAYPOINT,
    first_difference,
    leg_length_m,
    standard_count,
    standard_items,
    waypoints_of,
)
from usvstation.link.standard_transfer import RETRIES, TIMEOUT_S

KEY = bytes(range(40, 72))


@st.composite
def plans(draw: st.DrawFn, eq11: bool = False) -> list[dict]:
    """Timed plans; with `eq11` their times follow paper 000's eq. 11 (dT = 2 L / (v + v'))
    as every planner of this project makes them, else times and speeds are unrelated."""
    n = draw(st.integers(2, 40))
    wps, t = [], 0.0
    for i in range(n):
        x = draw(st.floats(-300, 300, allow_nan=False))
        y = draw(st.floats(-300, 300, allow_nan=False))
        speed = draw(st.floats(0.2, 5) if eq11 else st.floats(0, 5))
        if i:
            a = wps[-1]
            length = math.hypot(x - a["x"], y - a["y"])
            t += max(2 * length / (a["speed"] + speed), 0.5) if eq11 else \
                draw(st.floats(1.0, 60.0))
        wps.append({"x": x, "y": y, "t": t, "speed": speed,
                    "heading_deg": draw(st.floats(-180, 180))})
    return wps


@given(plans(), st.booleans())
@settings(max_examples=60, deadline=None)
def test_standard_items_carry_every_waypoint_and_leg_speed(wps: list[dict], home: bool) -> None:
    mission = mission_from_plan(wps, FRAME, 9)
    items = standard_items(mission.items, home=home)
    assert len(items) == standard_count(mission.count, home)
    assert [it.seq for it in items] == list(range(len(items)))
    assert [it.command for it in items[int(home):]] == \
        [NAV_WAYPOINT, DO_CHANGE_SPEED] * (mission.count - 1) + [NAV_WAYPOINT]
    back = waypoints_of(items, home)
    assert [(w.lat_e7, w.lon_e7) for w in back] == [(it.lat, it.lon) for it in mission.items]
    wire_plan = plan_from_mission(mission)  # the waypoints as the wire holds them
    for i, w in enumerate(back[:-1]):
        assert w.leg_speed is not None
        a, b = wire_plan[i], wire_plan[i + 1]
        dt = b["t"] - a["t"]
        on_wire = math.hypot(b["x"] - a["x"], b["y"] - a["y"]) / dt
        assert abs(w.leg_speed - on_wire) <= 0.01 + (0.02 + 0.001 * on_wire) / dt + 1e-6
    assert back[-1].leg_speed is None


@given(plans(eq11=True))
@settings(max_examples=60, deadline=None)
def test_leg_speeds_of_eq11_plans_within_1_cm_s_of_the_plan(wps: list[dict]) -> None:
    """Every planner here times its legs by eq. 11: a ground station reads each leg's
    planned speed within 1 cm/s, however short the leg."""
    back = waypoints_of(standard_items(mission_from_plan(wps, FRAME, 9).items))
    for i, w in enumerate(back[:-1]):
        a, b = wps[i], wps[i + 1]
        planned = math.hypot(b["x"] - a["x"], b["y"] - a["y"]) / (b["t"] - a["t"])
        if 2 * math.hypot(b["x"] - a["x"], b["y"] - a["y"]) / (a["speed"] + b["speed"]) < 0.5:
            continue  # a leg stretched to 0.5 s does not follow eq. 11
        assert abs(w.leg_speed - planned) < 0.01, (i, w.leg_speed, planned)


def test_first_difference_names_the_item() -> None:
    m = make_mission(7, 5)
    items = standard_items(m.items)
    assert first_difference(items, items) is None
    moved = (*items[:2], replace(items[2], x=items[2].x + 1), *items[3:])
    assert "item 2 differs" in first_difference(items, moved)
    slower = (*items[:3], replace(items[3], param2=items[3].param2 - 0.05), *items[4:])
    assert "DO_CHANGE_SPEED" in first_difference(items, slower)
    assert "holds 8 items, 9 were sent" in first_difference(items, items[:8])
    home = standard_items(m.items, home=True)
    other_home = (replace(home[0], x=1, y=2), *home[1:])  # the vehicle's own home in item 0
    assert first_difference(home, other_home, home=True) is None


def _upload(h: StandardHarness, mission, limit_s: float = 120.0) -> UploadResult:
    assert h.until(lambda: h.station.link_up, 10)
    h.station.start_upload(mission, h.t)
    assert h.until(lambda: h.of(UploadResult), limit_s), "the upload never ended"
    return h.of(UploadResult)[-1]


def _command(h: StandardHarness, name: str, *args: int) -> CommandOutcome:
    n = len(h.of(CommandOutcome))
    h.station.send_command(name, h.t, *args)
    assert h.until(lambda: len(h.of(CommandOutcome)) > n, 30)
    return h.of(CommandOutcome)[-1]


def test_upload_reads_back_and_reports_the_mission_held() -> None:
    h = StandardHarness()
    m = make_mission(7, 32)
    result = _upload(h, m)
    assert result.ok and result.reason == "uploaded and read back identical"
    assert h.vehicle.mission == list(standard_items(m.items, home=True))
    rep = h.station.report
    assert (rep.state, rep.active_id, rep.active_crc32, rep.active_count) == \
        ("READY", 7, m.crc, 32)
    h.station.start_readback(7, 32, h.t)
    assert h.until(lambda: h.of(ReadbackResult), 30)
    assert h.of(ReadbackResult)[-1].items == m.items


@given(loss=st.floats(0.0, 0.3), seed=st.integers(0, 10_000))
@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
def test_upload_under_loss_is_whole_or_refused_never_half(loss: float, seed: int) -> None:
    h = StandardHarness(loss=loss, seed=seed)
    m = make_mission(11, 32)
    sent = list(standard_items(m.items, home=True))
    result = _upload(h, m, limit_s=300)
    if result.ok:
        assert h.vehicle.mission == sent
        assert h.station.report.active_id == 11
    else:
        assert result.reason
        assert h.station.tracker.mission is None  # never startable
        assert h.vehicle.mission in ([], sent)  # the vehicle commits whole missions only
        assert _command(h, "start", 11, m.crc).reason == "NO_MISSION"


def test_start_hold_resume_abort_as_modes_with_the_timed_stream() -> None:
    h = StandardHarness()
    m = make_mission(7, 8)
    assert _upload(h, m).ok
    modes = PROFILES["ardupilot-rover"].modes
    out = _command(h, "start", 7, m.crc)
    assert out.accepted and h.vehicle.armed and h.vehicle.mode == modes["guided"]
    assert h.station.report.state == "RUNNING"
    n = len(h.vehicle.targets)
    h.until(lambda: len(h.vehicle.targets) >= n + 10, 5)
    gaps = [b.time_boot_ms - a.time_boot_ms for a, b in zip(h.vehicle.targets[-10:],
                                                         h.vehicle.targets[-9:], strict=False)]
    assert all(190 <= g <= 210 for g in gaps)  # 5 Hz
    assert _command(h, "hold").accepted and h.vehicle.mode == modes["hold"]
    assert h.station.report.state == "HOLD"
    held = len(h.vehicle.targets)
    h.until(lambda: False, 2)
    assert len(h.vehicle.targets) == held  # no targets while HOLD
    assert _command(h, "resume").accepted and h.vehicle.mode == modes["guided"]
    out = _command(h, "abort")
    assert out.accepted and not h.vehicle.armed and h.vehicle.mode == modes["hold"]
    assert h.station.report.state == "ABORTED" and h.station.report.active_id == 0
    assert h.vehicle.commands[-1] == (mav.MAV_CMD_COMPONENT_ARM_DISARM,
                                      (0.0, 21196.0, 0.0, 0.0, 0.0, 0.0, 0.0))


def test_auto_without_the_stream_and_completion_from_item_reached() -> None:
    h = StandardHarness(guided=False)
    m = make_mission(7, 4)
    assert _upload(h, m).ok
    assert _command(h, "start", 7, m.crc).accepted
    assert h.vehicle.mode == PROFILES["ardupilot-rover"].modes["auto"]
    assert not h.vehicle.targets
    last = standard_count(4, home=True) - 1
    h.vehicle.send(h.vehicle.codec.mav.mission_item_reached_encode(last), h.t)
    assert h.until(lambda: h.station.report.state == "DONE", 5)


def test_guided_completes_at_the_last_waypoint_after_its_time() -> None:
    h = StandardHarness()
    m = make_mission(7, 3, speed=5.0, x0=20.0, y0=0.0)
    assert _upload(h, m).ok
    assert _command(h, "start", 7, m.crc).accepted
    assert h.until(lambda: h.station.report.state == "DONE", m.items[-1].t_ms / 1000 + 10)
    assert h.t >= m.items[-1].t_ms / 1000


def test_px4_hold_refused_by_the_vehicle_holds_in_offboard_where_it_is() -> None:
    h = StandardHarness(profile="px4")
    px4 = PROFILES["px4"]
    h.vehicle.refused_modes = {px4.modes["hold"]}  # as MAVSDK's action server does
    m = make_mission(7, 8)
    assert _upload(h, m).ok
    assert _command(h, "start", 7, m.crc).accepted
    h.until(lambda: False, 2)
    out = _command(h, "hold")
    assert out.accepted and h.vehicle.mode == px4.modes["guided"]
    assert h.station.report.state == "HOLD"
    assert any(isinstance(e, StatusTextReceived) and "holding in GUIDED" in e.text
               for e in h.events)
    n = len(h.vehicle.targets)
    h.until(lambda: len(h.vehicle.targets) > n + 5, 3)
    still = h.vehicle.targets[n:]
    assert {(t.lat_int, t.lon_int) for t in still} == {(still[0].lat_int, still[0].lon_int)}
    assert all(t.vx == 0 and t.vy == 0 for t in still)
    assert _command(h, "resume").accepted and h.station.report.state == "RUNNING"


def test_guided_refused_falls_back_to_the_uploaded_mission_in_auto() -> None:
    h = StandardHarness()
    h.vehicle.refused_modes = {PROFILES["ardupilot-rover"].modes["guided"]}
    m = make_mission(7, 8)
    assert _upload(h, m).ok
    assert _command(h, "start", 7, m.crc).accepted
    assert h.vehicle.mode == PROFILES["ardupilot-rover"].modes["auto"]
    assert h.station.schedule is None


def test_start_of_a_mission_not_held_is_denied_and_sends_nothing() -> None:
    h = StandardHarness()
    assert h.until(lambda: h.station.link_up, 10)
    out = _command(h, "start", 7, 1234)
    assert (out.result, out.reason) == (mav.MAV_RESULT_DENIED, "NO_MISSION")
    assert h.vehicle.commands == []


def test_a_command_without_answer_ends_after_the_retries() -> None:
    h = StandardHarness()
    assert h.until(lambda: h.station.link_up, 10)
    h.vehicle.receive = lambda data, now: None  # deaf, still talking
    t0 = h.t
    out = _command(h, "hold")
    assert out.result is None and "no COMMAND_ACK" in out.error
    assert h.t - t0 <= (RETRIES + 1) * TIMEOUT_S + 0.5


def test_the_vehicle_leaving_the_mode_on_its_own_is_a_failsafe() -> None:
    h = StandardHarness(guided=False)
    m = make_mission(7, 8)
    assert _upload(h, m).ok
    assert _command(h, "start", 7, m.crc).accepted
    h.until(lambda: False, 2.5)  # a heartbeat showed AUTO
    h.vehicle.mode = 0  # its pilot took MANUAL
    assert h.until(lambda: h.station.report.state == "FAILSAFE", 3)
    assert any(isinstance(e, StatusTextReceived) and "left the recovery for MANUAL" in e.text
               for e in h.events)
    assert _command(h, "resume").accepted and h.station.report.state == "RUNNING"


def test_a_speed_the_vehicle_holds_differently_shows_as_the_time_it_gives() -> None:
    h = StandardHarness()
    m = make_mission(7, 6)
    assert _upload(h, m).ok
    v = h.vehicle.mission
    v[4] = replace(v[4], param2=v[4].param2 * 0.5)  # leg 1 (item 4: home, wp0, spd0, wp1)
    h.station.start_readback(7, 6, h.t)
    assert h.until(lambda: h.of(ReadbackResult), 30)
    back = h.of(ReadbackResult)[-1]
    assert back.items is not None and "DO_CHANGE_SPEED" in back.error
    assert [a == b for a, b in zip(m.items, back.items, strict=True)] == \
        [True, True, False, False, False, False]
    leg = back.items[2].t_ms - back.items[1].t_ms
    assert abs(leg - 2 * (m.items[2].t_ms - m.items[1].t_ms)) <= 10  # 25 s, to 10 ms


@given(st.lists(st.floats(0.0, 400.0), min_size=1, max_size=20),
       st.floats(0.0, 30.0))
@settings(max_examples=50, deadline=None)
def test_schedule_is_linear_in_time_and_stops_while_held(times: list[float],
                                                       held: float) -> None:
    m = make_mission(7, 10)
    s = GuidedSchedule(m.items, started=100.0)
    for t in times:
        tgt = s.target(100.0 + t)
        assert tgt.t == pytest.approx(t)
        if not tgt.finished:
            a, b = m.items[tgt.waypoint_index], m.items[tgt.waypoint_index + 1]
            assert min(a.lat, b.lat) - 1 <= tgt.lat_e7 <= max(a.lat, b.lat) + 1
            assert a.t_ms <= t * 1000 <= b.t_ms
            speed = leg_length_m(a.lat, a.lon, b.lat, b.lon) / ((b.t_ms - a.t_ms) / 1000)
            assert math.hypot(tgt.vn, tgt.ve) == pytest.approx(speed, rel=1e-9)
    s.pause(110.0)
    frozen = s.target(110.0 + held)
    assert frozen.t == pytest.approx(10.0) and (frozen.vn, frozen.ve) == (0.0, 0.0)
    s.resume(110.0 + held)
    assert s.target(120.0 + held).t == pytest.approx(20.0)


def test_signing_set_up_on_ardupilot_then_unsigned_frames_refused() -> None:
    h = StandardHarness(key=KEY)
    assert h.until(lambda: h.station.link_up, 10)
    assert not h.station.signed
    assert h.until(lambda: h.vehicle.key == KEY, 10)  # SETUP_SIGNING reached it
    assert h.until(lambda: h.station.signed, 5)
    forged = wire.Codec(1, mav.MAV_COMP_ID_AUTOPILOT1, None).encode(
        mav.MAVLink_statustext_message(mav.MAV_SEVERITY_INFO, b"forged", 0, 0))
    before = h.station.refused["unsigned"]
    h.events += h.station.receive_data(forged, h.t)
    assert h.station.refused["unsigned"] == before + 1
    assert not any(isinstance(e, StatusTextReceived) and e.text == "forged" for e in h.events)


def test_px4_profile_is_not_sent_setup_signing() -> None:
    h = StandardHarness(profile="px4", key=KEY)
    assert h.until(lambda: h.station.link_up, 10)
    h.until(lambda: False, 12)
    assert h.vehicle.key is None and h.station.signing_sent == 0 and not h.station.signed


def test_reports_come_with_every_heartbeat() -> None:
    h = StandardHarness()
    h.until(lambda: False, 5.05)
    reports = h.of(BoatReport)
    assert 4 <= len(reports) <= 6 and reports[-1].report.state == "IDLE"
    assert UNIX0 > 0


def test_bench_standard_upload_is_whole_and_near_the_line_rate() -> None:
    """`bench link`'s standard_upload row (simulated time: the same on any machine)."""
    from usvstation.bench.link import standard_upload_run

    row = standard_upload_run(57600)
    assert row["completed"] and row["identical"] and row["retransmissions"] == 0
    assert row["bound_s"] <= row["time_s"] < 1.5 * row["bound_s"]
    assert row["verified_s"] > row["time_s"]  # the read-back follows the upload


def test_a_vehicle_signing_with_another_key_is_refused() -> None:
    h = StandardHarness(key=KEY)
    other = bytes(range(100, 132))
    h.vehicle.key = other
    h.vehicle.codec = wire.Codec(1, mav.MAV_COMP_ID_AUTOPILOT1, other,
                                 timestamp=wire.signing_time(UNIX0))
    h.until(lambda: False, 3)
    assert not h.station.link_up and h.station.refused["bad signature"] >= 3
    with pytest.raises(RuntimeError, match="link is down"):
        h.station.send_command("abort", h.t)


def test_a_lost_final_ack_is_settled_by_the_read_back() -> None:
    h = StandardHarness()
    h.drop_down = lambda m: m.get_type() == "MISSION_ACK"  # the vehicle's ACK never arrives
    m = make_mission(7, 6)
    result = _upload(h, m)
    assert result.ok and "the vehicle's" not in result.reason
    assert result.reason.startswith("uploaded and read back identical (the upload itself")
    assert "no answer to item 11 after 6 sends" in result.reason  # 12 items: home + 11
    assert h.station.report.active_id == 7 and h.vehicle.uploads == 1
