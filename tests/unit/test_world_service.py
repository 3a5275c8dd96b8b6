"""The world service: sentences in, `world` events out, silent tracks aged out."""

from __future__ import annotations

import asyncio

from usvstation.scenario import load_scenario
from usvstation.services.hub import LiveHub
from usvstation.services.world import WorldService

AIS = b"!AIVDM,1,1,,A,139>JhOP1T8fQ7PAMCl4lSh1P000,0*02"


def test_world_events_and_ageing() -> None:
    now = [100.0]
    hub = LiveHub()
    events: list[dict] = []
    hub.observers.append(lambda kind, data: events.append(data) if kind == "world" else None)

    async def main() -> None:
        svc = WorldService(hub, [], clock=lambda: now[0])
        await svc.start(load_scenario("case1"))
        svc.feed(AIS)
        svc.feed(b"$junk")
        while not any(any(t["id"] == "ais:211000001" for t in e["targets"]) for e in events):
            await asyncio.sleep(0.05)
        n = len(events)
        await asyncio.sleep(0.7)
        assert len(events) == n  # nothing changed: nothing published
        now[0] += svc.world.config.max_age_s + 1
        while len(events) == n:
            await asyncio.sleep(0.05)
        await svc.stop()

    asyncio.run(main())
    first = next(e for e in events if any(t["id"] == "ais:211000001" for t in e["targets"]))
    assert first["stats"]["sentences"] == 2 and first["stats"]["bad"] == 1
    assert {t["source"] for t in first["targets"]} == {"ais", "manual"}
    last = events[-1]
    assert [t["source"] for t in last["targets"]] == ["manual"] * 4  # case1's obstacles stay
    assert last["ramp"]["source"] == "origin" and last["own_ship"] is None
