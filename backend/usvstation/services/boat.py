"""The boat: link, embedded simulated boat, telemetry ingest, missions, commands, runs.

Safety rules kept here (the boat keeps its own, protocol/README.md):
- a mission is uploaded only while the link is up and no mission is running;
  START is sent only for the mission the boat verified (its MISSION_END ACK);
- every command needs an authenticated operator (api/) and the boat's ACK;
- the station never commands the boat on its own: not on errors, not on
  shutdown (the boat's link-loss failsafe takes over).
"""

from __future__ import annotations

import asyncio
import contextlib
import threading
import time
import uuid
from dataclasses import dataclass
from typing import Any

from usvstation.config import Settings
from usvstation.geo import RampFrame
from usvstation.link import messages as m
from usvstation.link.mission import MissionError, mission_from_plan
from usvstation.link.protocol import (
    BoatHeartbeat,
    DefinitionMismatch,
    LinkDown,
    LinkUp,
    StatusTextReceived,
    TelemetryReceived,
    UploadProgress,
)
from usvstation.link.station import BoatLink, LinkError
from usvstation.link.transport import PtyPair, open_stream
from usvstation.scenario import Scenario
from usvstation.services.hub import LiveHub
from usvstation.services.plans import PlanService
from usvstation.store.db import Store, utc_now
from usvstation.viz.view import ThreeDView

MISSION_STATES = ("uploading", "verified", "active", "completed", "failed", "aborted")
STATUS_KEPT = 50
PROGRESS_EVERY_S = 0.1  # at most this often per upload on the websocket


class BoatError(Exception):
    """A request the boat service refuses; `status` is the HTTP status to answer."""

    def __init__(self, status: int, message: str) -> None:
        super().__init__(message)
        self.status = status


@dataclass
class EmbeddedSim:
    """The simulated boat on the far end of a pty, in a thread with its own event loop."""

    scenario: Scenario
    settings: Settings

    def __post_init__(self) -> None:
        self.pair = PtyPair()
        self.device = self.pair.slave_path
        self._loop: asyncio.AbstractEventLoop | None = None
        self._stop: asyncio.Event | None = None
        self._ready = threading.Event()
        self._thread = threading.Thread(target=self._run, name="simulated-boat", daemon=True)

    def start(self) -> None:
        self._thread.start()
        self._ready.wait(10)

    def stop(self) -> None:
        if self._loop is not None and self._stop is not None:
            with contextlib.suppress(RuntimeError):
                self._loop.call_soon_threadsafe(self._stop.set)
        self._thread.join(3)
        self.pair.close()

    def _run(self) -> None:
        asyncio.run(self._main())

    async def _main(self) -> None:
        from usvstation.sim.boat import BoatConfig
        from usvstation.sim.runner import SimulatedBoat, make_boat, make_vehicle

        self._loop, self._stop = asyncio.get_running_loop(), asyncio.Event()
        o = self.scenario.origin
        frame = RampFrame(o.lat, o.lon, o.ramp_bearing_deg)
        s = self.settings
        config = BoatConfig(telemetry_hz=s.telemetry_hz, failsafe_timeout_s=s.heartbeat_timeout_s,
                            sim_speed=s.sim_speed)
        boat = make_boat(frame, config=config, vehicle=make_vehicle("dynamic", self.scenario))
        self._ready.set()
        await SimulatedBoat(boat).run(self.pair.master_stream(), self._stop)


class BoatService:
    """Owns the BoatLink; turns its events into stored telemetry, missions and live events."""

    def __init__(self, settings: Settings, store: Store, hub: LiveHub, plans: PlanService,
                 view: ThreeDView | None = None) -> None:
        self.settings, self.store, self.hub, self.plans = settings, store, hub, plans
        self.view = view
        self._run_t0: float | None = None  # boat time of the run's first telemetry
        self.link: BoatLink | None = None
        self.sim: EmbeddedSim | None = None
        self.device = settings.link
        self.missions: dict[str, dict[str, Any]] = {}
        self.frame: RampFrame | None = None  # ramp frame for x, y of telemetry
        self.run: int | None = None
        self.active: dict[str, Any] | None = None  # mission running on the boat
        self.telemetry: dict[str, Any] | None = None
        self.telemetry_at: float | None = None
        self.heartbeat: m.Heartbeat | None = None
        self.heartbeat_at: float | None = None
        self.status: list[dict[str, Any]] = []
        self.frames = 0
        self._last_progress: dict[str, float] = {}
        self._tasks: set[asyncio.Task] = set()

    # --- lifecycle -------------------------------------------------------------------------
    async def start(self, scenario: Scenario) -> None:
        self.missions = await asyncio.to_thread(recover_missions, self.store)
        await asyncio.to_thread(self.store.close_stale_runs)
        if scenario.origin is not None:
            o = scenario.origin
            self.frame = RampFrame(o.lat, o.lon, o.ramp_bearing_deg)
        if self.settings.link == "sim":
            if scenario.origin is None:
                raise ValueError("the simulated boat needs a working scenario with an origin")
            self.sim = EmbeddedSim(scenario, self.settings)
            self.sim.start()
            self.device = self.sim.device
        device, baud = self.device, self.settings.baud
        self.link = BoatLink(device, baud=baud, stream_factory=lambda: open_stream(device, baud))
        self.link.add_listener(self._on_event)
        await self.link.start()

    async def stop(self) -> None:
        """Close the link and the simulated boat; sends the boat nothing."""
        for task in self._tasks:
            task.cancel()
        if self.link is not None:
            await self.link.close()
        if self.sim is not None:
            await asyncio.to_thread(self.sim.stop)

    # --- state for the API -----------------------------------------------------------------
    @property
    def link_up(self) -> bool:
        return self.link is not None and self.link.link_up

    def snapshot(self) -> dict[str, Any]:
        now = time.monotonic()
        hb = self.heartbeat
        return {
            "link": {
                "up": self.link_up, "device": self.device, "simulated": self.sim is not None,
                "heartbeat_age_s": None if self.heartbeat_at is None
                else round(now - self.heartbeat_at, 3),
                "telemetry_age_s": None if self.telemetry_at is None
                else round(now - self.telemetry_at, 3),
                "frames": self.frames,
                **self._decoder_counts(),
                "error": (self.link.last_error or None) if self.link else None,
            },
            "boat": None if hb is None else {
                "mode": _name(m.Mode, hb.mode), "state": _name(m.State, hb.state),
                "flags": [f.name for f in m.Flag if hb.flags & f], "mission_id": hb.mission_id,
            },
            "telemetry": self.telemetry,
            "run": self.run,
            "mission": _public(self.active) if self.active else None,
            "status": self.status[-10:],
        }

    def _decoder_counts(self) -> dict[str, int | None]:
        """Frames lost (sequence gaps) and refused (bad CRC, length, ...) by the decoder."""
        if self.link is None:
            return {"frames_lost": None, "frames_bad": None}
        stats = self.link.protocol.decoder.stats
        return {"frames_lost": stats.lost, "frames_bad": stats.errors}

    def get_mission(self, mission_id: str) -> dict[str, Any] | None:
        mission = self.missions.get(mission_id)
        return _public(mission) if mission else None

    # --- missions ---------------------------------------------------------------------------
    async def create_mission(self, plan_id: str) -> dict[str, Any]:
        job = self.plans.get(plan_id)
        if job is None:
            raise BoatError(404, f"no plan {plan_id!r}")
        if job["status"] != "done":
            raise BoatError(409, f"plan {plan_id} is {job['status']}, not done")
        origin = job["scenario"].get("origin")
        if origin is None:
            raise BoatError(409, f"plan {plan_id}: its scenario has no origin, so its waypoints "
                                 "cannot be placed on the map")
        if self.active is not None:
            raise BoatError(409, f"mission {self.active['id']} is {self.active['state']} on the "
                                 "boat: abort it or let it complete first")
        if any(x["state"] == "uploading" for x in self.missions.values()):
            raise BoatError(409, "another mission is uploading")
        if not self.link_up:
            raise BoatError(503, "the boat link is down")
        frame = RampFrame(origin["lat"], origin["lon"], origin["ramp_bearing_deg"])
        wire_id = await asyncio.to_thread(self._next_wire_id)
        try:
            mission = mission_from_plan(job["plan"]["waypoints"], frame, wire_id)
        except MissionError as exc:
            raise BoatError(409, f"plan {plan_id} cannot be sent: {exc}") from None
        record = {
            "id": uuid.uuid4().hex[:12], "plan_id": plan_id, "wire_id": wire_id,
            "created_at": utc_now(), "state": "uploading",
            "progress": {"sent": 0, "acked": 0, "total": mission.count}, "error": None,
            "items": [i._asdict() for i in mission.items], "origin": origin,
        }
        self.missions[record["id"]] = record
        await self._save(record)
        task = asyncio.create_task(self._upload(record, mission))
        self._tasks.add(task)
        task.add_done_callback(self._tasks.discard)
        return _public(record)

    async def _upload(self, record: dict[str, Any], mission: Any) -> None:
        assert self.link is not None

        def progress(ev: UploadProgress) -> None:
            record["progress"].update(sent=ev.sent, acked=ev.acked, total=ev.count)
            now = time.monotonic()
            if now - self._last_progress.get(record["id"], 0.0) >= PROGRESS_EVERY_S \
                    or ev.acked == ev.count:
                self._last_progress[record["id"]] = now
                self.hub.publish("mission", _public(record))

        try:
            result = await self.link.upload_mission(mission, progress_cb=progress)
        except LinkError as exc:
            record.update(state="failed", error=str(exc))
        else:
            if result.ok:
                record["state"] = "verified"
                record["progress"].update(sent=result.count, acked=result.count)
                self._supersede(record)
            else:
                record.update(state="failed", error=result.reason)
        await self._save(record)

    def _supersede(self, record: dict[str, Any]) -> None:
        """Only the newest verified mission is on the boat; older verified ones are replaced."""
        for other in self.missions.values():
            if other is not record and other["state"] == "verified":
                other.update(state="failed",
                             error=f"replaced on the boat by mission {record['id']}")
                task = asyncio.create_task(self._save(other))
                self._tasks.add(task)
                task.add_done_callback(self._tasks.discard)

    def _next_wire_id(self) -> int:
        n = int(self.store.get_setting("next_wire_id") or 1)
        self.store.set_setting("next_wire_id", n % 65535 + 1)
        return n

    # --- commands ---------------------------------------------------------------------------
    async def command(self, name: str) -> dict[str, Any]:
        verified = [x for x in self.missions.values() if x["state"] == "verified"]
        mission = self.active
        if name == "start":
            if not verified:
                raise BoatError(409, "no verified mission to start: upload a plan first")
            mission = verified[-1]
        if not self.link_up or self.link is None:
            raise BoatError(503, "the boat link is down")
        wire_id = mission["wire_id"] if mission else 0
        try:
            outcome = await self.link.command(name, mission_id=wire_id)
        except LinkError as exc:
            raise BoatError(503, str(exc)) from None
        if outcome.result is None:
            raise BoatError(504, f"the boat did not acknowledge {name.upper()}: {outcome.error}")
        answer = {"command": name, "result": outcome.result.name,
                  "state": _name(m.State, outcome.state) if outcome.state is not None else None,
                  "mission": mission["id"] if mission else None}
        if outcome.result != m.CommandResult.ACCEPTED:
            raise BoatError(409, f"the boat refused {name.upper()}: {outcome.result.name}")
        if name == "start" and mission is not None:
            await self._begin_run(mission)
            # the ACK reports the boat's state: RUNNING there counts as seen running
            if outcome.state in (m.State.RUNNING, m.State.HOLD):
                mission["seen_running"] = True
        elif name == "abort" and self.active is not None:
            await self._end_run("aborted")
        return answer

    async def _begin_run(self, mission: dict[str, Any]) -> None:
        if self.active is not None and self.active is not mission:
            await self._end_run("aborted")
        self.run = await asyncio.to_thread(self.store.open_run, mission["id"], mission["plan_id"])
        origin = mission["origin"]
        self.frame = RampFrame(origin["lat"], origin["lon"], origin["ramp_bearing_deg"])
        mission.update(state="active", run=self.run, seen_running=False)
        self.active = mission
        self._run_t0 = None
        job = self.plans.get(mission["plan_id"])
        if self.view is not None and job and job.get("plan"):
            self.view.show_plan(job["plan"])
            self.view.clear_track()
        await self._save(mission)
        self.hub.publish("run", {"id": self.run, "mission": mission["id"], "state": "active"})

    async def _end_run(self, state: str) -> None:
        """Close the run; its telemetry is committed before anyone hears it ended."""
        mission, run = self.active, self.run
        self.active, self.run = None, None
        await asyncio.to_thread(self.store.writer.flush)
        if mission is not None:
            mission["state"] = state
            await self._save(mission)
        if run is not None:
            await asyncio.to_thread(self.store.close_run, run, state)
            self.hub.publish("run", {"id": run, "mission": mission and mission["id"],
                                     "state": state})

    # --- link events ---------------------------------------------------------------------------
    def _on_event(self, ev: Any) -> None:
        if isinstance(ev, TelemetryReceived):
            self._ingest(ev.telemetry)
        elif isinstance(ev, BoatHeartbeat | LinkUp):
            self.heartbeat, self.heartbeat_at = ev.heartbeat, time.monotonic()
            self._check_finished(ev.heartbeat.state, ev.heartbeat.mission_id)
            if isinstance(ev, LinkUp):
                self.hub.publish("link", {"up": True, "device": self.device})
        elif isinstance(ev, LinkDown):
            self.hub.publish("link", {"up": False, "reason": ev.reason})
        elif isinstance(ev, DefinitionMismatch):
            self.hub.publish("link", {"up": False, "reason": ev.message})
        elif isinstance(ev, StatusTextReceived):
            item = {"time": utc_now(), "severity": _name(m.Severity, ev.severity),
                    "text": ev.text}
            self.status = [*self.status[-(STATUS_KEPT - 1):], item]
            self.hub.publish("status", item)

    def _ingest(self, t: m.Telemetry) -> None:
        self.frames += 1
        row = telemetry_row(t, self.frame, self.run)
        self.store.writer.put(row)
        self.telemetry, self.telemetry_at = row, time.monotonic()
        self.hub.publish("telemetry", row)
        if self.view is not None and self.run is not None and row["x"] is not None:
            if self._run_t0 is None:
                self._run_t0 = row["boat_time"]
            self.view.add_track_point(row["x"], row["y"], row["boat_time"] - self._run_t0)
        self._check_finished(t.state, None)

    def _check_finished(self, state: int, wire_id: int | None) -> None:
        """End the run when the boat reports DONE or ABORTED for the running mission.

        Telemetry frames sent before the boat took the START still carry the
        previous state, so there DONE counts only after RUNNING or HOLD has been
        seen (in a frame or in START's ACK); a HEARTBEAT names the mission, so
        DONE for the running mission's id counts at once.
        """
        mission = self.active
        if mission is None or (wire_id is not None and wire_id != mission["wire_id"]):
            return
        if state in (m.State.RUNNING, m.State.HOLD):
            mission["seen_running"] = True
        elif state in (m.State.DONE, m.State.ABORTED) and (mission.get("seen_running")
                                                            or wire_id is not None):
            mission["seen_running"] = False
            final = "completed" if state == m.State.DONE else "aborted"
            task = asyncio.create_task(self._end_run(final))
            self._tasks.add(task)
            task.add_done_callback(self._tasks.discard)

    async def _save(self, record: dict[str, Any]) -> None:
        await asyncio.to_thread(self.store.save_mission, record)
        self.hub.publish("mission", _public(record))


def recover_missions(store: Store) -> dict[str, dict[str, Any]]:
    """Missions from the database; those a restart interrupted are closed with the reason."""
    missions = {}
    for mission in store.missions():
        if mission["state"] == "uploading":
            mission.update(state="failed", error="the station restarted during the upload")
            store.save_mission(mission)
        elif mission["state"] == "active":
            mission.update(state="aborted", error=(
                "the station restarted while this mission ran; the boat keeps its own "
                "state (see /api/boat) and holds station if the link was lost"))
            store.save_mission(mission)
        missions[mission["id"]] = mission
    return missions


def telemetry_row(t: m.Telemetry, frame: RampFrame | None, run: int | None) -> dict[str, Any]:
    """A TELEMETRY frame as a stored row: SI units, compass degrees, ramp-frame x, y."""
    lat, lon = t.lat_e7 / 1e7, t.lon_e7 / 1e7
    heading = t.heading_cdeg / 100.0
    x = y = ramp_heading = None
    if frame is not None:
        xs, ys = frame.to_ramp(lat, lon)
        x, y = round(float(xs), 3), round(float(ys), 3)
        ramp_heading = round(float(frame.compass_to_heading_deg(heading)), 2)
    return {
        "run": run, "time": utc_now(), "boat_time": t.time_ms / 1000.0, "lat": lat, "lon": lon,
        "x": x, "y": y, "heading_deg": heading, "course_deg": t.cog_cdeg / 100.0,
        "speed": t.sog_cms / 100.0, "ramp_heading_deg": ramp_heading,
        "yaw_rate_dps": t.yaw_rate_cdegs / 100.0, "fix_type": t.fix_type,
        "satellites": t.satellites, "hdop": t.hdop_c / 100.0,
        "thrust_left": t.thrust_left_pm / 1000.0, "thrust_right": t.thrust_right_pm / 1000.0,
        "battery_v": t.battery_mv / 1000.0, "waypoint_index": t.wp_index,
        "cross_track_m": t.xte_cm / 100.0, "mode": _name(m.State, t.state),
    }


def _name(enum: Any, value: int) -> str:
    try:
        return enum(value).name
    except ValueError:
        return str(value)


def _public(mission: dict[str, Any]) -> dict[str, Any]:
    return {k: mission.get(k) for k in ("id", "plan_id", "state", "progress", "error",
                                        "created_at", "wire_id", "run")}
