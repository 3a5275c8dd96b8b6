"""The station's side of a stock MAVLink autopilot (ArduPilot Rover, PX4) as a sans-IO
state machine: `serve --boat-protocol standard` (docs/link.md "Standard MAVLink").

    proto = StandardProtocol(StandardConfig(profile=PROFILES["ardupilot-rover"]), now)
    events = proto.receive_data(data, now)      # LinkEvents, as StationProtocol's
    events += proto.poll(now)                   # heartbeat, retries, the GUIDED stream
    wire = proto.data_to_send()
    proto.start_upload(mission, now)            # standard upload, then read back, compare

It hands the boat service the same typed events as usv-link 2's `StationProtocol`
(link/protocol.py `LinkEvent`): `LinkUp`, `LinkDown`, `TelemetryReceived` (from
GLOBAL_POSITION_INT, VFR_HUD, ATTITUDE, GPS_RAW_INT, SYS_STATUS), `BoatReport`,
`UploadProgress`, `UploadResult`, `ReadbackResult`, `CommandOutcome`,
`StatusTextReceived`, `BoatRebooted`. A stock autopilot has no USV_MISSION_STATE, so the
`BoatReport` is the station's own account (`RecoveryTracker`, one table): the mission it
uploaded and read back identical (by its usv-link id and CRC-32), and the recovery state
that the accepted commands, the vehicle's mode and its mission progress give.

The parts: the mission transfers and commands of link/standard_transfer.py, the vehicle
profile (`PROFILES`: which custom mode is AUTO, HOLD, GUIDED, LOITER, how to ask for one,
whether item 0 is the home), `GuidedSchedule` (SET_POSITION_TARGET_GLOBAL_INT at 5 Hz:
position and velocity along the timed plan, paused while held), and MAVLink 2 signing
(SETUP_SIGNING to a profile that supports it; unsigned frames are taken until the
vehicle's first signed one, refused after it).
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass, field, replace
from typing import Any

from usvstation.geometry import CDEG, CM, E7, MS
from usvstation.link import wire
from usvstation.link.mavlink import usv_recovery as mav
from usvstation.link.mission import Mission, MissionItem
from usvstation.link.protocol import (
    BoatRebooted,
    BoatReport,
    CommandOutcome,
    LinkConfig,
    LinkDown,
    LinkEvent,
    LinkMonitor,
    LinkUp,
    MissionState,
    RampPoseSample,
    ReadbackResult,
    RttEstimator,
    StatusTextReceived,
    Telemetry,
    TelemetryReceived,
    UploadProgress,
    UploadResult,
)
from usvstation.link.standard_mission import (
    StandardItem,
    f32,
    first_difference,
    leg_length_m,
    leg_speeds,
    standard_items,
    waypoints_of,
)
from usvstation.link.standard_transfer import (
    ITEM_TIMEOUT_S,
    RESULT_NAMES,
    TIMEOUT_S,
    CommandDone,
    CommandSender,
    MissionDownload,
    MissionUpload,
    SendCommand,
    SendCount,
    SendItem,
    SendMissionAck,
    SendRequestItem,
    SendRequestList,
    TransferDone,
    TransferEvent,
    TransferProgress,
    TransferRequest,
)

INF = float("inf")
ARM, DISARM_FORCE = 1.0, 21196.0  # MAV_CMD_COMPONENT_ARM_DISARM param1; param2 forces
TARGET_MASK = (mav.POSITION_TARGET_TYPEMASK_AX_IGNORE | mav.POSITION_TARGET_TYPEMASK_AY_IGNORE
               | mav.POSITION_TARGET_TYPEMASK_AZ_IGNORE
               | mav.POSITION_TARGET_TYPEMASK_YAW_IGNORE
               | mav.POSITION_TARGET_TYPEMASK_YAW_RATE_IGNORE)
VEHICLE_TYPES_REFUSED = frozenset((mav.MAV_TYPE_GCS, mav.MAV_TYPE_ADSB,
                                   mav.MAV_TYPE_ONBOARD_CONTROLLER))


# ----------------------------------------------------------------------------- profiles


@dataclass(frozen=True)
class VehicleProfile:
    """What a kind of autopilot calls its modes and how it is asked for one.

    `modes` maps the station's roles (auto, hold, guided, loiter) to the vehicle's
    HEARTBEAT.custom_mode; `names` names every custom mode the profile knows (for the
    console); `mode_params` is how DO_SET_MODE carries a custom mode ("number": param2 =
    the mode; "px4": param2 = main mode, param3 = sub mode); `home_item`: the vehicle keeps
    its home in mission item 0; `signing`: it takes SETUP_SIGNING; `hold_fallback`: where
    the vehicle refuses its hold mode, the station holds it in GUIDED at its position."""

    name: str
    title: str
    modes: dict[str, int]
    names: dict[int, str]
    mode_params: str
    home_item: bool
    signing: bool
    hold_fallback: bool

    def mode_name(self, custom_mode: int) -> str:
        return self.names.get(custom_mode, f"mode {custom_mode}")

    def set_mode_params(self, role: str) -> tuple[float, ...]:
        mode = self.modes[role]
        flag = float(mav.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED)
        if self.mode_params == "px4":
            return (flag, float((mode >> 16) & 0xFF), float((mode >> 24) & 0xFF))
        return (flag, float(mode))


def _px4(main: int, sub: int = 0) -> int:
    return (main << 16) | (sub << 24)


ARDUPILOT_ROVER_MODES = {0: "MANUAL", 1: "ACRO", 3: "STEERING", 4: "HOLD", 5: "LOITER",
                         6: "FOLLOW", 7: "SIMPLE", 8: "DOCK", 9: "CIRCLE", 10: "AUTO",
                         11: "RTL", 12: "SMART_RTL", 15: "GUIDED", 16: "INITIALISING"}
PX4_MODES = {_px4(1): "MANUAL", _px4(2): "ALTCTL", _px4(3): "POSCTL", _px4(4, 1): "AUTO.READY",
             _px4(4, 2): "AUTO.TAKEOFF", _px4(4, 3): "AUTO.LOITER", _px4(4, 4): "AUTO.MISSION",
             _px4(4, 5): "AUTO.RTL", _px4(4, 6): "AUTO.LAND", _px4(5): "ACRO",
             _px4(6): "OFFBOARD", _px4(7): "STABILIZED"}
PROFILES: dict[str, VehicleProfile] = {
    "ardupilot-rover": VehicleProfile(
        "ardupilot-rover", "ArduPilot Rover (boat frame)",
        {"auto": 10, "hold": 4, "guided": 15, "loiter": 5}, ARDUPILOT_ROVER_MODES, "number",
        home_item=True, signing=True, hold_fallback=False),
    "px4": VehicleProfile(
        "px4", "PX4 (rover / boat)",
        {"auto": _px4(4, 4), "hold": _px4(4, 3), "guided": _px4(6), "loiter": _px4(4, 3)},
        PX4_MODES, "px4", home_item=False, signing=False, hold_fallback=True),
}


@dataclass(frozen=True)
class StandardConfig(LinkConfig):
    """usv-link's `LinkConfig` (ids, baud, link timeout, retry floors) and what a stock
    autopilot needs: its profile, whether START follows the timed plan in GUIDED (else the
    uploaded mission in AUTO), the position-target rate and the arrival radius."""

    profile: VehicleProfile = PROFILES["ardupilot-rover"]
    guided: bool = True
    target_period_s: float = 0.2  # SET_POSITION_TARGET_GLOBAL_INT at 5 Hz
    arrive_radius_m: float = 3.0  # GUIDED: the last waypoint reached within this
    signing_period_s: float = 5.0  # SETUP_SIGNING again while the vehicle does not sign
    heartbeat_period_s: float = 0.5
    vehicle_component: int = mav.MAV_COMP_ID_AUTOPILOT1


# ----------------------------------------------------------------------------- the schedule


@dataclass(frozen=True)
class Target:
    """Where the boat should be at plan time `t` and how it should move (NED, m/s)."""

    t: float
    lat_e7: int
    lon_e7: int
    vn: float
    ve: float
    waypoint_index: int  # the leg's first waypoint
    finished: bool  # past the last waypoint's time


class GuidedSchedule:
    """Position and velocity along a timed mission (position linear in time on each leg,
    paper 000 eq. 9) at station time; `pause`/`resume` stop and shift it (HOLD)."""

    def __init__(self, items: tuple[MissionItem, ...], started: float) -> None:
        self.items, self.started = items, started
        self.paused_at: float | None = None
        self.held_s = 0.0

    def plan_time(self, now: float) -> float:
        end = self.paused_at if self.paused_at is not None else now
        return max(0.0, end - self.started - self.held_s)

    def pause(self, now: float) -> None:
        if self.paused_at is None:
            self.paused_at = now

    def resume(self, now: float) -> None:
        if self.paused_at is not None:
            self.held_s += now - self.paused_at
            self.paused_at = None

    def target(self, now: float) -> Target:
        t = self.plan_time(now)
        items = self.items
        ms = t * 1000.0
        if ms >= items[-1].t_ms:
            last = items[-1]
            return Target(t, last.lat, last.lon, 0.0, 0.0, len(items) - 1, True)
        i = max(k for k in range(len(items) - 1) if items[k].t_ms <= ms)
        a, b = items[i], items[i + 1]
        f = (ms - a.t_ms) / (b.t_ms - a.t_ms)
        dt = (b.t_ms - a.t_ms) / 1000.0
        length = leg_length_m(a.lat, a.lon, b.lat, b.lon)
        bearing = _bearing(a, b)
        speed = length / dt if self.paused_at is None else 0.0
        return Target(t, round(a.lat + f * (b.lat - a.lat)), round(a.lon + f * (b.lon - a.lon)),
                      speed * math.cos(bearing), speed * math.sin(bearing), i, False)


def _bearing(a: MissionItem, b: MissionItem) -> float:
    """Compass bearing (rad) from a to b on the local tangent plane."""
    phi = math.radians((a.lat + b.lat) * 0.5e-7)
    dn = (b.lat - a.lat)
    de = (b.lon - a.lon) * math.cos(phi)
    return math.atan2(de, dn)


# ----------------------------------------------------------------------------- recovery state

IDLE, READY, RUNNING, HOLD, DONE, ABORTED, FAILSAFE = (
    "IDLE", "READY", "RUNNING", "HOLD", "DONE", "ABORTED", "FAILSAFE")

RECOVERY: dict[tuple[str, str], str] = {
    # (state, what happened) -> next state; anything else leaves the state as it is
    **{(s, "verified"): READY for s in (IDLE, READY, DONE, ABORTED)},
    **{(s, "dropped"): IDLE for s in (READY, DONE, ABORTED, IDLE)},
    (READY, "started"): RUNNING,
    **{(s, "held"): HOLD for s in (RUNNING, HOLD, FAILSAFE)},
    **{(s, "resumed"): RUNNING for s in (HOLD, FAILSAFE)},
    **{(s, "aborted"): ABORTED for s in (IDLE, READY, RUNNING, HOLD, DONE, FAILSAFE)},
    (RUNNING, "completed"): DONE,
    (RUNNING, "left mode"): FAILSAFE,  # the vehicle left the ordered mode on its own
    **{(s, "rebooted"): IDLE for s in (READY, RUNNING, HOLD, DONE, ABORTED, FAILSAFE)},
}
"""The station's account of a stock autopilot's recovery (docs/link.md): its own
USV_MISSION_STATE, from what the vehicle acknowledged and reports."""


@dataclass
class RecoveryTracker:
    state: str = IDLE
    mission: Mission | None = None  # uploaded and read back identical
    waypoint_index: int = 0

    def apply(self, what: str) -> bool:
        new = RECOVERY.get((self.state, what), self.state)
        changed = new != self.state
        self.state = new
        if new in (IDLE, ABORTED):
            self.mission = None if what in ("dropped", "aborted", "rebooted") else self.mission
        return changed


@dataclass
class VehicleStatus:
    """What the vehicle's HEARTBEAT, MISSION_CURRENT and clock said last."""

    custom_mode: int | None = None
    armed: bool = False
    vehicle_type: int = 0
    autopilot: int = 0
    system_status: int = 0
    mission_seq: int = 0
    mission_total: int = 0
    boot_ms: int = 0


@dataclass
class Action:
    """A recovery command in steps (arm, then a mode; a mode, then disarm): its outcome once
    every step answered (`essential` steps decide it; the others run whatever happens)."""

    seq: int
    name: str
    steps: list[tuple[int, tuple[float, ...], str]]  # (command, params, what it does)
    essential: set[int] = field(default_factory=set)  # indexes into steps
    index: int = 0
    results: dict[int, CommandDone] = field(default_factory=dict)  # by step, the last


# ----------------------------------------------------------------------------- the protocol


class StandardProtocol:
    """The station side of a standard MAVLink 2 vehicle: bytes and `now` in, bytes and
    LinkEvents out. One upload (with its readback), one readback and one action at a
    time."""

    def __init__(self, config: StandardConfig, now: float, *, key: bytes | None = None,
                 unix_time: float = 0.0, session: int | None = None) -> None:
        self.config = cfg = config
        self.profile = cfg.profile
        self.key = key
        self.codec = wire.Codec(cfg.station_id, wire.STATION_COMPONENT, key,
                                link_id=cfg.link_id, timestamp=wire.signing_time(unix_time),
                                allow_unsigned=tuple(mav.mavlink_map) if key else ())
        self.vehicle_signs = False  # the vehicle's frames arrive signed (then required)
        self.unix_time, self._t0 = unix_time, now
        self.now = now
        self.session = session or 0
        self.monitor = _VehicleMonitor(cfg, now)
        self.rtt = RttEstimator(cfg)
        self.status = VehicleStatus()
        self.mode_changes = 0
        self._upload_note = ""
        self.tracker = RecoveryTracker()
        self.report: MissionState | None = None
        self.report_at = -INF
        self.telemetry: Telemetry | None = None
        self.latest: dict[str, Any] = {}
        self.refused: Counter[str] = Counter()
        self.frames_lost = 0
        self._last_seq: int | None = None
        self.radio: Any = None
        self.commands = CommandSender(max(TIMEOUT_S, self.rtt.timeout))
        self.upload: MissionUpload | None = None
        self.upload_mission: Mission | None = None
        self.upload_items: tuple[StandardItem, ...] = ()
        self.upload_started = now
        self.download: MissionDownload | None = None
        self.download_for: tuple[str, int] | None = None  # ("verify" | "read", mission id)
        self.action: Action | None = None
        self._action_seq = 0
        self.schedule: GuidedSchedule | None = None
        self.guided_hold: tuple[int, int] | None = None  # a HOLD kept in GUIDED (fallback)
        self.next_target = now
        self.targets_sent = 0
        self.next_signing = now
        self.signing_sent = 0
        self.ramp_pose: RampPoseSample | None = None  # kept; a stock autopilot has no frame
        self.ordered_mode: int | None = None  # the mode the station last set and got
        self.mode_confirmed = False  # a HEARTBEAT showed the ordered mode since
        self._pending_outcomes: list[LinkEvent] = []
        self._out = bytearray()
        self.bytes_sent = self.bytes_received = 0

    # ---- state
    @property
    def link_up(self) -> bool:
        return self.monitor.link_up

    @property
    def other_systems(self) -> Counter[int]:
        return self.monitor.other_systems

    @property
    def signed(self) -> bool:
        """Both directions signed: we sign, and the vehicle's frames arrive signed."""
        return self.key is not None and self.vehicle_signs

    @property
    def streaming(self) -> bool:
        """Position targets flow: a HOLD kept in GUIDED, or the timed plan while it runs,
        is being started or resumed, and at its end (the boat keeps the last target)."""
        if self.guided_hold is not None:
            return True
        if self.schedule is None or not self.link_up:
            return False
        a = self.action
        return self.tracker.state in (RUNNING, DONE) or (
            a is not None and a.name in ("start", "resume"))

    @property
    def mode_name(self) -> str | None:
        c = self.status.custom_mode
        return None if c is None else self.profile.mode_name(c)

    def boat_uptime_ms(self, now: float) -> int | None:
        return None  # a stock autopilot has no timed hot swap (no TIMESYNC-aligned clock)

    def set_ramp_pose(self, pose: RampPoseSample | None) -> None:
        """Kept for the station's wiring; a stock autopilot tracks in fixed coordinates."""
        self.ramp_pose = pose

    def _stamp(self, now: float) -> int:
        return wire.signing_time(self.unix_time + (now - self._t0))

    # ---- input
    def receive_data(self, data: bytes, now: float) -> list[LinkEvent]:
        self.bytes_received += len(data)
        msgs, refused = self.codec.feed(data)
        for r in refused:
            self.refused[r.reason] += 1
        events: list[LinkEvent] = []
        for msg in msgs:
            events += self._handle(msg, now)
        return events + self.poll(now)

    def _handle(self, msg: Any, now: float) -> list[LinkEvent]:
        kind = msg.get_type()
        if kind == "RADIO_STATUS":
            self.radio = msg
            return []
        src = msg.get_srcSystem()
        if src == self.config.station_id:
            self.monitor.echoes += 1
            return []
        if src != self.config.boat_id or msg.get_srcComponent() != self.config.vehicle_component:
            self.monitor.other_systems[src] += 1
            return []
        if self.key is not None and msg._signed and not self.vehicle_signs:
            self.vehicle_signs = True  # from now on the vehicle's frames must be signed
            self.codec.require_signed()
        seq = msg.get_seq()
        if self._last_seq is not None:
            self.frames_lost += (seq - self._last_seq - 1) % 256
        self._last_seq = seq
        events = self.monitor.on_boat_frame(msg, now)
        self.latest[kind] = msg
        handler = _FROM_VEHICLE.get(kind)
        if handler is not None:
            events += handler(self, msg, now)
        return events

    def _on_heartbeat(self, hb: Any, now: float) -> list[LinkEvent]:
        st = self.status
        before = (st.custom_mode, st.armed)
        st.custom_mode = hb.custom_mode
        st.armed = bool(hb.base_mode & mav.MAV_MODE_FLAG_SAFETY_ARMED)
        st.vehicle_type, st.autopilot, st.system_status = hb.type, hb.autopilot, hb.system_status
        events: list[LinkEvent] = []
        if st.custom_mode == self.ordered_mode:
            self.mode_confirmed = True
        elif self.tracker.state == RUNNING and self.mode_confirmed and self.action is None:
            name = self.profile.mode_name(st.custom_mode)
            self._pause_schedule(now)
            self.tracker.apply("left mode")
            events.append(StatusTextReceived(mav.MAV_SEVERITY_WARNING,
                                             f"the vehicle left the recovery for {name}"))
        if (st.custom_mode, st.armed) != before:
            self.mode_changes += 1
        return events + self._report(now)  # about 1 Hz, like usv-link's USV_MISSION_STATE

    def _on_mission_current(self, m: Any, now: float) -> list[LinkEvent]:
        self.status.mission_seq, self.status.mission_total = m.seq, m.total
        if self.schedule is None and self.tracker.mission is not None:
            self.tracker.waypoint_index = self._waypoint_of(m.seq)
        return []

    def _on_item_reached(self, m: Any, now: float) -> list[LinkEvent]:
        mission = self.tracker.mission
        if mission is None or self.schedule is not None:
            return []
        self.tracker.waypoint_index = self._waypoint_of(m.seq)
        if m.seq == len(self.upload_items_for(mission)) - 1 and self.tracker.apply("completed"):
            return [StatusTextReceived(mav.MAV_SEVERITY_INFO, "mission complete"),
                    *self._report(now)]
        return []

    def _waypoint_of(self, seq: int) -> int:
        return max(0, (seq - int(self.profile.home_item)) // 2)

    def upload_items_for(self, mission: Mission) -> tuple[StandardItem, ...]:
        return standard_items(mission.items, home=self.profile.home_item)

    def _on_position(self, gp: Any, now: float) -> list[LinkEvent]:
        events: list[LinkEvent] = []
        st = self.status
        if st.boot_ms and gp.time_boot_ms + 5000 < st.boot_ms:  # its clock went back
            events += self._rebooted(now)
        st.boot_ms = gp.time_boot_ms
        if self.schedule is not None and self.tracker.state == RUNNING:
            target = self.schedule.target(now)
            self.tracker.waypoint_index = target.waypoint_index
            last = self.schedule.items[-1]
            if target.finished and leg_length_m(gp.lat, gp.lon, last.lat, last.lon) \
                    <= self.config.arrive_radius_m and self.tracker.apply("completed"):
                events.append(StatusTextReceived(mav.MAV_SEVERITY_INFO, "mission complete"))
                events += self._report(now)
        self.telemetry = self._telemetry(gp)
        events.append(TelemetryReceived(self.telemetry, received_at=now))
        return events

    def _rebooted(self, now: float) -> list[LinkEvent]:
        self.tracker.apply("rebooted")
        self.tracker.mission, self.schedule, self.guided_hold = None, None, None
        return [BoatRebooted(0, 0), *self._report(now)]

    def _on_statustext(self, m: Any, now: float) -> list[LinkEvent]:
        return [StatusTextReceived(m.severity, m.text)]

    def _on_command_ack(self, ack: Any, now: float) -> list[LinkEvent]:
        if ack.target_system not in (0, self.config.station_id):
            return []
        return self._command_done(self.commands.on_ack(ack.command, ack.result, now), now)

    def _on_request(self, r: Any, now: float) -> list[LinkEvent]:
        up = self.upload
        if up is None or r.mission_type != mav.MAV_MISSION_TYPE_MISSION \
                or r.target_system not in (0, self.config.station_id):
            return []
        out, ev = up.on_request(r.seq, now)
        self._queue(out, now)
        return self._transfer_events(ev, now)

    def _on_mission_ack(self, a: Any, now: float) -> list[LinkEvent]:
        if a.mission_type != mav.MAV_MISSION_TYPE_MISSION \
                or a.target_system not in (0, self.config.station_id):
            return []
        if self.upload is not None and not self.upload.done:
            return self._transfer_events(self.upload.on_ack(a.type), now)
        if self.download is not None and not self.download.done:
            return self._transfer_events(self.download.on_ack(a.type), now)
        return []

    def _on_count(self, c: Any, now: float) -> list[LinkEvent]:
        dl = self.download
        if dl is None or c.mission_type != mav.MAV_MISSION_TYPE_MISSION:
            return []
        out, ev = dl.on_count(c.count, now)
        self._queue(out, now)
        return self._transfer_events(ev, now)

    def _on_item(self, m: Any, now: float) -> list[LinkEvent]:
        dl = self.download
        if dl is None or m.mission_type != mav.MAV_MISSION_TYPE_MISSION:
            return []
        out, ev = dl.on_item(StandardItem.from_msg(m), now)
        self._queue(out, now)
        return self._transfer_events(ev, now)

    # ---- the station's account of the recovery
    def _report(self, now: float) -> list[LinkEvent]:
        t, st = self.tracker, self.status
        m = t.mission
        self.report = MissionState(
            uptime_ms=st.boot_ms, boot_id=0, state=t.state,
            active_id=m.mission_id if m else 0, active_crc32=m.crc if m else 0,
            active_count=m.count if m else 0, current_seq=t.waypoint_index, staging=0,
            staged_id=0, staged_crc32=0, staged_received=0, staged_count=0, swap_at_ms=0,
            station_session=self.session, rejected=0)
        self.report_at = now
        return [BoatReport(self.report, received_at=now)]

    def _telemetry(self, gp: Any) -> Telemetry:
        get = self.latest.get
        gps, att, sysst = get("GPS_RAW_INT"), get("ATTITUDE"), get("SYS_STATUS")
        vn, ve = CM.from_wire(gp.vx), CM.from_wire(gp.vy)
        speed = math.hypot(vn, ve)
        heading = CDEG.from_wire(gp.hdg) if gp.hdg != 0xFFFF else \
            (math.degrees(att.yaw) % 360 if att is not None else 0.0)
        course = math.degrees(math.atan2(ve, vn)) % 360 if speed > 0.01 else heading
        return Telemetry(
            time_s=MS.from_wire(gp.time_boot_ms), lat=E7.from_wire(gp.lat),
            lon=E7.from_wire(gp.lon), speed=round(speed, 3), course_deg=round(course, 2),
            heading_deg=round(heading, 2),
            yaw_rate_dps=round(math.degrees(att.yawspeed), 3) if att is not None else 0.0,
            fix_type=gps.fix_type if gps is not None else 0,
            satellites=gps.satellites_visible if gps is not None else 0,
            hdop=gps.eph / 100 if gps is not None and gps.eph != 0xFFFF else 0.0,
            battery_v=sysst.voltage_battery / 1000
            if sysst is not None and sysst.voltage_battery != 0xFFFF else 0.0,
            waypoint_index=self.tracker.waypoint_index, state=self.tracker.state)

    # ---- timers
    def poll(self, now: float) -> list[LinkEvent]:
        self.now = now
        events = self.monitor.poll(now)
        if events:
            events += self._fail_pending(f"link lost: {events[-1].reason}", now)
        if self.monitor.due_heartbeat(now):
            self._send(self.codec.mav.heartbeat_encode(
                mav.MAV_TYPE_GCS, mav.MAV_AUTOPILOT_INVALID, 0, 0, mav.MAV_STATE_ACTIVE), now)
        if self.link_up and self.key is not None and self.profile.signing \
                and not self.vehicle_signs and now >= self.next_signing:
            self.next_signing = now + self.config.signing_period_s
            self._send_setup_signing(now)
        for machine in (self.upload, self.download):
            if machine is not None and not machine.done:
                out, ev = machine.poll(now)
                self._queue(out, now)
                events += self._transfer_events(ev, now)
        sends, done = self.commands.poll(now)
        for s in sends:
            self._send_command(s, now)
        events += self._command_done(done, now)
        if now >= self.next_target and self.streaming:
            self.next_target = now + self.config.target_period_s
            self._send_target(now)
        return events

    def _fail_pending(self, reason: str, now: float) -> list[LinkEvent]:
        events: list[LinkEvent] = []
        for machine in (self.upload, self.download):
            if machine is not None and not machine.done:
                events += self._transfer_events(machine.cancel(reason), now)
        events += self._command_done(self.commands.fail_all(reason), now)
        return events

    def connection_lost(self, reason: str, now: float) -> list[LinkEvent]:
        return self.monitor.lost(reason) + self._fail_pending(f"link lost: {reason}", now)

    def next_deadline(self) -> float:
        d = min(self.monitor.next_deadline(), self.commands.next_deadline())
        for machine in (self.upload, self.download):
            if machine is not None:
                d = min(d, machine.next_deadline())
        if self.streaming:
            d = min(d, self.next_target)
        if self.link_up and self.key is not None and self.profile.signing \
                and not self.vehicle_signs:
            d = min(d, self.next_signing)
        return d

    # ---- requests: missions
    def _require_link(self) -> None:
        if not self.monitor.link_up:
            raise RuntimeError("the vehicle link is down")

    def _busy(self) -> str | None:
        if self.upload is not None and not self.upload.done:
            return "a mission is uploading"
        if self.download is not None and not self.download.done:
            return "the vehicle's mission is being read"
        return None

    def start_upload(self, mission: Mission, now: float, swap_at_ms: int = 0) -> None:
        """Upload `mission` with the standard protocol, read it back and compare; the
        UploadResult is ok only when the vehicle's copy is identical. A stock autopilot has
        no timed hot swap: swap_at_ms must be 0."""
        self._require_link()
        if swap_at_ms:
            raise RuntimeError("a stock autopilot has no timed hot swap")
        busy = self._busy()
        if busy:
            raise RuntimeError(busy)
        if self.tracker.state in (RUNNING, HOLD, FAILSAFE):
            raise RuntimeError(f"the vehicle is {self.tracker.state}: HOLD does not allow an "
                               "upload; ABORT first")
        self.upload_mission, self.upload_started = mission, now
        self.upload_items = self.upload_items_for(mission)
        # whatever the vehicle held is no longer a mission the station has verified: an
        # upload that fails half way may leave a mixture in some autopilots
        self.tracker.apply("dropped")
        self.tracker.mission, self.schedule = None, None
        self.upload = MissionUpload(self.upload_items, timeout_s=self._timeout())
        self._queue(self.upload.start(now), now)

    def start_readback(self, mission_id: int, count: int, now: float) -> None:
        """Read the vehicle's mission and compare it with mission `mission_id` as uploaded;
        ReadbackResult.items: the usv-link items, with the vehicle's positions, when they
        match; None with the first difference when they do not."""
        self._require_link()
        busy = self._busy()
        if busy:
            raise RuntimeError(busy)
        self._start_download("read", mission_id, now)

    def _start_download(self, why: str, mission_id: int, now: float) -> None:
        self.download = MissionDownload(timeout_s=self._timeout(),
                                        item_timeout_s=max(ITEM_TIMEOUT_S, self.rtt.timeout))
        self.download_for = (why, mission_id)
        self._queue(self.download.start(now), now)

    def _timeout(self) -> float:
        return max(TIMEOUT_S, self.rtt.timeout)

    def _transfer_events(self, events: list[TransferEvent], now: float) -> list[LinkEvent]:
        out: list[LinkEvent] = []
        for ev in events:
            if isinstance(ev, TransferProgress):
                out += self._progress(ev)
            elif isinstance(ev, TransferDone):
                out += self._transfer_done(ev, now)
        return out

    def _progress(self, ev: TransferProgress) -> list[LinkEvent]:
        """An upload's progress in waypoints (the items the vehicle asked for); the
        read-back that follows it reports nothing until its verdict."""
        m, up = self.upload_mission, self.upload
        if m is None or up is None or up.done or ev.done >= ev.count:
            return []
        acked = m.count * ev.done // max(1, ev.count)
        return [UploadProgress(m.mission_id, acked, m.count, sent=acked)]

    def _transfer_done(self, ev: TransferDone, now: float) -> list[LinkEvent]:
        if self.upload is not None and self.upload.result is ev:
            return self._upload_done(ev, now)
        if self.download is not None and self.download.result is ev:
            return self._download_done(ev, now)
        return []

    def _upload_done(self, ev: TransferDone, now: float) -> list[LinkEvent]:
        m = self.upload_mission
        assert m is not None
        all_requested = self.upload is not None \
            and self.upload.highest == len(self.upload_items) - 1
        if ev.ok or (all_requested and self.link_up):
            # read it back: the vehicle's copy decides (its final ACK may have been lost)
            self._start_download("verify", m.mission_id, now)
            self._upload_note = "" if ev.ok else ev.reason
            return []
        self._clear_mission(now)
        return [self._upload_result(False, f"standard upload failed: {ev.reason}", now)]

    def _upload_result(self, ok: bool, reason: str, now: float) -> UploadResult:
        m = self.upload_mission
        assert m is not None
        up = self.upload
        retrans = (up.retransmissions if up else 0) + \
            (self.download.retransmissions if self.download else 0)
        return UploadResult(m.mission_id, ok, reason, m.count, retrans, now - self.upload_started)

    def _download_done(self, ev: TransferDone, now: float) -> list[LinkEvent]:
        why, mission_id = self.download_for or ("read", 0)
        self.download_for = None
        m = self.upload_mission if why == "verify" else self._mission_for(mission_id)
        if why == "verify":
            assert m is not None
            if not ev.ok or ev.items is None:
                self._clear_mission(now)
                return [self._upload_result(False, f"uploaded, but the read-back failed: "
                                                   f"{ev.reason}", now)]
            diff = first_difference(self.upload_items, ev.items, self.profile.home_item)
            if diff is not None:
                self._clear_mission(now)
                return [self._upload_result(False, f"read back differs: {diff}", now)]
            self.tracker.mission = m
            self.tracker.waypoint_index = 0
            self.tracker.apply("verified")
            note = f" (the upload itself ended: {self._upload_note})" if self._upload_note \
                else ""
            return [UploadProgress(m.mission_id, m.count, m.count, sent=m.count),
                    self._upload_result(True, "uploaded and read back identical" + note, now),
                    *self._report(now)]
        if not ev.ok or ev.items is None:
            return [ReadbackResult(mission_id, None, ev.reason)]
        if m is None:
            return [ReadbackResult(mission_id, None, "refused: the station did not upload "
                                                     f"mission {mission_id} to this vehicle")]
        diff = first_difference(self.upload_items_for(m), ev.items, self.profile.home_item)
        items = m.items if diff is None else _vehicle_copy(m, ev.items, self.profile.home_item)
        if items is None:
            return [ReadbackResult(mission_id, None, f"refused: the vehicle holds another "
                                                     f"mission ({diff})")]
        return [ReadbackResult(mission_id, items, "" if diff is None else diff)]

    def _mission_for(self, mission_id: int) -> Mission | None:
        for m in (self.tracker.mission, self.upload_mission):
            if m is not None and m.mission_id == mission_id:
                return m
        return None

    def _clear_mission(self, now: float) -> None:
        """After a failed upload: the vehicle holds no mission rather than a mixture."""
        self.tracker.mission = None
        if self.link_up:
            self._send(self.codec.mav.mission_clear_all_encode(
                self.config.boat_id, self.config.vehicle_component,
                mav.MAV_MISSION_TYPE_MISSION), now)

    # ---- requests: commands
    def send_command(self, name: str, now: float, mission_id: int = 0,
                     mission_crc: int = 0) -> int:
        """start/hold/resume/abort as the profile's steps; returns the action's seq (its
        CommandOutcome carries it). HOLD and ABORT replace an action in progress."""
        self._require_link()
        name = name.lower()
        if self.action is not None and name not in ("hold", "abort"):
            raise RuntimeError(f"{self.action.name.upper()} is still in progress")
        self._action_seq += 1
        action = self._plan_action(name, self._action_seq, wire.to_u32(mission_id),
                                   wire.to_u32(mission_crc), now)
        if self.action is not None:
            self.commands.fail_all(f"replaced by {name.upper()}")
            self._pending_outcomes.append(self._outcome(self.action, None, "replaced by "
                                                        f"{name.upper()}"))
        if not action.steps:  # START of a mission the vehicle does not hold, or not READY
            held = self.tracker.mission
            reason = "NO_MISSION" if held is None else "MISSION_MISMATCH" \
                if (held.mission_id, held.crc) != (wire.to_u32(mission_id),
                                                   wire.to_u32(mission_crc)) else "WRONG_STATE"
            self._pending_outcomes.append(CommandOutcome(action.seq, name,
                                                         mav.MAV_RESULT_DENIED, reason))
            return action.seq
        self.action = action
        self._next_step(now)
        return action.seq

    def _plan_action(self, name: str, seq: int, mission_id: int, crc: int,
                     now: float) -> Action:
        p = self.profile
        mode = "guided" if self.config.guided else "auto"
        arm = mav.MAV_CMD_COMPONENT_ARM_DISARM
        set_mode = mav.MAV_CMD_DO_SET_MODE
        if name == "start":
            m = self.tracker.mission
            if m is None or (m.mission_id, m.crc) != (mission_id, crc) \
                    or self.tracker.state != READY:
                return Action(seq, name, [])  # refused in _next_step
            return Action(seq, name, [(arm, (ARM,), "arm"),
                                      (set_mode, p.set_mode_params(mode), mode)], {0, 1})
        if name == "hold":
            return Action(seq, name, [(set_mode, p.set_mode_params("hold"), "hold")], {0})
        if name == "resume":
            resume = "guided" if self.schedule is not None else "auto"
            return Action(seq, name, [(set_mode, p.set_mode_params(resume), resume)], {0})
        if name == "abort":
            return Action(seq, name, [(set_mode, p.set_mode_params("hold"), "hold"),
                                      (arm, (0.0, DISARM_FORCE), "disarm")], {1})
        raise RuntimeError(f"unknown command {name!r}: start, hold, resume or abort")

    def _next_step(self, now: float) -> None:
        a = self.action
        assert a is not None
        if a.name == "start" and a.index == 1 and self.config.guided:
            self._begin_schedule(now)  # targets flow before the mode switch (PX4 OFFBOARD)
        command, params, _ = a.steps[a.index]
        for s in self.commands.send(command, params, now):
            self._send_command(s, now)

    def _command_done(self, done: list[CommandDone], now: float) -> list[LinkEvent]:
        events: list[LinkEvent] = list(self._pending_outcomes)
        self._pending_outcomes = []
        for d in done:
            a = self.action
            if a is None or a.index >= len(a.steps) or a.steps[a.index][0] != d.command:
                continue
            a.results[a.index] = d
            events += self._step_done(a, d, now)
        return events

    def _step_done(self, a: Action, d: CommandDone, now: float) -> list[LinkEvent]:
        what = a.steps[a.index][2]
        if a.name == "hold" and not d.accepted and d.result is not None \
                and self.profile.hold_fallback and what == "hold":
            return self._guided_hold(a, now, d)
        essential_failed = a.index in a.essential and not d.accepted
        if essential_failed and a.name not in ("abort",):
            if a.name == "start" and what == "guided" and d.result is not None:
                a.steps[a.index] = (mav.MAV_CMD_DO_SET_MODE,
                                    self.profile.set_mode_params("auto"), "auto")
                self.schedule = None  # GUIDED refused: the uploaded mission in AUTO
                self._send_command(self.commands.send(*a.steps[a.index][:2], now)[0], now)
                return [StatusTextReceived(mav.MAV_SEVERITY_WARNING, "GUIDED refused: "
                                           "following the uploaded mission in AUTO")]
            return self._finish_action(a, d, now)
        a.index += 1
        if a.index < len(a.steps):
            self._next_step(now)
            return []
        return self._finish_action(a, d, now)

    def _guided_hold(self, a: Action, now: float, d: CommandDone) -> list[LinkEvent]:
        """The vehicle refused its hold mode: keep it where it is in GUIDED (the station
        streams its position at rest)."""
        gp = self.latest.get("GLOBAL_POSITION_INT")
        if gp is None:
            return self._finish_action(a, d, now)
        self._pause_schedule(now)
        self.guided_hold = (gp.lat, gp.lon)
        self.next_target = now
        self._send_target(now)
        a.steps[a.index] = (mav.MAV_CMD_DO_SET_MODE, self.profile.set_mode_params("guided"),
                            "hold in guided")
        self._send_command(self.commands.send(*a.steps[a.index][:2], now)[0], now)
        hold = self.profile.mode_name(self.profile.modes["hold"])
        return [StatusTextReceived(mav.MAV_SEVERITY_WARNING,
                                   f"{hold} refused: holding in GUIDED at the boat's position")]

    def _finish_action(self, a: Action, d: CommandDone, now: float) -> list[LinkEvent]:
        self.action = None
        ok = all(i in a.results and a.results[i].accepted for i in a.essential)
        if ok:
            self._apply_action(a, now)
        result = mav.MAV_RESULT_ACCEPTED if ok else d.result
        error = "" if ok else (d.error or "")
        return [self._outcome(a, result, error, d), *self._report(now)]

    def _outcome(self, a: Action, result: int | None, error: str,
                 d: CommandDone | None = None) -> CommandOutcome:
        reason = ""
        if result is not None and result != mav.MAV_RESULT_ACCEPTED and d is not None:
            step = a.steps[min(a.index, len(a.steps) - 1)][2] if a.steps else ""
            reason = f"{step.upper()} {RESULT_NAMES.get(result, str(result))}"
        return CommandOutcome(a.seq, a.name, result, reason, error)

    def _apply_action(self, a: Action, now: float) -> None:
        p = self.profile
        self.mode_confirmed = False
        if a.name == "start":
            self.tracker.apply("started")
            self.ordered_mode = p.modes["guided" if self.schedule is not None else "auto"]
        elif a.name == "hold":
            self._pause_schedule(now)
            self.tracker.apply("held")
            self.ordered_mode = p.modes["guided" if self.guided_hold else "hold"]
        elif a.name == "resume":
            self.guided_hold = None
            if self.schedule is not None:
                self.schedule.resume(now)
            self.tracker.apply("resumed")
            self.ordered_mode = p.modes["guided" if self.schedule is not None else "auto"]
        elif a.name == "abort":
            self.schedule, self.guided_hold, self.ordered_mode = None, None, None
            self.tracker.apply("aborted")

    def _pause_schedule(self, now: float) -> None:
        if self.schedule is not None:
            self.schedule.pause(now)

    def _begin_schedule(self, now: float) -> None:
        m = self.tracker.mission
        if m is None:
            return
        self.schedule = GuidedSchedule(m.items, now)
        self.next_target = now
        self._send_target(now)

    # ---- output
    def _send(self, msg: Any, now: float) -> None:
        self._out += self.codec.encode(msg, self._stamp(now))

    def _send_command(self, s: SendCommand, now: float) -> None:
        self._send(self.codec.mav.command_long_encode(
            self.config.boat_id, self.config.vehicle_component, s.command, s.confirmation,
            *s.params), now)

    def _send_target(self, now: float) -> None:
        if self.guided_hold is not None:
            lat, lon, vn, ve = *self.guided_hold, 0.0, 0.0
        elif self.schedule is not None:
            t = self.schedule.target(now)
            lat, lon, vn, ve = t.lat_e7, t.lon_e7, t.vn, t.ve
        else:
            return
        self._send(self.codec.mav.set_position_target_global_int_encode(
            int((now - self._t0) * 1000) & 0xFFFFFFFF, self.config.boat_id,
            self.config.vehicle_component, mav.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT, TARGET_MASK,
            lat, lon, 0.0, vn, ve, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0), now)
        self.targets_sent += 1

    def _send_setup_signing(self, now: float) -> None:
        assert self.key is not None
        self._send(self.codec.mav.setup_signing_encode(
            self.config.boat_id, self.config.vehicle_component, list(self.key),
            self._stamp(now)), now)
        self.signing_sent += 1

    def _queue(self, requests: list[TransferRequest], now: float) -> None:
        enc, b, c = self.codec.mav, self.config.boat_id, self.config.vehicle_component
        t = mav.MAV_MISSION_TYPE_MISSION
        for r in requests:
            if isinstance(r, SendCount):
                msg = enc.mission_count_encode(b, c, r.count, t)
            elif isinstance(r, SendItem):
                i = r.item
                msg = enc.mission_item_int_encode(b, c, i.seq, i.frame, i.command, 0,
                                                  i.autocontinue, i.param1, i.param2,
                                                  i.param3, i.param4, i.x, i.y, i.z, t)
            elif isinstance(r, SendRequestList):
                msg = enc.mission_request_list_encode(b, c, t)
            elif isinstance(r, SendRequestItem):
                msg = enc.mission_request_int_encode(b, c, r.seq, t)
            else:
                assert isinstance(r, SendMissionAck)
                msg = enc.mission_ack_encode(b, c, r.result, t)
            self._send(msg, now)

    def data_to_send(self) -> bytes:
        data = bytes(self._out)
        self._out.clear()
        self.bytes_sent += len(data)
        return data


def _vehicle_copy(mission: Mission, held: tuple[StandardItem, ...],
                  home: bool) -> tuple[MissionItem, ...] | None:
    """The vehicle's copy in usv-link items: its positions, and its leg speeds as the
    waypoint times they give (a standard mission carries no time, course or heading: those
    stay as uploaded); None when it holds another number of waypoints."""
    wps = waypoints_of(held, home)
    if len(wps) != mission.count:
        return None
    sent_speeds = leg_speeds(mission.items)
    out: list[MissionItem] = []
    for i, (it, w) in enumerate(zip(mission.items, wps, strict=True)):
        t_ms = it.t_ms
        if i > 0:
            prev, speed = out[-1], wps[i - 1].leg_speed
            if speed is None or f32(speed) != f32(sent_speeds[i - 1]):
                length = leg_length_m(prev.lat, prev.lon, w.lat_e7, w.lon_e7)
                dt_ms = round(1000 * length / speed) if speed else 0xFFFFFFFF
                t_ms = min(0xFFFFFFFF, prev.t_ms + dt_ms)
            else:
                t_ms = prev.t_ms + (it.t_ms - mission.items[i - 1].t_ms)
        out.append(replace(it, lat=w.lat_e7, lon=w.lon_e7, t_ms=t_ms))
    return tuple(out)


class _VehicleMonitor(LinkMonitor):
    """usv-link's LinkMonitor; the link comes up on any vehicle's HEARTBEAT (not only a
    SURFACE_BOAT: an ArduPilot Rover not yet set to the boat frame says GROUND_ROVER)."""

    def on_boat_frame(self, msg: Any, now: float) -> list[LinkEvent]:
        self.last_rx = now
        if self.link_up:
            return []
        if msg.get_type() == "HEARTBEAT" and msg.type not in VEHICLE_TYPES_REFUSED:
            self.link_up = True
            return [LinkUp(self.cfg.boat_id)]
        return []


_FROM_VEHICLE = {
    "HEARTBEAT": StandardProtocol._on_heartbeat,
    "MISSION_CURRENT": StandardProtocol._on_mission_current,
    "MISSION_ITEM_REACHED": StandardProtocol._on_item_reached,
    "GLOBAL_POSITION_INT": StandardProtocol._on_position,
    "STATUSTEXT": StandardProtocol._on_statustext,
    "COMMAND_ACK": StandardProtocol._on_command_ack,
    "MISSION_REQUEST_INT": StandardProtocol._on_request,
    "MISSION_REQUEST": StandardProtocol._on_request,
    "MISSION_ACK": StandardProtocol._on_mission_ack,
    "MISSION_COUNT": StandardProtocol._on_count,
    "MISSION_ITEM_INT": StandardProtocol._on_item,
}
"""What the station does with each message of the vehicle (the rest is kept in `latest`)."""

__all__ = ["PROFILES", "LinkDown", "StandardConfig", "StandardProtocol", "VehicleProfile"]
