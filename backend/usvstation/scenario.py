"""Scenario file model (shared/DESIGN.md "Scenario file", stable).

All positions are in the ramp frame (metres, x out to sea along the ramp
centre line, y to its left); headings counter-clockwise from +x in degrees.
Validation names the field and the reason; unknown fields are errors.
"""

from __future__ import annotations

import json
import math
from importlib import resources
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from usvstation.planning.options import IGAOptions
from usvstation.world.ships import MotherShip, TrafficShip

_STRICT = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False)

Metres = Annotated[float, Field(description="metres")]
PositiveMetres = Annotated[float, Field(gt=0.0, description="metres, > 0")]


class Origin(BaseModel):
    """Geographic anchor of the ramp frame: the ramp end and the bearing of +x."""

    model_config = _STRICT
    lat: float = Field(ge=-90.0, le=90.0)
    lon: float = Field(ge=-180.0, le=180.0)
    ramp_bearing_deg: float = Field(0.0, ge=-360.0, le=360.0)


class Start(BaseModel):
    model_config = _STRICT
    x: Metres
    y: Metres
    heading_deg: float = Field(180.0, ge=-360.0, le=360.0)
    speed: float = Field(1.0, ge=0.0, description="m/s")


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
    vx: float = 0.0
    vy: float = 0.0

    @property
    def moving(self) -> bool:
        return self.vx != 0.0 or self.vy != 0.0


class Vessel(BaseModel):
    """The USV: hull length D_USV, speed and manoeuvring limits, compensation radius R_c."""

    model_config = _STRICT
    length: PositiveMetres = 1.2
    speed_min: float = Field(0.2, gt=0.0, description="m/s")
    speed_max: float = Field(3.0, gt=0.0, description="m/s")
    accel_max: float = Field(0.5, gt=0.0, description="m/s^2")
    turn_max_deg: float = Field(60.0, gt=0.0, le=180.0)
    compensation_radius: float = Field(1.0, ge=0.0, description="R_c of eq. 7, m")

    @model_validator(mode="after")
    def _speed_range(self) -> Vessel:
        if self.speed_min >= self.speed_max:
            raise ValueError(
                f"vessel.speed_min: must be below speed_max "
                f"(got speed_min={self.speed_min}, speed_max={self.speed_max})"
            )
        return self


class Environment(BaseModel):
    """Current and wind; directions in the ramp frame, where the flow goes to."""

    model_config = _STRICT
    current_speed: float = Field(0.0, ge=0.0, description="m/s")
    current_dir_deg: float = Field(0.0, ge=-360.0, le=360.0)
    wind_speed: float = Field(0.0, ge=0.0, description="m/s")
    wind_dir_deg: float = Field(0.0, ge=-360.0, le=360.0)


class Scenario(BaseModel):
    """One planning problem: start, goal, obstacles, vessel, environment."""

    model_config = _STRICT
    name: str = Field(min_length=1, max_length=200)
    kind: Literal["recovery", "transit"] = "recovery"
    description: str = ""
    origin: Origin | None = None
    start: Start
    goal: Goal = Field(default_factory=Goal)
    obstacles: list[Obstacle] = Field(default_factory=list, max_length=500)
    vessel: Vessel = Field(default_factory=Vessel)
    environment: Environment = Field(default_factory=Environment)
    planner: IGAOptions | None = None
    mother_ship: MotherShip | None = None  # a moving ramp, for the simulated sea
    traffic: list[TrafficShip] = Field(default_factory=list, max_length=100)  # other vessels

    @model_validator(mode="after")
    def _geometry(self) -> Scenario:
        if self.kind == "recovery":
            if self.goal.x != 0.0 or self.goal.y != 0.0:
                raise ValueError(
                    f"goal: a recovery ends at the ramp end (0, 0) "
                    f"(got ({self.goal.x:g}, {self.goal.y:g}))"
                )
            if self.start.x <= 0.0:
                raise ValueError(
                    f"start.x: a recovery starts out to sea, x > 0 in the ramp frame "
                    f"(got {self.start.x:g})"
                )
        elif math.hypot(self.start.x - self.goal.x, self.start.y - self.goal.y) < 1.0:
            raise ValueError("goal: must lie at least 1 m from the start")
        for field, point in (("start", self.start), ("goal", self.goal)):
            for i, obs in enumerate(self.obstacles):
                r_l = self.inflated_radius(obs)
                if math.hypot(point.x - obs.x, point.y - obs.y) < r_l:
                    raise ValueError(
                        f"{field}: ({point.x:g}, {point.y:g}) lies inside obstacles[{i}] "
                        f"inflated to R_l = {r_l:g} m (eq. 7) at t = 0"
                    )
        return self

    def inflated_radius(self, obstacle: Obstacle) -> float:
        """R_l = R_obs + D_USV + R_c (paper 000 eq. 7)."""
        return obstacle.radius + self.vessel.length + self.vessel.compensation_radius

    def planner_options(self, **overrides: Any) -> IGAOptions:
        """The scenario's planner options with `overrides` applied (validated)."""
        base = self.planner.model_dump(exclude_unset=True) if self.planner else {}
        return IGAOptions(**{**base, **overrides})


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
            msg = f"{msg} (got {err['input']!r})"
        parts.append(f"{loc}: {msg}" if loc else msg)
    return "; ".join(parts)


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
    return parse_scenario(data)
