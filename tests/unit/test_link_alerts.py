"""The station's link alerts: a go-around and the boat's over-capacity notice (issue 24)."""

from __future__ import annotations

from dataclasses import replace

from usvstation.link.protocol import BoatReport, LinkDown, LinkUp, MissionState, StatusTextReceived
from usvstation.services.alerts import LinkAlerts

BASE = MissionState(1000, 7, "RUNNING", 3, 99, 12, 10, 0, 0, 0, 0, 0, 0, 1, 0)


def report(state: str, over: bool = False) -> BoatReport:
    return BoatReport(replace(BASE, state=state, over_capacity=over), received_at=0.0)


def test_a_go_around_raises_one_warning_with_the_boats_reason():
    raised = []
    alerts = LinkAlerts(raised.append)
    alerts.on_link_event(report("RUNNING"))
    alerts.on_link_event(StatusTextReceived(4, "go-around: gate 15 m: cross-track 1.2 m"))
    for state in ("GO_AROUND", "GO_AROUND", "HOLD", "GO_AROUND"):  # a HOLD in between: one
        alerts.on_link_event(report(state))
    assert [(a.level, a.kind) for a in raised] == [("warning", "go_around")]
    assert "gate 15 m: cross-track 1.2 m" in raised[0].message
    assert "RESUME" in raised[0].message
    alerts.on_link_event(report("RUNNING"))  # the new approach, then a second go-around
    alerts.on_link_event(report("GO_AROUND"))
    assert [a.kind for a in raised] == ["go_around", "go_around"]


def test_over_capacity_is_raised_once_per_notice():
    raised = []
    alerts = LinkAlerts(raised.append)
    for over in (False, True, True, False, True):
        alerts.on_link_event(report("HOLD", over))
    assert [a.kind for a in raised] == ["over_capacity", "over_capacity"]
    assert raised[0].message == "the current exceeds what the boat can hold: drifting"


def test_link_loss_alerts_are_unchanged():
    raised = []
    alerts = LinkAlerts(raised.append)
    alerts.on_link_event(LinkDown("silent 3 s"))
    alerts.on_link_event(LinkDown("silent 3 s"))
    alerts.on_link_event(LinkUp(1))
    assert [(a.level, a.kind) for a in raised] == [("warning", "link_lost"),
                                                   ("advisory", "link_restored")]
