"""Link alerts: the boat link lost (a warning) ends when the link is back, from the link's
own events.

They go through the plan monitor's `raise_alert`, so they are stored with the run they
happened in (store/alerts.py), exported and pushed to the live hub like every other alert:
one alert while the link is down, ended (not a second alert) when it is up again. An alert a
previous station process left active is ended when this one starts (services/monitor.py), so
a restart never leaves a "link lost" open beside a link that is up.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from usvstation.link.protocol import LinkDown, LinkEvent, LinkUp
from usvstation.world.monitor import AlertEvent


class LinkAlerts:
    """A BoatLink listener: a warning when the link goes down, ended when it is back."""

    def __init__(self, raise_alert: Callable[[AlertEvent], Any]) -> None:
        self.raise_alert = raise_alert
        self.link_lost = False

    def on_link_event(self, ev: LinkEvent) -> None:
        if isinstance(ev, LinkDown):
            if not self.link_lost:
                self.link_lost = True
                self.raise_alert(AlertEvent("warning", "link_lost",
                                            f"link to the boat lost: {ev.reason}"))
        elif isinstance(ev, LinkUp) and self.link_lost:
            self.link_lost = False
            self.raise_alert(AlertEvent(None, "link_lost", "link to the boat restored",
                                        announce=False, rose=False))
