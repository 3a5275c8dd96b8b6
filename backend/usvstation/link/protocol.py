"""Station side of usv-link 2 as sans-IO state machines (protocol/README.md "Station").

Nothing here does I/O or reads a clock: callers pass received bytes, the monotonic time
`now` (seconds) in, and take bytes and events out:

    proto = StationProtocol(LinkConfig(), now, key=key, unix_time=clock.unix())
    events = proto.receive_data(data, now)   # bytes from the radio
    events += proto.poll(now)                # timers: heartbeat, retries, link loss
    wire = proto.data_to_send()              # bytes for the radio
    proto.next_deadline()                    # when poll() is due next

The parts: `LinkMonitor` (fixed heartbeat schedule, link loss, only the paired boat id
counts), `RttEstimator` (retry timeouts from measured round trips and the frame airtime
at the configured baud), `MissionUploader` (windowed BEGIN/ITEM/END), `Readback`
(USV_MISSION_READ), `CommandSender` (COMMAND_INT keyed by session, seq and code), and the
ramp pose stream (USV_RAMP_POSE, `set_ramp_pose`: the latest pose of the moving ramp, sent
every `ramp_pose_period_s` with its instant mapped to the boat's uptime through TIMESYNC).
"""

from __future__ import annotations

import random
from collections import Counter, deque
from dataclasses import dataclass, field
from typing import Any

from usvstation.geometry import CDEG, CM, E7, MS, require_finite
from usvstation.link import wire
from usvstation.link.mavlink import usv_recovery as mav
from usvstation.link.mission import Mission, MissionItem

INF = float("inf")
ITEM_FRAME_BYTES = 12 + 28 + 13  # signed USV_MISSION_ITEM
ACK_FRAME_BYTES = 12 + 14 + 13  # signed USV_MISSION_ACK


@dataclass(frozen=True)
class LinkConfig:
    """Station timing; every value is in protocol/README.md "Timeouts and limits"."""

    boat_id: int = wire.BOAT_ID
    station_id: int = wire.STATION_ID
    baud: int = 57600
    heartbeat_period_s: float = 0.25  # fixed schedule; the boat fails safe after 3 s
    link_timeout_s: float = 3.0  # no frame from the boat: link down
    timesync_period_s: float = 1.0
    window: int = 8  # mission items in flight
    max_attempts: int = 10  # per mission message
    command_attempts: int = 5
    min_timeout_s: float = 0.2  # radio, serial driver and scheduling latency
    max_timeout_s: float = 3.0
    link_id: int = 0  # MAVLink signing link id of this station
    ramp_pose_period_s: float = 0.25  # USV_RAMP_POSE while a pose is set (at least 2 Hz)

    def __post_init__(self) -> None:
        if not 1 <= self.boat_id <= 254 or not 1 <= self.station_id <= 255:
            raise ValueError(f"boat_id must be 1..254 and station_id 1..255, got "
                             f"{self.boat_id}, {self.station_id}")
        if self.boat_id == self.station_id:
            raise ValueError(f"boat_id and station_id are both {self.boat_id}")
        if not 0 < self.heartbeat_period_s <= 0.5:
            raise ValueError(f"heartbeat_period_s must be in (0, 0.5], got "
                             f"{self.heartbeat_period_s}")
        if self.baud <= 0:
            raise ValueError(f"baud must be positive, got {self.baud}")
        if not 0 < self.ramp_pose_period_s <= 0.5:
            raise ValueError(f"ramp_pose_period_s must be in (0, 0.5], got "
                             f"{self.ramp_pose_period_s}")

    def airtime(self, nbytes: int) -> float:
        """Seconds to send nbytes at the configured baud (8N1: 10 bits a byte)."""
        return nbytes * 10 / self.baud


# ----------------------------------------------------------------------------- typed reports


@dataclass(frozen=True)
class MissionState:
    """USV_MISSION_STATE: what the boat holds; the station's truth about missions."""

    uptime_ms: int
    boot_id: int
    state: str  # USV_BOAT_STATE name: IDLE, READY, RUNNING, HOLD, DONE, ABORTED, FAILSAFE,
    # GO_AROUND
    active_id: int
    active_crc32: int
    active_count: int
    current_seq: int
    staging: int  # USV_STAGING_STATE
    staged_id: int
    staged_crc32: int
    staged_received: int
    staged_count: int
    swap_at_ms: int
    station_session: int
    rejected: int
    over_capacity: bool = False  # flags: USV_STATE_FLAG_OVER_CAPACITY

    @classmethod
    def from_msg(cls, m: Any) -> MissionState:
        flags = getattr(m, "flags", 0) or 0  # an extension field: 0 from an older boat
        return cls(m.uptime_ms, m.boot_id, wire.BOAT_STATES.get(m.state, str(m.state)),
                   m.active_id, m.active_crc32, m.active_count, m.current_seq, m.staging,
                   m.staged_id, m.staged_crc32, m.staged_received, m.staged_count,
                   m.swap_at_ms, m.station_session, m.rejected,
                   bool(flags & mav.USV_STATE_FLAG_OVER_CAPACITY))


@dataclass(frozen=True)
class Telemetry:
    """One position report (GLOBAL_POSITION_INT) with the latest of the other streams."""

    time_s: float
    lat: float
    lon: float
    speed: float  # m/s over ground
    course_deg: float  # compass
    heading_deg: float  # compass
    yaw_rate_dps: float = 0.0  # clockwise positive
    fix_type: int = 0
    satellites: int = 0
    hdop: float = 0.0
    battery_v: float = 0.0
    thrust_left: float = 0.0
    thrust_right: float = 0.0
    cross_track_m: float = 0.0
    waypoint_index: int = 0
    state: str = "IDLE"


@dataclass(frozen=True)
class RampPoseSample:
    """The moving ramp's pose at station time `t` (the instant of the own-ship fix it
    comes from): WGS-84 degrees, the compass bearing of the ramp frame's +x, the ramp
    end's velocity over ground and the ship's yaw rate (rad/s, clockwise positive)."""

    t: float
    lat: float
    lon: float
    bearing_deg: float
    vn: float = 0.0
    ve: float = 0.0
    yaw_rate: float = 0.0

    def __post_init__(self) -> None:
        require_finite(self, "ramp pose")
        if not (-90.0 <= self.lat <= 90.0 and -180.0 <= self.lon <= 180.0):
            raise ValueError(f"ramp pose: lat, lon out of range: {self.lat}, {self.lon}")


# ----------------------------------------------------------------------------- events


@dataclass(frozen=True)
class LinkUp:
    """The paired boat's HEARTBEAT (type SURFACE_BOAT) arrived after silence."""

    system_id: int


@dataclass(frozen=True)
class LinkDown:
    reason: str


@dataclass(frozen=True)
class Received:
    """A report the boat sent, stamped with the station time it arrived (`received_at`)."""

    received_at: float = field(kw_only=True)


@dataclass(frozen=True)
class BoatReport(Received):
    """USV_MISSION_STATE: the boat's mission, its state and its clock."""

    report: MissionState


@dataclass(frozen=True)
class TelemetryReceived(Received):
    """GLOBAL_POSITION_INT with the latest of the boat's other reports."""

    telemetry: Telemetry


@dataclass(frozen=True)
class BoatRebooted:
    """The boot id in the boat's mission report changed: it restarted (clock sync is reset)."""

    old_boot_id: int
    new_boot_id: int


@dataclass(frozen=True)
class StatusTextReceived:
    severity: int  # MAV_SEVERITY
    text: str


@dataclass(frozen=True)
class UploadProgress:
    mission_id: int
    acked: int
    count: int
    sent: int = 0


@dataclass(frozen=True)
class UploadResult:
    """ok: the boat acknowledged END (activated, or scheduled the swap). ok False says why;
    the boat never activates a partial mission, and USV_MISSION_STATE is the final word."""

    mission_id: int
    ok: bool
    reason: str
    count: int
    retransmissions: int
    duration_s: float


@dataclass(frozen=True)
class ReadbackResult:
    mission_id: int
    items: tuple[MissionItem, ...] | None  # None: failed (error says why)
    error: str = ""


@dataclass(frozen=True)
class CommandOutcome:
    """The boat's answer to a command, or result None with the error (never open-ended)."""

    seq: int
    command: str
    result: int | None  # MAV_RESULT
    reason: str = ""  # USV_COMMAND_REASON name when not accepted
    error: str = ""

    @property
    def accepted(self) -> bool:
        return self.result == mav.MAV_RESULT_ACCEPTED


LinkEvent = (LinkUp | LinkDown | BoatReport | TelemetryReceived | BoatRebooted
             | StatusTextReceived | UploadProgress | UploadResult | ReadbackResult
             | CommandOutcome)
"""Everything the station protocol reports, and BoatLink hands its listeners."""


# ----------------------------------------------------------------------------- timing


class RttEstimator:
    """Retry timeout from measured round trips (Jacobson/Karels, RFC 6298 constants),
    never below min_timeout_s nor two frame airtimes at the baud, never above
    max_timeout_s. Round trips count from the frame's departure at the baud."""

    def __init__(self, cfg: LinkConfig) -> None:
        self.cfg = cfg
        self.srtt: float | None = None
        self.rttvar = 0.0
        self.floor = max(cfg.min_timeout_s,
                         2 * cfg.airtime(ITEM_FRAME_BYTES + ACK_FRAME_BYTES) + 0.02)

    def sample(self, rtt: float) -> None:
        if rtt <= 0:
            return
        if self.srtt is None:
            self.srtt, self.rttvar = rtt, rtt / 2
        else:
            self.rttvar = 0.75 * self.rttvar + 0.25 * abs(self.srtt - rtt)
            self.srtt = 0.875 * self.srtt + 0.125 * rtt
    @property
    def timeout(self) -> float:
        if self.srtt is None:  # nothing measured yet: a window's airtime and a margin
            base = self.cfg.airtime(self.cfg.window * ITEM_FRAME_BYTES + ACK_FRAME_BYTES) * 2 \
                + 0.25
        else:
            base = self.srtt + 4 * self.rttvar
        return min(max(base, self.floor), self.cfg.max_timeout_s)


# ----------------------------------------------------------------------------- link monitor


class LinkMonitor:
    """Heartbeats on a fixed schedule; link up from the paired boat's HEARTBEAT until no
    frame from that system id arrived for link_timeout_s. Frames from other ids are
    counted per id, never taken as the boat's."""

    def __init__(self, cfg: LinkConfig, now: float) -> None:
        self.cfg = cfg
        self.link_up = False
        self.last_rx = -INF
        self.next_heartbeat = now
        self.other_systems: Counter[int] = Counter()
        self.echoes = 0

    def due_heartbeat(self, now: float) -> bool:
        if now < self.next_heartbeat:
            return False
        period = self.cfg.heartbeat_period_s
        self.next_heartbeat += period
        if self.next_heartbeat <= now:  # fell behind (a stalled loop): keep the grid
            self.next_heartbeat += ((now - self.next_heartbeat) // period + 1) * period
        return True

    def on_boat_frame(self, msg: Any, now: float) -> list[LinkEvent]:
        self.last_rx = now
        if self.link_up:
            return []
        if msg.get_type() == "HEARTBEAT" and msg.type == mav.MAV_TYPE_SURFACE_BOAT:
            self.link_up = True
            return [LinkUp(self.cfg.boat_id)]
        return []

    def poll(self, now: float) -> list[LinkEvent]:
        if self.link_up and now - self.last_rx > self.cfg.link_timeout_s:
            self.link_up = False
            return [LinkDown(f"no frame from boat {self.cfg.boat_id} for "
                             f"{self.cfg.link_timeout_s:.1f} s")]
        return []

    def lost(self, reason: str) -> list[LinkEvent]:
        if not self.link_up:
            return []
        self.link_up = False
        return [LinkDown(reason)]

    def next_deadline(self) -> float:
        d = self.next_heartbeat
        if self.link_up:
            d = min(d, self.last_rx + self.cfg.link_timeout_s + 1e-3)
        return d


# ----------------------------------------------------------------------------- uploader

BEGIN, END = -1, -2  # keys of the non-item messages
STAGE_BEGIN, STAGE_ITEM, STAGE_END, STAGE_READ = 1, 2, 3, 4


class MissionUploader:
    """BEGIN, then items in a sliding window (the boat's ACK.seq is cumulative: items
    staged contiguously from 0), then END. Each message is retried after the adaptive
    timeout, at most max_attempts times; the first missing item is also sent again at
    once on the second ACK that does not advance (fast retransmit). A refusal ends the
    upload with its reason, except MISSING_ITEMS at END, which goes back to the first
    missing item."""

    def __init__(self, mission: Mission, cfg: LinkConfig, rtt: RttEstimator, now: float,
                 swap_at_ms: int = 0) -> None:
        self.mission, self.cfg, self.rtt = mission, cfg, rtt
        self.swap_at_ms = swap_at_ms
        self.started = now
        self.phase = "begin"
        self.base = 0  # items acknowledged contiguously
        self.attempts: Counter[int] = Counter()
        self.deadlines: dict[int, float] = {}
        self.sent_at: dict[int, float] = {}
        self.next_index = 0
        self.retransmissions = 0
        self.dup_acks = 0  # ACKs that did not advance base since it last moved
        self.result: UploadResult | None = None

    @property
    def done(self) -> bool:
        return self.result is not None

    def _send(self, key: int, now: float, ahead: int = 0) -> list[tuple[str, Any]]:
        n = self.attempts[key]
        if n >= self.cfg.max_attempts:
            what = {BEGIN: "USV_MISSION_BEGIN", END: "USV_MISSION_END"}.get(key, f"item {key}")
            self._finish(False, f"{what} not acknowledged after {n} attempts", now)
            return []
        if n:
            self.retransmissions += 1
        self.attempts[key] = n + 1
        self.sent_at[key] = now if n == 0 else -INF  # Karn: no RTT sample from a retry
        self.deadlines[key] = now + self.rtt.timeout + ahead * self.cfg.airtime(ITEM_FRAME_BYTES)
        return [("begin" if key == BEGIN else "end" if key == END else "item", key)]

    def mark(self, key: int, departure: float) -> None:
        """The frame of `key` leaves the station at `departure` (the line at the baud):
        its retry deadline and its RTT sample count from then."""
        if key in self.deadlines:
            self.deadlines[key] = departure + self.rtt.timeout
            if self.sent_at.get(key, -INF) > -INF:
                self.sent_at[key] = departure

    def _finish(self, ok: bool, reason: str, now: float) -> None:
        self.deadlines.clear()
        self.result = UploadResult(self.mission.mission_id, ok, reason, self.mission.count,
                                   self.retransmissions, now - self.started)

    def start(self, now: float) -> list[tuple[str, Any]]:
        return self._send(BEGIN, now)

    def _fill(self, now: float) -> list[tuple[str, Any]]:
        out: list[tuple[str, Any]] = []
        count = self.mission.count
        if self.phase != "items":
            return out
        self.next_index = max(self.next_index, self.base)
        in_flight = sum(1 for k in self.deadlines if k >= 0)
        while self.next_index < count and in_flight < self.cfg.window:
            if self.next_index not in self.deadlines:
                out += self._send(self.next_index, now, ahead=len(out))
                in_flight += 1
            self.next_index += 1
        if self.base >= count:
            self.phase = "end"
            out += self._send(END, now)
        return out

    def _sample(self, key: int, now: float) -> None:
        t = self.sent_at.get(key, -INF)
        if t > -INF:
            self.rtt.sample(now - t)

    def handle(self, ack: Any, now: float) -> tuple[list[tuple[str, Any]], list[LinkEvent]]:
        """A USV_MISSION_ACK from the boat (already known to be for this mission)."""
        if self.done:
            return [], []
        ok = ack.result == mav.USV_MISSION_ACCEPTED
        if ack.stage == STAGE_BEGIN and self.phase == "begin":
            if not ok:
                return self._refused("USV_MISSION_BEGIN", ack, now)
            self._sample(BEGIN, now)
            self.deadlines.pop(BEGIN, None)
            self.phase = "items"
            self.base = min(ack.seq, self.mission.count)
            return self._fill(now), [self._progress()]
        if ack.stage == STAGE_ITEM and self.phase == "items":
            if not ok and ack.result != mav.USV_MISSION_BAD_SEQ:
                return self._refused(f"item {ack.seq}", ack, now)
            if ack.seq > self.base:
                covered = range(self.base, min(ack.seq, self.mission.count))
                if all(self.sent_at.get(k, -INF) > -INF for k in covered):
                    self._sample(ack.seq - 1, now)  # Karn: nothing it covers was resent
                for k in range(self.base, min(ack.seq, self.mission.count)):
                    self.deadlines.pop(k, None)
                self.base = min(ack.seq, self.mission.count)
                self.dup_acks = 0
                return self._fill(now), [self._progress()]
            self.dup_acks += 1
            out: list[tuple[str, Any]] = []
            if self.dup_acks == 2 and self.base in self.deadlines:
                # fast retransmit: two later items arrived, so `base` was lost
                out = self._send(self.base, now)
                if self.done:
                    return [], [self.result]
            return out + self._fill(now), []
        if ack.stage == STAGE_END and self.phase == "end":
            if ack.result == mav.USV_MISSION_MISSING_ITEMS and ack.seq < self.mission.count:
                self.deadlines.pop(END, None)
                self.phase, self.base, self.next_index = "items", ack.seq, ack.seq
                return self._fill(now), []
            if not ok:
                return self._refused("USV_MISSION_END", ack, now)
            self._finish(True, "activated" if not self.swap_at_ms else "swap scheduled", now)
            return [], [self.result]
        return [], []

    def _refused(self, what: str, ack: Any, now: float) -> tuple[list, list[LinkEvent]]:
        name = wire.MISSION_RESULTS.get(ack.result, f"result {ack.result}")
        self._finish(False, f"boat refused {what}: {name}", now)
        return [], [self.result]

    def _progress(self) -> UploadProgress:
        sent = sum(1 for k in self.attempts if k >= 0)
        return UploadProgress(self.mission.mission_id, self.base, self.mission.count, sent)

    def poll(self, now: float) -> tuple[list[tuple[str, Any]], list[LinkEvent]]:
        if self.done:
            return [], []
        out: list[tuple[str, Any]] = []
        for key, deadline in sorted(self.deadlines.items(), key=lambda kv: kv[1]):
            if deadline <= now:
                out += self._send(key, now, ahead=len(out))
                if self.done:
                    return [], [self.result]
        return out, []

    def fail(self, reason: str, now: float) -> list[LinkEvent]:
        if self.done:
            return []
        self._finish(False, reason, now)
        return [self.result]

    def next_deadline(self) -> float:
        return min(self.deadlines.values(), default=INF)


class Readback:
    """Read a mission back item by item (USV_MISSION_READ), windowed and retried."""

    def __init__(self, mission_id: int, count: int, cfg: LinkConfig, rtt: RttEstimator) -> None:
        self.mission_id, self.count, self.cfg, self.rtt = mission_id, count, cfg, rtt
        self.items: dict[int, MissionItem] = {}
        self.attempts: Counter[int] = Counter()
        self.deadlines: dict[int, float] = {}
        self.result: ReadbackResult | None = None

    def _fill(self, now: float) -> list[int]:
        out = []
        for seq in range(self.count):
            if len(self.deadlines) >= self.cfg.window:
                break
            if seq in self.items or seq in self.deadlines:
                continue
            out += self._send(seq, now, len(out))
        return out

    def _send(self, seq: int, now: float, ahead: int) -> list[int]:
        if self.attempts[seq] >= self.cfg.max_attempts:
            self.result = ReadbackResult(self.mission_id, None,
                                         f"item {seq} not read after {self.attempts[seq]} "
                                         "attempts")
            self.deadlines.clear()
            return []
        self.attempts[seq] += 1
        self.deadlines[seq] = now + self.rtt.timeout + ahead * self.cfg.airtime(ACK_FRAME_BYTES)
        return [seq]

    def mark(self, seq: int, departure: float) -> None:
        if seq in self.deadlines:
            self.deadlines[seq] = departure + self.rtt.timeout

    def start(self, now: float) -> list[int]:
        return self._fill(now)

    def on_item(self, it: MissionItem, now: float) -> tuple[list[int], list[LinkEvent]]:
        if self.result is not None or not 0 <= it.seq < self.count:
            return [], []
        self.items[it.seq] = it
        self.deadlines.pop(it.seq, None)
        if len(self.items) == self.count:
            self.result = ReadbackResult(self.mission_id,
                                         tuple(self.items[i] for i in range(self.count)))
            return [], [self.result]
        return self._fill(now), []

    def on_refusal(self, ack: Any) -> list[LinkEvent]:
        if self.result is not None:
            return []
        name = wire.MISSION_RESULTS.get(ack.result, str(ack.result))
        self.result = ReadbackResult(self.mission_id, None, f"boat refused the read: {name}")
        self.deadlines.clear()
        return [self.result]

    def poll(self, now: float) -> tuple[list[int], list[LinkEvent]]:
        if self.result is not None:
            return [], []
        out: list[int] = []
        for seq, d in sorted(self.deadlines.items(), key=lambda kv: kv[1]):
            if d <= now:
                out += self._send(seq, now, len(out))
                if self.result is not None:
                    return [], [self.result]
        return out, []

    def next_deadline(self) -> float:
        return min(self.deadlines.values(), default=INF)


# ----------------------------------------------------------------------------- commands


@dataclass
class _Pending:
    name: str
    code: int
    x: int
    y: int
    deadline: float
    attempts: int


class CommandSender:
    """COMMAND_INT with param1 = seq, param2 = session; an ACK counts only when its
    command and result_param2 match a pending (seq, code) of this session. Retries reuse
    the seq; after command_attempts the outcome is "no answer", so every call ends."""

    def __init__(self, cfg: LinkConfig, rtt: RttEstimator, session: int) -> None:
        self.cfg, self.rtt, self.session = cfg, rtt, session
        self._next_seq = random.Random(session).randrange(1, 1 << 20)
        self.pending: dict[int, _Pending] = {}

    def send(self, name: str, now: float, x: int = 0, y: int = 0) -> int:
        if name not in wire.COMMANDS:
            raise ValueError(f"command: unknown {name!r}; known: {', '.join(wire.COMMANDS)}")
        seq = self._next_seq
        self._next_seq = self._next_seq % ((1 << 24) - 1) + 1
        self.pending[seq] = _Pending(name, wire.COMMANDS[name], x, y,
                                     now + self.rtt.timeout, 1)
        return seq

    def handle(self, ack: Any) -> list[LinkEvent]:
        p = self.pending.get(ack.result_param2)
        if p is None or p.code != ack.command:
            return []  # not the answer to a command of this session
        if ack.result == mav.MAV_RESULT_IN_PROGRESS:
            return []
        del self.pending[ack.result_param2]
        reason = "" if ack.result == mav.MAV_RESULT_ACCEPTED else \
            wire.COMMAND_REASONS.get(ack.progress, str(ack.progress))
        return [CommandOutcome(ack.result_param2, p.name, ack.result, reason)]

    def due(self, now: float) -> tuple[list[int], list[LinkEvent]]:
        resend, events = [], []
        for seq, p in list(self.pending.items()):
            if p.deadline > now:
                continue
            if p.attempts >= self.cfg.command_attempts:
                del self.pending[seq]
                events.append(CommandOutcome(seq, p.name, None,
                                             error=f"no COMMAND_ACK after {p.attempts} attempts"))
            else:
                p.attempts += 1
                p.deadline = now + self.rtt.timeout
                resend.append(seq)
        return resend, events

    def fail_all(self, reason: str) -> list[LinkEvent]:
        events = [CommandOutcome(seq, p.name, None, error=reason)
                  for seq, p in self.pending.items()]
        self.pending.clear()
        return events

    def next_deadline(self) -> float:
        return min((p.deadline for p in self.pending.values()), default=INF)


# ----------------------------------------------------------------------------- station


@dataclass
class StationProtocol:
    """The whole station side: codec + link monitor + uploader + readback + commands."""

    config: LinkConfig = field(default_factory=LinkConfig)
    now: float = 0.0
    key: bytes | None = None
    unix_time: float = wire.EPOCH_2015 + 3.0e8  # wall clock at `now`, for signing
    session: int | None = None

    def __post_init__(self) -> None:
        cfg = self.config
        if self.session is None:
            self.session = random.SystemRandom().randrange(1, 1 << 24)
        self._t0 = self.now
        self.codec = wire.Codec(cfg.station_id, wire.STATION_COMPONENT, self.key,
                                link_id=cfg.link_id, timestamp=self._stamp(self.now),
                                allow_unsigned=(mav.MAVLINK_MSG_ID_RADIO_STATUS,))
        self.monitor = LinkMonitor(cfg, self.now)
        self.rtt = RttEstimator(cfg)
        self.commands = CommandSender(cfg, self.rtt, self.session)
        self.upload: MissionUploader | None = None
        self.readback: Readback | None = None
        self.report: MissionState | None = None
        self.report_at = -INF
        # Recent reports in boat time: a telemetry row is labelled with the state the boat
        # reported for its own instant, not the newest one (an ACK and a report overtake
        # telemetry queued behind them on a slow radio).
        self._reports: deque[MissionState] = deque(maxlen=64)
        self.telemetry: Telemetry | None = None
        self.latest: dict[str, Any] = {}  # latest message of each type from the boat
        self.radio: Any = None  # latest RADIO_STATUS
        self.refused: Counter[str] = Counter()
        self.frames_lost = 0
        self._last_seq: int | None = None
        self.next_timesync = self.now
        self._timesync_sent: dict[int, float] = {}
        self.clock_offset_s: float | None = None  # boat uptime - station now
        # TIMESYNC samples (station instant, boat uptime s): offset and rate of the boat
        # clock (a simulated boat's runs --sim-speed times faster)
        self._sync: deque[tuple[float, float]] = deque(maxlen=16)
        self.ramp_pose: RampPoseSample | None = None
        self.next_ramp_pose = self.now
        self.ramp_poses_sent = 0
        self._out = bytearray()
        self.bytes_sent = self.bytes_received = 0
        self.tx_free_at = self.now  # when our side of the line (at the baud) is idle

    # ---- state
    @property
    def link_up(self) -> bool:
        return self.monitor.link_up

    @property
    def other_systems(self) -> Counter[int]:
        return self.monitor.other_systems

    def _stamp(self, now: float) -> int:
        return wire.signing_time(self.unix_time + (now - self._t0))

    @property
    def clock_rate(self) -> float:
        """Boat seconds per station second from the TIMESYNC samples of the last 15 s (1.0
        until they span 2 s): a real boat's crystal is within 1e-4 of 1."""
        if len(self._sync) < 2 or self._sync[-1][0] - self._sync[0][0] < 2.0:
            return 1.0
        (s0, b0), (s1, b1) = self._sync[0], self._sync[-1]
        return min(max((b1 - b0) / (s1 - s0), 1e-3), 1e3)

    def boat_uptime_ms(self, now: float) -> int | None:
        """The boat's uptime at station time `now` (past or future), from TIMESYNC: the
        latest sample carried at the measured clock rate (else the last
        USV_MISSION_STATE)."""
        if self._sync:
            s, b = self._sync[-1]
            return int((b + self.clock_rate * (now - s)) * 1000)
        if self.clock_offset_s is not None:
            return int((now + self.clock_offset_s) * 1000)
        if self.report is not None:
            return self.report.uptime_ms + int((now - self.report_at) * 1000)
        return None

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
            self.radio = msg  # the radio's own report (its own system id)
            return []
        src = msg.get_srcSystem()
        if src == self.config.station_id:
            self.monitor.echoes += 1  # our own frames looped back
            return []
        if src != self.config.boat_id:
            self.monitor.other_systems[src] += 1
            return []
        events = self.monitor.on_boat_frame(msg, now)
        seq = msg.get_seq()
        if self._last_seq is not None:
            self.frames_lost += (seq - self._last_seq - 1) % 256  # MAVLink sequence gaps
        self._last_seq = seq
        self.latest[kind] = msg
        if kind == "USV_MISSION_STATE":
            rep = MissionState.from_msg(msg)
            if self.report is not None and rep.boot_id != self.report.boot_id:
                events.append(BoatRebooted(self.report.boot_id, rep.boot_id))
                self.clock_offset_s = None
                self._sync.clear()
                self._reports.clear()
            self.report, self.report_at = rep, now
            self._reports.append(rep)
            events.append(BoatReport(rep, received_at=now))
        elif kind == "GLOBAL_POSITION_INT":
            self.telemetry = self._telemetry(msg)
            events.append(TelemetryReceived(self.telemetry, received_at=now))
        elif kind == "COMMAND_ACK":
            if msg.target_system in (0, self.config.station_id):
                events += self.commands.handle(msg)
        elif kind == "USV_MISSION_ACK":
            events += self._mission_ack(msg, now)
        elif kind == "USV_MISSION_ITEM":
            rb = self.readback
            if rb is not None and msg.mission_id == rb.mission_id:
                seqs, ev = rb.on_item(MissionItem.from_msg(msg), now)
                self._queue_reads(seqs, now)
                events += ev
        elif kind == "STATUSTEXT":
            events.append(StatusTextReceived(msg.severity, msg.text))
        elif kind == "TIMESYNC":
            sent = self._timesync_sent.pop(msg.ts1, None)
            if sent is not None and msg.tc1 > 0:
                rtt = now - sent
                self.rtt.sample(rtt)
                self.clock_offset_s = msg.tc1 / 1e9 + rtt / 2 - now
                self._sync.append((sent + rtt / 2, msg.tc1 / 1e9))
        return events

    def _mission_ack(self, ack: Any, now: float) -> list[LinkEvent]:
        up, rb = self.upload, self.readback
        if ack.stage == STAGE_READ:
            if rb is not None and ack.mission_id == rb.mission_id:
                return rb.on_refusal(ack)
            return []
        if up is not None and ack.mission_id == up.mission.mission_id:
            out, events = up.handle(ack, now)
            self._queue_upload(out, now)
            return events
        return []

    def _telemetry(self, gp: Any) -> Telemetry:
        get = self.latest.get
        gps, att = get("GPS_RAW_INT"), get("ATTITUDE")
        sysst, thr, nav = get("SYS_STATUS"), get("USV_THRUST"), get("NAV_CONTROLLER_OUTPUT")
        vn, ve = CM.from_wire(gp.vx), CM.from_wire(gp.vy)
        from math import atan2, degrees, hypot

        speed = hypot(vn, ve)  # current, unlike VFR_HUD (1 Hz)
        course = degrees(atan2(ve, vn)) % 360 if hypot(vn, ve) > 0.01 else \
            (CDEG.from_wire(gp.hdg) if gp.hdg != 0xFFFF else 0.0)
        rep = self._report_at(gp.time_boot_ms)
        state = rep.state if rep is not None else "IDLE"
        return Telemetry(
            time_s=MS.from_wire(gp.time_boot_ms), lat=E7.from_wire(gp.lat),
            lon=E7.from_wire(gp.lon),
            speed=round(speed, 3), course_deg=round(course, 2),
            heading_deg=CDEG.from_wire(gp.hdg) if gp.hdg != 0xFFFF else 0.0,
            yaw_rate_dps=round(degrees(att.yawspeed), 3) if att is not None else 0.0,
            fix_type=gps.fix_type if gps is not None else 0,
            satellites=gps.satellites_visible if gps is not None else 0,
            hdop=gps.eph / 100 if gps is not None and gps.eph != 0xFFFF else 0.0,
            battery_v=sysst.voltage_battery / 1000 if sysst is not None else 0.0,
            thrust_left=thr.left_pm / 1000 if thr is not None else 0.0,
            thrust_right=thr.right_pm / 1000 if thr is not None else 0.0,
            cross_track_m=round(thr.cross_track, 3) if thr is not None else
            (nav.xtrack_error if nav is not None else 0.0),
            waypoint_index=rep.current_seq if rep is not None else 0,
            state=state)

    def _report_at(self, time_boot_ms: int) -> MissionState | None:
        """The boat's report in effect at its own instant `time_boot_ms`: the newest report
        not after it (the oldest one kept when all are later)."""
        for rep in reversed(self._reports):
            if rep.uptime_ms <= time_boot_ms:
                return rep
        return self._reports[0] if self._reports else self.report

    def poll(self, now: float) -> list[LinkEvent]:
        self.now = now
        events = self.monitor.poll(now)
        if events:  # link lost: pending work cannot complete
            reason = events[-1].reason
            events += self._fail_pending(f"link lost: {reason}", now)
        if self.monitor.due_heartbeat(now):
            self._send(self.codec.mav.heartbeat_encode(
                mav.MAV_TYPE_GCS, mav.MAV_AUTOPILOT_INVALID, 0, 0, mav.MAV_STATE_ACTIVE), now)
        if now >= self.next_timesync:
            self.next_timesync = now + self.config.timesync_period_s
            ts1 = int(now * 1e9) & 0x7FFFFFFFFFFFFFFF
            self._timesync_sent = {k: v for k, v in self._timesync_sent.items()
                                   if now - v < 5.0}
            self._timesync_sent[ts1] = self._send(self.codec.mav.timesync_encode(0, ts1), now)
        if self.ramp_pose is not None and now >= self.next_ramp_pose:
            self.next_ramp_pose = now + self.config.ramp_pose_period_s
            self._send_ramp_pose(now)
        if self.upload is not None:
            out, ev = self.upload.poll(now)
            self._queue_upload(out, now)
            events += ev
        if self.readback is not None:
            seqs, ev = self.readback.poll(now)
            self._queue_reads(seqs, now)
            events += ev
        resend, ev = self.commands.due(now)
        for seq in resend:
            self._send_command(seq, now)
        return events + ev

    def _fail_pending(self, reason: str, now: float) -> list[LinkEvent]:
        events = self.commands.fail_all(reason)
        if self.upload is not None:
            events += self.upload.fail(f"{reason} (during the upload)", now)
        if self.readback is not None and self.readback.result is None:
            self.readback.result = ReadbackResult(self.readback.mission_id, None, reason)
            events.append(self.readback.result)
        return events

    def connection_lost(self, reason: str, now: float) -> list[LinkEvent]:
        """The transport closed (port gone): the link is down at once."""
        return self.monitor.lost(reason) + self._fail_pending(f"link lost: {reason}", now)

    # ---- requests
    def _require_link(self) -> None:
        if not self.monitor.link_up:
            raise RuntimeError("the boat link is down")

    def start_upload(self, mission: Mission, now: float, swap_at_ms: int = 0) -> None:
        """Begin uploading (swap_at_ms: hot swap at that boat uptime); RuntimeError if the
        link is down or another upload runs."""
        self._require_link()
        if self.upload is not None and not self.upload.done:
            raise RuntimeError(f"mission {self.upload.mission.mission_id} is still uploading")
        self.upload = MissionUploader(mission, self.config, self.rtt, now, swap_at_ms)
        self._queue_upload(self.upload.start(now), now)

    def start_readback(self, mission_id: int, count: int, now: float) -> None:
        self._require_link()
        if self.readback is not None and self.readback.result is None:
            raise RuntimeError(f"mission {self.readback.mission_id} is being read back")
        self.readback = Readback(mission_id, count, self.config, self.rtt)
        self._queue_reads(self.readback.start(now), now)

    def send_command(self, name: str, now: float, mission_id: int = 0,
                     mission_crc: int = 0) -> int:
        self._require_link()
        seq = self.commands.send(name, now, wire.to_i32(mission_id), wire.to_i32(mission_crc))
        self._send_command(seq, now)
        return seq

    def send_guidance(self, heading_cdeg: int, speed_cms: int, valid_ms: int) -> None:
        self._require_link()
        self._send(self.codec.mav.usv_guidance_encode(
            self.config.boat_id, wire.BOAT_COMPONENT, heading_cdeg % 36000,
            max(0, min(0xFFFF, speed_cms)), max(1, min(0xFFFF, valid_ms))), self.now)

    def set_ramp_pose(self, pose: RampPoseSample | None) -> None:
        """The latest pose of the moving ramp (None: the ramp is the fixed scenario origin,
        nothing is streamed). `poll` sends it every `ramp_pose_period_s` while the link is
        up and the boat's clock is known; each frame carries the pose's own instant
        (`pose.t` mapped to the boat's uptime), so the boat extrapolates an old pose by
        its true age."""
        self.ramp_pose = pose

    def _send_ramp_pose(self, now: float) -> None:
        p = self.ramp_pose
        up = self.boat_uptime_ms(p.t) if p is not None else None
        if p is None or up is None or up < 0 or not self.monitor.link_up:
            return
        self._send(self.codec.mav.usv_ramp_pose_encode(
            self.config.boat_id, wire.BOAT_COMPONENT, up & 0xFFFFFFFF, E7.to_wire(p.lat),
            E7.to_wire(p.lon), CDEG.to_wire(p.bearing_deg % 360.0), p.vn, p.ve, p.yaw_rate),
            now)
        self.ramp_poses_sent += 1

    # ---- output
    def _send(self, msg: Any, now: float) -> float:
        """Queue one frame; returns when it will have left at the configured baud."""
        data = self.codec.encode(msg, self._stamp(now))
        self._out += data
        self.tx_free_at = max(self.tx_free_at, now) + self.config.airtime(len(data))
        return self.tx_free_at

    def _send_command(self, seq: int, now: float) -> None:
        p = self.commands.pending[seq]
        departure = self._send(self.codec.mav.command_int_encode(
            self.config.boat_id, wire.BOAT_COMPONENT, mav.MAV_FRAME_MISSION, p.code, 0, 0,
            float(seq), float(self.session), 0.0, 0.0, p.x, p.y, 0.0), now)
        p.deadline = departure + self.rtt.timeout

    def _queue_upload(self, out: list[tuple[str, Any]], now: float) -> None:
        up = self.upload
        if up is None:
            return
        m, b = up.mission, self.config.boat_id
        enc = self.codec.mav
        for kind, key in out:
            if kind == "begin":
                msg = enc.usv_mission_begin_encode(b, wire.BOAT_COMPONENT, m.mission_id, m.crc,
                                                   m.count, up.swap_at_ms)
            elif kind == "end":
                msg = enc.usv_mission_end_encode(b, wire.BOAT_COMPONENT, m.mission_id, m.crc,
                                                 m.count)
            else:
                it = m.items[key]
                msg = enc.usv_mission_item_encode(b, wire.BOAT_COMPONENT, it.mission_id, it.seq,
                                                  it.lat, it.lon, it.t_ms, it.speed_cms,
                                                  it.course_cdeg, it.heading_cdeg)
            up.mark({"begin": BEGIN, "end": END}.get(kind, key), self._send(msg, now))

    def _queue_reads(self, seqs: list[int], now: float) -> None:
        rb = self.readback
        for seq in seqs:
            rb.mark(seq, self._send(self.codec.mav.usv_mission_read_encode(
                self.config.boat_id, wire.BOAT_COMPONENT, rb.mission_id, seq), now))

    def data_to_send(self) -> bytes:
        data = bytes(self._out)
        self._out.clear()
        self.bytes_sent += len(data)
        return data

    def next_deadline(self) -> float:
        d = min(self.monitor.next_deadline(), self.commands.next_deadline(), self.next_timesync)
        if self.ramp_pose is not None:
            d = min(d, self.next_ramp_pose)
        if self.upload is not None and not self.upload.done:
            d = min(d, self.upload.next_deadline())
        if self.readback is not None and self.readback.result is None:
            d = min(d, self.readback.next_deadline())
        return d
