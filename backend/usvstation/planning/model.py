"""The typed plan: what every planner returns (pure, no I/O).

A `Plan` is the domain type; the stable plan format (shared/DESIGN.md "Plan output",
`records.PlanDocument`) is made from it only at the edges (the API, the store, the CLI, the
independent checker, which reads nothing but that format) by `Plan.to_document`, and
`Plan.from_document` reads a stored one back. The two are exact inverses for every plan a
planner makes: the same keys in the same order, the same values.

Metrics are open-ended by design (each planner adds its own figures, in its own order), so
`PlanMetrics` keeps them as an ordered mapping and gives the keys every planner reports as
typed properties. Sections a planner adds besides the stable ones (the IGA's `encoding` and
`history`) are kept as they are, in order, in `Plan.sections`.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field, replace
from typing import Any, Generic, TypeVar, cast

from usvstation import records

T = TypeVar("T")
_STABLE = ("planner", "scenario", "seed", "waypoints", "metrics", "smoothed", "warnings")


@dataclass(frozen=True)
class Waypoint:
    """One timed waypoint in the ramp frame: position (m), time (s) after the plan's start,
    speed over ground (m/s), the hull heading leaving it and, where the planner gives it,
    the course over ground of the segment (degrees, ramp frame)."""

    x: float
    y: float
    t: float
    speed: float
    heading_deg: float
    course_deg: float | None = None

    def to_document(self) -> records.Waypoint:
        doc: dict[str, float] = {"x": self.x, "y": self.y, "t": self.t, "speed": self.speed,
                                 "heading_deg": self.heading_deg}
        if self.course_deg is not None:
            doc["course_deg"] = self.course_deg
        return cast(records.Waypoint, doc)

    @classmethod
    def from_document(cls, doc: Mapping[str, Any]) -> Waypoint:
        return cls(doc["x"], doc["y"], doc["t"], doc["speed"], doc["heading_deg"],
                   doc.get("course_deg"))


@dataclass(frozen=True)
class SmoothedPath:
    """B-spline samples of a plan (`degree` 3, or 2 when 3 came too close), whether they
    keep clear of the inflated obstacles, the least water they leave the hull, and the
    control points added to keep them clear (`repaired`, in the document when not 0)."""

    degree: int
    collision_free: bool
    min_clearance_m: float | None
    points: tuple[Waypoint, ...]
    repaired: int = 0  # control points added to clear it (smoothing.repair); 0: none

    def to_document(self) -> dict[str, Any]:
        doc = {"degree": self.degree, "collision_free": self.collision_free,
               "min_clearance_m": self.min_clearance_m,
               "points": [p.to_document() for p in self.points]}
        if self.repaired:
            doc["repaired"] = self.repaired
        return doc

    @classmethod
    def from_document(cls, doc: Mapping[str, Any]) -> SmoothedPath:
        return cls(doc["degree"], doc["collision_free"], doc.get("min_clearance_m"),
                   tuple(Waypoint.from_document(p) for p in doc["points"]),
                   int(doc.get("repaired", 0)))


class _Metric(Generic[T]):
    """A metric every plan has, read by its name from `PlanMetrics.values`."""

    def __set_name__(self, owner: type, name: str) -> None:
        self.key = name

    def __get__(self, metrics: PlanMetrics, owner: type | None = None) -> T:
        return metrics.values[self.key]


@dataclass(frozen=True)
class PlanMetrics(Mapping[str, Any]):
    """A plan's figures in the planner's order: the ones every planner reports as attributes,
    the planner's own by key (`metrics["stop_reason"]`). Never changed in place: `updated`
    gives a copy with keys replaced or added (at the end)."""

    values: Mapping[str, Any]

    def __post_init__(self) -> None:
        object.__setattr__(self, "values", dict(self.values))

    def __getitem__(self, key: str) -> Any:
        return self.values[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self.values)

    def __len__(self) -> int:
        return len(self.values)

    def updated(self, **changes: Any) -> PlanMetrics:
        return PlanMetrics({**self.values, **changes})

    # the figures every planner reports (shared/DESIGN.md "Plan output")
    fitness = _Metric[float | None]()  # the IGA's eq. 10 fitness; None for the others
    length_m = _Metric[float]()
    duration_s = _Metric[float]()
    min_clearance_m = _Metric[float | None]()  # hull to obstacle; None without obstacles
    collision_free = _Metric[bool]()
    generations = _Metric[int]()
    elapsed_s = _Metric[float]()

    def to_document(self) -> records.PlanMetrics:
        return cast(records.PlanMetrics, dict(self.values))


@dataclass(frozen=True)
class Plan:
    """A planner's plan: timed waypoints from the start (t = 0) to the goal, its metrics, the
    warnings it comes with (less than eq. 7's margin, a time budget reached, ...), the
    smoothed path where the planner makes one, and the planner's extra sections."""

    planner: str
    scenario: str
    seed: int
    waypoints: tuple[Waypoint, ...]
    metrics: PlanMetrics
    warnings: tuple[str, ...] = ()
    smoothed: SmoothedPath | None = None
    sections: Mapping[str, Any] = field(default_factory=dict)

    def warned(self, *warnings: str) -> Plan:
        """The same plan with `warnings` added after its own."""
        return replace(self, warnings=(*self.warnings, *warnings))

    def with_metrics(self, **changes: Any) -> Plan:
        """The same plan with metrics replaced or added (at the end)."""
        return replace(self, metrics=self.metrics.updated(**changes))

    def to_document(self) -> records.PlanDocument:
        """The stable plan format: planner, scenario, seed, waypoints, metrics, the extra
        sections, smoothed (when there is one), warnings."""
        doc: dict[str, Any] = {
            "planner": self.planner, "scenario": self.scenario, "seed": self.seed,
            "waypoints": [w.to_document() for w in self.waypoints],
            "metrics": self.metrics.to_document(),
            **self.sections,
        }
        if self.smoothed is not None:
            doc["smoothed"] = self.smoothed.to_document()
        doc["warnings"] = list(self.warnings)
        return cast(records.PlanDocument, doc)

    @classmethod
    def from_document(cls, doc: Mapping[str, Any]) -> Plan:
        """A plan read back from its stable format (a stored plan, a plan JSON file); keys
        outside the stable ones become `sections`. Waypoint keys beyond the stable ones are
        not kept, and a document without `warnings` reads as a plan without any."""
        smoothed = doc.get("smoothed")
        return cls(
            planner=doc["planner"], scenario=doc["scenario"], seed=doc["seed"],
            waypoints=tuple(Waypoint.from_document(w) for w in doc["waypoints"]),
            metrics=PlanMetrics(doc["metrics"]),
            warnings=tuple(doc.get("warnings", ())),
            smoothed=None if smoothed is None else SmoothedPath.from_document(smoothed),
            sections={k: v for k, v in doc.items() if k not in _STABLE},
        )

