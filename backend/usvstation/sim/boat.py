"""The boat side of usv-link 2 as a sans-IO state machine (protocol/README.md "Boat").

`BoatProtocol` is what the firmware does (protocol/c/boat/ is the same in C): it obeys
only its paired station's signed frames addressed to it, refreshes its link-loss timer
only on those, keeps a duplicate memory per (session, seq, command) that a new station
session clears and that expires after 5 s (HOLD and ABORT always execute), stages
missions and activates them atomically after END (count, ranges, CRC-32), swaps a
running mission at a boat-clock instant, fails safe 3 s after its station went silent,
and reports what it holds (USV_MISSION_STATE) after every HEARTBEAT and on every change.

It drives any `Vehicle` (sim/vehicle.py) through set_mission/start/hold/resume/abort/
set_guidance/clear_guidance/step/state only, and `set_frame` where the vehicle has it
(sim/dynamic.py, and KinematicVehicle). Time comes in as `now` (link clock, s); the boat
clock (uptime) runs `sim_speed` times faster.

The moving ramp (USV_RAMP_POSE, protocol/README.md "The ramp pose stream"): the mission's
waypoints are ramp-frame points (placed through the scenario origin, the ramp's pose at
the sea's start); each pose, labelled with the boat uptime it refers to, becomes the
vehicle's `RampMotion` (sim/frame.py), extrapolated with its velocity and yaw rate to
every control step. Without a USV_RAMP_POSE frame for `ramp_timeout_s` (link time; a
repeated pose counts, the station's own-ship age is its own alert) the pose is stale:
the frame is frozen where it was extrapolated to, a RUNNING boat goes to HOLD over ground
(a ship making way opens the distance; a dead-reckoned ramp that in truth slowed would
not), and a STATUSTEXT says so; the next pose moves the frame again (the boat stays in
HOLD until the operator resumes). A boat that never received a pose tracks in the fixed
frame of the scenario origin (the shore trial).
"""

from __future__ import annotations

import math
import random
from collections import Counter, deque
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from usvstation.geo import RampFrame
from usvstation.geometry import CDEG, CM, E7, MS
from usvstation.link import wire
from usvstation.link.mavlink import usv_recovery as mav
from usvstation.link.mission import (
    MIN_ITEMS,
    MissionItem,
    distance_m,
    item_problem,
    sequence_problem,
)
from usvstation.link.standard_mission import (
    MISSION_STATES,
    StandardItem,
    nav_seq,
    standard_armed,
    standard_items,
    standard_mode,
)
from usvstation.sim.frame import RampMotion
from usvstation.sim.sensors import Battery, GpsNoise
from usvstation.sim.vehicle import Vehicle, Waypoint

S_IDLE, S_READY, S_RUNNING, S_HOLD, S_DONE, S_ABORTED, S_FAILSAFE, S_GO_AROUND = range(8)
UNDER_WAY = (S_RUNNING, S_HOLD, S_FAILSAFE, S_GO_AROUND)  # a mission is being flown
SWAPPABLE = (S_RUNNING, S_GO_AROUND)  # a hot swap may be staged (GO_AROUND: at standby)
ST_NONE, ST_RECEIVING, ST_VERIFIED = range(3)
R = mav  # result and reason constants live in the generated module
STAGE_BEGIN, STAGE_ITEM, STAGE_END, STAGE_READ = 1, 2, 3, 4
PERSIST_PERIOD_S = 1.0  # the signing floor is written to non-volatile memory this often


@dataclass(frozen=True)
class BoatConfig:
    boat_id: int = wire.BOAT_ID
    station_id: int = wire.STATION_ID
    telemetry_hz: float = 5.0  # 0 < hz <= 50, per second of boat time
    failsafe_timeout_s: float = 3.0  # link time without a valid frame from the station
    heartbeat_period_s: float = 1.0  # boat time
    sim_speed: float = 1.0  # boat seconds per link-clock second
    max_step_s: float = 0.05  # vehicle integration step, boat time
    start_radius_m: float = 10.0  # START refused farther than this from waypoint 0
    staging_timeout_s: float = 30.0  # staging dropped after this long without progress
    duplicate_expiry_s: float = 5.0  # duplicate memory entry lifetime
    baud: int | None = None  # UART model: telemetry only while the line is idle
    link_id: int = 0
    ramp_timeout_s: float = 2.0  # link time without USV_RAMP_POSE: the pose is stale

    def __post_init__(self) -> None:
        if not 0 < self.telemetry_hz <= 50:
            raise ValueError(f"telemetry_hz must be in (0, 50], got {self.telemetry_hz}")
        if self.failsafe_timeout_s <= 0:
            raise ValueError("failsafe_timeout_s must be positive")
        if self.sim_speed <= 0:
            raise ValueError(f"sim_speed must be positive, got {self.sim_speed}")
        if self.boat_id == self.station_id:
            raise ValueError(f"boat_id and station_id are both {self.boat_id}")
        if self.ramp_timeout_s <= 0:
            raise ValueError(f"ramp_timeout_s must be positive, got {self.ramp_timeout_s}")


@dataclass
class NonVolatile:
    """What survives a reboot (flash on the STM32): the highest signing timestamp the
    boat accepted from its station, written at most every PERSIST_PERIOD_S. After a boot
    the boat accepts only station timestamps above it + 2 PERSIST_PERIOD_S, so nothing
    recorded before the reboot can be replayed; `exact`: written at a clean shutdown with
    the last timestamp accepted, so above it is enough."""

    sign_floor: int = 0
    exact: bool = False


@dataclass
class _Staging:
    mission_id: int
    crc32: int
    count: int
    swap_at_ms: int
    items: dict[int, MissionItem] = field(default_factory=dict)
    state: int = ST_RECEIVING
    touched: float = 0.0  # link time of the last progress

    @property
    def contiguous(self) -> int:
        n = 0
        while n in self.items:
            n += 1
        return n


@dataclass(frozen=True)
class ActiveMission:
    mission_id: int
    crc32: int
    items: tuple[MissionItem, ...]


class BoatProtocol:
    """The simulated boat's protocol engine: feed bytes and time in, take bytes out."""

    def __init__(self, vehicle: Vehicle, frame: RampFrame, config: BoatConfig | None = None,
                 *, key: bytes | None = None, nv: NonVolatile | None = None,
                 gps: GpsNoise | None = None, battery: Battery | None = None,
                 now: float = 0.0, unix_time: float = wire.EPOCH_2015 + 3.0e8,
                 boot_id: int | None = None) -> None:
        self.vehicle, self.frame = vehicle, frame
        self.cfg = cfg = config or BoatConfig()
        self.gps, self.battery = gps or GpsNoise(), battery or Battery()
        self.nv = nv if nv is not None else NonVolatile()
        self.key = key
        self.unix_time, self.started = unix_time, now
        self.boot_id = boot_id if boot_id is not None else random.SystemRandom().getrandbits(32)
        margin = 0 if self.nv.exact else int(2 * PERSIST_PERIOD_S * wire.TICKS_PER_S)
        floor = self.nv.sign_floor + margin if self.nv.sign_floor else 0
        self.codec = wire.Codec(cfg.boat_id, wire.BOAT_COMPONENT, key, link_id=cfg.link_id,
                                timestamp=wire.signing_time(unix_time), stream_floor=floor,
                                allow_unsigned=(mav.MAVLINK_MSG_ID_RADIO_STATUS,))
        self.state = S_IDLE
        self.active: ActiveMission | None = None
        self.staging: _Staging | None = None
        self.expired_id = 0
        self.session = 0
        self.memory: dict[tuple[int, int, int], tuple[Any, float]] = {}
        self.linked = False
        self.last_rx = -math.inf
        self.last_now = now
        self.boat_time = 0.0
        self.next_telemetry = 0.0
        self.next_heartbeat = 0.0
        self.next_persist = now
        self.guided_until: float | None = None
        self.rejected = 0
        self.refusals: Counter[str] = Counter()
        self.other_systems: Counter[int] = Counter()
        self.echoes = 0
        self.failsafes = 0
        self.executed: list[tuple[float, str]] = []  # (uptime s, command) actually executed
        self.activations: list[tuple[float, int]] = []  # (uptime s, mission id) flown from
        self.telemetry_dropped = 0
        self.log: list[str] = []  # status texts, for the runner to print
        self.last_notice: str | None = None  # the vehicle's standing notice, sent once
        self._standby_said = False
        self._text_budget_at = -math.inf
        self._swap_mission: ActiveMission | None = None
        self._urgent = bytearray()
        self._telemetry: deque[Any] = deque()  # messages, signed when they go out
        self._line_free_at = now
        self.ramp = RampMotion()  # the ramp frame in the vehicle's world frame, boat time
        self.ramp_rx: float | None = None  # link time of the latest USV_RAMP_POSE
        self.ramp_stale = False
        self.ramp_poses = 0
        self._std_items: tuple[ActiveMission, tuple[StandardItem, ...]] | None = None
        self._std_reached: tuple[int, int] = (0, 0)  # (mission id, waypoints reported)

    # ---- I/O boundary
    @property
    def uptime_ms(self) -> int:
        return int(round(self.boat_time * 1000, 6)) & 0xFFFFFFFF

    def newest_station_timestamp(self) -> int:
        """The highest signing timestamp accepted from the station (0: none yet)."""
        return max((t for (_, sysid, _), t in self.codec.streams.items()
                    if sysid == self.cfg.station_id), default=0)

    def _stamp(self, now: float) -> int:
        return wire.signing_time(self.unix_time + now - self.started)

    def receive_data(self, data: bytes, now: float) -> None:
        self.update(now)
        msgs, refused = self.codec.feed(data)
        for r in refused:
            self._refuse(r.reason, r.system_id, now)
        for msg in msgs:
            self._handle(msg, now)

    def data_to_send(self, now: float | None = None) -> bytes:
        """ACKs, answers and status first, then telemetry; with `cfg.baud` telemetry goes
        out only while the modelled UART is idle (it never delays an ACK by more than
        one telemetry frame)."""
        out = bytes(self._urgent)
        self._urgent.clear()
        baud = self.cfg.baud
        t = self.last_now if now is None else now
        if baud:
            self._line_free_at = max(self._line_free_at, t) + len(out) * 10 / baud
        while self._telemetry and (not baud or self._line_free_at <= t):
            # signed now, not when queued: signing timestamps must rise in sending order
            frame = self.codec.encode(self._telemetry.popleft(), self._stamp(t))
            out += frame
            if baud:
                self._line_free_at = max(self._line_free_at, t) + len(frame) * 10 / baud
        return out

    def _send(self, msg: Any, now: float, *, telemetry: bool = False) -> None:
        if telemetry:
            self._telemetry.append(msg)
            while len(self._telemetry) > 16:
                self._telemetry.popleft()
                self.telemetry_dropped += 1
        else:
            self._urgent += self.codec.encode(msg, self._stamp(now))

    def _text(self, severity: int, text: str, now: float) -> None:
        self.log.append(text)
        self._send(self.codec.mav.statustext_encode(severity, text[:50].encode()), now)

    def _refuse(self, reason: str, src: int, now: float) -> None:
        self.rejected = min(0xFFFF, self.rejected + 1)
        self.refusals[reason] += 1
        if now - self._text_budget_at >= 1.0:  # at most one report a second
            self._text_budget_at = now
            self._text(mav.MAV_SEVERITY_WARNING,
                       f"refused {reason} frame from {src} ({self.rejected} total)", now)

    # ---- reports
    def _heartbeat(self, now: float) -> None:
        e = self.codec.mav
        status = mav.MAV_STATE_CRITICAL if self.state == S_FAILSAFE else \
            mav.MAV_STATE_ACTIVE if self.state in (S_RUNNING, S_HOLD, S_GO_AROUND) \
            else mav.MAV_STATE_STANDBY
        base = mav.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED | (
            mav.MAV_MODE_FLAG_AUTO_ENABLED if self.state == S_RUNNING else 0)
        base |= mav.MAV_MODE_FLAG_SAFETY_ARMED if standard_armed(self.state) else 0
        self._send(e.heartbeat_encode(mav.MAV_TYPE_SURFACE_BOAT, mav.MAV_AUTOPILOT_GENERIC,
                                      base, standard_mode(self.state), status), now)
        self._send(e.sys_status_encode(0, 0, 0, 0, round(self.battery.voltage * 1000), -1, -1,
                                       0, self.rejected, 0, 0, 0, 0), now)
        self._report(now)

    def _report(self, now: float) -> None:
        a, s = self.active, self.staging
        self._send(self.codec.mav.usv_mission_state_encode(
            self.uptime_ms, self.boot_id, self.state,
            a.mission_id if a else 0, a.crc32 if a else 0, len(a.items) if a else 0,
            min(self.vehicle.state.waypoint_index, 0xFFFF),
            s.state if s else ST_NONE, s.mission_id if s else 0, s.crc32 if s else 0,
            s.contiguous if s else 0, s.count if s else 0,
            s.swap_at_ms if s and s.state == ST_VERIFIED else 0,
            self.session, self.rejected, self.flags), now)

    @property
    def flags(self) -> int:
        """USV_MISSION_STATE.flags: USV_STATE_FLAG_OVER_CAPACITY while the vehicle says it
        cannot hold its point."""
        return mav.USV_STATE_FLAG_OVER_CAPACITY if self.last_notice else 0

    # ---- messages
    def _handle(self, msg: Any, now: float) -> None:
        kind = msg.get_type()
        src = msg.get_srcSystem()
        if src == self.cfg.boat_id:
            self.echoes += 1  # our own frames heard back: never a station
            return
        if kind in _GCS_READS:  # any ground station may read (signed, with the key)
            return self._on_gcs_read(msg, src, now)
        addressed = kind in _COMMANDING
        if src != self.cfg.station_id:
            if kind != "RADIO_STATUS":
                self.other_systems[src] += 1
            if addressed:
                self._refuse("wrong sender", src, now)
            return
        if kind == "RADIO_STATUS":
            return  # unsigned radio report: never refreshes the link timer
        target = getattr(msg, "target_system", self.cfg.boat_id)
        if target != self.cfg.boat_id:
            return  # for another boat
        self.last_rx = now
        if self.key is not None:
            ts = self.newest_station_timestamp()
            if now >= self.next_persist and ts > self.nv.sign_floor:
                self.nv.sign_floor = ts
                self.next_persist = now + PERSIST_PERIOD_S
        if not self.linked:
            self.linked = True
            self._text(mav.MAV_SEVERITY_INFO, "link up" if self.state != S_FAILSAFE
                       else "link back; failsafe hold: RESUME or ABORT", now)
        handler = _FROM_STATION.get(kind)
        if handler is not None:
            handler(self, msg, now)

    def _on_timesync(self, msg: Any, now: float) -> None:
        if msg.tc1 == 0:
            self._send(self.codec.mav.timesync_encode(int(self.boat_time * 1e9) or 1, msg.ts1),
                       now)

    def _on_command(self, c: Any, now: float) -> None:
        seq, session, code = int(c.param1), int(c.param2), c.command
        if session != self.session:  # a new station session: forget the old one's commands
            self.session = session
            self.memory.clear()
        self.memory = {k: v for k, v in self.memory.items()
                       if now - v[1] < self.cfg.duplicate_expiry_s}
        key = (session, seq, code)
        name = wire.COMMAND_NAMES.get(code)
        if key in self.memory and name not in ("hold", "abort"):
            self._send(self.memory[key][0], now)  # a retry: the same answer, not executed
            return
        result, reason = self._execute(name, c, now)
        ack = self.codec.mav.command_ack_encode(code, result, reason, seq, self.cfg.station_id,
                                                wire.STATION_COMPONENT)
        self.memory[key] = (ack, now)
        self._send(ack, now)
        self._report(now)

    def _on_command_long(self, c: Any, now: float) -> None:
        """usv-link commands are COMMAND_INT only: anything else is unsupported."""
        self._send(self.codec.mav.command_ack_encode(
            c.command, R.MAV_RESULT_UNSUPPORTED, R.USV_COMMAND_REASON_UNKNOWN_COMMAND, 0,
            self.cfg.station_id, wire.STATION_COMPONENT), now)

    def _execute(self, name: str | None, c: Any, now: float) -> tuple[int, int]:
        denied = R.MAV_RESULT_DENIED
        if name is None:
            return R.MAV_RESULT_UNSUPPORTED, R.USV_COMMAND_REASON_UNKNOWN_COMMAND
        st = self.state
        if name == "start":
            a = self.active
            if a is None:
                return denied, R.USV_COMMAND_REASON_NO_MISSION
            if (wire.to_u32(c.x), wire.to_u32(c.y)) != (a.mission_id, a.crc32):
                self._text(mav.MAV_SEVERITY_WARNING,
                           f"START refused: holds mission {a.mission_id}", now)
                return denied, R.USV_COMMAND_REASON_MISSION_MISMATCH
            if st != S_READY:
                return denied, R.USV_COMMAND_REASON_WRONG_STATE
            dist = self._distance_to(a.items[0])
            if dist > self.cfg.start_radius_m:
                self._text(mav.MAV_SEVERITY_WARNING, f"START refused: {dist:.1f} m from "
                           f"waypoint 0 (limit {self.cfg.start_radius_m:g} m)", now)
                return denied, R.USV_COMMAND_REASON_TOO_FAR
            self.vehicle.start()
            self.state = S_RUNNING
            self.activations.append((self.boat_time, a.mission_id))
        elif name == "hold":  # always acts: whatever moves stops and keeps station
            if st in UNDER_WAY:
                self.vehicle.hold()
                self._clear_guidance()
                self.state = S_HOLD
        elif name == "resume":
            if st == S_RUNNING:
                return R.MAV_RESULT_ACCEPTED, R.USV_COMMAND_REASON_NONE
            if st == S_GO_AROUND:  # a new approach, from the standby point only
                problem = self.vehicle.reapproach()
                if problem:
                    self._text(mav.MAV_SEVERITY_WARNING, f"RESUME refused: {problem}", now)
                    return denied, R.USV_COMMAND_REASON_WRONG_STATE
                self.state = S_RUNNING
                self._text(mav.MAV_SEVERITY_INFO, "new approach from standby", now)
            elif st not in (S_HOLD, S_FAILSAFE):
                return denied, R.USV_COMMAND_REASON_WRONG_STATE
            else:
                self.vehicle.resume()
                self.state = S_GO_AROUND if self._going_around() else S_RUNNING
        elif name == "abort":  # always acts: thrusters stop, missions and staging dropped
            self.vehicle.abort()
            self._clear_guidance()
            self.active, self.staging = None, None
            self.state = S_ABORTED
        self.executed.append((self.boat_time, name))
        return R.MAV_RESULT_ACCEPTED, R.USV_COMMAND_REASON_NONE

    def _distance_to(self, it: MissionItem) -> float:
        s = self.vehicle.state
        if not self.ramp.identity:  # both in the ramp frame
            wx, wy = self.frame.to_ramp(E7.from_wire(it.lat), E7.from_wire(it.lon))
            bx, by = self.ramp.at(self.boat_time).to_ramp(s.x, s.y)
            return math.hypot(float(wx) - bx, float(wy) - by)
        lat, lon = self.frame.to_geodetic(s.x, s.y)
        return distance_m(E7.to_wire(float(lat)), E7.to_wire(float(lon)), it.lat, it.lon)

    def _mission_ack(self, mission_id: int, seq: int, result: int, stage: int,
                     now: float) -> None:
        self._send(self.codec.mav.usv_mission_ack_encode(
            self.cfg.station_id, wire.STATION_COMPONENT, mission_id, seq, result, stage), now)

    def _on_begin(self, b: Any, now: float) -> None:
        mid = b.mission_id
        st = self.staging
        if mid == 0:
            return self._mission_ack(mid, 0, R.USV_MISSION_UNKNOWN_MISSION, STAGE_BEGIN, now)
        if not MIN_ITEMS <= b.count <= wire.MAX_MISSION_ITEMS:
            self._text(mav.MAV_SEVERITY_WARNING, f"mission {mid}: count {b.count} outside "
                       f"{MIN_ITEMS}..{wire.MAX_MISSION_ITEMS}", now)
            return self._mission_ack(mid, 0, R.USV_MISSION_BAD_COUNT, STAGE_BEGIN, now)
        running = self.state in UNDER_WAY
        if (b.swap_at_ms == 0 and running) or (b.swap_at_ms and self.state not in SWAPPABLE):
            return self._mission_ack(mid, 0, R.USV_MISSION_DENIED, STAGE_BEGIN, now)
        if st is not None and (st.mission_id, st.crc32, st.count, st.swap_at_ms) == \
                (mid, b.crc32, b.count, b.swap_at_ms):
            st.touched = now  # a retry of BEGIN: keep what is staged
        elif st is not None and st.state == ST_VERIFIED:
            return self._mission_ack(mid, 0, R.USV_MISSION_BUSY, STAGE_BEGIN, now)
        else:
            self.staging = st = _Staging(mid, b.crc32, b.count, b.swap_at_ms, touched=now)
        self._mission_ack(mid, st.contiguous, R.USV_MISSION_ACCEPTED, STAGE_BEGIN, now)
        self._report(now)

    def _on_item(self, m: Any, now: float) -> None:
        st, a = self.staging, self.active
        it = MissionItem.from_msg(m)
        if st is None or st.mission_id != it.mission_id:
            if a is not None and a.mission_id == it.mission_id and it.seq < len(a.items) \
                    and a.items[it.seq] == it:  # a late retry of the active mission's item
                return self._mission_ack(it.mission_id, len(a.items), R.USV_MISSION_ACCEPTED,
                                         STAGE_ITEM, now)
            result = R.USV_MISSION_EXPIRED if it.mission_id == self.expired_id \
                else R.USV_MISSION_UNKNOWN_MISSION
            return self._mission_ack(it.mission_id, 0, result, STAGE_ITEM, now)
        if st.state == ST_VERIFIED:
            return self._mission_ack(it.mission_id, st.count, R.USV_MISSION_ACCEPTED,
                                     STAGE_ITEM, now)
        if it.seq >= st.count:
            return self._mission_ack(it.mission_id, st.contiguous, R.USV_MISSION_BAD_SEQ,
                                     STAGE_ITEM, now)
        problem = item_problem(it)
        if problem:
            self._text(mav.MAV_SEVERITY_WARNING, f"item {it.seq}: {problem}", now)
            return self._mission_ack(it.mission_id, it.seq, R.USV_MISSION_OUT_OF_RANGE,
                                     STAGE_ITEM, now)
        st.items[it.seq] = it
        st.touched = now
        self._mission_ack(it.mission_id, st.contiguous, R.USV_MISSION_ACCEPTED, STAGE_ITEM, now)

    def _on_end(self, e: Any, now: float) -> None:
        st, a = self.staging, self.active
        mid = e.mission_id
        if st is None or st.mission_id != mid:
            if a is not None and (a.mission_id, a.crc32) == (mid, e.crc32):
                return self._mission_ack(mid, len(a.items), R.USV_MISSION_ACCEPTED, STAGE_END,
                                         now)  # a retry after the activation
            result = R.USV_MISSION_EXPIRED if mid == self.expired_id \
                else R.USV_MISSION_UNKNOWN_MISSION
            return self._mission_ack(mid, 0, result, STAGE_END, now)
        if st.state == ST_VERIFIED:
            return self._mission_ack(mid, st.count, R.USV_MISSION_ACCEPTED, STAGE_END, now)
        if (e.crc32, e.count) != (st.crc32, st.count):
            return self._mission_ack(mid, st.contiguous, R.USV_MISSION_CRC_MISMATCH, STAGE_END,
                                     now)
        n = st.contiguous
        if n < st.count:
            return self._mission_ack(mid, n, R.USV_MISSION_MISSING_ITEMS, STAGE_END, now)
        items = tuple(st.items[i] for i in range(st.count))
        bad = sequence_problem(items)
        if bad:
            self.staging = None
            self._text(mav.MAV_SEVERITY_WARNING, f"item {bad[0]}: t_ms not increasing", now)
            return self._mission_ack(mid, bad[0], R.USV_MISSION_OUT_OF_RANGE, STAGE_END, now)
        if wire.item_crc32(items) != st.crc32:
            self.staging = None
            return self._mission_ack(mid, 0, R.USV_MISSION_CRC_MISMATCH, STAGE_END, now)
        mission = ActiveMission(mid, st.crc32, items)
        if st.swap_at_ms:
            problem = "instant passed" if st.swap_at_ms <= self.uptime_ms else \
                self._swap_problem()
            if problem:
                self.staging = None
                self._text(mav.MAV_SEVERITY_WARNING, f"swap of {mid} refused: {problem}",
                           now)
                return self._mission_ack(mid, 0, R.USV_MISSION_DENIED, STAGE_END, now)
            st.state = ST_VERIFIED
            self._swap_mission = mission
            self._mission_ack(mid, st.count, R.USV_MISSION_ACCEPTED, STAGE_END, now)
            self._report(now)
            return None
        if self.state in UNDER_WAY:
            self.staging = None
            return self._mission_ack(mid, 0, R.USV_MISSION_DENIED, STAGE_END, now)
        self.vehicle.set_mission(self._waypoints(items))  # built whole, then swapped in
        self.active, self.staging, self.state = mission, None, S_READY
        self._mission_ack(mid, st.count, R.USV_MISSION_ACCEPTED, STAGE_END, now)
        self._text(mav.MAV_SEVERITY_INFO, f"mission {mid} active: {len(items)} waypoints", now)
        self._report(now)
        return None

    def _on_read(self, r: Any, now: float) -> None:
        a, st = self.active, self.staging
        items: dict[int, MissionItem] | tuple[MissionItem, ...] | None = None
        if a is not None and a.mission_id == r.mission_id:
            items = a.items
        elif st is not None and st.mission_id == r.mission_id:
            items = st.items
        if items is None:
            return self._mission_ack(r.mission_id, 0, R.USV_MISSION_UNKNOWN_MISSION,
                                     STAGE_READ, now)
        it = items[r.seq] if (isinstance(items, dict) and r.seq in items) or \
            (isinstance(items, tuple) and r.seq < len(items)) else None
        if it is None:
            return self._mission_ack(r.mission_id, r.seq, R.USV_MISSION_BAD_SEQ, STAGE_READ,
                                     now)
        self._send(self.codec.mav.usv_mission_item_encode(
            self.cfg.station_id, wire.STATION_COMPONENT, it.mission_id, it.seq, it.lat, it.lon,
            it.t_ms, it.speed_cms, it.course_cdeg, it.heading_cdeg), now)
        return None

    def _on_guidance(self, g: Any, now: float) -> None:
        if self.state != S_RUNNING or g.valid_ms == 0:
            return
        compass = CDEG.from_wire(g.heading_cdeg)
        heading = math.radians(float(self.frame.compass_to_heading_deg(compass)))
        heading -= self.ramp.at(self.boat_time).theta  # the vehicle steers in the ramp frame
        self.vehicle.set_guidance(heading, CM.from_wire(g.speed_cms))
        self.guided_until = now + MS.from_wire(g.valid_ms)

    def _on_ramp_pose(self, p: Any, now: float) -> None:
        """USV_RAMP_POSE: every one keeps the stream fresh; the newest pose (by its boat
        instant) moves the vehicle's frame."""
        t = MS.from_wire(p.time_boot_ms)
        first, stale = self.ramp_rx is None, self.ramp_stale
        self.ramp_rx = now
        if not (first or stale) and t <= self.ramp.t0:
            return  # not newer than the pose in use (repeated, or reordered)
        x, y = self.frame.to_ramp(E7.from_wire(p.lat), E7.from_wire(p.lon))
        theta = math.radians(float(self.frame.compass_to_heading_deg(
            CDEG.from_wire(p.bearing_cdeg))))
        vx, vy = self.frame.vector_to_ramp(p.ve, p.vn)
        self.ramp = RampMotion(float(x), float(y), theta, float(vx), float(vy), -p.yaw_rate, t)
        self.ramp_stale = False
        self.ramp_poses += 1
        self._set_frame(reanchor=first or stale)
        if stale:
            self._text(mav.MAV_SEVERITY_INFO, "ramp pose back" + (
                ": RESUME to go on" if self.state == S_HOLD else ""), now)

    def _set_frame(self, reanchor: bool) -> None:
        set_frame = getattr(self.vehicle, "set_frame", None)
        if set_frame is not None:
            set_frame(self.ramp, reanchor=reanchor)

    def _ramp_lost(self, now: float) -> None:
        """No pose for ramp_timeout_s: freeze the frame; a running boat holds over ground."""
        self.ramp_stale = True
        self.ramp = self.ramp.frozen(self.boat_time)
        self._set_frame(reanchor=True)
        if self.state in (S_RUNNING, S_GO_AROUND):
            self.vehicle.hold()
            self._clear_guidance()
            self.state = S_HOLD
            self._text(mav.MAV_SEVERITY_WARNING, f"ramp pose stale "
                       f"{self.cfg.ramp_timeout_s:g} s: holding", now)
            self._report(now)
        else:
            self._text(mav.MAV_SEVERITY_WARNING, "ramp pose stale: frame frozen", now)

    def _clear_guidance(self) -> None:
        if self.guided_until is not None:
            self.vehicle.clear_guidance()
            self.guided_until = None

    def _waypoints(self, items: tuple[MissionItem, ...]) -> list[Waypoint]:
        """Wire items (geodetic) to the vehicle's world frame (the sim's ramp frame)."""
        lat = E7.from_wire(np.array([it.lat for it in items]))
        lon = E7.from_wire(np.array([it.lon for it in items]))
        x, y = self.frame.to_ramp(lat, lon)
        heading = np.radians(self.frame.compass_to_heading_deg(
            CDEG.from_wire(np.array([it.heading_cdeg for it in items]))))
        return [Waypoint(float(x[i]), float(y[i]), MS.from_wire(it.t_ms),
                         CM.from_wire(it.speed_cms), float(heading[i]))
                for i, it in enumerate(items)]

    # ---- standard MAVLink for ground stations (docs/link.md "Standard MAVLink")
    def _standard_items(self) -> tuple[StandardItem, ...]:
        """The active mission as standard items (NAV_WAYPOINT + DO_CHANGE_SPEED)."""
        a = self.active
        if a is None:
            return ()
        if self._std_items is None or self._std_items[0] is not a:
            self._std_items = (a, standard_items(a.items))
        return self._std_items[1]

    def _on_gcs_read(self, msg: Any, src: int, now: float) -> None:
        """MISSION_REQUEST_LIST / _INT / MISSION_REQUEST from any ground station (the
        paired station or another, read-only): the active mission as standard items.
        Reading never refreshes the link-loss timer."""
        if src != self.cfg.station_id:
            self.other_systems[src] += 1
        if msg.target_system not in (0, self.cfg.boat_id) or msg.get_type() == "MISSION_ACK":
            return
        e, comp = self.codec.mav, msg.get_srcComponent()
        mtype = getattr(msg, "mission_type", mav.MAV_MISSION_TYPE_MISSION)
        items = self._standard_items() if mtype == mav.MAV_MISSION_TYPE_MISSION else ()
        if msg.get_type() == "MISSION_REQUEST_LIST":
            self._send(e.mission_count_encode(src, comp, len(items), mtype), now)
            return
        if msg.seq >= len(items):
            self._send(e.mission_ack_encode(src, comp, mav.MAV_MISSION_INVALID_SEQUENCE, mtype),
                       now)
            return
        it = items[msg.seq]
        if msg.get_type() == "MISSION_REQUEST":  # the deprecated float form, answered in kind
            self._send(e.mission_item_encode(
                src, comp, it.seq, it.frame, it.command, 0, it.autocontinue, it.param1,
                it.param2, it.param3, it.param4, it.x * 1e-7, it.y * 1e-7, it.z, mtype), now)
            return
        self._send(e.mission_item_int_encode(
            src, comp, it.seq, it.frame, it.command, 0, it.autocontinue, it.param1, it.param2,
            it.param3, it.param4, it.x, it.y, it.z, mtype), now)

    def _on_standard_upload(self, msg: Any, now: float) -> None:
        """A standard upload from the paired station: usv-link 2 uploads in the dialect."""
        self._send(self.codec.mav.mission_ack_encode(
            self.cfg.station_id, msg.get_srcComponent(), mav.MAV_MISSION_UNSUPPORTED,
            getattr(msg, "mission_type", 0)), now)

    def _mission_current(self, now: float) -> None:
        """MISSION_CURRENT with the heartbeat: the waypoint steered to (its NAV item)."""
        items = self._standard_items()
        seq = nav_seq(min(self.vehicle.state.waypoint_index, max(0, len(items) // 2))) \
            if items else 0
        self._send(self.codec.mav.mission_current_encode(
            seq, len(items), MISSION_STATES.get(self.state, mav.MISSION_STATE_ACTIVE),
            int(self.state == S_RUNNING)), now, telemetry=True)

    def _items_reached(self, now: float) -> None:
        """MISSION_ITEM_REACHED for every waypoint passed since the last (the last one when
        the mission completes)."""
        a = self.active
        if a is None or self.state not in (S_RUNNING, S_HOLD, S_FAILSAFE, S_DONE):
            return
        reached = len(a.items) if self.state == S_DONE else \
            min(self.vehicle.state.waypoint_index, len(a.items))
        mission, done = self._std_reached
        done = done if mission == a.mission_id else 0
        for k in range(done, reached):
            self._send(self.codec.mav.mission_item_reached_encode(nav_seq(k)), now)
        self._std_reached = (a.mission_id, max(done, reached))

    # ---- time
    def update(self, now: float) -> None:
        """Advance to link time `now`: vehicle (up to a swap instant exactly), guidance
        expiry, failsafe, staging expiry, telemetry and heartbeat on a fixed boat-time grid."""
        dt_link = max(0.0, now - self.last_now)
        self.last_now = now
        notice = getattr(self.vehicle, "notice", None)  # e.g. current beyond what HOLD can hold
        if notice != self.last_notice:
            self.last_notice = notice
            if notice:
                self._text(mav.MAV_SEVERITY_WARNING, notice[:50], now)
            self._report(now)  # the over-capacity flag changed
        target = self.boat_time + dt_link * self.cfg.sim_speed
        while True:  # each timer at its own boat-time instant, in order
            st = self.staging
            swap_t = MS.from_wire(st.swap_at_ms) if st is not None and st.state == ST_VERIFIED \
                and st.swap_at_ms else math.inf
            due = min(swap_t, self.next_heartbeat, self.next_telemetry)
            if due > target:
                break
            self._advance(due - self.boat_time)
            if due == swap_t:
                self._do_swap(now)
                continue
            full = False
            if self.next_heartbeat <= due:
                self._heartbeat(now)
                self._mission_current(now)
                self.next_heartbeat = _next_on_grid(self.next_heartbeat, self.boat_time,
                                                    self.cfg.heartbeat_period_s)
                full = True
            if self.next_telemetry <= due:
                self._send_telemetry(now, full)
                self.next_telemetry = _next_on_grid(self.next_telemetry, self.boat_time,
                                                    1.0 / self.cfg.telemetry_hz)
        self._advance(target - self.boat_time)
        if self.guided_until is not None and now >= self.guided_until:
            self._clear_guidance()
        if self.state == S_RUNNING and self.vehicle.state.mission_complete:
            self._final_fix(now)
            self.state = S_DONE
            self._text(mav.MAV_SEVERITY_INFO, f"mission {self.active.mission_id} complete", now)
            self._report(now)
        self._follow_go_around(now)
        self._items_reached(now)
        if self.ramp_rx is not None and not self.ramp_stale and \
                now - self.ramp_rx > self.cfg.ramp_timeout_s:
            self._ramp_lost(now)
        if self.linked and now - self.last_rx > self.cfg.failsafe_timeout_s:
            self._failsafe(now)
        st = self.staging
        if st is not None and st.state == ST_RECEIVING and \
                now - st.touched > self.cfg.staging_timeout_s:
            self.expired_id, self.staging = st.mission_id, None
            self._text(mav.MAV_SEVERITY_WARNING, f"staging of {st.mission_id} expired", now)
            self._report(now)

    def _going_around(self) -> bool:
        return getattr(self.vehicle, "go_around", None) is not None

    def _follow_go_around(self, now: float) -> None:
        """RUNNING -> GO_AROUND when the vehicle misses a gate; say when it reached the
        standby point (RESUME then starts a new approach)."""
        if self.state == S_RUNNING and self._going_around():
            self.state = S_GO_AROUND
            self._clear_guidance()
            self._standby_said = False
            self._text(mav.MAV_SEVERITY_WARNING, f"go-around: {self.vehicle.go_around}", now)
            self._report(now)
        if self.state == S_GO_AROUND and not self._standby_said and \
                getattr(self.vehicle, "phase", "") == "standby":
            self._standby_said = True
            self._text(mav.MAV_SEVERITY_INFO, "go-around: at standby, RESUME to approach",
                       now)

    def _swap_problem(self, new: ActiveMission | None = None) -> str:
        """Why a hot swap cannot be taken now ('' when it can): the boat must be RUNNING,
        and not committed to its final approach (inside its first gate: its gates decide
        arrival or go-around), or GO_AROUND keeping station at its standby point (the
        station's new approach), `new`'s first waypoint then within the START radius."""
        if self.state == S_RUNNING:
            return "on the final approach" if getattr(self.vehicle, "committed", False) \
                else ""
        if self.state != S_GO_AROUND:
            return "not running"
        if not getattr(self.vehicle, "at_standby", False):
            return "go-around not at standby yet"
        if new is not None:
            dist = self._distance_to(new.items[0])
            if dist > self.cfg.start_radius_m:
                return f"{dist:.1f} m from waypoint 0"
        return ""

    def _do_swap(self, now: float) -> None:
        st, new = self.staging, self._swap_mission
        self.staging = None
        problem = "not running" if new is None else self._swap_problem(new)
        if problem:
            self._text(mav.MAV_SEVERITY_WARNING, f"swap to {st.mission_id} dropped: "
                       f"{problem}", now)
        else:
            approach = self.state == S_GO_AROUND
            self.vehicle.set_mission(self._waypoints(new.items))
            self.vehicle.start()
            self.active, self.state = new, S_RUNNING
            self.activations.append((self.boat_time, new.mission_id))
            self._text(mav.MAV_SEVERITY_INFO, ("new approach: mission" if approach else
                                               "swapped to mission") +
                       f" {new.mission_id} at {self.uptime_ms} ms", now)
        self._swap_mission = None
        self._report(now)

    def _failsafe(self, now: float) -> None:
        self.linked = False
        if self.state in (S_RUNNING, S_HOLD, S_GO_AROUND):
            self.vehicle.hold()
            self._clear_guidance()
            self.state = S_FAILSAFE
            self.failsafes += 1
            self._text(mav.MAV_SEVERITY_CRITICAL,
                       f"failsafe: no station for {self.cfg.failsafe_timeout_s:g} s", now)
        else:
            self._text(mav.MAV_SEVERITY_WARNING, "link lost", now)
        self._report(now)

    def _advance(self, dt: float) -> None:
        end = self.boat_time + dt
        while end - self.boat_time > 1e-9:
            h = min(end - self.boat_time, self.cfg.max_step_s)
            self.vehicle.step(h)
            s = self.vehicle.state
            self.battery.step(h, s.thrust_left, s.thrust_right)
            self.boat_time += h
        self.boat_time = max(self.boat_time, end)

    def next_deadline(self) -> float:
        """Link time of the next timer (telemetry, heartbeat, failsafe, guidance, swap)."""
        speed = self.cfg.sim_speed
        boat_next = min(self.next_telemetry, self.next_heartbeat)
        st = self.staging
        if st is not None and st.state == ST_VERIFIED and st.swap_at_ms:
            boat_next = min(boat_next, MS.from_wire(st.swap_at_ms))
        d = self.last_now + max(0.0, boat_next - self.boat_time) / speed
        if self.linked:
            d = min(d, self.last_rx + self.cfg.failsafe_timeout_s + 1e-3)
        if self.ramp_rx is not None and not self.ramp_stale:
            d = min(d, self.ramp_rx + self.cfg.ramp_timeout_s + 1e-3)
        if self.guided_until is not None:
            d = min(d, self.guided_until)
        if self._telemetry and self.cfg.baud:
            d = min(d, self._line_free_at)
        return d

    # ---- telemetry
    def _final_fix(self, now: float) -> None:
        """At the mission's end, ahead of the DONE report: the telemetry still queued, then
        the position where the boat finished, so a run's track ends where the boat did
        (however busy the line was)."""
        while self._telemetry:
            self._urgent += self.codec.encode(self._telemetry.popleft(), self._stamp(now))
        self._send_telemetry(now, urgent=True)

    def _send_telemetry(self, now: float, full: bool = False, urgent: bool = False) -> None:
        """USV_THRUST and GLOBAL_POSITION_INT (last: it completes a station row) at
        telemetry_hz; ATTITUDE, GPS_RAW_INT, VFR_HUD, NAV_CONTROLLER_OUTPUT with `full`;
        `urgent`: ahead of the queued telemetry, never dropped."""
        s = self.vehicle.state
        e = self.codec.mav
        # a vehicle with sensors reports what it measures; a kinematic one its truth, so
        # its fixes get the GPS error here
        sensed = getattr(self.vehicle, "sensed", False)
        dx, dy = (0.0, 0.0) if sensed else self.gps.sample(1.0 / self.cfg.telemetry_hz)
        fix_type, satellites, hdop = getattr(self.vehicle, "gnss_status", None) or (
            self.gps.fix_type, self.gps.satellites, self.gps.hdop)
        lat, lon = self.frame.to_geodetic(s.x + dx, s.y + dy)
        lat_e7, lon_e7 = E7.to_wire(float(lat)), E7.to_wire(float(lon))
        compass = self.frame.heading_to_compass_deg
        cog = float(compass(math.degrees(s.course))) % 360
        hdg = float(compass(math.degrees(s.heading))) % 360
        t_ms = self.uptime_ms
        yaw = math.radians(hdg)
        yaw = yaw - 2 * math.pi if yaw > math.pi else yaw
        vn, ve = s.speed * math.cos(math.radians(cog)), s.speed * math.sin(math.radians(cog))
        xte = s.cross_track_error  # positive left of the track, as on the wire
        send = self._send
        if full:  # the slower streams: once a second, with the heartbeat
            send(e.attitude_encode(t_ms, 0.0, 0.0, yaw, 0.0, 0.0, -s.yaw_rate), now,
                 telemetry=True)
            send(e.gps_raw_int_encode(
                int(self.boat_time * 1e6), fix_type, lat_e7, lon_e7, 0,
                _clamp(round(hdop * 100), 0, 0xFFFE), 0xFFFF,
                _clamp(CM.to_wire(s.speed), 0, 0xFFFE), CDEG.to_wire(cog),
                satellites), now, telemetry=True)
            throttle = _clamp(round(50 * (abs(s.thrust_left) + abs(s.thrust_right))), 0, 100)
            send(e.vfr_hud_encode(s.speed, s.speed, round(hdg) % 360, throttle, 0.0, 0.0), now,
                 telemetry=True)
            send(e.nav_controller_output_encode(0.0, 0.0, round(hdg), round(cog), 0, 0.0, 0.0,
                                                xte), now, telemetry=True)
        send(e.usv_thrust_encode(t_ms, _clamp(round(s.thrust_left * 1000), -1000, 1000),
                                 _clamp(round(s.thrust_right * 1000), -1000, 1000), xte, 0.0),
             now, telemetry=not urgent)
        send(e.global_position_int_encode(t_ms, lat_e7, lon_e7, 0, 0,
                                          _clamp(CM.to_wire(vn), -32768, 32767),
                                          _clamp(CM.to_wire(ve), -32768, 32767), 0,
                                          CDEG.to_wire(hdg)), now, telemetry=not urgent)


_FROM_STATION = {
    "HEARTBEAT": lambda self, msg, now: None,
    "TIMESYNC": BoatProtocol._on_timesync,
    "COMMAND_INT": BoatProtocol._on_command,
    "COMMAND_LONG": BoatProtocol._on_command_long,
    "USV_MISSION_BEGIN": BoatProtocol._on_begin,
    "USV_MISSION_ITEM": BoatProtocol._on_item,
    "USV_MISSION_END": BoatProtocol._on_end,
    "USV_MISSION_READ": BoatProtocol._on_read,
    "USV_GUIDANCE": BoatProtocol._on_guidance,
    "USV_RAMP_POSE": BoatProtocol._on_ramp_pose,
}

_COMMANDING = frozenset(("COMMAND_INT", "COMMAND_LONG", "USV_MISSION_BEGIN", "USV_MISSION_ITEM",
                         "USV_MISSION_END", "USV_MISSION_READ", "USV_GUIDANCE",
                         "USV_RAMP_POSE"))


_FROM_STATION.update({
    "MISSION_COUNT": BoatProtocol._on_standard_upload,
    "MISSION_CLEAR_ALL": BoatProtocol._on_standard_upload,
})
_GCS_READS = frozenset(("MISSION_REQUEST_LIST", "MISSION_REQUEST_INT", "MISSION_REQUEST",
                        "MISSION_ACK"))
_COMMANDING = _COMMANDING | frozenset((
    "MISSION_COUNT", "MISSION_ITEM_INT", "MISSION_ITEM", "MISSION_CLEAR_ALL",
    "MISSION_SET_CURRENT", "SET_MODE", "SET_POSITION_TARGET_GLOBAL_INT",
    "SET_POSITION_TARGET_LOCAL_NED", "MANUAL_CONTROL", "SETUP_SIGNING", "PARAM_SET",
    "RC_CHANNELS_OVERRIDE", "MISSION_WRITE_PARTIAL_LIST"))
"""Standard messages that would command the boat: refused from anyone but the paired
station (which uses usv-link 2's own for what they do)."""


def _next_on_grid(scheduled: float, now: float, period: float) -> float:
    """The next instant on the fixed grid scheduled + k * period after now."""
    nxt = scheduled + period
    if nxt <= now:
        nxt += ((now - nxt) // period + 1) * period
    return nxt


def _clamp(v: int, lo: int, hi: int) -> int:
    return lo if v < lo else hi if v > hi else v
