"""Scenario models of the simulated sea: a mother ship under way and scripted traffic.

These are the scenario's optional `mother_ship` and `traffic` fields (shared/DESIGN.md
"Scenario file"). Positions are in the ramp frame at t = 0 (the scenario's `origin`),
courses are compass degrees over ground, speeds m/s.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

_STRICT = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False)
Point = Annotated[list[float], Field(min_length=2, max_length=2, description="[x, y], m")]


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


class MotherShip(BaseModel):
    """The mother ship under way, and its hull.

    Its heading follows from the scenario origin: heading = ramp_bearing_deg -
    lever_arm.ramp_bearing_offset_deg; `course_deg` may differ from it (drift). It sails
    `course_deg` at `speed` over ground; each of its timed `manoeuvres` (s after the start)
    sets a new course (the ship turns to it at `turn_rate_deg_s`, its hull turning with its
    course, so the stern ramp swings) and/or a new speed (at once).

    The hull, in the ramp frame (issue 27): with `beam` it occupies x in
    [-length, 0], |y| <= beam / 2, its stern at the ramp end; `outline` (a
    polygon of [x, y] points) replaces that box. The ramp opening is
    `ramp_width` wide, centred on the ramp axis at the ramp end. Without
    `beam` or `outline` the ship has no shape: the planners see the ramp alone.
    """

    model_config = _STRICT
    speed: float = Field(0.0, ge=0.0, le=15.0, description="m/s over ground")
    course_deg: float = Field(0.0, ge=-360.0, le=360.0, description="compass, over ground")
    lever_arm: LeverArm = Field(default_factory=LeverArm)
    length: float = Field(60.0, gt=0.0, le=400.0)
    mmsi: int = Field(257000000, ge=100000000, le=999999999)
    manoeuvres: list[Manoeuvre] = Field(default_factory=list, max_length=50)
    turn_rate_deg_s: float = Field(2.0, gt=0.0, le=30.0, description="rate of a course change")
    beam: float | None = Field(None, gt=0.0, le=100.0, description="m; the hull is a box")
    ramp_width: float = Field(3.0, gt=0.0, le=50.0, description="m, the ramp opening")
    outline: list[Point] | None = Field(
        None, min_length=3, max_length=200,
        description="hull polygon of [x, y] points in the ramp frame, m (replaces the box)")

    @model_validator(mode="after")
    def _shape(self) -> MotherShip:
        times = [m.t for m in self.manoeuvres]
        if times != sorted(times):
            raise ValueError("mother_ship.manoeuvres: must be in time order")
        if self.beam is not None and self.ramp_width >= self.beam:
            raise ValueError(f"mother_ship.ramp_width: must be narrower than the beam "
                             f"(got {self.ramp_width:g} m, beam {self.beam:g} m)")
        if self.outline is not None:
            if any(abs(c) > 2000.0 for p in self.outline for c in p):
                raise ValueError("mother_ship.outline: every point within 2 km of the ramp end")
            ring = self.outline
            area = 0.5 * sum(a[0] * b[1] - b[0] * a[1]
                             for a, b in zip(ring, ring[1:] + ring[:1], strict=True))
            if abs(area) < 1.0:
                raise ValueError("mother_ship.outline: the polygon encloses no area "
                                 f"({abs(area):g} m^2)")
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
