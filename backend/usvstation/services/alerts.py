"""Operator alerts: a severity-ranked log that the console shows and acknowledges.

Each alert is `{id, time, level, kind, message, target_id, run_id, acknowledged}`,
level one of advisory < caution < warning. New alerts and acknowledgements go to
the live hub as `{"type": "alert", "data": alert}`. Raised here: the link to the
boat lost (warning) and back (advisory), from the link's own events. The log
lives in memory for the station's lifetime (newest `KEPT` alerts).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from dataclasses import asdict, dataclass
from typing import Literal

from usvstation.link.protocol import DefinitionMismatch, LinkDown, LinkUp
from usvstation.services.hub import LiveHub
from usvstation.store.db import utc_now

Level = Literal["advisory", "caution", "warning"]
KEPT = 500


@dataclass
class Alert:
    id: int
    time: str
    level: Level
    kind: str
    message: str
    target_id: str | None
    run_id: int | None
    acknowledged: bool = False


class AlertService:
    """Raises, lists and acknowledges alerts; `run_id()` names the run going on, if any."""

    def __init__(self, hub: LiveHub, run_id: Callable[[], int | None] = lambda: None) -> None:
        self.hub, self.run_id = hub, run_id
        self.alerts: list[Alert] = []
        self._ids = itertools.count(1)
        self._link_lost = False

    def raise_alert(self, level: Level, kind: str, message: str,
                    target_id: str | None = None) -> Alert:
        alert = Alert(next(self._ids), utc_now(), level, kind, message, target_id, self.run_id())
        self.alerts = [*self.alerts[-(KEPT - 1):], alert]
        self.hub.publish("alert", asdict(alert))
        return alert

    def acknowledge(self, alert_id: int) -> Alert | None:
        for alert in self.alerts:
            if alert.id == alert_id:
                if not alert.acknowledged:
                    alert.acknowledged = True
                    self.hub.publish("alert", asdict(alert))
                return alert
        return None

    def on_link_event(self, ev: object) -> None:
        """A BoatLink listener: one warning when the link goes down, one advisory when back."""
        if isinstance(ev, LinkDown | DefinitionMismatch):
            if not self._link_lost:
                self._link_lost = True
                reason = ev.reason if isinstance(ev, LinkDown) else ev.message
                self.raise_alert("warning", "link_lost", f"link to the boat lost: {reason}")
        elif isinstance(ev, LinkUp) and self._link_lost:
            self._link_lost = False
            self.raise_alert("advisory", "link_restored", "link to the boat restored")
