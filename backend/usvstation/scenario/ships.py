"""Scenario models of the simulated sea: a mother ship under way and scripted traffic.

These are the scenario's optional `mother_ship` and `traffic` fields (shared/DESIGN.md
"Scenario file"). Positions are in the ramp frame at t = 0 (the scenario's `origin`),
courses are compass degrees over ground, speeds m/s.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

_STRICT = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False)


class LeverArm(BaseModel):
    """Where the ramp end sits on the ship, from the ship's position reference (GNSS antenna).

    `forward` metres along the bow (negative: aft), `starboard` metres to starboard;
    `ramp_bearing_offset_deg` is the bearing of the ramp frame's +x axis relative to the
    ship's heading (180 for a stern ramp: +x points astern, out to sea).
    """

    model_config = _STRICT
    forward: float = Field(-20.0, ge=-500.0, le=500.0)
    starboard: float = Field(0.0, ge=-100.0, le=100.0)
    ramp_bearing_offset_deg: float = Field(180.0, ge=-360.0, le=360.0)


class MotherShip(BaseModel):
    """The mother ship under way at constant course and speed over ground.

    Its heading follows from the scenario origin: heading = ramp_bearing_deg -
    lever_arm.ramp_bearing_offset_deg; `course_deg` may differ from it (drift).
    """

    model_config = _STRICT
    speed: float = Field(0.0, ge=0.0, le=15.0, description="m/s over ground")
    course_deg: float = Field(0.0, ge=-360.0, le=360.0, description="compass, over ground")
    lever_arm: LeverArm = Field(default_factory=LeverArm)
    length: float = Field(60.0, gt=0.0, le=400.0)
    mmsi: int = Field(257000000, ge=100000000, le=999999999)


class Manoeuvre(BaseModel):
    """At `t` seconds after the start: a new course and/or speed, taken at once."""

    model_config = _STRICT
    t: float = Field(ge=0.0, description="s after the start")
    course_deg: float | None = Field(None, ge=-360.0, le=360.0)
    speed: float | None = Field(None, ge=0.0, le=30.0)

    @model_validator(mode="after")
    def _something(self) -> Manoeuvre:
        if self.course_deg is None and self.speed is None:
            raise ValueError("manoeuvre: give course_deg, speed or both")
        return self


class TrafficStart(BaseModel):
    model_config = _STRICT
    x: float
    y: float


class TrafficShip(BaseModel):
    """Another vessel: starts at (x, y) of the ramp frame at t = 0 and sails a scripted course.

    `report` says how the station learns of it: its own AIS (class A: types 1 and 5;
    class B: types 18 and 24) or the mother ship's radar (ARPA TTM).
    """

    model_config = _STRICT
    mmsi: int = Field(ge=100000000, le=999999999)
    name: str = Field("", max_length=20)
    start: TrafficStart
    course_deg: float = Field(ge=-360.0, le=360.0)
    speed: float = Field(ge=0.0, le=30.0)
    length: float = Field(10.0, gt=0.0, le=400.0)
    beam: float | None = Field(None, gt=0.0, le=80.0)
    report: Literal["ais", "arpa"] = "ais"
    ais_class: Literal["A", "B"] = "A"
    manoeuvres: list[Manoeuvre] = Field(default_factory=list, max_length=50)

    @model_validator(mode="after")
    def _ordered(self) -> TrafficShip:
        times = [m.t for m in self.manoeuvres]
        if times != sorted(times):
            raise ValueError("manoeuvres: must be in time order")
        return self
