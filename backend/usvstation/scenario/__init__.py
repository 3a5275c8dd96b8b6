"""Scenario file model (shared/DESIGN.md "Scenario file", stable).

All positions are in the ramp frame (metres, x out to sea along the ramp
centre line, y to its left); headings counter-clockwise from +x in degrees.
Validation names the field and the reason; unknown fields are errors.
"""

from __future__ import annotations

import itertools
import json
import math
from importlib import resources
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from usvstation.geometry import inflated_radius
from usvstation.scenario.hull import start_refusal
from usvstation.scenario.options import IGAOptions
from usvstation.scenario.ships import MotherShip, TrafficShip

_STRICT = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False)

MAX_COORD = 20_000.0  # m: every position within 20 km of the ramp end
MAX_SPEED = 30.0  # m/s: every speed, current and wind
MAX_ECHO = 80  # characters of a bad value echoed in an error message

Metres = Annotated[float, Field(ge=-MAX_COORD, le=MAX_COORD, description="metres, |x| <= 20 km")]
PositiveMetres = Annotated[float, Field(gt=0.0, le=MAX_COORD, description="metres, > 0")]
Speed = Annotated[float, Field(ge=0.0, le=MAX_SPEED, description="m/s")]
Velocity = Annotated[float, Field(ge=-MAX_SPEED, le=MAX_SPEED, description="m/s")]


class Origin(BaseModel):
    """Geographic anchor of the ramp frame: the ramp end and the bearing of +x."""

    model_config = _STRICT
    lat: float = Field(ge=-90.0, le=90.0)
    lon: float = Field(ge=-180.0, le=180.0)
    ramp_bearing_deg: float = Field(0.0, ge=-360.0, le=360.0)


class Start(BaseModel):
    """Where the boat is when the plan starts: position, hull heading and speed over
    ground (its course over ground follows from these and the current)."""

    model_config = _STRICT
    x: Metres
    y: Metres
    heading_deg: float = Field(180.0, ge=-360.0, le=360.0, description="hull heading, deg")
    speed: float = Field(
        1.0, ge=0.0, le=MAX_SPEED,
        description="m/s over ground (in the scenario's frame: with a moving ramp, relative "
                    "to the ramp); the plan's first waypoint speed")


class Goal(BaseModel):
    model_config = _STRICT
    x: Metres = 0.0
    y: Metres = 0.0


class Obstacle(BaseModel):
    """Circle centred at (x + vx t, y + vy t) at time t after the plan starts (eq. 8)."""

    model_config = _STRICT
    x: Metres
    y: Metres
    radius: PositiveMetres
    vx: Velocity = 0.0
    vy: Velocity = 0.0

    @property
    def moving(self) -> bool:
        return self.vx != 0.0 or self.vy != 0.0


class Vessel(BaseModel):
    """The USV: hull length D_USV, speed and manoeuvring limits, compensation radius R_c."""

    model_config = _STRICT
    length: float = Field(1.2, gt=0.0, le=200.0, description="hull length D_USV, m")
    speed_min: float = Field(0.2, gt=0.0, le=MAX_SPEED, description="m/s")
    speed_max: float = Field(3.0, gt=0.0, le=MAX_SPEED, description="m/s")
    accel_max: float = Field(0.5, gt=0.0, le=20.0, description="m/s^2")
    turn_max_deg: float = Field(60.0, gt=0.0, le=180.0)
    compensation_radius: float = Field(1.0, ge=0.0, le=1000.0, description="R_c of eq. 7, m")
    time_margin_s: float = Field(
        3.0, ge=0.0, le=60.0,
        description="the hull stays clear of moving obstacles when this many seconds early "
        "or late anywhere on the plan",
    )
    # The ramp's tolerances and the approach gates (issue 24, docs/tracking.md).
    arrival_offset_m: float = Field(0.3, gt=0.0, le=10.0, description="an arrival: the "
                                    "hull within this of the ramp axis at the ramp end, m")
    arrival_heading_deg: float = Field(5.0, gt=0.0, le=45.0, description="an arrival: the "
                                       "hull within this of the arrival heading")
    contact_offset_m: float = Field(0.5, gt=0.0, le=10.0, description="a contact farther "
                                    "off the axis than this is a bad arrival, m")
    contact_heading_deg: float = Field(8.0, gt=0.0, le=60.0, description="a contact more "
                                       "askew than this is a bad arrival")
    gates_m: list[float] = Field([30.0, 15.0, 5.0], min_length=1, max_length=8,
                                 description="approach gates: distances from the ramp end, "
                                 "descending, m")
    standby_m: float = Field(50.0, gt=0.0, le=10000.0, description="the go-around's standby "
                             "point: this far out from the ramp end on the axis, m")

    @model_validator(mode="after")
    def _speed_range(self) -> Vessel:
        if self.speed_min >= self.speed_max:
            raise ValueError(
                f"vessel.speed_min: must be below speed_max "
                f"(got speed_min={self.speed_min}, speed_max={self.speed_max})"
            )
        return self

    @model_validator(mode="after")
    def _ramp_limits(self) -> Vessel:
        if self.arrival_offset_m >= self.contact_offset_m:
            raise ValueError("vessel.arrival_offset_m: must be below contact_offset_m "
                             f"(got {self.arrival_offset_m} and {self.contact_offset_m})")
        if self.arrival_heading_deg >= self.contact_heading_deg:
            raise ValueError("vessel.arrival_heading_deg: must be below contact_heading_deg "
                             f"(got {self.arrival_heading_deg} and "
                             f"{self.contact_heading_deg})")
        g = self.gates_m
        if any(not (0.0 < x <= 1000.0) for x in g) or any(b >= a for a, b in itertools.pairwise(g)):
            raise ValueError(f"vessel.gates_m: must be positive, at most 1000 and strictly "
                             f"descending (got {g})")
        if self.standby_m <= g[0]:
            raise ValueError(f"vessel.standby_m: must lie beyond the first gate "
                             f"(got {self.standby_m} <= {g[0]})")
        return self


class Environment(BaseModel):
    """Current and wind; directions in the ramp frame, where the flow goes to."""

    model_config = _STRICT
    current_speed: Speed = 0.0
    current_dir_deg: float = Field(0.0, ge=-360.0, le=360.0)
    wind_speed: Speed = 0.0
    wind_dir_deg: float = Field(0.0, ge=-360.0, le=360.0)
    # Set when the station plans for a moving ramp: the ramp frame's own velocity (ramp
    # axes) already folded into current_* as an apparent current, so the water's current
    # is current + frame velocity and folding the frame in again changes nothing.
    frame_vx: Velocity = 0.0
    frame_vy: Velocity = 0.0


class Scenario(BaseModel):
    """One planning problem: start, goal, obstacles, vessel, environment."""

    model_config = _STRICT
    name: str = Field(min_length=1, max_length=200)
    kind: Literal["recovery", "transit"] = "recovery"
    description: str = Field("", max_length=10_000)
    origin: Origin | None = None
    start: Start
    goal: Goal = Field(default_factory=Goal)
    obstacles: list[Obstacle] = Field(default_factory=list, max_length=2000)
    vessel: Vessel = Field(default_factory=Vessel)
    environment: Environment = Field(default_factory=Environment)
    planner: IGAOptions | None = None
    mother_ship: MotherShip | None = None  # a moving ramp, for the simulated sea
    traffic: list[TrafficShip] = Field(default_factory=list, max_length=100)  # other vessels

    @model_validator(mode="after")
    def _geometry(self) -> Scenario:
        if self.kind == "recovery" and (self.goal.x != 0.0 or self.goal.y != 0.0):
            raise ValueError(
                f"goal: a recovery ends at the ramp end (0, 0) "
                f"(got ({self.goal.x:g}, {self.goal.y:g}))"
            )
        if math.hypot(self.start.x - self.goal.x, self.start.y - self.goal.y) < 1.0:
            raise ValueError("goal: must lie at least 1 m from the start")
        refusal = start_refusal(self)
        if refusal:
            raise ValueError(refusal)
        for field, point in (("start", self.start), ("goal", self.goal)):
            for i, obs in enumerate(self.obstacles):
                r_l = inflated_radius(obs.radius, self.vessel.length,
                                      self.vessel.compensation_radius)
                if math.hypot(point.x - obs.x, point.y - obs.y) < r_l:
                    raise ValueError(
                        f"{field}: ({point.x:g}, {point.y:g}) lies inside obstacles[{i}] "
                        f"inflated to R_l = {r_l:g} m (eq. 7) at t = 0"
                    )
        return self

    def planner_options(self, **overrides: Any) -> IGAOptions:
        """The scenario's planner options with `overrides` applied (validated)."""
        base = self.planner.model_dump(exclude_unset=True) if self.planner else {}
        return IGAOptions(**{**base, **overrides})

    def with_budget(self, time_budget_s: float | None = None,
                    max_evaluations: int | None = None) -> Scenario:
        """A copy whose `planner` section carries this budget (every planner honours it);
        None keeps the scenario's own."""
        given = {k: v for k, v in (("time_budget_s", time_budget_s),
                                   ("max_evaluations", max_evaluations)) if v is not None}
        if not given:
            return self
        base = self.planner.model_dump(exclude_unset=True) if self.planner else {}
        return self.model_copy(update={"planner": IGAOptions(**{**base, **given})})


def scenario_at(
    scenario: Scenario, x: float, y: float, heading_deg: float, speed: float, t: float
) -> Scenario:
    """The scenario seen from a boat at ramp-frame (x, y) with hull heading and speed over
    ground, `t` s after the scenario's t = 0: obstacles propagated to that instant (eq. 8),
    which becomes the new t = 0. Raises ScenarioError (one line) if the result is not a
    valid scenario."""
    data = scenario.model_dump()
    data["start"] = {"x": float(x), "y": float(y), "heading_deg": float(heading_deg) % 360.0,
                     "speed": float(speed)}
    for o in data["obstacles"]:
        o["x"] += o["vx"] * t
        o["y"] += o["vy"] * t
    return parse_scenario(data)


class ScenarioError(ValueError):
    """A scenario could not be read or is invalid; the message is one line naming the field."""


def format_validation_error(exc: ValidationError) -> str:
    """One line: `field.path: reason (got value)` for every error, joined by '; '."""
    parts = []
    for err in exc.errors(include_url=False):
        loc = "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in err["loc"])
        loc = loc.lstrip(".")
        msg = err["msg"].removeprefix("Value error, ")
        if err["type"] == "extra_forbidden":
            msg = "unknown field"
        elif err["type"] == "missing":
            msg = "required field is missing"
        elif "input" in err and not isinstance(err["input"], dict | list):
            msg = f"{msg} (got {echo(err['input'])})"
        parts.append(f"{loc}: {msg}" if loc else msg)
    return "; ".join(parts)


def echo(value: Any) -> str:
    """A bad value as shown in an error message: its repr, at most MAX_ECHO characters."""
    if isinstance(value, int) and not isinstance(value, bool) and value.bit_length() > 200:
        return f"an integer of about {int(value.bit_length() * 0.30103)} digits"
    text = repr(value)
    return text if len(text) <= MAX_ECHO else text[: MAX_ECHO - 3] + "..."


def bundled_scenario_names() -> list[str]:
    """Names of the public benchmark scenarios shipped with the package."""
    folder = resources.files("usvstation") / "scenarios"
    return sorted(p.name[:-5] for p in folder.iterdir() if p.name.endswith(".json"))


def bundled_scenario_dir() -> Path:
    return Path(str(resources.files("usvstation") / "scenarios"))


def parse_scenario(data: Any) -> Scenario:
    """Validate decoded JSON as a scenario; raise ScenarioError with one line."""
    try:
        return Scenario.model_validate(data)
    except ValidationError as exc:
        raise ScenarioError(format_validation_error(exc)) from None


def load_scenario(ref: str | Path) -> Scenario:
    """Load a scenario from a file path, or by name from the bundled public suite."""
    path = Path(ref)
    if not path.exists() and str(ref) in bundled_scenario_names():
        path = bundled_scenario_dir() / f"{ref}.json"
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        names = ", ".join(bundled_scenario_names())
        raise ScenarioError(
            f"{ref}: no such scenario file (bundled scenarios: {names})"
        ) from None
    except (OSError, UnicodeDecodeError) as exc:
        raise ScenarioError(f"{ref}: cannot read scenario file ({exc})") from None
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise ScenarioError(
            f"{ref}: not valid JSON at line {exc.lineno} column {exc.colno} ({exc.msg})"
        ) from None
    except (ValueError, RecursionError) as exc:  # e.g. an integer of more than 4300 digits
        raise ScenarioError(f"{ref}: not valid JSON ({echo(str(exc))})") from None
    return parse_scenario(data)
