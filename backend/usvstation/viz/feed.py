"""The 3D view's feed from the live hub: a run's plan when it starts, then its track, and
the world's targets (dangerous ones from the plan monitor) at the present time.

The composition root (station.py) registers `ThreeDFeed.on_event` as a hub observer, so
no service knows the view exists. x, y are ramp-frame metres; t counts from the run's
first fix (the plan's t = 0 is its START), so the track and the plan share the time axis;
outside a run the targets are drawn at t = 0.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import cast

from usvstation.records import (
    MonitorAssessment,
    PlanDocument,
    RunEvent,
    TelemetryRow,
    WorldSnapshot,
)
from usvstation.viz.view import ThreeDView


class ThreeDFeed:
    """Shows the running mission's plan and its boat-reported track in the 3D view."""

    def __init__(self, view: ThreeDView,
                 plan_of_mission: Callable[[str], PlanDocument | None]) -> None:
        self.view, self.plan_of_mission = view, plan_of_mission
        self.run: int | None = None
        self.t0: float | None = None  # boat time of the run's first fix
        self.now_s = 0.0  # mission time of the latest fix of the run (0 outside one)
        self.dangerous: frozenset[str] = frozenset()

    def on_event(self, kind: str, data: Mapping[str, object]) -> None:
        if kind == "run":
            self._on_run(cast(RunEvent, data))
        elif kind == "telemetry":
            self._on_fix(cast(TelemetryRow, data))
        elif kind == "world":
            world = cast(WorldSnapshot, data)
            self.view.show_targets(list(world["targets"]), self.now_s if self.run else 0.0,
                                   self.dangerous)
        elif kind == "monitor":
            m = cast(MonitorAssessment, data)
            self.dangerous = frozenset(t["id"] for t in m["targets"]
                                       if t["min_clearance_m"] < m.get("margin_m", 0.0))

    def _on_run(self, ev: RunEvent) -> None:
        if ev["state"] == "active":
            self.run, self.t0 = ev["id"], None
            plan = self.plan_of_mission(ev["mission"])
            if plan is not None:
                self.view.show_plan(plan)
                self.view.clear_track()
        elif ev["id"] == self.run:
            self.run, self.now_s, self.dangerous = None, 0.0, frozenset()

    def _on_fix(self, row: TelemetryRow) -> None:
        if self.run is None or row["run"] != self.run or row["x"] is None or row["y"] is None \
                or row["boat_time"] is None:
            return
        if self.t0 is None:
            self.t0 = row["boat_time"]
        self.now_s = row["boat_time"] - self.t0
        self.view.add_track_point(row["x"], row["y"], self.now_s)
