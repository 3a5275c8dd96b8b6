"""Link alerts: the boat link lost (warning) and back (advisory), from the link's own events,
and two boats answering as the paired boat id (warning, services/boat_link.py DuplicateWatch).

They are raised through the plan monitor's `raise_alert`, so they are stored with their run
(store/alerts.py), exported and pushed to the live hub like every other alert.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from usvstation.link.protocol import LinkDown, LinkEvent, LinkUp
from usvstation.records import DuplicateBoat
from usvstation.world.monitor import AlertEvent


class LinkAlerts:
    """A BoatLink listener: one warning when the link goes down, one advisory when it is back."""

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
            self.raise_alert(AlertEvent("advisory", "link_restored", "link to the boat restored"))

    def on_duplicate(self, found: DuplicateBoat) -> None:
        """Two boats with the paired id (their boot ids alternate): one warning each time."""
        ids = ", ".join(f"{b:#010x}" for b in found["boot_ids"])
        self.raise_alert(AlertEvent(
            "warning", "duplicate_boat",
            f"two boats answer as the paired boat id (boot ids {ids}): the station cannot "
            "tell their reports apart, so mission states are not updated; switch the "
            "intruder off or re-key the link"))
