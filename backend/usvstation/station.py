"""The station: one object that owns the store, the live hub, plan jobs and the boat link."""

from __future__ import annotations

import asyncio
import json
from typing import Any

from usvstation.config import Settings, resolve_token
from usvstation.link.protocol import BoatReport
from usvstation.scenario import Scenario, bundled_scenario_dir, parse_scenario
from usvstation.services.alerts import LinkAlerts
from usvstation.services.boat import BoatService
from usvstation.services.hub import LiveHub
from usvstation.services.monitor import MonitorService
from usvstation.services.plans import PlanService
from usvstation.services.world import WorldService
from usvstation.store.alerts import AlertStore
from usvstation.store.db import Store
from usvstation.viz.view import ThreeDView

DEFAULT_SCENARIO = "case1"


class Station:
    """Composition root; `start` and `stop` run inside the server's lifespan."""

    def __init__(self, settings: Settings) -> None:
        self.settings = settings
        self.token = resolve_token(settings)
        self.store = Store(settings.data_dir)
        self.hub = LiveHub()
        self.plans = PlanService(self.store, self.hub, settings.plan_workers)
        self.view = ThreeDView(settings.host, settings.viser_port)
        self.boat = BoatService(settings, self.store, self.hub, self.plans, self.view)
        self.world = WorldService(self.hub, settings.nmea, simulate=settings.link == "sim",
                                  sim_speed=settings.sim_speed)
        self.alerts = AlertStore(self.store)
        self.monitor = MonitorService(self.hub, self.alerts, self.world, self.boat, self.plans,
                                      settings.replan)
        self.link_alerts = LinkAlerts(self.monitor.raise_alert)

    async def start(self) -> None:
        self.store.start()
        await self.plans.start()
        scenario = await self.working_scenario()
        await asyncio.to_thread(self.view.start)
        self.view.show_scenario(scenario)
        await self.world.start(scenario)
        await self.boat.start(scenario)
        if self.boat.link is not None:
            self.boat.link.add_listener(self.link_alerts.on_link_event)
            self.boat.link.add_listener(self._publish_heartbeat)

    def _publish_heartbeat(self, ev: object) -> None:
        """Each boat report (USV_MISSION_STATE, about 1 Hz) to the live clients with the
        link's counters (as in GET /api/boat `link`), so no console polls for them."""
        if isinstance(ev, BoatReport):
            rep = ev.report
            self.hub.publish("heartbeat", {"state": rep.state, "mission_id": rep.active_id,
                                           "link": self.boat.snapshot()["link"]})

    async def stop(self) -> None:
        """Close the link, stop plan workers, flush telemetry; the boat is sent nothing."""
        await self.monitor.stop()
        await self.world.stop()
        await self.boat.stop()
        await asyncio.to_thread(self.view.stop)
        await self.plans.stop()
        await asyncio.to_thread(self.store.close)

    async def working_scenario(self) -> Scenario:
        data = await asyncio.to_thread(self.store.get_setting, "scenario")
        if data is None:
            path = bundled_scenario_dir() / f"{DEFAULT_SCENARIO}.json"
            data = json.loads(path.read_text(encoding="utf-8"))
        return parse_scenario(data)

    async def set_working_scenario(self, scenario: Scenario) -> None:
        await asyncio.to_thread(self.store.set_setting, "scenario",
                                scenario.model_dump(mode="json"))
        self.view.show_scenario(scenario)
        await self.world.use_scenario(scenario)
        self.hub.publish("scenario", {"name": scenario.name})

    def health(self) -> dict[str, Any]:
        w = self.store.writer
        return {
            "status": "ok" if w.error is None else "degraded",
            "telemetry_writer": {"received": w.stats.received, "committed": w.stats.committed,
                                 "error": None if w.error is None else repr(w.error)},
            "plans": {s: sum(1 for j in self.plans.jobs.values() if j["status"] == s)
                      for s in ("queued", "running")},
            "websocket_clients": len(self.hub.subscribers),
            "link_up": self.boat.link_up,
            "viser_port": self.view.port,
        }
