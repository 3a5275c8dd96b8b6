"""The standard MAVLink mission and command protocols, ground-station side, sans-IO.

`MissionUpload` (MISSION_COUNT, then the vehicle pulls each item with MISSION_REQUEST_INT
or MISSION_REQUEST and ends with MISSION_ACK), `MissionDownload` (MISSION_REQUEST_LIST,
MISSION_COUNT, MISSION_REQUEST_INT per item, our MISSION_ACK) and `CommandSender`
(COMMAND_LONG, retried with `confirmation` counted up, until a COMMAND_ACK of that command
that is not IN_PROGRESS) as the MAVLink microservice specifications describe them
(mavlink.io "Mission Protocol" and "Command Protocol": a message without its answer is
sent again after the timeout, 1.5 s by default and 0.25 s while items are streaming, at
most 5 retries; a transfer that runs out of retries fails and says where).

Each machine takes the decoded values and `now` in and returns what to send as small
typed requests (`Send*`) and what happened as typed events (`TransferProgress`,
`TransferDone`, `CommandDone`); link/standard.py turns the requests into frames. Nothing
here encodes, reads a clock or does I/O.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from usvstation.link.mavlink import usv_recovery as mav
from usvstation.link.standard_mission import StandardItem

INF = float("inf")
RETRIES = 5  # after the first send (mavlink.io: "Retries (max): 5")
TIMEOUT_S = 1.5  # MISSION_COUNT, MISSION_REQUEST_LIST, a command: "Timeout (default)"
ITEM_TIMEOUT_S = 0.25  # while items stream: "Timeout (mission items)"
MISSION_RESULTS = {v: e.name.removeprefix("MAV_MISSION_")
                   for v, e in mav.enums["MAV_MISSION_RESULT"].items() if v < 20}
RESULT_NAMES = {v: e.name.removeprefix("MAV_RESULT_")
                for v, e in mav.enums["MAV_RESULT"].items() if v < 20}


# ----------------------------------------------------------------------------- requests


@dataclass(frozen=True)
class SendCount:
    count: int


@dataclass(frozen=True)
class SendItem:
    item: StandardItem


@dataclass(frozen=True)
class SendRequestList:
    pass


@dataclass(frozen=True)
class SendRequestItem:
    seq: int


@dataclass(frozen=True)
class SendMissionAck:
    result: int


@dataclass(frozen=True)
class SendCommand:
    command: int
    params: tuple[float, float, float, float, float, float, float]
    confirmation: int


TransferRequest = SendCount | SendItem | SendRequestList | SendRequestItem | SendMissionAck
"""What a mission transfer asks link/standard.py to send."""


# ----------------------------------------------------------------------------- events


@dataclass(frozen=True)
class TransferProgress:
    """Items the vehicle has taken (upload) or we have received (download) of `count`."""

    done: int
    count: int


@dataclass(frozen=True)
class TransferDone:
    """A transfer's end: ok, or why not; a download's items (None unless ok)."""

    ok: bool
    reason: str
    items: tuple[StandardItem, ...] | None = None
    retransmissions: int = 0


@dataclass(frozen=True)
class CommandDone:
    """A command's end: the vehicle's MAV_RESULT, or None after every retry."""

    command: int
    result: int | None
    error: str = ""

    @property
    def accepted(self) -> bool:
        return self.result == mav.MAV_RESULT_ACCEPTED


TransferEvent = TransferProgress | TransferDone


@dataclass
class Timer:
    """One awaited answer: its deadline and the sends left."""

    deadline: float = INF
    sends: int = 0

    def arm(self, now: float, timeout: float) -> None:
        self.deadline = now + timeout
        self.sends += 1

    def expired(self, now: float) -> bool:
        return now >= self.deadline

    @property
    def exhausted(self) -> bool:
        return self.sends > RETRIES


# ----------------------------------------------------------------------------- upload


@dataclass
class MissionUpload:
    """Upload `items` (seq 0..n-1). The vehicle drives the transfer: it requests each item
    (in any order, again when it lost one) and ends with MISSION_ACK. We resend
    MISSION_COUNT until the first request, and the last requested item when the vehicle
    goes quiet; the vehicle's ACK with an error ends the upload with its name."""

    items: tuple[StandardItem, ...]
    timeout_s: float = TIMEOUT_S
    timer: Timer = field(default_factory=Timer)
    last: int | None = None  # the item the vehicle asked for last
    highest: int = -1
    retransmissions: int = 0
    result: TransferDone | None = None

    @property
    def done(self) -> bool:
        return self.result is not None

    def start(self, now: float) -> list[TransferRequest]:
        self.timer.arm(now, self.timeout_s)
        return [SendCount(len(self.items))]

    def on_request(self, seq: int, now: float) -> tuple[list[TransferRequest],
                                                        list[TransferEvent]]:
        if self.done:
            return [], []
        if not 0 <= seq < len(self.items):
            return [], self._finish(False, f"the vehicle asked for item {seq} of "
                                           f"{len(self.items)}")
        if seq <= self.highest:
            self.retransmissions += 1
        self.last, self.highest = seq, max(self.highest, seq)
        self.timer = Timer()
        self.timer.arm(now, self.timeout_s)
        return [SendItem(self.items[seq])], [TransferProgress(seq, len(self.items))]

    def on_ack(self, result: int) -> list[TransferEvent]:
        if self.done:
            return []
        if result == mav.MAV_MISSION_ACCEPTED:
            if self.highest < len(self.items) - 1:
                return self._finish(False, f"the vehicle accepted the mission after item "
                                           f"{self.highest} of {len(self.items)}")
            return [TransferProgress(len(self.items), len(self.items)),
                    *self._finish(True, "accepted")]
        name = MISSION_RESULTS.get(result, str(result))
        return self._finish(False, f"the vehicle refused the mission: {name}")

    def poll(self, now: float) -> tuple[list[TransferRequest], list[TransferEvent]]:
        if self.done or not self.timer.expired(now):
            return [], []
        if self.timer.exhausted:
            what = "MISSION_COUNT" if self.last is None else f"item {self.last}"
            return [], self._finish(False, f"no answer to {what} after {RETRIES + 1} sends")
        self.retransmissions += 1
        self.timer.arm(now, self.timeout_s)
        if self.last is None:
            return [SendCount(len(self.items))], []
        return [SendItem(self.items[self.last])], []

    def cancel(self, reason: str) -> list[TransferEvent]:
        return self._finish(False, reason) if not self.done else []

    def _finish(self, ok: bool, reason: str) -> list[TransferEvent]:
        self.result = TransferDone(ok, reason, None, self.retransmissions)
        self.timer = Timer()
        return [self.result]

    def next_deadline(self) -> float:
        return INF if self.done else self.timer.deadline


# ----------------------------------------------------------------------------- download


@dataclass
class MissionDownload:
    """Read the vehicle's mission: MISSION_REQUEST_LIST until MISSION_COUNT, then each item
    in order with MISSION_REQUEST_INT (again after `item_timeout_s`), then our MISSION_ACK."""

    timeout_s: float = TIMEOUT_S
    item_timeout_s: float = ITEM_TIMEOUT_S
    timer: Timer = field(default_factory=Timer)
    count: int | None = None
    items: list[StandardItem] = field(default_factory=list)
    retransmissions: int = 0
    result: TransferDone | None = None

    @property
    def done(self) -> bool:
        return self.result is not None

    def start(self, now: float) -> list[TransferRequest]:
        self.timer.arm(now, self.timeout_s)
        return [SendRequestList()]

    def on_count(self, count: int, now: float) -> tuple[list[TransferRequest],
                                                        list[TransferEvent]]:
        if self.done or self.count is not None:
            return [], []  # a repeated MISSION_COUNT (our list request was sent twice)
        self.count = count
        if count == 0:
            return [SendMissionAck(mav.MAV_MISSION_ACCEPTED)], self._finish(True, "empty")
        return self._request(now), []

    def on_item(self, item: StandardItem, now: float) -> tuple[list[TransferRequest],
                                                                list[TransferEvent]]:
        if self.done or self.count is None or item.seq != len(self.items):
            return [], []  # a late duplicate, or not ours
        self.items.append(item)
        events: list[TransferEvent] = [TransferProgress(len(self.items), self.count)]
        if len(self.items) == self.count:
            return [SendMissionAck(mav.MAV_MISSION_ACCEPTED)], \
                events + self._finish(True, "complete")
        return self._request(now), events

    def on_ack(self, result: int) -> list[TransferEvent]:
        """The vehicle ended the transfer (an error: no mission, a bad sequence)."""
        if self.done or result == mav.MAV_MISSION_ACCEPTED:
            return []
        return self._finish(False, f"the vehicle refused the read: "
                                   f"{MISSION_RESULTS.get(result, str(result))}")

    def _request(self, now: float) -> list[TransferRequest]:
        self.timer = Timer()
        self.timer.arm(now, self.item_timeout_s)
        return [SendRequestItem(len(self.items))]

    def poll(self, now: float) -> tuple[list[TransferRequest], list[TransferEvent]]:
        if self.done or not self.timer.expired(now):
            return [], []
        what = "MISSION_REQUEST_LIST" if self.count is None else f"item {len(self.items)}"
        if self.timer.exhausted:
            return [SendMissionAck(mav.MAV_MISSION_OPERATION_CANCELLED)], \
                self._finish(False, f"no answer to {what} after {RETRIES + 1} sends")
        self.retransmissions += 1
        if self.count is None:
            self.timer.arm(now, self.timeout_s)
            return [SendRequestList()], []
        self.timer.arm(now, self.item_timeout_s)
        return [SendRequestItem(len(self.items))], []

    def cancel(self, reason: str) -> list[TransferEvent]:
        return self._finish(False, reason) if not self.done else []

    def _finish(self, ok: bool, reason: str) -> list[TransferEvent]:
        self.result = TransferDone(ok, reason, tuple(self.items) if ok else None,
                                   self.retransmissions)
        self.timer = Timer()
        return [self.result]

    def next_deadline(self) -> float:
        return INF if self.done else self.timer.deadline


# ----------------------------------------------------------------------------- commands


@dataclass
class PendingCommand:
    command: int
    params: tuple[float, float, float, float, float, float, float]
    timer: Timer = field(default_factory=Timer)
    confirmation: int = 0


class CommandSender:
    """COMMAND_LONG with the command protocol's retries: one pending command per id; an
    ACK IN_PROGRESS keeps it waiting (a longer deadline, no resend); any other result, or
    no answer after RETRIES resends, ends it."""

    def __init__(self, timeout_s: float = TIMEOUT_S) -> None:
        self.timeout_s = timeout_s
        self.pending: dict[int, PendingCommand] = {}

    def send(self, command: int, params: tuple[float, ...], now: float) -> list[SendCommand]:
        p7 = tuple(float(v) for v in (*params, 0, 0, 0, 0, 0, 0, 0)[:7])
        cmd = PendingCommand(command, p7)  # type: ignore[arg-type]
        self.pending[command] = cmd
        cmd.timer.arm(now, self.timeout_s)
        return [SendCommand(command, cmd.params, 0)]

    def on_ack(self, command: int, result: int, now: float) -> list[CommandDone]:
        cmd = self.pending.get(command)
        if cmd is None:
            return []
        if result == mav.MAV_RESULT_IN_PROGRESS:
            cmd.timer.deadline = now + 3 * self.timeout_s
            return []
        del self.pending[command]
        return [CommandDone(command, result)]

    def poll(self, now: float) -> tuple[list[SendCommand], list[CommandDone]]:
        sends: list[SendCommand] = []
        done: list[CommandDone] = []
        for code, cmd in list(self.pending.items()):
            if not cmd.timer.expired(now):
                continue
            if cmd.timer.exhausted:
                del self.pending[code]
                done.append(CommandDone(code, None, f"no COMMAND_ACK after "
                                                    f"{RETRIES + 1} sends"))
                continue
            cmd.confirmation = min(255, cmd.confirmation + 1)
            cmd.timer.arm(now, self.timeout_s)
            sends.append(SendCommand(code, cmd.params, cmd.confirmation))
        return sends, done

    def fail_all(self, reason: str) -> list[CommandDone]:
        done = [CommandDone(code, None, reason) for code in self.pending]
        self.pending.clear()
        return done

    def next_deadline(self) -> float:
        return min((c.timer.deadline for c in self.pending.values()), default=INF)
