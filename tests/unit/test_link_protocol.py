"""Sans-IO station and boat state machines over an in-memory link with a simulated clock."""

from __future__ import annotations

import math

import pytest
from link_harness import FRAME, Harness, make_mission, telemetry_count

from usvstation.link import messages as m
from usvstation.link.codec import Encoder, FrameDecoder
from usvstation.link.mission import MissionError, mission_from_plan, plan_from_mission
from usvstation.link.protocol import (
    CommandOutcome,
    DefinitionMismatch,
    LinkDown,
    LinkUp,
    StatusTextReceived,
    UploadProgress,
    UploadResult,
)
from usvstation.sim.boat import BoatConfig, BoatProtocol
from usvstation.sim.vehicle import KinematicVehicle


def upload(h: Harness, mission, seconds: float = 30.0) -> UploadResult:
    h.station.start_upload(mission, h.t)
    assert h.run(seconds, until=lambda: h.station.upload.done)
    return h.station.upload.result


def command(h: Harness, code, mission_id: int = 0) -> CommandOutcome:
    cid = h.station.send_command(code, h.t, mission_id)
    h.run(5.0, until=lambda: any(o.command_id == cid for o in h.of(CommandOutcome)))
    return next(o for o in h.of(CommandOutcome) if o.command_id == cid)


def test_handshake_brings_both_sides_up():
    h = Harness()
    h.connect()
    assert h.of(LinkUp)[0].heartbeat.sender == m.Sender.BOAT
    assert h.t < 0.1  # the boat answers the first station heartbeat at once


def test_upload_activates_the_identical_mission_with_progress():
    h = Harness()
    h.connect()
    mission = make_mission(7, 32)
    res = upload(h, mission)
    assert res.ok and res.reason == "activated" and res.retransmissions == 0
    assert h.boat.active.items == mission.items
    assert h.boat.state == m.State.READY
    progress = [p.acked for p in h.of(UploadProgress)]
    assert progress == list(range(0, 33))
    back = plan_from_mission(mission, FRAME)
    assert all(abs(b["x"] - w["x"]) < 0.02 and abs(b["y"] - w["y"]) < 0.02
               for b, w in zip(back, make_plan(), strict=True))


def make_plan():
    from link_harness import plan_waypoints

    return plan_waypoints(32)


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("loss", [0.1, 0.2, 0.4])
def test_lossy_upload_never_activates_a_partial_mission(loss, seed):
    h = Harness(loss=loss, seed=seed)
    assert h.run(20.0, until=lambda: h.station.link_up and h.boat.linked)
    mission = make_mission(9, 32)
    try:
        res = upload(h, mission, 60.0)
    except RuntimeError:
        return  # the link dropped before the upload could start: nothing activated
    if res.ok:
        assert h.boat.active.items == mission.items
    else:
        assert res.reason
        assert h.boat.active is None or h.boat.active.items == mission.items
    if loss <= 0.1:
        assert res.ok, res.reason


def _boat_and_station_messages(boat: BoatProtocol, msgs: list, now: float = 0.0) -> list:
    enc = Encoder()
    hb = m.Heartbeat(m.DEFINITION_CRC, m.PROTOCOL_VERSION, m.Sender.STATION, 0, 0, 0, 0, 0)
    boat.receive_data(enc.encode_many([hb, *msgs]), now)
    return [x for x in FrameDecoder().feed(boat.data_to_send())
            if isinstance(x, m.MissionAck | m.MissionNak | m.CommandAck)]


def _boat() -> BoatProtocol:
    return BoatProtocol(KinematicVehicle(), FRAME, BoatConfig())


def test_duplicates_are_idempotent_and_conflicts_refused():
    boat, mission = _boat(), make_mission(3, 4)
    it = mission.items[1]
    answers = _boat_and_station_messages(
        boat, [mission.begin(), it, it, mission.begin(), it._replace(speed_cms=1)])
    assert answers[0] == m.MissionAck(3, m.MissionStage.BEGIN, 0, 0)
    assert answers[1] == answers[2] == m.MissionAck(3, m.MissionStage.ITEM, 1, 1)
    assert answers[3] == m.MissionAck(3, m.MissionStage.BEGIN, 0, 1)  # a retry keeps items
    assert answers[4] == m.MissionNak(3, m.MissionStage.ITEM, 1, m.NakReason.CONFLICT, 1)


def test_end_verifies_completeness_and_crc_before_activating():
    boat, mission = _boat(), make_mission(3, 4)
    items = list(mission.items)
    answers = _boat_and_station_messages(boat, [mission.begin(), *items[:3], mission.end()])
    assert answers[-1] == m.MissionNak(3, m.MissionStage.END, 3, m.NakReason.MISSING_ITEMS, 3)
    assert boat.active is None
    bad = items[3]._replace(lat_e7=items[3].lat_e7 + 1)  # corrupted, CRC cannot match
    answers = _boat_and_station_messages(boat, [bad, mission.end()])
    assert answers[-1].reason == m.NakReason.CRC_MISMATCH and boat.active is None
    answers = _boat_and_station_messages(boat, [mission.begin(), *items, mission.end()])
    assert answers[-1] == m.MissionAck(3, m.MissionStage.END, 0, 4)
    assert boat.active.items == mission.items
    # a late duplicate of an item or END of the active mission is acknowledged again
    answers = _boat_and_station_messages(boat, [items[2], mission.end()])
    assert [a.stage for a in answers] == [m.MissionStage.ITEM, m.MissionStage.END]
    assert all(isinstance(a, m.MissionAck) for a in answers)


def test_a_new_upload_never_disturbs_the_active_mission_until_verified():
    boat = _boat()
    first, second = make_mission(1, 4), make_mission(2, 6)
    _boat_and_station_messages(boat, [first.begin(), *first.items, first.end()])
    _boat_and_station_messages(boat, [second.begin(), *second.items[:5], second.end()])
    assert boat.active.mission_id == 1 and boat.active.items == first.items


def test_boat_refuses_uploads_while_running_and_bad_begin():
    boat, mission = _boat(), make_mission(5, 3)
    naks = _boat_and_station_messages(boat, [m.MissionBegin(6, 0, 0, 0, 0, 0),
                                             m.MissionBegin(6, 300, 0, 0, 0, 0),
                                             m.MissionItem(8, 0, 0, 0, 0, 0, 0)])
    assert [a.reason for a in naks] == [m.NakReason.BAD_COUNT, m.NakReason.TOO_MANY_ITEMS,
                                        m.NakReason.UNKNOWN_MISSION]
    _boat_and_station_messages(boat, [mission.begin(), *mission.items, mission.end()])
    acks = _boat_and_station_messages(boat, [m.Command(1, m.CommandCode.START, 5),
                                             mission.begin(), mission.end()])
    assert acks[0].result == m.CommandResult.ACCEPTED
    # a new BEGIN is refused while running; a repeated END of the running mission is
    # acknowledged again (its first ACK may have been lost) without touching anything
    assert acks[1:] == [m.MissionNak(5, m.MissionStage.BEGIN, 0, m.NakReason.BUSY, 0),
                        m.MissionAck(5, m.MissionStage.END, 0, 3)]
    assert boat.state == m.State.RUNNING


def test_commands_follow_the_state_table_and_execute_once():
    h = Harness()
    h.connect()
    assert command(h, m.CommandCode.START, 7).result == m.CommandResult.NO_MISSION
    assert upload(h, make_mission(7, 8)).ok
    assert command(h, m.CommandCode.RESUME).result == m.CommandResult.REJECTED_STATE
    assert command(h, m.CommandCode.START, 8).result == m.CommandResult.MISSION_MISMATCH
    out = command(h, m.CommandCode.START, 7)
    assert out.accepted and out.state == m.State.RUNNING
    h.run(1.0)
    assert h.vehicle.state.speed > 0
    assert command(h, m.CommandCode.HOLD).state == m.State.HOLD
    x = h.vehicle.state.x
    h.run(1.0)
    assert h.vehicle.state.x == x and h.vehicle.state.speed == 0
    assert command(h, m.CommandCode.RESUME).state == m.State.RUNNING
    assert command(h, m.CommandCode.ABORT).state == m.State.ABORTED
    assert h.boat.active is None
    assert command(h, m.CommandCode.START, 7).result == m.CommandResult.NO_MISSION


def test_a_retried_command_is_executed_once():
    boat, mission = _boat(), make_mission(5, 3)
    _boat_and_station_messages(boat, [mission.begin(), *mission.items, mission.end()])
    start = m.Command(11, m.CommandCode.START, 5)
    acks = _boat_and_station_messages(boat, [start, m.Command(12, m.CommandCode.HOLD, 0), start])
    assert acks[0] == acks[2] == m.CommandAck(11, m.CommandCode.START, 0, m.State.RUNNING)
    assert boat.state == m.State.HOLD  # the repeated START did not run again


def test_lost_command_acks_are_retried_then_reported():
    h = Harness()
    h.connect()
    h.up = False
    cid = h.station.send_command(m.CommandCode.HOLD, h.t)
    h.run(2.0)
    out = [o for o in h.of(CommandOutcome) if o.command_id == cid]
    assert out and out[0].result is None and "after 5 attempts" in out[0].error


def test_link_loss_failsafe_and_recovery_without_restart():
    h = Harness()
    h.connect()
    assert upload(h, make_mission(7, 32)).ok
    assert command(h, m.CommandCode.START, 7).accepted
    h.run(2.0)
    h.up = False
    t_off, boat_last_rx, station_last_rx = h.t, h.boat.last_rx, h.station.monitor.last_rx
    assert h.run(4.0, until=lambda: h.boat.failsafe)
    t_boat = h.t
    assert h.run(4.0, until=lambda: not h.station.link_up)
    t_station = h.t
    # detected within 3.5 s of the radio going off, and not before 3 s of silence
    assert t_boat - t_off <= 3.5 and t_station - t_off <= 3.5, (t_boat, t_station, t_off)
    assert t_boat - boat_last_rx >= 3.0 and t_station - station_last_rx >= 3.0
    assert h.boat.state == m.State.HOLD and h.boat.flags & m.Flag.FAILSAFE
    assert "failsafe hold" in h.boat.log[-1] or any("failsafe hold" in x for x in h.boat.log)
    before = telemetry_count(h)
    h.up = True
    assert h.run(2.0, until=lambda: h.station.link_up and h.boat.linked)
    h.run(1.0)
    assert telemetry_count(h) >= before + 4  # 5 Hz resumed
    assert h.boat.state == m.State.HOLD  # stays safe until the operator resumes
    texts = [e.text for e in h.of(StatusTextReceived)]
    assert any("RESUME" in t for t in texts)
    assert command(h, m.CommandCode.RESUME).state == m.State.RUNNING
    assert not h.boat.flags & m.Flag.FAILSAFE
    assert [type(e) for e in h.events if isinstance(e, LinkUp | LinkDown)] == \
        [LinkUp, LinkDown, LinkUp]


def test_definition_mismatch_is_reported_naming_both_versions():
    h = Harness()
    other = m.Heartbeat(0x12345678, 2, m.Sender.BOAT, 0, 0, 0, 0, 0)
    from usvstation.link.codec import encode_frame, encode_payload

    frame = encode_frame(0, 0, encode_payload(other), version=2)
    h.events += h.station.receive_data(frame, 0.0)
    mm = h.of(DefinitionMismatch)
    assert len(mm) == 1
    msg = mm[0].message
    assert "boat speaks usv-link v2 (definitions 0x12345678)" in msg
    assert f"station speaks usv-link v1 (definitions 0x{m.DEFINITION_CRC:08X})" in msg
    with pytest.raises(RuntimeError, match="mismatch"):
        h.station.send_command(m.CommandCode.START, 0.0)
    boat = _boat()
    boat.receive_data(Encoder().encode(other._replace(sender=m.Sender.STATION)), 0.0)
    texts = [x.text for x in FrameDecoder().feed(boat.data_to_send())
             if isinstance(x, m.StatusText)]
    assert texts == [f"mismatch station v2 0x12345678 boat v1 0x{m.DEFINITION_CRC:08X}"]
    assert not boat.linked


@pytest.mark.parametrize("hz", [5, 50])
def test_telemetry_rate(hz):
    h = Harness(boat_cfg=BoatConfig(telemetry_hz=hz))
    h.connect()
    n0 = telemetry_count(h)
    h.run(4.0, dt=0.005)
    assert abs((telemetry_count(h) - n0) - 4 * hz) <= 2


def test_sim_speed_runs_boat_time_faster():
    h = Harness(boat_cfg=BoatConfig(sim_speed=10.0))
    h.connect()
    t0 = h.boat.boat_time
    h.run(1.0)
    assert h.boat.boat_time - t0 == pytest.approx(10.0, abs=0.15)
    assert h.boat.linked  # link timing stays in link (wall) time: no false failsafe


def test_mission_is_flown_with_position_linear_in_time_and_completes():
    h = Harness(boat_cfg=BoatConfig(sim_speed=20.0))
    h.connect()
    mission = make_mission(4, 6)
    assert upload(h, mission).ok
    h.vehicle = h.boat.vehicle
    assert command(h, m.CommandCode.START, 4).accepted
    assert h.run(30.0, until=lambda: h.boat.state == m.State.DONE)
    last = plan_from_mission(mission, FRAME)[-1]
    s = h.vehicle.state
    assert math.hypot(s.x - last["x"], s.y - last["y"]) < 0.05
    assert any("complete" in e.text for e in h.of(StatusTextReceived))


def test_guidance_setpoint_steers_then_expires():
    h = Harness()
    h.connect()
    assert upload(h, make_mission(4, 6)).ok
    assert command(h, m.CommandCode.START, 4).accepted
    h.run(0.5)
    h.station.send_guidance(0, 200, 500)  # due north at 2 m/s for 0.5 s
    h.run(0.2)
    assert h.boat.mode == m.Mode.GUIDED
    assert math.degrees(h.vehicle.state.heading) == pytest.approx(FRAME.ramp_bearing_deg - 0.0)
    h.run(0.5)
    assert h.boat.mode == m.Mode.AUTO


def test_mission_from_plan_refuses_bad_input_with_a_clear_message():
    wps = [{"x": 0, "y": 0, "t": 0, "speed": 1, "heading_deg": 0},
           {"x": 1, "y": 0, "t": 0, "speed": 1, "heading_deg": 0}]
    with pytest.raises(MissionError, match="waypoint 1: t_ms 0 not after"):
        mission_from_plan(wps, FRAME, 1)
    with pytest.raises(MissionError, match="waypoint 0: speed -1"):
        mission_from_plan([{**wps[0], "speed": -1}], FRAME, 1)
    with pytest.raises(MissionError, match="mission_id"):
        mission_from_plan(wps[:1], FRAME, 0)


def test_a_looped_back_line_is_not_a_link():
    """Each side ignores its own heartbeat echoed back (a loopback plug or a radio echo)."""
    h = Harness()
    h.station.poll(0.0)
    echo = h.station.data_to_send()
    assert h.station.receive_data(echo, 0.01) == [] and not h.station.link_up
    h.boat.update(0.0)
    h.boat.receive_data(h.boat.data_to_send(), 0.01)
    assert not h.boat.linked


def test_upload_failure_reasons_name_the_message():
    from usvstation.link.protocol import LinkConfig, MissionUploader

    mission = make_mission(7, 4)
    up = MissionUploader(mission, LinkConfig(), 0.0)
    assert up.start(0.0) == [mission.begin()]
    sent, _ = up.handle(m.MissionAck(7, m.MissionStage.BEGIN, 0, 0), 0.01)
    assert sent == list(mission.items)  # window of 8 holds all 4
    _, events = up.handle(m.MissionNak(7, m.MissionStage.ITEM, 2, m.NakReason.UNKNOWN_MISSION,
                                       0), 0.02)
    assert events[0].reason == "boat refused item 2: UNKNOWN_MISSION" and not events[0].ok
    up = MissionUploader(mission, LinkConfig(max_attempts=3), 0.0)
    up.start(0.0)
    for t in (0.31, 0.62, 0.93):
        _, events = up.poll(t)
    assert events[0].reason == "MISSION_BEGIN not acknowledged after 3 attempts"
