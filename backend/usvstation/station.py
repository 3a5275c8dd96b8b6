"""The station: one object that owns the store, the live hub, plan jobs and the boat link."""

from __future__ import annotations

import asyncio
import json
import logging
import random
from collections.abc import Callable

from usvstation.clock import REAL_CLOCK, Clock, utc_iso
from usvstation.config import ExposureError, Settings, Tokens, resolve_token
from usvstation.link.protocol import BoatReport, LinkEvent
from usvstation.link.station import LinkHost, LinkThread, PeakMeter, SameLoop
from usvstation.records import HeartbeatGap, PlanDocument, StationHealth
from usvstation.scenario import Origin, Scenario, bundled_scenario_dir, parse_scenario
from usvstation.services.alerts import LinkAlerts
from usvstation.services.boat import BoatService
from usvstation.services.boat_link import OpenedLink
from usvstation.services.hub import LiveHub
from usvstation.services.monitor import MonitorService
from usvstation.services.plans import PlanService
from usvstation.services.simboat import EmbeddedSim, InProcessSim
from usvstation.services.standard_boat import StandardBoatService
from usvstation.services.world import WorldService
from usvstation.sim.vehicle import Vehicle
from usvstation.store.alerts import AlertStore
from usvstation.store.db import Store
from usvstation.viz.feed import ThreeDFeed
from usvstation.viz.view import ThreeDView

DEFAULT_SCENARIO = "case1"
LAG_PROBE_S = 0.05  # the loop-lag monitor wakes this often
LAG_WINDOW_S = 60.0
log = logging.getLogger("usvstation")


class LoopLagMonitor:
    """How late the event loop wakes a task that sleeps LAG_PROBE_S: the worst of the last
    minute and of the whole run (a blocking call shows up as its own length)."""

    def __init__(self, clock: Clock = REAL_CLOCK) -> None:
        self.clock = clock
        self.meter = PeakMeter(LAG_WINDOW_S)
        self._task: asyncio.Task | None = None

    @property
    def worst_ever(self) -> float:
        return self.meter.worst_ever

    def start(self) -> None:
        self._task = asyncio.get_running_loop().create_task(self._run(), name="loop-lag")

    def stop(self) -> None:
        if self._task is not None:
            self._task.cancel()

    async def _run(self) -> None:
        while True:
            t0 = self.clock.now()
            await self.clock.sleep(LAG_PROBE_S)
            now = self.clock.now()
            self.record(now, max(0.0, now - t0 - LAG_PROBE_S))

    def record(self, now: float, lag: float) -> None:
        self.meter.record(now, lag)

    def worst_last_minute(self) -> float:
        return self.meter.worst_since(self.clock.now())


class Station:
    """Composition root; `start` and `stop` run inside the server's lifespan.

    Every part gets `clock` (clock.py). `in_process` is the station of simulated time (sea
    trials, in-process tests; `clock` a SimClock): plans run inline, the simulated boat
    (`--link sim`) runs on the station's loop over an in-memory pipe, the boat link too
    (one loop: one order of events), the simulated sea feeds the world directly, and the 3D
    view's server is not started. Otherwise (`serve`) the boat link runs on a thread and
    event loop of its own (link/station.py `LinkThread`), so nothing the web API does can
    delay a heartbeat; `link` is one `serve` opened there before anything else."""

    def __init__(self, settings: Settings, clock: Clock = REAL_CLOCK, *,
                 in_process: bool = False, scenario: Scenario | None = None,
                 entropy: random.Random | None = None,
                 link: OpenedLink | None = None) -> None:
        self.settings, self.clock, self.in_process = settings, clock, in_process
        # ids and sessions: unpredictable by default; seeded in simulated time (a trial)
        self.entropy = entropy or random.SystemRandom()
        self._initial_scenario = scenario  # becomes the working scenario at start
        self.token = resolve_token(settings)
        viewer = settings.viewer_token
        if viewer is not None and (not viewer or viewer == self.token):
            raise ExposureError("--viewer-token must be non-empty and differ from the operator "
                                "token")
        self.tokens = Tokens(self.token, viewer)
        self.store = Store(settings.data_dir, clock)
        self.hub = LiveHub()
        self.plans = PlanService(self.store, self.hub, 0 if in_process else settings.plan_workers,
                                 timeout_s=settings.plan_timeout_s, clock=clock,
                                 memory_mb=settings.plan_memory_mb, queue_max=settings.plan_queue)
        self.view = ThreeDView("127.0.0.1", settings.viser_port)  # served to browsers at /3d/
        self.lag = LoopLagMonitor(clock)
        self._watch: asyncio.Task | None = None
        self.started = self.stopped = False
        # the one place that decides where the link runs
        self.link_host: LinkHost = link.host if link is not None else \
            SameLoop() if in_process else LinkThread()
        boat_service = StandardBoatService if settings.boat_protocol == "standard" \
            else BoatService
        self.boat = boat_service(settings, self.store, self.hub, self.plans, clock=clock,
                                 entropy=self.entropy, host=self.link_host,
                                 link=link.link if link is not None else None)
        self.opened_device = link.device if link is not None else None
        self.sim: EmbeddedSim | InProcessSim | None = None
        self.hub.observers.append(ThreeDFeed(self.view, self._plan_of_mission).on_event)
        self.world = WorldService(self.hub, settings.nmea, simulate=settings.link == "sim",
                                  sim_speed=settings.sim_speed, clock=clock,
                                  sea_over_udp=not in_process)
        self.alerts = AlertStore(self.store)
        self.monitor = MonitorService(self.hub, self.alerts, self.world, self.boat, self.plans,
                                      settings.replan, clock=clock)
        self.link_alerts = LinkAlerts(self.monitor.raise_alert)
        # in_process: builds the simulated boat's vehicle (a sea trial's sensors and hull)
        self.sim_vehicle: Callable[[Scenario], Vehicle] | None = None

    async def start(self) -> None:
        """Start everything (once; the server's lifespan calls it again harmlessly). The
        boat link first: the boat fails safe 3 s after the station's last frame, so nothing
        slow (plan workers, the 3D view) comes before it."""
        if self.started:
            return
        self.started = True
        self.lag.start()
        self.store.start()
        if self._initial_scenario is not None:
            await asyncio.to_thread(self.store.set_setting, "scenario",
                                    self._initial_scenario.model_dump(mode="json"))
        scenario = await self.working_scenario()
        if scenario.origin is None:
            origin = await self.default_origin()
            log.warning("usv-station: warning: the working scenario %r has no origin; the boat "
                        "link uses the default origin %.6f, %.6f, ramp bearing %.1f deg",
                        scenario.name, origin.lat, origin.lon, origin.ramp_bearing_deg)
            placed = scenario.model_copy(update={"origin": origin})
        else:
            placed = scenario
        await self._open_link(placed)
        await self.plans.start()
        if not self.in_process:
            await asyncio.to_thread(self.view.start)
        self.view.show_scenario(scenario)
        await self.world.start(placed)
        self._watch = asyncio.get_running_loop().create_task(self._watch_health())

    async def _open_link(self, scenario: Scenario) -> None:
        """The embedded simulated boat (with `--link sim`) and the boat link."""
        device, factory = self.opened_device, None
        if self.settings.link == "sim" and self.in_process:  # on this loop, in memory
            self.sim = InProcessSim(scenario, self.settings, self.boat.key, self.clock,
                                    self.sim_vehicle, boot_id=self.entropy.getrandbits(32))
            self.sim.start()
            device, factory = "memory", self.sim.station_stream
        elif self.settings.link == "sim":  # the embedded simulated boat on a pty
            self.sim = EmbeddedSim(scenario, self.settings, self.boat.key)
            await asyncio.to_thread(self.sim.start)
            device = self.sim.device
        # the moving ramp: its pose streamed to the boat, telemetry x, y in its frame
        self.world.pose_listeners.append(self.boat.set_ramp_pose)
        self.boat.listeners += [self.link_alerts.on_link_event, self._publish_heartbeat]
        self.boat.on_duplicate = self.link_alerts.on_duplicate
        await self.boat.start(scenario, device, simulated=self.sim is not None,
                              stream_factory=factory)
        if self.boat.handler is not None:
            self.boat.handler.moving_frame = self.world.current_frame

    def _publish_heartbeat(self, ev: LinkEvent) -> None:
        """Each boat report (USV_MISSION_STATE, about 1 Hz) to the live clients with the
        link's counters (as in GET /api/boat `link`), so no console polls for them."""
        if isinstance(ev, BoatReport):
            rep = ev.report
            self.hub.publish("heartbeat", {"state": rep.state, "mission_id": rep.active_id,
                                           "link": self.boat.snapshot()["link"]})

    async def stop(self) -> None:
        """Close the link, stop plan workers, flush telemetry; the boat is sent nothing."""
        if self.stopped:
            return
        self.stopped = True
        if self._watch is not None:
            self._watch.cancel()
        self.lag.stop()
        await self.monitor.stop()
        await self.world.stop()
        await self.boat.stop()
        if isinstance(self.sim, InProcessSim):
            await self.sim.stop()
        elif self.sim is not None:
            await asyncio.to_thread(self.sim.stop)
        if not self.in_process:
            await asyncio.to_thread(self.view.stop)
        await self.plans.stop()
        await asyncio.to_thread(self.store.close)

    async def working_scenario(self) -> Scenario:
        data = await asyncio.to_thread(self.store.get_setting, "scenario")
        if data is None:
            path = bundled_scenario_dir() / f"{DEFAULT_SCENARIO}.json"
            data = json.loads(path.read_text(encoding="utf-8"))
        return parse_scenario(data)

    @staticmethod
    async def default_origin() -> Origin:
        """The bundled default scenario's origin, for a working scenario that has none."""
        path = bundled_scenario_dir() / f"{DEFAULT_SCENARIO}.json"
        data = json.loads(await asyncio.to_thread(path.read_text, encoding="utf-8"))
        return Origin(**data["origin"])

    async def _watch_health(self) -> None:
        """Publish a `health` event on the websocket whenever the status or its reason changes."""
        last = None
        while True:
            h = self.health()
            now = (h["status"], h["reasons"])
            if now != last:
                self.hub.publish("health", {"status": h["status"], "reasons": h["reasons"],
                                            "telemetry_writer": h["telemetry_writer"]})
                last = now
            await self.clock.sleep(0.5)

    async def set_working_scenario(self, scenario: Scenario) -> None:
        await asyncio.to_thread(self.store.set_setting, "scenario",
                                scenario.model_dump(mode="json"))
        self.view.show_scenario(scenario)
        await self.world.use_scenario(scenario)
        self.hub.publish("scenario", {"name": scenario.name})

    def _plan_of_mission(self, mission_id: str) -> PlanDocument | None:
        """The plan a mission was made from (for the 3D view), if it is known."""
        rec = self.boat.missions.get(mission_id)
        job = self.plans.get(rec.plan_id) if rec is not None else None
        return job["plan"] if job is not None else None

    def health(self) -> StationHealth:
        """Station health, no boat data: status ok or degraded with the reasons."""
        w = self.store.writer
        reasons: list[str] = []
        if w.error is not None:
            reasons.append(f"telemetry writer: {w.error}")
        plans = self.plans.health()
        if plans["workers"] and plans["workers_alive"] == 0 and self.plans.started:
            reasons.append("no plan worker alive")
        return {
            "status": "degraded" if reasons else "ok",
            "reasons": reasons,
            "telemetry_writer": {"received": w.stats.received, "committed": w.stats.committed,
                                 "queued": w.queued, "dropped": w.stats.dropped,
                                 "retries": w.stats.retries, "error": w.error},
            "plans": plans,
            "websocket_clients": len(self.hub.subscribers),
            "link_up": self.boat.link_up,
            "loop_lag_ms": {"worst_last_minute": round(1000 * self.lag.worst_last_minute(), 1),
                            "worst_since_start": round(1000 * self.lag.worst_ever, 1)},
            "link_heartbeat_gap_ms": self._heartbeat_gap(),
            "link_on_own_loop": isinstance(self.link_host, LinkThread),
            "link_nice": getattr(self.link_host, "nice", None),
        }

    def _heartbeat_gap(self) -> HeartbeatGap:
        link = self.boat.link
        if link is None:
            return {"worst_last_minute": 0.0, "worst_since_start": 0.0, "heartbeats": 0,
                    "late": []}
        meter = link.heartbeat_gap
        return {"worst_last_minute": round(1000 * meter.worst_since(link.clock.now()), 1),
                "worst_since_start": round(1000 * meter.worst_ever, 1),
                "heartbeats": meter.count,
                "late": [(utc_iso(t), round(1000 * gap, 1))
                         for t, gap in list(link.late_heartbeats)]}
