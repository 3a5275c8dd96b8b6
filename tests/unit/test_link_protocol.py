"""usv-link 2 state machines, station and boat, on a simulated clock (tests/unit/link_harness)."""

from __future__ import annotations

import itertools

import pytest
from link_harness import KEY, UNIX0, Harness, make_mission

from usvstation.link import wire
from usvstation.link.mavlink import usv_recovery as mav
from usvstation.link.protocol import (
    CommandOutcome,
    CommandSender,
    LinkConfig,
    LinkUp,
    ReadbackResult,
    RttEstimator,
    StatusTextReceived,
    TelemetryReceived,
    UploadResult,
)
from usvstation.sim.boat import BoatConfig


def _upload(h: Harness, mission, seconds: float = 30.0, **kw) -> UploadResult:
    n = len(h.of(UploadResult))
    h.station.start_upload(mission, h.t, **kw)
    assert h.run(seconds, until=lambda: len(h.of(UploadResult)) > n)
    return h.of(UploadResult)[-1]


def _command(h: Harness, name: str, mission=None) -> CommandOutcome:
    n = len(h.of(CommandOutcome))
    args = (mission.mission_id, mission.crc) if mission is not None else ()
    h.station.send_command(name, h.t, *args)
    assert h.run(20.0, until=lambda: len(h.of(CommandOutcome)) > n)
    return h.of(CommandOutcome)[-1]


def _texts(h: Harness) -> list[str]:
    return [e.text for e in h.of(StatusTextReceived)]


def _station_frames(h: Harness, key: bytes | None = KEY, system_id: int = 255) -> wire.Codec:
    """Hand-made station frames on their own signing stream (link id 7)."""
    return wire.Codec(system_id, wire.STATION_COMPONENT, key, link_id=7,
                      timestamp=wire.signing_time(UNIX0 + h.t))


def test_handshake_brings_both_sides_up_with_the_paired_ids():
    h = Harness()
    h.connect()
    assert h.of(LinkUp)[0].system_id == 1
    assert h.boat.linked and h.station.report.state == "IDLE"
    assert h.station.report.boot_id == h.boat.boot_id


def test_upload_activates_the_identical_mission_and_readback_matches():
    h = Harness()
    h.connect()
    m = make_mission(7)
    res = _upload(h, m)
    assert res.ok and res.retransmissions == 0
    assert h.boat.active.items == m.items and h.boat.state == 1  # READY
    h.run(1.1)
    assert (h.station.report.active_id, h.station.report.active_crc32) == (m.mission_id, m.crc)
    h.station.start_readback(m.mission_id, m.count, h.t)
    assert h.run(5, until=lambda: h.of(ReadbackResult))
    assert h.of(ReadbackResult)[-1].items == m.items
    assert h.station.refused == {} and h.boat.refusals == {}  # nothing out of order


def test_acks_overtaking_telemetry_keep_signing_timestamps_rising():
    h = Harness(boat_cfg=BoatConfig(baud=9600, telemetry_hz=20))
    h.connect()
    m = make_mission(7)
    assert _upload(h, m).ok and _command(h, "start", m).accepted
    h.run(3.0)
    assert h.station.refused == {}


@pytest.mark.parametrize(("loss", "seed"), [(0.1, 1), (0.2, 2), (0.3, 3), (0.5, 4)])
def test_lossy_uploads_never_activate_a_partial_mission(loss, seed):
    h = Harness(loss=loss, seed=seed)
    h.connect()
    m = make_mission(9)
    res = _upload(h, m, seconds=120)
    if res.ok:
        assert h.boat.active.items == m.items
    else:
        assert h.boat.active is None or h.boat.active.items == m.items


def test_boat_refuses_short_missions_and_out_of_range_values_naming_the_field():
    h = Harness()
    h.connect()
    c = _station_frames(h)
    e = c.mav
    h.extra_to_boat.append(c.encode(e.usv_mission_begin_encode(1, 1, 5, 0, 1, 0)))
    h.extra_to_boat.append(c.encode(e.usv_mission_begin_encode(1, 1, 6, 0, 2, 0)))
    h.extra_to_boat.append(c.encode(e.usv_mission_item_encode(1, 1, 6, 0, 0, 0, 0, 4000, 0, 0)))
    h.run(0.5)
    assert "mission 5: count 1 outside 2..256" in _texts(h)
    assert "item 0: speed_cms 4000 above 3000" in _texts(h)
    assert h.boat.staging.items == {} and h.boat.active is None


def test_end_checks_completeness_and_crc_before_activating():
    h = Harness()
    h.connect()
    m = make_mission(8, n=4)
    c = _station_frames(h)
    e = c.mav

    def item(it):
        return c.encode(e.usv_mission_item_encode(1, 1, it.mission_id, it.seq, it.lat, it.lon,
                                                  it.t_ms, it.speed_cms, it.course_cdeg,
                                                  it.heading_cdeg))

    acks = []
    h.station._handle = lambda msg, now: acks.append(msg) or []  # see the boat's answers
    h.extra_to_boat.append(c.encode(e.usv_mission_begin_encode(1, 1, 8, m.crc, 4, 0)))
    h.extra_to_boat += [item(m.items[0]), item(m.items[1]), item(m.items[3])]
    h.extra_to_boat.append(c.encode(e.usv_mission_end_encode(1, 1, 8, m.crc, 4)))
    h.run(0.3)
    end = [a for a in acks if a.get_type() == "USV_MISSION_ACK" and a.stage == 3][-1]
    assert (end.result, end.seq) == (mav.USV_MISSION_MISSING_ITEMS, 2)
    assert h.boat.active is None
    h.extra_to_boat.append(item(m.items[2]))
    h.extra_to_boat.append(c.encode(e.usv_mission_end_encode(1, 1, 8, m.crc ^ 1, 4)))
    h.run(0.3)
    end = [a for a in acks if a.get_type() == "USV_MISSION_ACK" and a.stage == 3][-1]
    assert end.result == mav.USV_MISSION_CRC_MISMATCH and h.boat.active is None
    h.extra_to_boat.append(c.encode(e.usv_mission_end_encode(1, 1, 8, m.crc, 4)))
    h.run(0.3)
    assert h.boat.active.items == m.items


def test_staging_expires_after_30_s_and_abort_clears_it():
    h = Harness()
    h.connect()
    c = _station_frames(h)
    h.extra_to_boat.append(c.encode(c.mav.usv_mission_begin_encode(1, 1, 21, 0, 5, 0)))
    h.run(29.0)
    assert h.boat.staging is not None
    h.run(1.5)
    assert h.boat.staging is None and "staging of 21 expired" in _texts(h)
    c2 = _station_frames(h)
    h.extra_to_boat.append(c2.encode(c2.mav.usv_mission_begin_encode(1, 1, 22, 0, 5, 0)))
    h.run(0.2)
    assert h.boat.staging.mission_id == 22
    assert _command(h, "abort").accepted and h.boat.staging is None


def test_start_names_the_mission_and_is_refused_far_from_waypoint_0():
    h = Harness(x=60.0, y=10.0)  # 25 m from waypoint 0 at (85, 10)
    h.connect()
    m = make_mission(3)
    assert _upload(h, m).ok
    wrong = _command(h, "start", make_mission(4))
    assert wrong.reason == "MISSION_MISMATCH" and h.boat.state == 1
    far = _command(h, "start", m)
    assert far.result == mav.MAV_RESULT_DENIED and far.reason == "TOO_FAR"
    text = next(t for t in _texts(h) if "from waypoint 0" in t)
    assert text.startswith("START refused: 24.9 m") and text.endswith("(limit 10 m)")


def test_duplicates_answered_once_but_hold_and_abort_always_act():
    h = Harness()
    h.connect()
    m = make_mission(5)
    assert _upload(h, m).ok
    assert _command(h, "start", m).accepted
    c = _station_frames(h)
    e = c.mav
    session = h.station.session

    def cmd(code, seq, x=0, y=0):
        return c.encode(e.command_int_encode(1, 1, 0, code, 0, 0, float(seq), float(session),
                                             0, 0, x, y, 0))

    h.extra_to_boat.append(cmd(mav.MAV_CMD_USV_HOLD, 500))
    h.run(0.2)
    assert h.boat.state == 3  # HOLD
    h.extra_to_boat.append(cmd(mav.MAV_CMD_USV_RESUME, 501))
    h.run(0.2)
    h.extra_to_boat.append(cmd(mav.MAV_CMD_USV_RESUME, 501))  # a retry: not executed again
    h.extra_to_boat.append(cmd(mav.MAV_CMD_USV_HOLD, 500))  # same key: HOLD acts anyway
    h.run(0.2)
    names = [n for _, n in h.boat.executed]
    assert names == ["start", "hold", "resume", "hold"] and h.boat.state == 3
    h.run(5.5)  # the memory expires after 5 s
    h.extra_to_boat.append(cmd(mav.MAV_CMD_USV_RESUME, 501))
    h.run(0.2)
    assert h.boat.executed[-1][1] == "resume" and h.boat.state == 2


def test_a_new_session_clears_the_duplicate_memory():
    h = Harness()
    h.connect()
    m = make_mission(5)
    assert _upload(h, m).ok
    seq = h.station.commands._next_seq
    assert _command(h, "start", m).accepted
    assert _command(h, "hold").accepted
    h.restart_station(session=4242)
    h.connect()
    h.station.commands._next_seq = seq  # the new process reuses the old ids
    assert _command(h, "resume").accepted
    assert [n for _, n in h.boat.executed] == ["start", "hold", "resume"]
    assert h.boat.state == 2 and h.boat.session == 4242


def test_an_ack_for_another_command_or_seq_is_not_the_answer():
    cfg = LinkConfig()
    sender = CommandSender(cfg, RttEstimator(cfg), session=9)
    seq = sender.send("hold", 0.0)
    enc = wire.Codec(1, 1).mav

    def ack(code, s):
        return enc.command_ack_encode(code, 0, 0, s, 255, 190)

    assert sender.handle(ack(mav.MAV_CMD_USV_START, seq)) == []
    assert sender.handle(ack(mav.MAV_CMD_USV_HOLD, seq + 1)) == []
    out = sender.handle(ack(mav.MAV_CMD_USV_HOLD, seq))
    assert out[0].accepted and out[0].seq == seq
    seq2 = sender.send("abort", 0.0)
    events, t = [], 0.0
    while not events:  # no answer: retried, then an outcome within bounded time
        t += 0.05
        events += sender.due(t)[1]
        assert t < cfg.command_attempts * cfg.max_timeout_s + 1
    assert events[0].seq == seq2 and events[0].result is None


def test_echo_and_other_boats_do_not_keep_the_link_alive():
    h = Harness()
    h.connect()
    m = make_mission(5)
    assert _upload(h, m).ok and _command(h, "start", m).accepted
    other = wire.Codec(2, 1, KEY, timestamp=wire.signing_time(UNIX0 + h.t))
    h.echo, h.station_silent = True, True
    t0 = h.t
    while h.boat.state != 6 and h.t - t0 < 5:  # FAILSAFE
        h.extra_to_boat.append(other.encode(other.mav.heartbeat_encode(
            mav.MAV_TYPE_SURFACE_BOAT, 0, 0, 0, 0)))
        h.run(0.1)
    assert h.boat.state == 6 and h.t - t0 <= 3.5
    assert h.boat.echoes > 0 and h.boat.other_systems[2] > 0


def test_station_heartbeats_on_a_fixed_schedule_and_telemetry_on_boat_time():
    h = Harness()
    times = []
    for _ in range(400):
        h.step(0.0137)
        sent = h.tap[-1] if h.tap and h.tap[-1][0] == h.t else None
        if sent and any(f[7] == 0 and f[8] == 0 and f[9] == 0
                        for f in wire.split_frames(sent[1])):
            times.append(h.t)
    gaps = [b - a for a, b in itertools.pairwise(times)]
    assert max(gaps) <= 0.25 + 0.0137 and min(gaps) >= 0.25 - 0.0137
    tel = []
    h.station._telemetry = lambda gp: tel.append(gp.time_boot_ms) or h.station.telemetry
    h.run(3.0, dt=0.013)
    assert {b - a for a, b in itertools.pairwise(tel)} == {200}


def test_acks_go_out_before_queued_telemetry():
    h = Harness(boat_cfg=BoatConfig(baud=9600, telemetry_hz=50))
    h.connect()
    h.run(1.0)
    h.boat.update(h.t + 0.2)  # ten telemetry cycles queue up behind the 9600 baud line
    h.t += 0.2
    assert len(h.boat._telemetry) > 0
    c = _station_frames(h)
    h.boat.receive_data(c.encode(c.mav.command_int_encode(
        1, 1, 0, mav.MAV_CMD_USV_HOLD, 0, 0, 1.0, 5.0, 0, 0, 0, 0, 0)), h.t)
    ids = [f[7] | f[8] << 8 | f[9] << 16 for f in wire.split_frames(h.boat.data_to_send(h.t))]
    telemetry = {mav.MAVLINK_MSG_ID_GLOBAL_POSITION_INT, mav.MAVLINK_MSG_ID_USV_THRUST}
    first_telemetry = min((k for k, i in enumerate(ids) if i in telemetry), default=len(ids))
    assert ids.index(mav.MAVLINK_MSG_ID_COMMAND_ACK) < first_telemetry
    assert len(h.boat._telemetry) > 0  # the telemetry still waits for the line


def test_unsigned_guidance_is_refused_and_counted_signed_guidance_steers():
    h = Harness()
    h.connect()
    m = make_mission(5)
    assert _upload(h, m).ok and _command(h, "start", m).accepted
    bad = wire.Codec(255, 190)
    h.extra_to_boat.append(bad.encode(bad.mav.usv_guidance_encode(1, 1, 0, 200, 2000)))
    h.run(0.2)
    assert h.boat.guided_until is None and h.boat.refusals["unsigned"] == 1
    h.station.send_guidance(0, 200, 2000)
    h.run(0.2)
    assert h.boat.guided_until is not None
    h.run(2.5)
    assert h.boat.guided_until is None  # expired: back to the mission


def test_timesync_aligns_the_boat_clock_and_rtt_bounds_the_timeout():
    h = Harness()
    h.connect()
    h.run(2.0)
    est = h.station.boat_uptime_ms(h.t)
    assert abs(est - h.boat.uptime_ms) <= 20
    rtt = h.station.rtt
    assert rtt.floor <= rtt.timeout <= h.link_cfg.max_timeout_s
    slow = RttEstimator(LinkConfig(baud=9600))
    assert slow.floor > RttEstimator(LinkConfig(baud=57600)).floor  # airtime at the baud
    slow.sample(100.0)
    assert slow.timeout == LinkConfig().max_timeout_s


def test_hot_swap_at_the_instant_old_then_new():
    h = Harness(loss=0.2, seed=3)
    h.connect()
    old = make_mission(30, n=16)
    assert _upload(h, old, seconds=60).ok and _command(h, "start", old).accepted
    h.run(3.0)
    new = make_mission(31, n=16, y0=11.0)
    swap_at = h.station.boat_uptime_ms(h.t) + 6000
    assert _upload(h, new, seconds=60, swap_at_ms=swap_at).ok
    assert h.boat.active.mission_id == 30
    h.run(8.0)
    assert h.boat.active.items == new.items
    (_t_old, id_old), (t_new, id_new) = h.boat.activations
    assert (id_old, id_new) == (30, 31) and abs(t_new * 1000 - swap_at) < 1


def test_replayed_frames_are_refused_by_the_running_boat():
    h = Harness()
    h.connect()
    m = make_mission(5)
    assert _upload(h, m).ok
    recorded = b"".join(d for _, d in h.tap)
    before = h.boat.refusals["replayed"]
    h.boat.receive_data(recorded, h.t)
    assert h.boat.refusals["replayed"] - before == len(wire.split_frames(recorded))


def test_telemetry_overtaken_by_a_hold_report_keeps_the_state_of_its_own_instant():
    """On a slow radio the HOLD ACK and report jump the telemetry queue; fixes taken before
    the boat held are still labelled RUNNING (the boat's view, not the station's newest)."""
    h = Harness(boat_cfg=BoatConfig(baud=19200, telemetry_hz=20))
    h.connect()
    m = make_mission(9)
    assert _upload(h, m).ok
    assert _command(h, "start", m).accepted
    t_start = h.boat.executed[-1][0]
    h.run(2.0)
    assert _command(h, "hold").accepted
    t_hold = h.boat.executed[-1][0]
    h.run(2.0)
    rows = [e.telemetry for e in h.of(TelemetryReceived)]
    before = [r for r in rows if t_start < r.time_s < t_hold]
    after = [r for r in rows if r.time_s >= t_hold]
    assert len(before) > 10 and len(after) > 10
    assert {r.state for r in before} == {"RUNNING"}
    assert {r.state for r in after} == {"HOLD"}


def test_a_completed_mission_reports_where_it_ended_before_done_on_a_full_line():
    """The line is too slow for the telemetry (19200 baud, 20 Hz: the boat drops frames),
    yet the last position the station hears before the boat reports DONE is where the
    mission ended, so a run's track ends at the ramp."""
    from link_harness import FRAME

    from usvstation.link.protocol import BoatReport, TelemetryReceived

    h = Harness(boat_cfg=BoatConfig(baud=19200, telemetry_hz=20))
    h.connect()
    m = make_mission(7, n=4, speed=3.0)
    assert _upload(h, m).ok and _command(h, "start", m).accepted
    assert h.run(60, until=lambda: h.station.report.state == "DONE")
    assert h.boat.telemetry_dropped > 0
    done = next(i for i, e in enumerate(h.events)
                if isinstance(e, BoatReport) and e.report.state == "DONE")
    last = [e for e in h.events[:done] if isinstance(e, TelemetryReceived)][-1].telemetry
    x, y = FRAME.to_ramp(last.lat, last.lon)
    assert abs(float(x)) < 0.05 and abs(float(y)) < 0.05
