"""Runs: a run is open while the boat reports RUNNING, HOLD, FAILSAFE or GO_AROUND with a
mission; its telemetry goes into the run, and it closes with the mission's final state."""

from __future__ import annotations

import asyncio

from usvstation.geo import RampFrame
from usvstation.services.boat_link import LinkHandler
from usvstation.services.hub import LiveHub
from usvstation.services.missions import MissionRecord
from usvstation.services.plans import PlanService
from usvstation.store.db import Store


class Runs:
    """Opens and closes runs in the store as missions become active and leave it."""

    def __init__(self, store: Store, hub: LiveHub, plans: PlanService) -> None:
        self.store, self.hub, self.plans = store, hub, plans
        self.handler: LinkHandler | None = None

    async def begin(self, rec: MissionRecord) -> None:
        """Open a run for an active mission (also after a station restart mid-run)."""
        h = self.handler
        if rec.run is not None and h is not None and h.run == rec.run:
            return
        rec.run = -1  # claimed: reports arrive faster than the store answers
        run = await asyncio.to_thread(self.store.open_run, rec.id, rec.plan_id)
        rec.run = run
        if h is not None:
            h.run, h.run_t0 = run, None
            h.frame = RampFrame(rec.origin["lat"], rec.origin["lon"],
                                rec.origin["ramp_bearing_deg"])
        self.hub.publish("run", {"id": run, "mission": rec.id, "state": "active"})

    async def end(self, rec: MissionRecord) -> None:
        """Close the run; its telemetry is committed before anyone hears it ended."""
        run, h = rec.run, self.handler
        if h is not None and h.run == run:
            h.run = None
        await asyncio.to_thread(self.store.writer.flush)
        if run is not None and run > 0:
            await asyncio.to_thread(self.store.close_run, run, rec.state.value)
            self.hub.publish("run", {"id": run, "mission": rec.id, "state": rec.state.value})
