"""Link alerts, from the link's own events: the boat link lost (a warning, ended when the link
is back), a go-around (a warning: the boat missed an approach gate and stands by for a new
approach; ended when it flies its mission again or the mission ends), the boat's
over-capacity notice (a warning: the current exceeds what it can hold; ended when it can
again), and two boats answering as the paired boat id (a warning, services/boat_link.py
DuplicateWatch).

They go through the plan monitor's `raise_alert`, so they are stored with the run they
happened in (store/alerts.py), exported and pushed to the live hub like every other alert:
one alert while the link is down, ended (not a second alert) when it is up again. An alert a
previous station process left active is ended when this one starts (services/monitor.py), so
a restart never leaves a "link lost" open beside a link that is up.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from usvstation.link.protocol import BoatReport, LinkDown, LinkEvent, LinkUp, StatusTextReceived
from usvstation.records import DuplicateBoat
from usvstation.world.monitor import AlertEvent

GO_AROUND_TEXT = "go-around:"  # the boat's STATUSTEXT giving the reason


class LinkAlerts:
    """A BoatLink listener: one alert per cause (link lost, go-around, over capacity), raised
    when the cause appears and ended when it clears."""

    def __init__(self, raise_alert: Callable[[AlertEvent], Any]) -> None:
        self.raise_alert = raise_alert
        self.link_lost = False
        self.state: str | None = None
        self.over_capacity = False
        self.go_around_reason = ""

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
        elif isinstance(ev, StatusTextReceived) and ev.text.startswith(GO_AROUND_TEXT) and \
                "standby" not in ev.text:
            self.go_around_reason = ev.text.removeprefix(GO_AROUND_TEXT).strip()
        elif isinstance(ev, BoatReport):
            self._on_report(ev)

    def _on_report(self, ev: BoatReport) -> None:
        state, previous = ev.report.state, self.state
        self.state = state
        if state == "GO_AROUND" and previous not in (None, "GO_AROUND", "HOLD", "FAILSAFE"):
            why = f" ({self.go_around_reason})" if self.go_around_reason else ""
            self.raise_alert(AlertEvent(
                "warning", "go_around", f"the boat went around{why}: it flies to its standby "
                "point; RESUME there for a new approach"))
        elif previous == "GO_AROUND" and state not in ("GO_AROUND", "HOLD", "FAILSAFE"):
            self.raise_alert(AlertEvent(None, "go_around", f"the boat is {state}",
                                        announce=False, rose=False))
        if ev.report.over_capacity and not self.over_capacity:
            self.raise_alert(AlertEvent("warning", "over_capacity",
                                        "the current exceeds what the boat can hold: drifting"))
        elif self.over_capacity and not ev.report.over_capacity:
            self.raise_alert(AlertEvent(None, "over_capacity", "the boat holds its position "
                                        "again", announce=False, rose=False))
        self.over_capacity = ev.report.over_capacity

    def on_duplicate(self, found: DuplicateBoat) -> None:
        """Two boats with the paired id (their boot ids alternate): one warning each time."""
        ids = ", ".join(f"{b:#010x}" for b in found["boot_ids"])
        self.raise_alert(AlertEvent(
            "warning", "duplicate_boat",
            f"two boats answer as the paired boat id (boot ids {ids}): the station cannot "
            "tell their reports apart, so mission states are not updated; switch the "
            "intruder off or re-key the link"))
