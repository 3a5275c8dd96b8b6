"""The station's link alerts: one per cause (link lost, a go-around, the boat's over-capacity
notice), raised when the cause appears and ended (level None) when it clears."""

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
    alerts.on_link_event(report("RUNNING"))  # the new approach ends it; a second go-around
    alerts.on_link_event(report("GO_AROUND"))
    assert [(a.level, a.kind) for a in raised] == [
        ("warning", "go_around"), (None, "go_around"), ("warning", "go_around")]


def test_over_capacity_is_raised_once_per_notice_and_ends_with_it():
    raised = []
    alerts = LinkAlerts(raised.append)
    for over in (False, True, True, False, True):
        alerts.on_link_event(report("HOLD", over))
    assert [(a.level, a.kind) for a in raised] == [
        ("warning", "over_capacity"), (None, "over_capacity"), ("warning", "over_capacity")]
    assert raised[0].message == "the current exceeds what the boat can hold: drifting"


def test_link_loss_is_one_alert_ended_when_the_link_is_back():
    raised = []
    alerts = LinkAlerts(raised.append)
    alerts.on_link_event(LinkDown("silent 3 s"))
    alerts.on_link_event(LinkDown("silent 3 s"))
    alerts.on_link_event(LinkUp(1))
    assert [(a.level, a.kind) for a in raised] == [("warning", "link_lost"),
                                                   (None, "link_lost")]
