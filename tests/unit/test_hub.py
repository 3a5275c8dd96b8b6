"""Live fan-out: a slow client coalesces telemetry and never blocks the others."""

import asyncio
import json

from usvstation.services.hub import LiveHub


def test_slow_client_drops_old_telemetry_but_keeps_events():
    hub = LiveHub(queue_size=10)
    fast, slow = hub.subscribe(), hub.subscribe()

    async def drain_fast():
        got = []
        while fast.outbox:
            got.append(json.loads(await fast.next()))
        return got

    received = []
    for i in range(100):
        hub.publish("telemetry", {"i": i})
        received += asyncio.run(drain_fast())
        if i == 50:
            hub.publish("mission", {"state": "verified"})
    assert [m["data"]["i"] for m in received if m["type"] == "telemetry"] == list(range(100))
    kinds = [k for k, _ in slow.outbox]
    assert len(slow.outbox) == 10 and "mission" in kinds
    newest = [json.loads(t)["data"]["i"] for k, t in slow.outbox if k == "telemetry"]
    assert newest == list(range(91, 100))  # the newest positions survive
    assert slow.dropped == 91


def test_client_that_never_reads_is_cut_off():
    hub = LiveHub(queue_size=2)
    sub = hub.subscribe()
    for i in range(2005):
        hub.publish("mission", {"i": i})
    assert sub.closed and sub not in hub.subscribers
    assert asyncio.run(sub.next()) is not None  # what is queued can still be read
