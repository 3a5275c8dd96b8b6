"""Sea-trial SPEC.toml (docs/trials.md): how many episodes, and the families each episode
draws its conditions from.

    name = "smoke"            # default: the file's stem
    episodes = 20
    seed = 1                  # episode i is drawn from (seed, i) alone
    base = ["case1"]          # bundled scenarios (or JSON paths) an episode starts from
    planner = "iga"
    replan = "auto"           # the station's policy: auto | confirm (the mate confirms) | off
    time_limit_s = 300        # of simulated time after START

    [families]                # one value drawn uniformly per episode from each list
    mother_ship_speed = [0.0, 0.5, 1.0]     # m/s, the ship's course along its heading
    mother_ship_turn_deg = [0.0, -20.0, 30.0]  # a course change 10-40 s into the sea, 2 deg/s
    traffic = ["none", "crossing", "head_on", "overtaking", "turning"]
    current = ["steady", "step", "reversal"]
    current_speed = [0.0, 0.3]              # m/s, towards a drawn direction
    sea_state = [0, 2]
    sensor = ["rtk", "gnss", "rtk-moving-base"]
    drag_scale = [1.0, 1.25]                # the hull against the model the boat was tuned on
    thrust_scale = [1.0, 0.85]
    link_loss = ["none", "burst"]           # burst: 2-6 s of radio silence mid-run
    operator_hold = ["none", "hold"]        # hold: HOLD for 5-15 s mid-run, then RESUME
"""

from __future__ import annotations

from pathlib import Path
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator

from usvstation.campaign.spec import load_toml
from usvstation.planning.registry import planner_names

TRAFFIC = ("none", "crossing", "head_on", "overtaking", "turning")
CURRENTS = ("steady", "step", "reversal")
SENSORS = ("exact", "rtk", "gnss", "rtk-moving-base")  # sim/sensors.py SENSOR_PROFILES
LINK_LOSS = ("none", "burst")
HOLDS = ("none", "hold")


class TrialError(ValueError):
    """A trial could not be read or run; one line naming the field."""


def _non_empty(values: list, allowed: tuple[str, ...] | None = None) -> list:
    if not values:
        raise ValueError("needs at least one value")
    if allowed is not None:
        for v in values:
            if v not in allowed:
                raise ValueError(f"unknown value {v!r}; available: {', '.join(allowed)}")
    return values


class Families(BaseModel):
    """The lists an episode draws its conditions from (one value each, uniformly)."""

    model_config = ConfigDict(extra="forbid")
    mother_ship_speed: list[float] = Field(default_factory=lambda: [0.0])
    mother_ship_turn_deg: list[float] = Field(default_factory=lambda: [0.0])
    traffic: list[str] = Field(default_factory=lambda: ["none"])
    current: list[str] = Field(default_factory=lambda: ["steady"])
    current_speed: list[float] = Field(default_factory=lambda: [0.0])
    sea_state: list[int] = Field(default_factory=lambda: [0])
    sensor: list[str] = Field(default_factory=lambda: ["rtk"])
    drag_scale: list[float] = Field(default_factory=lambda: [1.0])
    thrust_scale: list[float] = Field(default_factory=lambda: [1.0])
    link_loss: list[str] = Field(default_factory=lambda: ["none"])
    operator_hold: list[str] = Field(default_factory=lambda: ["none"])

    @field_validator("traffic")
    @classmethod
    def _traffic(cls, v: list[str]) -> list[str]:
        return _non_empty(v, TRAFFIC)

    @field_validator("current")
    @classmethod
    def _current(cls, v: list[str]) -> list[str]:
        return _non_empty(v, CURRENTS)

    @field_validator("sensor")
    @classmethod
    def _sensor(cls, v: list[str]) -> list[str]:
        return _non_empty(v, SENSORS)

    @field_validator("link_loss")
    @classmethod
    def _link(cls, v: list[str]) -> list[str]:
        return _non_empty(v, LINK_LOSS)

    @field_validator("operator_hold")
    @classmethod
    def _hold(cls, v: list[str]) -> list[str]:
        return _non_empty(v, HOLDS)

    @field_validator("mother_ship_speed", "current_speed")
    @classmethod
    def _speeds(cls, v: list[float]) -> list[float]:
        if any(not 0.0 <= x <= 3.0 for x in _non_empty(v)):
            raise ValueError("speeds must be within 0-3 m/s")
        return v

    @field_validator("mother_ship_turn_deg")
    @classmethod
    def _turns(cls, v: list[float]) -> list[float]:
        if any(not -90.0 <= x <= 90.0 for x in _non_empty(v)):
            raise ValueError("turns must be within -90..90 degrees")
        return v

    @field_validator("sea_state")
    @classmethod
    def _sea(cls, v: list[int]) -> list[int]:
        if any(not 0 <= x <= 5 for x in _non_empty(v)):
            raise ValueError("sea states must be within 0-5")
        return v

    @field_validator("drag_scale", "thrust_scale")
    @classmethod
    def _scales(cls, v: list[float]) -> list[float]:
        if any(not 0.5 <= x <= 1.5 for x in _non_empty(v)):
            raise ValueError("scales must be within 0.5-1.5")
        return v


class TrialSpec(BaseModel):
    model_config = ConfigDict(extra="forbid")
    name: str = "trial"
    episodes: int = Field(ge=1, le=100_000)
    seed: int = Field(1, ge=0, le=2**31)
    base: list[str] = Field(default_factory=lambda: ["case1"], min_length=1)
    planner: str = "iga"
    replan: Literal["auto", "confirm", "off"] = "auto"
    time_limit_s: float = Field(300.0, gt=0.0, le=3600.0)
    families: Families = Field(default_factory=Families)

    @field_validator("planner")
    @classmethod
    def _planner(cls, v: str) -> str:
        if v not in planner_names():
            raise ValueError(f"unknown planner {v!r}; available: {', '.join(planner_names())}")
        return v


def load_spec(path: Path) -> TrialSpec:
    """The spec of a TOML file; TrialError (one line naming the field) when it is wrong."""
    return load_toml(path, TrialSpec, TrialError, "trial")
