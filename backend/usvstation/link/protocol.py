"""Station side of usv-link as sans-IO state machines (protocol/README.md "Station").

Nothing here does I/O or reads a clock: callers pass received bytes and the current
time `now` (seconds, monotonic) in, and take bytes to send and events out:

    proto = StationProtocol(LinkConfig(), now)
    events = proto.receive_data(data, now)   # bytes from the boat
    events += proto.poll(now)                # timers: heartbeat, retries, link loss
    wire = proto.data_to_send()              # bytes for the boat
    proto.next_deadline()                    # when poll() is due next

MissionUploader, CommandSender and LinkMonitor are the parts; StationProtocol
routes messages between them and the codec.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from usvstation.link import messages as m
from usvstation.link.codec import Encoder, FrameDecoder
from usvstation.link.mission import Mission

INF = float("inf")


@dataclass(frozen=True)
class LinkConfig:
    """Timing of the station side; defaults suit 57600 baud (see README "Timeouts")."""

    heartbeat_period_s: float = m.HEARTBEAT_PERIOD_MS / 1000
    link_timeout_s: float = m.LINK_TIMEOUT_MS / 1000
    ack_timeout_s: float = 0.3  # MISSION_* and COMMAND answer timeout per attempt
    max_attempts: int = 10  # per mission message (item, begin, end)
    window: int = 8  # mission items in flight
    command_attempts: int = 5


# ----------------------------------------------------------------------------- events


@dataclass(frozen=True)
class LinkUp:
    """A boat HEARTBEAT with matching protocol version and definitions arrived."""

    heartbeat: m.Heartbeat


@dataclass(frozen=True)
class LinkDown:
    reason: str


@dataclass(frozen=True)
class DefinitionMismatch:
    """The boat speaks another protocol version or definition set: nothing is exchanged."""

    message: str
    boat_version: int
    boat_definition_crc: int


@dataclass(frozen=True)
class BoatHeartbeat:
    heartbeat: m.Heartbeat


@dataclass(frozen=True)
class TelemetryReceived:
    telemetry: m.Telemetry
    received_at: float


@dataclass(frozen=True)
class StatusTextReceived:
    severity: m.Severity
    text: str


@dataclass(frozen=True)
class UploadProgress:
    mission_id: int
    acked: int
    count: int
    sent: int = 0  # distinct items sent at least once


@dataclass(frozen=True)
class UploadResult:
    """The end of an upload. ok: the boat activated exactly this mission (MISSION_END ACK)."""

    mission_id: int
    ok: bool
    reason: str
    count: int
    retransmissions: int
    duration_s: float


@dataclass(frozen=True)
class CommandOutcome:
    """The answer to a COMMAND; result None when no COMMAND_ACK came (error says why)."""

    command_id: int
    command: m.CommandCode
    result: m.CommandResult | None
    state: m.State | None
    error: str = ""

    @property
    def accepted(self) -> bool:
        return self.result == m.CommandResult.ACCEPTED


Event = Any  # one of the dataclasses above


# ----------------------------------------------------------------------------- uploader


class MissionUploader:
    """Reliable upload: BEGIN, then items with a sliding window, then END.

    Each message is retransmitted after `ack_timeout_s` without its ACK, at most
    `max_attempts` times; a MISSION_NAK ends the upload with its reason, except
    MISSING_ITEMS, which re-sends the missing item. The boat activates the mission
    only on its END ACK, so a failed upload never leaves a partial mission active.
    """

    def __init__(self, mission: Mission, config: LinkConfig, now: float) -> None:
        self.mission = mission
        self.cfg = config
        self.started = now
        self.phase = "begin"
        self.acked: set[int] = set()
        self.attempts: dict[Any, int] = {}
        self.deadlines: dict[Any, float] = {}  # key ("begin" | "end" | index) -> ack deadline
        self.next_index = 0
        self.retransmissions = 0
        self.result: UploadResult | None = None

    @property
    def done(self) -> bool:
        return self.result is not None

    @property
    def items_sent(self) -> int:
        return sum(1 for key in self.attempts if isinstance(key, int))

    def start(self, now: float) -> list[Any]:
        return self._send("begin", now)

    def _message(self, key: Any) -> Any:
        if key == "begin":
            return self.mission.begin()
        if key == "end":
            return self.mission.end()
        return self.mission.items[key]

    def _send(self, key: Any, now: float) -> list[Any]:
        n = self.attempts.get(key, 0)
        if n >= self.cfg.max_attempts:
            what = f"item {key}" if isinstance(key, int) else f"MISSION_{str(key).upper()}"
            self._finish(False, f"{what} not acknowledged after {n} attempts", now)
            return []
        if n:
            self.retransmissions += 1
        self.attempts[key] = n + 1
        self.deadlines[key] = now + self.cfg.ack_timeout_s
        return [self._message(key)]

    def _finish(self, ok: bool, reason: str, now: float) -> None:
        self.deadlines.clear()
        self.result = UploadResult(self.mission.mission_id, ok, reason, self.mission.count,
                                   self.retransmissions, now - self.started)

    def _fill_window(self, now: float) -> list[Any]:
        out: list[Any] = []
        count = self.mission.count
        while self.phase == "items" and len(self.deadlines) < self.cfg.window:
            while self.next_index < count and self.next_index in self.acked:
                self.next_index += 1
            if self.next_index >= count:
                break
            out += self._send(self.next_index, now)
            self.next_index += 1
        if self.phase == "items" and len(self.acked) == count:
            self.phase = "end"
            out += self._send("end", now)
        return out

    def handle(self, msg: Any, now: float) -> tuple[list[Any], list[Event]]:
        """A MISSION_ACK or MISSION_NAK from the boat."""
        if self.done or msg.mission_id != self.mission.mission_id:
            return [], []
        if isinstance(msg, m.MissionNak):
            return self._nak(msg, now)
        stage = msg.stage
        if stage == m.MissionStage.BEGIN and self.phase == "begin":
            self.deadlines.pop("begin", None)
            self.phase = "items"
            out = self._fill_window(now)
            return out, [UploadProgress(self.mission.mission_id, 0, self.mission.count,
                                        self.items_sent)]
        if stage == m.MissionStage.ITEM and msg.index < self.mission.count:
            self.deadlines.pop(msg.index, None)
            if msg.index in self.acked or self.phase != "items":
                return self._fill_window(now), []
            self.acked.add(msg.index)
            out = self._fill_window(now)
            progress = UploadProgress(self.mission.mission_id, len(self.acked),
                                      self.mission.count, self.items_sent)
            return out, [progress]
        if stage == m.MissionStage.END and self.phase == "end":
            self._finish(True, "activated", now)
            return [], [self.result]
        return [], []

    def _nak(self, nak: m.MissionNak, now: float) -> tuple[list[Any], list[Event]]:
        reason = m.NakReason(nak.reason) if nak.reason in m.NakReason._value2member_map_ \
            else nak.reason
        if reason == m.NakReason.MISSING_ITEMS and self.phase == "end" \
                and nak.index < self.mission.count:
            self.acked.discard(nak.index)  # the boat lost it: back to the items phase
            self.deadlines.pop("end", None)
            self.phase = "items"
            self.next_index = min(self.next_index, nak.index)
            return self._fill_window(now), []
        if nak.stage == m.MissionStage.ITEM:
            what = f"item {nak.index}"
        else:
            what = f"MISSION_{m.MissionStage(nak.stage).name}" \
                if nak.stage in m.MissionStage._value2member_map_ else "a mission message"
        name = reason.name if isinstance(reason, m.NakReason) else f"reason {reason}"
        self._finish(False, f"boat refused {what}: {name}", now)
        return [], [self.result]

    def poll(self, now: float) -> tuple[list[Any], list[Event]]:
        """Retransmit what timed out; finish when a message ran out of attempts."""
        if self.done:
            return [], []
        out: list[Any] = []
        for key, deadline in sorted(self.deadlines.items(), key=lambda kv: kv[1]):
            if deadline <= now:
                out += self._send(key, now)
                if self.done:
                    return [], [self.result]
        return out, []

    def fail(self, reason: str, now: float) -> list[Event]:
        if self.done:
            return []
        self._finish(False, reason, now)
        return [self.result]

    def next_deadline(self) -> float:
        return min(self.deadlines.values(), default=INF)


# ----------------------------------------------------------------------------- commands


class CommandSender:
    """COMMAND with ACK, timeout and bounded retry; retries reuse the command_id."""

    def __init__(self, config: LinkConfig) -> None:
        self.cfg = config
        self._next_id = 1
        self.pending: dict[int, tuple[m.Command, float, int]] = {}  # id -> msg, deadline, n

    def send(self, command: m.CommandCode, now: float, mission_id: int = 0) -> tuple[int, Any]:
        cid = self._next_id
        self._next_id = self._next_id % 0xFFFF + 1
        msg = m.Command(cid, int(command), mission_id)
        self.pending[cid] = (msg, now + self.cfg.ack_timeout_s, 1)
        return cid, msg

    def handle(self, ack: m.CommandAck) -> list[Event]:
        sent = self.pending.pop(ack.command_id, None)
        if sent is None or sent[0].command != ack.command:
            return []  # a duplicate answer to a retry, or not an answer to this command
        result = m.CommandResult(ack.result) if ack.result in m.CommandResult._value2member_map_ \
            else None
        state = m.State(ack.state) if ack.state in m.State._value2member_map_ else None
        err = "" if result is not None else f"unknown result code {ack.result}"
        return [CommandOutcome(ack.command_id, m.CommandCode(ack.command), result, state, err)]

    def poll(self, now: float) -> tuple[list[Any], list[Event]]:
        out, events = [], []
        for cid, (msg, deadline, n) in list(self.pending.items()):
            if deadline > now:
                continue
            if n >= self.cfg.command_attempts:
                del self.pending[cid]
                events.append(CommandOutcome(cid, m.CommandCode(msg.command), None, None,
                                             f"no COMMAND_ACK after {n} attempts"))
            else:
                self.pending[cid] = (msg, now + self.cfg.ack_timeout_s, n + 1)
                out.append(msg)
        return out, events

    def fail_all(self, reason: str) -> list[Event]:
        events = [CommandOutcome(cid, m.CommandCode(msg.command), None, None, reason)
                  for cid, (msg, _, _) in self.pending.items()]
        self.pending.clear()
        return events

    def next_deadline(self) -> float:
        return min((d for _, d, _ in self.pending.values()), default=INF)


# ----------------------------------------------------------------------------- link monitor


def mismatch_message(peer: str, hb: m.Heartbeat, me: str = "station") -> str:
    return (f"protocol definition mismatch: {peer} speaks {m.PROTOCOL} v{hb.protocol_version} "
            f"(definitions 0x{hb.definition_crc:08X}), {me} speaks {m.PROTOCOL} "
            f"v{m.PROTOCOL_VERSION} (definitions 0x{m.DEFINITION_CRC:08X})")


def heartbeat_matches(hb: m.Heartbeat) -> bool:
    return hb.protocol_version == m.PROTOCOL_VERSION and hb.definition_crc == m.DEFINITION_CRC


class LinkMonitor:
    """Heartbeat sender and link-loss detector: the link is up from a matching boat
    HEARTBEAT until no valid frame arrived for `link_timeout_s`."""

    def __init__(self, config: LinkConfig, now: float) -> None:
        self.cfg = config
        self.started = now
        self.link_up = False
        self.mismatch: DefinitionMismatch | None = None
        self.last_rx = -INF
        self.next_heartbeat = now

    def heartbeat(self, now: float) -> m.Heartbeat:
        return m.Heartbeat(m.DEFINITION_CRC, m.PROTOCOL_VERSION, m.Sender.STATION, 0, 0, 0, 0,
                           int((now - self.started) * 1000) & 0xFFFFFFFF)

    def on_frame(self, now: float) -> None:
        if self.link_up:
            self.last_rx = now

    def on_heartbeat(self, hb: m.Heartbeat, now: float) -> list[Event]:
        if not heartbeat_matches(hb):
            was = self.mismatch
            self.mismatch = DefinitionMismatch(mismatch_message("boat", hb), hb.protocol_version,
                                               hb.definition_crc)
            events: list[Event] = [] if was == self.mismatch else [self.mismatch]
            if self.link_up:
                self.link_up = False
                events.append(LinkDown(self.mismatch.message))
            return events
        self.mismatch = None
        self.last_rx = now
        if self.link_up:
            return []
        self.link_up = True
        return [LinkUp(hb)]

    def poll(self, now: float) -> tuple[list[Any], list[Event]]:
        out: list[Any] = []
        if now >= self.next_heartbeat:
            out.append(self.heartbeat(now))
            self.next_heartbeat = now + self.cfg.heartbeat_period_s
        if self.link_up and now - self.last_rx > self.cfg.link_timeout_s:
            self.link_up = False
            return out, [LinkDown(f"no frame from the boat for {self.cfg.link_timeout_s:.1f} s")]
        return out, []

    def lost(self, reason: str) -> list[Event]:
        if not self.link_up:
            return []
        self.link_up = False
        return [LinkDown(reason)]

    def next_deadline(self) -> float:
        d = self.next_heartbeat
        if self.link_up:
            d = min(d, self.last_rx + self.cfg.link_timeout_s + 1e-3)
        return d


# ----------------------------------------------------------------------------- station


@dataclass
class StationProtocol:
    """The whole station side: codec + link monitor + uploader + command sender."""

    config: LinkConfig = field(default_factory=LinkConfig)
    now: float = 0.0
    on_send: Callable[[Any], None] | None = None

    def __post_init__(self) -> None:
        self.encoder = Encoder()
        self.decoder = FrameDecoder()
        self.monitor = LinkMonitor(self.config, self.now)
        self.commands = CommandSender(self.config)
        self.upload: MissionUploader | None = None
        self.boat_heartbeat: m.Heartbeat | None = None
        self.telemetry: m.Telemetry | None = None
        self._out = bytearray()
        self.bytes_sent = 0
        self.bytes_received = 0

    # ---- state
    @property
    def link_up(self) -> bool:
        return self.monitor.link_up

    @property
    def mismatch(self) -> DefinitionMismatch | None:
        return self.monitor.mismatch

    # ---- input
    def receive_data(self, data: bytes, now: float) -> list[Event]:
        self.bytes_received += len(data)
        events: list[Event] = []
        for msg in self.decoder.feed(data):
            events += self._handle(msg, now)
        return events + self.poll(now)

    def _handle(self, msg: Any, now: float) -> list[Event]:
        if isinstance(msg, m.Heartbeat):
            if msg.sender == m.Sender.STATION and heartbeat_matches(msg):
                return []  # our own heartbeat echoed by a looped-back line: not the boat
            events = self.monitor.on_heartbeat(msg, now)
            if heartbeat_matches(msg):
                self.boat_heartbeat = msg
                events.append(BoatHeartbeat(msg))
            return events
        if not self.monitor.link_up:
            return []  # nothing is trusted before a matching handshake
        self.monitor.on_frame(now)
        if isinstance(msg, m.Telemetry):
            self.telemetry = msg
            return [TelemetryReceived(msg, now)]
        if isinstance(msg, m.MissionAck | m.MissionNak) and self.upload is not None:
            out, events = self.upload.handle(msg, now)
            self._queue(out)
            return events
        if isinstance(msg, m.CommandAck):
            return self.commands.handle(msg)
        if isinstance(msg, m.StatusText):
            sev = m.Severity(msg.severity) if msg.severity in m.Severity._value2member_map_ \
                else m.Severity.INFO
            return [StatusTextReceived(sev, msg.text)]
        return []

    def poll(self, now: float) -> list[Event]:
        self.now = now
        out, events = self.monitor.poll(now)
        self._queue(out)
        if events:  # link lost: pending work cannot complete
            reason = events[-1].reason
            events += self.commands.fail_all(f"link lost: {reason}")
            if self.upload is not None:
                events += self.upload.fail(f"link lost during upload: {reason}", now)
        if self.upload is not None:
            out, ev = self.upload.poll(now)
            self._queue(out)
            events += ev
        out, ev = self.commands.poll(now)
        self._queue(out)
        return events + ev

    def connection_lost(self, reason: str, now: float) -> list[Event]:
        """The transport closed (port gone): the link is down at once."""
        events = self.monitor.lost(reason)
        events += self.commands.fail_all(f"link lost: {reason}")
        if self.upload is not None:
            events += self.upload.fail(f"link lost during upload: {reason}", now)
        return events

    # ---- requests
    def start_upload(self, mission: Mission, now: float) -> None:
        """Begin uploading; raises RuntimeError if the link is down or an upload runs."""
        self._require_link()
        if self.upload is not None and not self.upload.done:
            raise RuntimeError(f"mission {self.upload.mission.mission_id} is still uploading")
        self.upload = MissionUploader(mission, self.config, now)
        self._queue(self.upload.start(now))

    def send_command(self, command: m.CommandCode, now: float, mission_id: int = 0) -> int:
        self._require_link()
        cid, msg = self.commands.send(command, now, mission_id)
        self._queue([msg])
        return cid

    def send_guidance(self, heading_cdeg: int, speed_cms: int, valid_ms: int) -> None:
        self._require_link()
        self._queue([m.GuidanceSetpoint(heading_cdeg % 36000, speed_cms, valid_ms)])

    def _require_link(self) -> None:
        if self.monitor.mismatch is not None:
            raise RuntimeError(self.monitor.mismatch.message)
        if not self.monitor.link_up:
            raise RuntimeError("the boat link is down")

    # ---- output
    def _queue(self, msgs: list[Any]) -> None:
        for msg in msgs:
            self._out += self.encoder.encode(msg)
            if self.on_send is not None:
                self.on_send(msg)

    def data_to_send(self) -> bytes:
        data = bytes(self._out)
        self._out.clear()
        self.bytes_sent += len(data)
        return data

    def next_deadline(self) -> float:
        d = min(self.monitor.next_deadline(), self.commands.next_deadline())
        if self.upload is not None and not self.upload.done:
            d = min(d, self.upload.next_deadline())
        return d
