"""Missions as the station sees them: derived from what the boat reports, at every report.

The boat's USV_MISSION_STATE (after every HEARTBEAT and on every change) names the
mission it holds (id + CRC-32), its staging and its state. `TRANSITIONS` is the whole
mission state machine: (state, what the boat reports about this mission) -> next state.
An upload's own result only decides while the boat has not said otherwise: a lost END
ACK leaves the mission "failed" only until the next report shows the boat holds it, and
a boat reboot makes a verified mission "gone" at the first report of the new boot.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field

from usvstation.geo import RampFrame
from usvstation.link.mission import Mission, MissionItem, Origin
from usvstation.link.protocol import MissionState
from usvstation.records import MissionRow, MissionView, RampOrigin


class MissionStatus(enum.StrEnum):
    UPLOADING = "uploading"  # the upload runs
    VERIFIED = "verified"  # the boat holds it, READY for START
    ACTIVE = "active"  # the boat runs it (RUNNING, HOLD, FAILSAFE or GO_AROUND)
    COMPLETED = "completed"  # the boat reported DONE with it
    ABORTED = "aborted"  # the boat dropped it on ABORT
    FAILED = "failed"  # the upload failed and the boat does not hold it
    GONE = "gone"  # the boat no longer holds it (rebooted, replaced)


class Seen(enum.Enum):
    """What one USV_MISSION_STATE says about one mission."""

    HELD_READY = "held, READY"
    HELD_RUNNING = "held, RUNNING/HOLD/FAILSAFE/GO_AROUND"
    HELD_DONE = "held, DONE"
    STAGED = "staged"
    DROPPED_BY_ABORT = "not held, boat ABORTED"
    NOT_HELD = "not held"


M, S = MissionStatus, Seen
TRANSITIONS: dict[tuple[MissionStatus, Seen], MissionStatus] = {
    # an upload in progress ends when the boat reports holding the mission
    (M.UPLOADING, S.HELD_READY): M.VERIFIED,
    (M.UPLOADING, S.HELD_RUNNING): M.ACTIVE,  # a hot swap took effect
    # a failed upload whose END the boat did take (its ACK was lost)
    (M.FAILED, S.HELD_READY): M.VERIFIED,
    (M.FAILED, S.HELD_RUNNING): M.ACTIVE,
    (M.VERIFIED, S.HELD_RUNNING): M.ACTIVE,
    (M.VERIFIED, S.HELD_DONE): M.COMPLETED,
    (M.VERIFIED, S.DROPPED_BY_ABORT): M.ABORTED,
    (M.VERIFIED, S.NOT_HELD): M.GONE,
    (M.VERIFIED, S.STAGED): M.GONE,
    (M.ACTIVE, S.HELD_READY): M.VERIFIED,
    (M.ACTIVE, S.HELD_DONE): M.COMPLETED,
    (M.ACTIVE, S.DROPPED_BY_ABORT): M.ABORTED,
    (M.ACTIVE, S.NOT_HELD): M.GONE,
    (M.ACTIVE, S.STAGED): M.GONE,
    # the boat is the truth: a mission it holds again is what it says
    (M.GONE, S.HELD_READY): M.VERIFIED,
    (M.GONE, S.HELD_RUNNING): M.ACTIVE,
}
REASONS: dict[MissionStatus, str] = {
    M.GONE: "the boat no longer holds this mission (rebooted, or replaced)",
    M.ABORTED: "dropped by ABORT",
}


def seen(report: MissionState, wire_id: int, crc: int | None) -> Seen:
    """Classify a boat report for the mission (wire_id, crc)."""
    if report.active_id == wire_id and report.active_crc32 == crc:
        if report.state == "READY":
            return S.HELD_READY
        if report.state == "DONE":
            return S.HELD_DONE
        if report.state in ("RUNNING", "HOLD", "FAILSAFE", "GO_AROUND"):
            return S.HELD_RUNNING
    if report.staged_id == wire_id and report.staged_crc32 == crc:
        return S.STAGED
    return S.DROPPED_BY_ABORT if report.state == "ABORTED" else S.NOT_HELD


def next_status(status: MissionStatus, observation: Seen) -> MissionStatus:
    return TRANSITIONS.get((status, observation), status)


@dataclass
class MissionRecord:
    """One mission the station uploaded (persisted in the store's missions table)."""

    id: str
    plan_id: str
    wire_id: int
    created_at: str
    origin: RampOrigin
    items: list[dict[str, int]]
    state: MissionStatus = MissionStatus.UPLOADING
    sent: int = 0
    acked: int = 0
    error: str | None = None
    run: int | None = None
    crc: int | None = field(default=None)

    def __post_init__(self) -> None:
        self.state = MissionStatus(self.state)
        if self.crc is None:
            m = self.mission()
            self.crc = m.crc if m is not None else None

    def mission(self) -> Mission | None:
        try:
            items = tuple(MissionItem(**it) for it in self.items)
            o = self.origin
            return Mission(self.wire_id, items, Origin.from_frame(_frame(o)))
        except (TypeError, ValueError):
            return None  # a record of the old link format

    @property
    def total(self) -> int:
        return len(self.items)

    @property
    def opened_run(self) -> int | None:
        """The run's id once the store opened it (None while it is only claimed: -1)."""
        return self.run if self.run is not None and self.run > 0 else None

    def to_row(self) -> MissionRow:
        return {"id": self.id, "plan_id": self.plan_id, "wire_id": self.wire_id,
                "created_at": self.created_at, "state": self.state.value,
                "progress": {"sent": self.sent, "acked": self.acked, "total": self.total},
                "error": self.error, "run": self.opened_run, "origin": self.origin,
                "items": self.items}

    @classmethod
    def from_row(cls, row: MissionRow) -> MissionRecord:
        try:
            state = MissionStatus(row["state"])
        except ValueError:
            state = MissionStatus.FAILED
        return cls(row["id"], row["plan_id"], int(row["wire_id"]), row["created_at"],
                   row["origin"], row["items"], state, row["progress"]["sent"],
                   row["progress"]["acked"], row.get("error"), row.get("run"))

    def public(self) -> MissionView:
        return {"id": self.id, "plan_id": self.plan_id, "state": self.state.value,
                "progress": {"sent": self.sent, "acked": self.acked, "total": self.total},
                "error": self.error, "created_at": self.created_at, "wire_id": self.wire_id,
                "crc32": self.crc, "run": self.opened_run}

    def apply(self, report: MissionState) -> bool:
        """Derive the state from a boat report; True when it changed."""
        new = next_status(self.state, seen(report, self.wire_id, self.crc))
        if new == self.state:
            return False
        self.state = new
        if new in (M.VERIFIED, M.ACTIVE, M.COMPLETED):
            self.error = None
        elif new in REASONS:
            self.error = REASONS[new]
        return True


def _frame(origin: RampOrigin) -> RampFrame:
    return RampFrame(origin["lat"], origin["lon"], origin["ramp_bearing_deg"])
