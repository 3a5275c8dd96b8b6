"""The live loop's edges: the plan monitor on every telemetry frame, alerts, re-planning.

`MonitorService` observes the live hub: a `run` event (state active) arms it with the
running plan, each `telemetry` frame of that run is assessed by world/monitor.py against
the world's targets. Each alert condition (kind, target) of a run is one alert record,
changed in place as its level changes and ended when the condition clears or the run ends
(a swapped re-plan keeps the run's alerts); it is stored (store/alerts.py) and published
as {"type": "alert", "data": record} at each change. The own ship's fix (stale, jumping)
is watched at every world tick, in a run or not, and the link's alerts (services/alerts.py)
end when the link is back; alerts a previous station process left active end at start-up.
A per-target table goes out as {"type": "monitor", ...} at most twice a second. Warnings go to
`ReplanService` (announced warnings and alarms only: at most one re-plan per cause in
`REPEAT_S`), which applies the `--replan` policy (world/replan.py): it plans the new
problem with the station's planner and, by policy, proposes it to the operator or swaps
it onto the boat. The swap itself is usv-link 2's hot swap, reached through
`BoatService.swap_mission(plan_id)`; without it a re-plan stops at "planned".
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
import math
import uuid
from collections.abc import Coroutine
from typing import cast

import numpy as np

from usvstation.clock import REAL_CLOCK, Clock
from usvstation.geometry import MS
from usvstation.planning.model import Plan
from usvstation.records import (
    Alert,
    MonitorAssessment,
    PlanJob,
    Replan,
    RunEvent,
    TelemetryRow,
)
from usvstation.scenario import Scenario, parse_scenario
from usvstation.services.boat import BoatService
from usvstation.services.errors import Conflict, NotFound, StationError
from usvstation.services.hub import LiveHub, Payload
from usvstation.services.plans import PlanService
from usvstation.services.world import WorldService
from usvstation.store.alerts import AlertStore
from usvstation.store.db import utc_now
from usvstation.world.model import RampPose, World, compass_to_enu
from usvstation.world.monitor import (
    REPEAT_S,
    STATIC_SPEED,
    AlertEvent,
    AlertTracker,
    Assessment,
    BoatState,
    MonitorConfig,
    TargetState,
    assess,
)
from usvstation.world.replan import (
    Policy,
    ReplanImpossible,
    ReplanState,
    decide,
    replan_scenario,
)

log = logging.getLogger(__name__)
MONITOR_EVERY_S = 0.5
MATCH_M = 2.0  # a plan's obstacle this close to a live target is that target
ASSESS_MIN_INTERVAL_S = 0.1  # every frame up to 10 Hz (telemetry runs at 5 Hz of boat time)
DEFAULT_TIME_MARGIN_S = 5.0
MIN_WARNING_M = 0.3  # the clearance warning threshold when R_c is smaller
OWN_SHIP_AGE_S = (3.0, 5.0, 8.0)  # a silent own-ship position: advisory, caution, warning
OWN_SHIP_AGE_BAND_S = 1.0
JUMP_HOLD_S = 30.0  # an own-ship jump stays a warning this long after the fix that jumped
URGENT = ("warning", "alarm")  # levels that may start a re-plan
AlertKey = tuple[int | None, str, str | None]  # (run or None for the station's, kind, target)
# Re-plans start this far ahead (wall-clock seconds, times --sim-speed in boat time) of the
# frame they are built from, where the boat swaps onto them: planning (tens of ms), the
# hot-swap upload (about 0.1 s for 30 waypoints at 57600 baud) and its retries fit well
# inside. A proposal the operator confirms is built afresh from the latest frame, so its
# instant never passes while the operator reads it.
SWAP_LEAD_S = 2.0
# On a loaded machine planning and the upload can outlast the lead: a swap instant that
# passed (or lies less than SWAP_UPLOAD_S ahead when the plan is ready) is planned again
# from the latest frame with twice the lead, up to SWAP_ATTEMPTS plans in all.
SWAP_UPLOAD_S = 0.5
SWAP_ATTEMPTS = 3
NO_HOT_SWAP = ("the boat link has no hot swap (usv-link 2, BoatService.swap_mission): "
               "the re-plan is kept as a plan; hold, abort and upload it to use it")


class MonitorService:
    """Assesses every telemetry frame of the running mission; raises alerts."""

    def __init__(self, hub: LiveHub, alerts: AlertStore, world: WorldService,
                 boat: BoatService, plans: PlanService, policy: Policy,
                 clock: Clock = REAL_CLOCK) -> None:
        self.hub, self.alerts, self.world, self.boat, self.plans = hub, alerts, world, boat, plans
        self.clock = clock
        self.replan = ReplanService(self, policy)
        self.run: int | None = None
        # the first run of a recovery: the runs a hot swap opens continue it, and its alerts
        self.episode: int | None = None
        self.episode_runs: set[int] = set()
        self.handover = False  # the run ended replaced by a swap: the next run continues
        self.scenario: Scenario | None = None
        self.waypoints: np.ndarray | None = None
        self.t0: float | None = None  # boat time of the plan's t = 0
        self.config = MonitorConfig()
        self.tracker = AlertTracker(self.config)  # the running plan's conditions
        self.ship_tracker = AlertTracker()  # the own ship's, in a run or not
        self.records: dict[AlertKey, Alert] = {}  # every alert that may still change
        self._ended_t: dict[AlertKey, float] = {}  # when a station alert last ended
        self.last: MonitorAssessment | None = None
        self.last_assessment: Assessment | None = None
        self.last_row: TelemetryRow | None = None
        # the latest assessment with what it was made from: (assessment, targets, boat,
        # ramp-frame velocity of the ship), for a re-plan built at any moment
        self.last_inputs: tuple[Assessment, list[TargetState], BoatState,
                                tuple[float, float]] | None = None
        self.frames = 0
        self._published_at = -1e9
        self._assessed_at = -1e9
        self._tasks: set[asyncio.Task] = set()
        hub.observers.append(self.on_event)
        world.tick_listeners.append(self.on_world_tick)
        # a previous station process ended without ending its alerts: their conditions
        # (a link, a run) ended with it; what still holds is raised afresh
        ended = alerts.end_active(utc_now(clock))
        if ended:
            log.info("ended %d alert(s) left active by a previous station process", ended)

    async def stop(self) -> None:
        for task in list(self._tasks):
            task.cancel()
        for task in list(self._tasks):
            with contextlib.suppress(asyncio.CancelledError, Exception):
                await task

    def spawn(self, coro: Coroutine[object, object, object]) -> None:
        task = asyncio.create_task(coro)
        self._tasks.add(task)
        task.add_done_callback(self._tasks.discard)

    # --- events ------------------------------------------------------------------------------
    def on_event(self, kind: str, data: Payload) -> None:
        if kind == "telemetry":
            self.on_telemetry(cast(TelemetryRow, data))
        elif kind == "run":
            run = cast(RunEvent, data)
            if run["state"] == "active":
                self.arm(run["id"], run.get("mission"))
            elif run["id"] == self.run:
                if run["state"] == "gone" and self.swap_plans():
                    self.handover = True  # hot-swapped: the swap's run goes on with it
                else:
                    self.disarm(run["state"])

    def arm(self, run: int, mission_id: str | None) -> None:
        """A run started: monitor its plan; the scenario's obstacles start where the plan
        assumed them (their t = 0 is the plan's start)."""
        mission = self.boat.missions.get(mission_id or "")
        job = self.plans.get(mission.plan_id) if mission is not None else None
        if not job or not job["plan"]:
            return
        continues = self.episode is not None and job["id"] in self.swap_plans()
        if not continues and (self.run is not None or self.handover):
            self.disarm("replaced")
        self.handover = False
        if self.episode is None:
            self.episode = run
        self.episode_runs.add(run)
        self.use_plan(job, run)
        t = self.world.clock.now()
        pose = self.world.world.ramp(t)
        if pose is not None and self.scenario is not None:
            self.world.world.set_manual(t, self._charted(pose, t), pose.frame)

    def swap_plans(self) -> set[str]:
        """The plans re-plans of this recovery are swapping or swapped onto the boat: a run
        of one of them continues the recovery (hot swaps open a run each, and the boat may
        report the new run before or after the old one ends)."""
        return {r["plan_id"] for r in self.replan.replans.values()
                if r["plan_id"] and r["state"] in ("planning", "proposed", "applied")
                and r["run_id"] in self.episode_runs}

    def _charted(self, pose: RampPose, t: float) -> list[tuple[float, float, float, float,
                                                               float]]:
        """The plan's obstacles as the world's `manual` tracks: where the plan put them at
        its start (the ramp's pose now), their velocity over ground (the plan's is relative
        to the ramp: the ramp's own velocity added); an obstacle the plan took from a live
        track (a plan of /api/world/scenario: within MATCH_M of an AIS or radar target now)
        is that track, not a second one."""
        assert self.scenario is not None
        fvx, fvy = (float(v) for v in pose.frame.vector_to_ramp(pose.ve, pose.vn))
        live = [(g["x"], g["y"]) for g in self.world.world.targets(t) if g["source"] != "manual"]
        return [(o.x, o.y, o.radius, o.vx + fvx, o.vy + fvy) for o in self.scenario.obstacles
                if not any(math.hypot(o.x - x, o.y - y) < MATCH_M for x, y in live)]

    def use_plan(self, job: PlanJob, run: int | None) -> None:
        """Monitor `job`'s plan from the next frame on (a new run, or a swapped re-plan)."""
        self.run = run
        self.scenario = parse_scenario(job["scenario"])
        if job["plan"] is None:
            raise ValueError(f"plan {job['id']} is {job['status']}: nothing to monitor")
        plan = Plan.from_document(job["plan"])
        self.waypoints = np.array([[w.x, w.y, w.t] for w in plan.waypoints], dtype=float)
        v = self.scenario.vessel
        self.config = MonitorConfig(
            clearance_margin_m=v.length / 2.0 + v.compensation_radius,
            clearance_warning_m=max(v.compensation_radius, MIN_WARNING_M),
            time_margin_s=float(getattr(v, "time_margin_s", DEFAULT_TIME_MARGIN_S)))
        self.tracker.config = self.config  # a swapped re-plan keeps the run's conditions
        self.t0 = None

    def disarm(self, state: str = "ended") -> None:
        """The run ended: its alerts end with it, and a re-plan still awaiting the operator
        is withdrawn (there is nothing left to swap it onto)."""
        for kind, target in list(self.tracker.levels):
            event = self.tracker.end(kind, target, f"run {self.run} {state}")
            if event is not None:
                self.record(event, scoped=True)
        self.replan.withdraw(self.episode_runs, f"run {self.run} {state} before the re-plan "
                             "was confirmed")
        self.records = {k: r for k, r in self.records.items() if k[0] is None}
        self.tracker = AlertTracker(self.config)
        self.run, self.waypoints, self.t0, self.episode = None, None, None, None
        self.episode_runs, self.handover = set(), False

    def on_telemetry(self, row: TelemetryRow) -> None:
        if self.waypoints is None or row.get("run") != self.run or row.get("lat") is None:
            return
        if self.t0 is None:
            if row.get("state") != "RUNNING":
                return
            self.t0 = float(row["boat_time"])
        now = self.world.clock.now()
        if now - self._assessed_at < ASSESS_MIN_INTERVAL_S:
            return  # a sped-up simulation: the event loop is not spent on every frame
        pose = self.world.world.ramp(now)
        if pose is None:
            return
        self._assessed_at = now
        frame = pose.frame
        bx, by = frame.to_ramp(row["lat"], row["lon"])
        ve, vn = compass_to_enu(float(row["speed"] or 0.0), float(row["course_deg"] or 0.0))
        rvx, rvy = frame.vector_to_ramp(ve - pose.ve, vn - pose.vn)
        fvx, fvy = frame.vector_to_ramp(pose.ve, pose.vn)
        boat = BoatState(float(bx), float(by), float(rvx), float(rvy),
                         float(row["boat_time"]) - self.t0,
                         float(frame.compass_to_heading_deg(row["heading_deg"])))
        targets = [TargetState(v["id"], v["x"], v["y"], v["rvx"], v["rvy"], v["radius"],
                               known=v["source"] == "manual", moving=v["speed"] > STATIC_SPEED)
                   for v in self.world.world.targets(now)]
        a = assess(self.waypoints, boat, targets, self.scenario.vessel.length, self.config,
                   (float(fvx), float(fvy)))
        self.frames += 1
        self.last_assessment, self.last_row = a, row
        self.last_inputs = (a, targets, boat, (float(fvx), float(fvy)))
        for event in self.tracker.update(a, now):
            record = self.record(event, scoped=True)
            if record is not None and event.level in URGENT and event.announce:
                self.replan.on_warning(record, a, targets, boat, (float(fvx), float(fvy)))
        if now - self._published_at >= MONITOR_EVERY_S:
            self._published_at = now
            self.last = self.summary(a)
            self.hub.publish("monitor", self.last)

    # --- alerts ------------------------------------------------------------------------------
    def on_world_tick(self, world: World, t: float) -> None:
        """The own ship's fix, at every world tick: stale (no fix for a while: the ramp is
        dead-reckoned) or jumping (further than its speed allows); ended without a fix."""
        own, tracker = world.own, self.ship_tracker
        events: list[AlertEvent | None]
        if own.t_fix is None:
            events = [tracker.end("own_ship_stale", None, "no own-ship source"),
                      tracker.end("own_ship_jump", None, "no own-ship source")]
        else:
            age = t - own.t_fix
            jumped = own.t_jump is not None and t - own.t_jump < JUMP_HOLD_S
            events = [
                tracker.step("own_ship_stale", None, age, OWN_SHIP_AGE_S, OWN_SHIP_AGE_BAND_S,
                             f"own ship position {age:.0f} s old: the ramp is dead-reckoned "
                             "from its last fix", t),
                tracker.step("own_ship_jump", None, 1.0 if jumped else 0.0,
                             (math.inf, math.inf, 0.5), 0.0,
                             f"own ship position jumped {own.jump_m or 0.0:.0f} m from the last "
                             f"fix, more than its speed allows ({own.jump_allowed_m or 0.0:.0f} "
                             "m): check the position source", t)]
        tracker.forget(t)
        for event in events:
            if event is not None:
                self.record(event)

    def raise_alert(self, event: AlertEvent) -> Alert | None:
        """A station alert (the link's): one record per kind, whatever the run."""
        return self.record(event)

    def record(self, event: AlertEvent, scoped: bool = False) -> Alert | None:
        """The alert record of this event's condition (`scoped`: of the running recovery, else
        of the station), made, changed or ended in place, stored and published; None for the
        end of a condition that has none. A condition that comes back reopens its record
        within the recovery, or for the station's within REPEAT_S of its end."""
        key: AlertKey = (self.episode if scoped else None, event.kind, event.target_id)
        record = self.records.get(key)
        now = utc_now(self.clock)
        if (not scoped and record is not None and not record["active"] and event.level
                and self.clock.now() - self._ended_t.get(key, -math.inf) >= REPEAT_S):
            record = None  # the station's condition back long after it ended: a new alert
        if event.level is None:
            if record is None or not record["active"]:
                return None
            record.update(active=False, ended_at=now, updated_at=now)
            self._ended_t[key] = self.clock.now()
        elif record is None:
            record = {
                "id": uuid.uuid4().hex[:12], "time": now, "level": event.level,
                "kind": event.kind, "message": event.message, "target_id": event.target_id,
                "run_id": self.run, "acknowledged": False,
                "active": True, "updated_at": now, "announced_at": now, "ended_at": None}
            self.records[key] = record
        else:
            record.update(level=event.level, message=event.message, active=True,
                          ended_at=None, updated_at=now)
            if event.announce:  # asks for attention again: to be acknowledged again
                record.update(acknowledged=False, announced_at=now)
        self._store(record)
        return record

    def _store(self, record: Alert) -> None:
        copy = cast(Alert, dict(record))
        self.spawn(asyncio.to_thread(self.alerts.save, copy))
        self.hub.publish("alert", copy)

    async def acknowledge(self, alert_id: str) -> Alert:
        """The operator acknowledged an alert (idempotent); NotFound if there is none."""
        for record in self.records.values():
            if record["id"] == alert_id:
                if not record["acknowledged"]:
                    record["acknowledged"] = True
                    await asyncio.to_thread(self.alerts.save, cast(Alert, dict(record)))
                self.hub.publish("alert", cast(Alert, dict(record)))
                return record
        stored = await asyncio.to_thread(self.alerts.acknowledge, alert_id)
        if stored is None:
            raise NotFound(f"no alert {alert_id!r}")
        self.hub.publish("alert", cast(Alert, stored))
        return cast(Alert, stored)

    def summary(self, a: Assessment) -> MonitorAssessment:
        step = max(1, len(a.path) // 60)
        return {
            "run": self.run, "plan_time_s": round(a.plan_time_s, 2), "slip_s": round(a.slip_s, 2),
            "cross_track_m": round(a.cross_track_m, 2),
            "min_clearance_m": None if a.min_clearance_m is None else round(a.min_clearance_m, 2),
            "targets": [{"id": t.id, "min_clearance_m": round(t.min_clearance_m, 2),
                         "t_min_s": round(t.t_min_s, 1), "dcpa_m": round(t.dcpa_m, 2),
                         "tcpa_s": round(t.tcpa_s, 1), "encounter": t.encounter,
                         "known": t.known, "moving": t.moving}
                        for t in a.targets],
            "path": [[round(float(x), 2), round(float(y), 2), round(float(s), 1)]
                     for x, y, s in a.path[::step]],
            "levels": {f"{k}:{t}" if t else k: lvl for (k, t), lvl in self.tracker.levels.items()},
            "margin_m": round(self.config.clearance_margin_m, 3),
        }


class ReplanService:
    """Applies the re-plan policy to warnings; keeps every re-plan with its run."""

    def __init__(self, monitor: MonitorService, policy: Policy) -> None:
        self.monitor, self.policy = monitor, policy
        self.replans: dict[str, Replan] = {}
        self.state = ReplanState()
        self._t_event: dict[str, float] = {}

    def on_warning(self, alert: Alert, a: Assessment, targets: list[TargetState],
                   boat: BoatState, frame_velocity: tuple[float, float]) -> None:
        m = self.monitor
        now = m.clock.now()
        action = decide(self.policy, alert["level"], alert["kind"], self.state, now)
        if action == "none" or m.scenario is None:
            return
        self.state = ReplanState(in_flight=True, last_t=now)
        record: Replan = {
            "id": uuid.uuid4().hex[:12], "created_at": utc_now(m.clock), "run_id": m.run,
            "alert_id": alert["id"], "plan_id": None, "policy": self.policy,
            "state": "planning", "error": None, "latency_ms": None, "mission_id": None,
            "dropped_targets": []}
        self.replans[record["id"]] = record
        self._t_event[record["id"]] = now
        scenario = self._problem(record, a, targets, boat, frame_velocity)
        if scenario is None:
            self.state = ReplanState(last_t=now)
            return
        m.spawn(self._plan(record, scenario, apply=action == "apply"))

    def _problem(self, record: Replan, a: Assessment, targets: list[TargetState],
                 boat: BoatState, frame_velocity: tuple[float, float],
                 lead_scale: float = 1.0) -> Scenario | None:
        """The re-planning problem from this assessment, starting SWAP_LEAD_S x `lead_scale`
        ahead (never more than a third of what is left of the plan); sets the record's swap
        instant, or fails the record (saved) and returns None."""
        m = self.monitor
        lead_s = min(SWAP_LEAD_S * lead_scale * max(1.0, m.world.sim_speed),
                     float(a.path[-1, 2]) / 3.0)
        boat_time = m.last_row["boat_time"] if m.last_row else 0.0
        try:
            scenario, dropped = replan_scenario(
                m.scenario, a, targets, float(np.hypot(boat.vx, boat.vy)), frame_velocity,
                lead_s=lead_s, seed=len(self.replans))
        except (ReplanImpossible, ValueError) as exc:
            record.update(state="failed", error=str(exc))
            self._save(record)
            return None
        record["dropped_targets"] = dropped
        # the new plan starts where the boat will be lead_s after this frame: swap there
        record["swap_at_ms"] = MS.to_wire(float(boat_time) + lead_s)
        self._save(record)
        return scenario

    async def _plan(self, record: Replan, scenario: Scenario, apply: bool) -> None:
        m = self.monitor
        try:
            for attempt in range(1, SWAP_ATTEMPTS + 1):
                record["attempts"] = attempt
                job = await m.plans.submit(scenario, "iga", scenario.planner.seed
                                           if scenario.planner else None)
                record["plan_id"] = job["id"]
                while job["status"] in ("queued", "running"):
                    await m.clock.sleep(0.02)
                if job["status"] != "done":
                    record.update(state="failed", error=job["error"])
                    return
                if not apply:
                    if record["run_id"] not in m.episode_runs:  # the run ended meanwhile
                        record.update(state="failed", error=f"run {record['run_id']} ended "
                                      "before the re-plan was ready")
                        return
                    record["state"] = "proposed"
                    return
                if not self._instant_passed(record):
                    await self._swap(record)
                    if record["state"] != "failed" or not self._instant_passed(record):
                        return
                record.update(state="failed", error=(
                    f"the swap instant {record['swap_at_ms']} ms passed before the boat had "
                    f"the plan ({attempt} attempt{'s' if attempt > 1 else ''})"))
                if attempt == SWAP_ATTEMPTS or m.last_inputs is None:
                    return
                # plan again from the latest frame, further ahead
                scenario = self._problem(record, *m.last_inputs, lead_scale=2.0 ** attempt)
                if scenario is None:
                    return
                record.update(state="planning", error=None)
        finally:
            self.state = ReplanState(in_flight=False,
                                     awaiting_operator=record["state"] == "proposed",
                                     last_t=self.state.last_t)
            self._save(record)

    def withdraw(self, runs: set[int], why: str) -> None:
        """Fail the proposals of these runs (their recovery ended): never left proposed."""
        for record in self.replans.values():
            if record["state"] == "proposed" and record["run_id"] in runs:
                record.update(state="failed", error=why)
                self._save(record)
        if self.state.awaiting_operator:
            self.state = ReplanState(last_t=self.state.last_t)

    def _proposed(self, replan_id: str) -> Replan:
        """The re-plan awaiting the operator; 404 or 409 otherwise."""
        record = self.replans.get(replan_id)
        if record is None:
            raise NotFound(f"no re-plan {replan_id!r}")
        if record["state"] != "proposed":
            raise Conflict(f"re-plan {replan_id} is {record['state']}, not proposed")
        return record

    async def confirm(self, replan_id: str) -> Replan:
        record = self._proposed(replan_id)
        if self.monitor.last_inputs is None or self.monitor.scenario is None:
            raise Conflict(f"re-plan {replan_id}: no running mission to re-plan")
        # the proposal was a preview: plan the same problem afresh from the latest frame,
        # so the swap instant lies ahead of the boat, and swap that plan
        self.state = ReplanState(in_flight=True, last_t=self.state.last_t)
        self._t_event[replan_id] = self.monitor.clock.now()
        record["proposed_plan_id"] = record["plan_id"]
        scenario = self._problem(record, *self.monitor.last_inputs)
        if scenario is None:
            self.state = ReplanState(last_t=self.state.last_t)
            raise Conflict(f"re-plan {replan_id}: {record['error']}")
        await self._plan(record, scenario, apply=True)
        if record["state"] != "applied":
            raise Conflict(f"re-plan {replan_id}: {record['error']}")
        return record

    async def reject(self, replan_id: str) -> Replan:
        record = self._proposed(replan_id)
        record["state"] = "rejected"
        self.state = ReplanState(last_t=self.state.last_t)
        self._save(record)
        return record

    def _instant_passed(self, record: Replan) -> bool:
        """Whether the boat's clock is within an upload's time of the swap instant."""
        link = getattr(self.monitor.boat, "link", None)
        up = link.boat_uptime_ms() if link is not None else None
        ahead_ms = MS.to_wire(SWAP_UPLOAD_S * max(1.0, self.monitor.world.sim_speed))
        return up is not None and up + ahead_ms >= record["swap_at_ms"]

    async def _swap(self, record: Replan) -> None:
        """Hot-swap the re-plan onto the boat (usv-link 2) and monitor it from then on."""
        m = self.monitor
        swap = getattr(m.boat, "swap_mission", None)
        if swap is None:
            record.update(state="planned", error=NO_HOT_SWAP)
            return
        try:
            mission = await swap(record["plan_id"], record["swap_at_ms"])
        except StationError as exc:
            record.update(state="failed", error=str(exc))
            return
        record.update(state="applied", mission_id=mission["id"], error=None,
                      latency_ms=round((m.clock.now() - self._t_event[record["id"]]) * 1000, 1))
        # the monitor follows the new plan once the boat flies it: the run its swap opens
        # (on_event "run"), not from the boat's acceptance, seconds before the swap instant

    def _save(self, record: Replan) -> None:
        m = self.monitor
        m.spawn(asyncio.to_thread(m.alerts.save_replan, record))
        m.hub.publish("replan", record)
