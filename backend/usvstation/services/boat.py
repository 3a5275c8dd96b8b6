"""The boat service: missions and commands on top of the link (services/boat_link.py), with
the mission state machine in services/missions.py, runs in services/runs.py and the
embedded simulated boat's lifetime in services/simboat.py (started by station.py).

Safety rules kept here (the boat keeps its own, protocol/README.md):
- one upload at a time; every mission state is derived from the boat's USV_MISSION_STATE;
- START names the mission and is sent with its id and CRC-32 only when the boat reports
  holding exactly that mission, READY;
- every command needs an authenticated operator (api/) and ends with the boat's answer,
  LinkUnavailable (link down) or NoAnswer (no answer after the bounded retries);
- the station never commands the boat on its own: not on errors, not on shutdown (the
  boat's link-loss failsafe takes over).
"""

from __future__ import annotations

import asyncio
import random
import uuid
from collections.abc import Awaitable, Callable, Coroutine

from usvstation.clock import REAL_CLOCK, Clock
from usvstation.config import Settings, resolve_link_key
from usvstation.geo import RampFrame
from usvstation.link import wire
from usvstation.link.mission import Mission, MissionError, MissionItem, mission_from_plan
from usvstation.link.protocol import (
    BoatRebooted,
    BoatReport,
    LinkEvent,
    RampPoseSample,
    UploadProgress,
)
from usvstation.link.station import BoatLink, LinkError, LinkHost, SameLoop
from usvstation.link.transport import ByteStream
from usvstation.records import (
    BoatSnapshot,
    CommandAnswer,
    DuplicateBoat,
    ItemDifference,
    MissionRow,
    MissionView,
    Readback,
)
from usvstation.scenario import Scenario
from usvstation.services.boat_link import LinkHandler, make_link
from usvstation.services.errors import (
    BoatRefused,
    Conflict,
    LinkUnavailable,
    MissionMismatch,
    NoAnswer,
    NotFound,
)
from usvstation.services.hub import LiveHub
from usvstation.services.missions import MissionRecord, MissionStatus
from usvstation.services.plans import PlanService
from usvstation.services.runs import Runs
from usvstation.store.db import Store, utc_now

PROGRESS_EVERY_S = 0.1  # at most this often per upload on the websocket
SWAPPABLE = ("RUNNING", "GO_AROUND")  # boat states an upload is a hot swap in (GO_AROUND:
# the boat takes it at its standby point as its new approach, protocol/README.md)
StreamFactory = Callable[[], Awaitable[ByteStream]]


class BoatService:
    """Missions, commands and runs; the link and the simulated boat are its parts."""

    def __init__(self, settings: Settings, store: Store, hub: LiveHub, plans: PlanService, *,
                 stream_factory: StreamFactory | None = None, clock: Clock = REAL_CLOCK,
                 entropy: random.Random | None = None, host: LinkHost | None = None,
                 link: BoatLink | None = None) -> None:
        self.settings, self.store, self.hub, self.plans = settings, store, hub, plans
        self.clock = clock
        # where the link runs (link/station.py): this loop by default; station.py gives
        # `serve` a LinkThread. `link`: one already opened there (serve opens it first)
        self.host: LinkHost = host or SameLoop()
        self._opened = link
        self.listeners: list[Callable[[LinkEvent], None]] = []  # every link event, here
        self.on_duplicate: Callable[[DuplicateBoat], None] | None = None
        # mission wire ids and the link's session: unpredictable (SystemRandom), or seeded
        # for a station in simulated time, whose runs are then the same every time
        self.entropy = entropy or random.SystemRandom()
        self.key = resolve_link_key(settings)
        self._stream_factory = stream_factory  # tests: an injected link
        self.simulated = False  # the embedded simulated boat is on the far end
        self.device = settings.link
        self.handler: LinkHandler | None = None
        self.missions: dict[str, MissionRecord] = {}
        self.uploading: MissionRecord | None = None
        self._last_progress: dict[str, float] = {}
        self._tasks: set[asyncio.Task] = set()
        self.runs = Runs(store, hub, plans)

    # --- lifecycle -------------------------------------------------------------------------
    async def start(self, scenario: Scenario, device: str | None = None,
                    simulated: bool = False,
                    stream_factory: StreamFactory | None = None) -> None:
        """Open the link on `device` (default: --link; or the streams `stream_factory` makes)
        and recover the missions; with `simulated` the far end is the embedded simulated
        boat (station.py starts it)."""
        rows = await asyncio.to_thread(recover_missions, self.store)
        self.missions = {k: MissionRecord.from_row(v) for k, v in rows.items()}
        await asyncio.to_thread(self.store.close_stale_runs)
        for rec in self.missions.values():
            if rec.state == MissionStatus.ACTIVE:
                rec.run = None  # its run closed as interrupted; the boat's report reopens one
        self.device, self.simulated = device or self.device, simulated
        await self.host.start()
        link = self._opened
        if link is None:
            link = make_link(self.settings, self.key, self.device,
                             stream_factory=stream_factory or self._stream_factory,
                             clock=self.clock, session=self.entropy.randrange(1, 1 << 24))
        handler = LinkHandler(link, self.device, self.store, self.hub,
                              self._on_report, self._on_reboot, host=self.host)
        handler.listeners = self.listeners
        handler.on_duplicate = self._on_duplicate
        self.handler = self.runs.handler = handler
        if scenario.origin is not None:
            o = scenario.origin
            handler.frame = RampFrame(o.lat, o.lon, o.ramp_bearing_deg)
        if self._opened is None:
            await self.host.call(link.start)

    async def stop(self) -> None:
        """Close the link (and let its loop go); sends the boat nothing."""
        for task in list(self._tasks):
            task.cancel()
        if self.handler is not None:
            await self.host.call(self.handler.link.close)
        await self.host.stop()

    def set_ramp_pose(self, sample: RampPoseSample | None) -> None:
        """The moving ramp's pose for the link to stream (from the station's loop)."""
        if self.handler is not None:
            self.host.post(self.handler.link.protocol.set_ramp_pose, sample)

    def _on_duplicate(self, found: DuplicateBoat) -> None:
        if self.on_duplicate is not None:
            self.on_duplicate(found)

    @property
    def link(self) -> BoatLink | None:
        return self.handler.link if self.handler else None

    @property
    def link_up(self) -> bool:
        return self.handler is not None and self.handler.link_up

    def _require_link(self) -> BoatLink:
        if self.handler is None or not self.handler.link_up:
            raise LinkUnavailable("the boat link is down")
        return self.handler.link

    # --- state for the API -----------------------------------------------------------------
    def snapshot(self) -> BoatSnapshot:
        snap: BoatSnapshot = self.handler.snapshot() if self.handler else {
            "link": {"up": False, "device": self.device}, "boat": None, "telemetry": None,
            "status": []}
        snap["link"]["simulated"] = self.simulated
        active = self._active_record()
        snap["run"] = self.handler.run if self.handler else None
        snap["mission"] = active.public() if active else None
        return snap

    def _active_record(self) -> MissionRecord | None:
        return next((r for r in reversed(self.missions.values())
                     if r.state in (MissionStatus.ACTIVE, MissionStatus.VERIFIED)), None)

    def get_mission(self, mission_id: str) -> MissionView | None:
        rec = self.missions.get(mission_id)
        return rec.public() if rec else None

    # --- missions ---------------------------------------------------------------------------
    async def create_mission(self, plan_id: str,
                             swap_at_ms: int | None = None) -> MissionView:
        """Upload a plan: staged for START, or (boat RUNNING, or GO_AROUND: the new approach
        it takes at its standby point) hot-swapped at `swap_at_ms` of boat uptime, by
        default the earliest instant the upload surely makes."""
        job = self.plans.get(plan_id)
        if job is None:
            raise NotFound(f"no plan {plan_id!r}")
        if job["status"] != "done":
            raise Conflict(f"plan {plan_id} is {job['status']}, not done")
        origin = job["scenario"].get("origin")
        if origin is None:
            raise Conflict(f"plan {plan_id}: its scenario has no origin, so its waypoints "
                                 "cannot be placed on the map")
        if self.uploading is not None:
            raise Conflict(f"mission {self.uploading.id} is uploading: one upload at a "
                                 "time")
        link = self._require_link()
        report = link.report
        if report is not None and report.state in ("HOLD", "FAILSAFE"):
            raise Conflict(f"the boat is {report.state}: RESUME or ABORT first")
        running = report is not None and report.state in SWAPPABLE
        if not running:
            swap_at_ms = 0
        elif swap_at_ms is None:
            swap_at_ms = self._swap_instant(link)
        frame = RampFrame(origin["lat"], origin["lon"], origin["ramp_bearing_deg"])
        wire_id = self.entropy.getrandbits(32) or 1
        try:
            mission = mission_from_plan(job["plan"]["waypoints"], frame, wire_id)
        except MissionError as exc:
            raise Conflict(f"plan {plan_id} cannot be sent: {exc}") from None
        rec = MissionRecord(uuid.uuid4().hex[:12], plan_id, wire_id, utc_now(self.clock), origin,
                            [it.as_dict() for it in mission.items])
        self.missions[rec.id] = rec
        self.uploading = rec
        await self._save(rec)
        self._spawn(self._upload(rec, mission, swap_at_ms))
        return rec.public()

    async def swap_mission(self, plan_id: str, swap_at_ms: int) -> MissionView:
        """Hot swap (usv-link 2): the RUNNING boat (or one at its go-around's standby point)
        replaces its mission by `plan_id`'s at `swap_at_ms` of its uptime, where the plan's
        t = 0 lies. Returns once the boat verified and scheduled it; 409 when it did not
        (the old mission runs on)."""
        report = self._require_link().report
        if report is None or report.state not in SWAPPABLE:
            state = report.state if report is not None else "not reporting"
            raise Conflict(f"a hot swap needs a RUNNING boat; it is {state}")
        rec = self.missions[(await self.create_mission(plan_id, swap_at_ms))["id"]]
        while self.uploading is rec:
            await self.clock.sleep(0.02)
        if rec.state in (MissionStatus.FAILED, MissionStatus.GONE):
            raise Conflict(f"hot swap of plan {plan_id} failed: {rec.error or rec.state}")
        return rec.public()

    def _swap_instant(self, link: BoatLink) -> int:
        """Boat uptime for a hot swap: after the upload's airtime at this baud, thrice,
        and at least 5 s from now (TIMESYNC-aligned)."""
        up = link.boat_uptime_ms()
        if up is None:
            raise LinkUnavailable("the boat's clock is not known yet (no TIMESYNC)")
        return up + 5000 + int(3 * 256 * 100 * 10 * 1000 / self.settings.baud)

    async def _upload(self, rec: MissionRecord, mission: Mission, swap_at_ms: int) -> None:
        link = self.link
        assert link is not None

        def progress(ev: UploadProgress) -> None:
            rec.sent, rec.acked = ev.sent, ev.acked
            now = self.clock.now()
            if now - self._last_progress.get(rec.id, 0.0) >= PROGRESS_EVERY_S \
                    or ev.acked == ev.count:
                self._last_progress[rec.id] = now
                self.hub.publish("mission", rec.public())

        on_progress = self.host.to_owner(progress)  # called on the link's loop
        try:
            result = await self.host.call(lambda: link.upload_mission(
                mission, progress_cb=on_progress, swap_at_ms=swap_at_ms))
        except LinkError as exc:
            ok, reason = False, str(exc)
        else:
            ok, reason = result.ok, result.reason
            if ok:
                rec.sent = rec.acked = result.count
        finally:
            self.uploading = None
        if not ok:
            rec.state, rec.error = MissionStatus.FAILED, reason
        report = link.report
        if report is not None:
            rec.apply(report)  # the boat's word wins (a lost END ACK, a swap)
        await self._save(rec)

    async def verify(self, mission_id: str) -> Readback:
        """Read the boat's copy back and compare it item by item with what was sent."""
        rec = self.missions.get(mission_id)
        if rec is None:
            raise NotFound(f"no mission {mission_id!r}")
        link = self._require_link()
        try:
            result = await self.host.call(lambda: link.read_mission(rec.wire_id, rec.total))
        except LinkError as exc:
            raise Conflict(str(exc)) from None
        if result.items is None:
            if "refused" in result.error:
                raise Conflict(f"mission {mission_id}: {result.error}")
            raise NoAnswer(f"mission {mission_id}: {result.error}")
        sent = [MissionItem(**it) for it in rec.items]
        diffs: list[ItemDifference] = [{"seq": i, "sent": a.as_dict(), "boat": b.as_dict()}
                 for i, (a, b) in enumerate(zip(sent, result.items, strict=True)) if a != b]
        return {"id": rec.id, "wire_id": rec.wire_id, "count": rec.total,
                "identical": not diffs, "differences": diffs}

    # --- commands ---------------------------------------------------------------------------
    async def command(self, name: str, mission_id: str | None = None) -> CommandAnswer:
        link = self._require_link()
        wire_id = crc = 0
        rec: MissionRecord | None = None
        if name == "start":
            if mission_id is None:
                if not any(r.state == MissionStatus.VERIFIED for r in self.missions.values()):
                    raise Conflict("no verified mission to start: upload a plan first")
                raise Conflict("START names its mission: send mission_id")
            rec = self.missions.get(mission_id)
            if rec is None:
                raise NotFound(f"no mission {mission_id!r}")
            report = link.report
            if report is None or report.active_id == 0:
                raise MissionMismatch("the boat holds no mission: upload one first")
            if (report.active_id, report.active_crc32) != (rec.wire_id, rec.crc):
                raise MissionMismatch(f"the boat holds another mission (wire id "
                                     f"{report.active_id}), not {mission_id}")
            wire_id, crc = rec.wire_id, rec.crc or 0
        try:
            outcome = await self.host.call(lambda: link.command(name, wire_id, crc))
        except LinkError as exc:
            raise LinkUnavailable(str(exc)) from None
        if outcome.result is None:
            raise NoAnswer(f"the boat did not acknowledge {name.upper()}: {outcome.error}")
        acked_at = link.protocol.now
        for _ in range(50):  # the boat reports its new state right after the ACK
            if link.protocol.report_at >= acked_at:
                break
            await self.clock.sleep(0.01)
        report = link.report
        answer: CommandAnswer = {"command": name, "result": _result_name(outcome.result),
                  "reason": outcome.reason or None,
                  "state": report.state if report is not None else None,
                  "mission": rec.id if rec else None}
        if not outcome.accepted:
            raise BoatRefused(f"the boat refused {name.upper()}: "
                                 f"{outcome.reason or answer['result']}")
        return answer

    # --- reports ----------------------------------------------------------------------------
    def _on_report(self, ev: BoatReport) -> None:
        """Every USV_MISSION_STATE: derive each mission's state; open/close runs. Not while
        two boats answer as the paired id (their reports cannot be told apart: the missions
        keep their states, the alert and /api/boat say why)."""
        if self.handler is not None and self.handler.duplicates.detected_at is not None:
            return
        for rec in self.missions.values():
            if rec is self.uploading:
                continue  # decided when its upload ends, then by the reports
            before = rec.state
            if rec.apply(ev.report):
                self._spawn(self._save(rec))
                if rec.state == MissionStatus.ACTIVE:
                    self._spawn(self._begin_run(rec))
                elif before == MissionStatus.ACTIVE:
                    self._spawn(self._end_run(rec))
            elif rec.state == MissionStatus.ACTIVE and rec.run is None:
                self._spawn(self._begin_run(rec))  # after a station restart mid-run

    def _on_reboot(self, ev: BoatRebooted) -> None:
        self.hub.publish("link", {"up": True, "rebooted": True, "boot_id": ev.new_boot_id})

    async def _begin_run(self, rec: MissionRecord) -> None:
        await self.runs.begin(rec)
        await self._save(rec)

    async def _end_run(self, rec: MissionRecord) -> None:
        await self.runs.end(rec)

    def _spawn(self, coro: Coroutine[object, object, object]) -> None:
        task = asyncio.get_running_loop().create_task(coro)
        self._tasks.add(task)
        task.add_done_callback(self._tasks.discard)

    async def _save(self, rec: MissionRecord) -> None:
        await asyncio.to_thread(self.store.save_mission, rec.to_row())
        self.hub.publish("mission", rec.public())


def recover_missions(store: Store) -> dict[str, MissionRow]:
    """Missions from the database after a restart. An upload the restart interrupted is
    failed (the boat's next report revives it if the boat took it whole); every other
    state is kept until the boat's first report derives it again."""
    missions = {}
    for mission in store.missions():
        if mission["state"] == "uploading":
            mission.update(state="failed", error="the station restarted during the upload")
            store.save_mission(mission)
        missions[mission["id"]] = mission
    return missions


def _result_name(result: int) -> str:
    entry = wire.mav.enums["MAV_RESULT"].get(result)
    return entry.name.removeprefix("MAV_RESULT_") if entry else str(result)
