"""Fan-out of live events to websocket clients without ever blocking the producer.

Each client has a bounded queue of pre-serialised messages. When a slow
client's queue is full, its oldest telemetry message is dropped to make room
(telemetry coalesces: only the newest position matters); other events are
never dropped, and a client that stays full is disconnected.
"""

from __future__ import annotations

import asyncio
import json
import logging
from collections import deque
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

log = logging.getLogger(__name__)
QUEUE_SIZE = 256
# An event's data: one of the station's records (usvstation/records.py), sent as JSON.
Payload = Mapping[str, object]
MAX_OVERFLOWS = 2000  # consecutive drops before a client is cut off


@dataclass(eq=False)
class Subscriber:
    """One websocket client's outbox."""

    outbox: deque[tuple[str, str]] = field(default_factory=deque)  # (kind, json text)
    ready: asyncio.Event = field(default_factory=asyncio.Event)
    dropped: int = 0
    overflows: int = 0
    closed: bool = False

    async def next(self) -> str | None:
        """The next message, or None once the hub has cut this client off."""
        while not self.outbox:
            if self.closed:
                return None
            self.ready.clear()
            await self.ready.wait()
        return self.outbox.popleft()[1]


class LiveHub:
    """Publishes events to every subscriber."""

    def __init__(self, queue_size: int = QUEUE_SIZE) -> None:
        self.queue_size = queue_size
        self.subscribers: set[Subscriber] = set()
        self.published = 0
        # in-process observers (kind, data), called synchronously; their faults are contained
        self.observers: list[Callable[[str, Payload], None]] = []

    def subscribe(self) -> Subscriber:
        sub = Subscriber()
        self.subscribers.add(sub)
        return sub

    def unsubscribe(self, sub: Subscriber) -> None:
        self.subscribers.discard(sub)
        sub.closed = True
        sub.ready.set()

    def publish(self, kind: str, data: Payload) -> None:
        """Queue an event for every client; O(clients), never awaits."""
        text = json.dumps({"type": kind, "data": data}, separators=(",", ":"))
        self.published += 1
        for sub in list(self.subscribers):
            self._offer(sub, kind, text)
        for observer in list(self.observers):
            try:
                observer(kind, data)
            except Exception:
                log.exception("live hub observer failed on a %s event", kind)

    def _offer(self, sub: Subscriber, kind: str, text: str) -> None:
        if len(sub.outbox) >= self.queue_size:
            for i, (k, _) in enumerate(sub.outbox):
                if k == "telemetry":
                    del sub.outbox[i]
                    sub.dropped += 1
                    break
            else:
                sub.overflows += 1
                if sub.overflows > MAX_OVERFLOWS:
                    self.unsubscribe(sub)
                    return
                sub.outbox.popleft()
                sub.dropped += 1
        else:
            sub.overflows = 0
        sub.outbox.append((kind, text))
        sub.ready.set()
