"""World model: own ship, its ramp pose and target tracks, predicted to any instant (pure).

No I/O and no clock: every update and query takes the station time `t` (seconds, any
monotonic origin). Geographic values are WGS-84 degrees and compass degrees (clockwise
from north); ramp-frame values follow shared/DESIGN.md "Frames". Tracks are dead-reckoned
at constant course and speed over ground from their last report.

The ramp pose comes from the own ship's position reference and heading through the lever
arm (scenario/ships.py LeverArm); without an own-ship fix the ramp is the fixed scenario
origin. Once the own ship has had a fix, the ramp never falls back to the origin: a silent
own ship is dead-reckoned from its last fix and marked stale after OWN_SHIP_STALE_S, and a
fix further from the last one than the ship's speed allows is recorded as a jump. Target
velocities are given over ground (`vx`, `vy`) and relative to the ramp (`rvx`, `rvy`): in
the ship-fixed ramp frame a target moves with the relative velocity.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Literal

import numpy as np
import pymap3d

from usvstation.geo import RampFrame
from usvstation.records import Target
from usvstation.scenario.ships import LeverArm

Source = Literal["ais", "arpa", "manual", "sim"]
DEFAULT_RADIUS_M = 5.0  # a target of unknown size
KNOT = 1852.0 / 3600.0  # m/s
OWN_SHIP_STALE_S = 3.0  # an own-ship fix older than this is stale (GNSS reports at 1-10 Hz)
# A fix further than JUMP_BASE_M + JUMP_FACTOR x max(speed, JUMP_MIN_SPEED) x dt from the
# last one is a jump: GNSS noise and a change of speed fit well inside, a wrong fix does not.
JUMP_BASE_M = 10.0
JUMP_FACTOR = 1.5
JUMP_MIN_SPEED = 1.0  # m/s
LOST_AFTER_S = 30.0  # a target silent this long is shown as lost (AIS class A: 2-10 s)


def compass_to_enu(speed: float, course_deg: float) -> tuple[float, float]:
    """Speed over ground and compass course to (east, north) velocity, m/s."""
    c = math.radians(course_deg)
    return speed * math.sin(c), speed * math.cos(c)


def enu_to_compass(ve: float, vn: float) -> tuple[float, float]:
    """(east, north) velocity to (speed, compass course in [0, 360))."""
    return math.hypot(ve, vn), math.degrees(math.atan2(ve, vn)) % 360.0


def offset_geodetic(lat: float, lon: float, east: float, north: float) -> tuple[float, float]:
    """The point `east`, `north` metres from (lat, lon) on the WGS-84 ellipsoid surface."""
    la, lo, _ = pymap3d.enu2geodetic(east, north, 0.0, lat, lon, 0.0, deg=True)
    return float(la), float(lo)


@dataclass(frozen=True)
class MotionReport:
    """A ship's position (WGS-84) and motion (compass degrees, m/s over ground) as one report
    gives them; what the report does not give is None."""

    lat: float | None = None
    lon: float | None = None
    heading_deg: float | None = None
    course_deg: float | None = None
    speed: float | None = None  # m/s over ground


@dataclass(frozen=True)
class OwnShipReport(MotionReport):
    """A partial own-ship report (GGA: position; HDT: heading; VTG: course, speed)."""


@dataclass(frozen=True)
class OwnShip(OwnShipReport):
    """The mother ship's last reported state; fields unknown so far are None."""

    t_fix: float | None = None  # station time of the last position
    t: float | None = None  # station time of the last report of any kind
    jump_m: float | None = None  # the last jump: distance between two fixes, m
    jump_allowed_m: float | None = None  # what the ship's speed allowed in that time
    t_jump: float | None = None  # station time of the last jump

    @property
    def has_fix(self) -> bool:
        return self.lat is not None and self.lon is not None

    def age(self, t: float) -> float | None:
        """Seconds since the last position fix (None without one)."""
        return None if self.t_fix is None else max(0.0, t - self.t_fix)

    def stale(self, t: float) -> bool:
        age = self.age(t)
        return age is not None and age > OWN_SHIP_STALE_S

    def velocity_enu(self) -> tuple[float, float]:
        if self.speed is None or self.course_deg is None:
            return 0.0, 0.0
        return compass_to_enu(self.speed, self.course_deg)

    def position_at(self, t: float) -> tuple[float, float]:
        """Dead-reckoned (lat, lon) at station time t."""
        assert self.lat is not None and self.lon is not None
        dt = t - (self.t_fix if self.t_fix is not None else t)
        ve, vn = self.velocity_enu()
        if dt == 0.0 or (ve == 0.0 and vn == 0.0):
            return self.lat, self.lon
        return offset_geodetic(self.lat, self.lon, ve * dt, vn * dt)


@dataclass(frozen=True)
class RampPose:
    """The ramp end on the sea: position, bearing of the ramp frame's +x, ground velocity."""

    lat: float
    lon: float
    ramp_bearing_deg: float
    ve: float = 0.0  # m/s east
    vn: float = 0.0  # m/s north
    moving: bool = False  # derived from a ship under way (not a fixed origin)

    @property
    def frame(self) -> RampFrame:
        return RampFrame(self.lat, self.lon, self.ramp_bearing_deg)


def ramp_pose(own: OwnShip, arm: LeverArm, t: float) -> RampPose:
    """The ramp end at station time t: own ship position + lever arm rotated by its heading.

    The heading falls back to the course over ground when no heading was reported.
    """
    lat, lon = own.position_at(t)
    heading = own.heading_deg if own.heading_deg is not None else (own.course_deg or 0.0)
    h = math.radians(heading)
    east = arm.forward * math.sin(h) + arm.starboard * math.cos(h)
    north = arm.forward * math.cos(h) - arm.starboard * math.sin(h)
    rlat, rlon = offset_geodetic(lat, lon, east, north)
    ve, vn = own.velocity_enu()
    return RampPose(rlat, rlon, (heading + arm.ramp_bearing_offset_deg) % 360.0, ve, vn,
                    moving=True)


def reference_in_ramp(arm: LeverArm) -> tuple[float, float]:
    """The ship's position reference (its GNSS antenna) in the ramp frame: the lever arm
    from the reference to the ramp end, reversed and turned into ramp axes (the bow points
    `ramp_bearing_offset_deg` counter-clockwise from +x, starboard 90 degrees clockwise of it)."""
    bow = math.radians(arm.ramp_bearing_offset_deg)
    stbd = bow - math.pi / 2.0
    return (-arm.forward * math.cos(bow) - arm.starboard * math.cos(stbd),
            -arm.forward * math.sin(bow) - arm.starboard * math.sin(stbd))


@dataclass(frozen=True)
class Track:
    """One target: its last report, dead-reckoned between reports."""

    id: str
    source: Source
    lat: float | None = None
    lon: float | None = None
    speed: float = 0.0  # over ground, m/s
    course_deg: float = 0.0  # over ground, compass
    heading_deg: float | None = None
    mmsi: int | None = None
    name: str | None = None
    length: float | None = None
    beam: float | None = None
    ais_class: str | None = None  # "A" or "B" for AIS targets
    t: float = 0.0  # station time of the last position report
    t_static: float | None = None  # last static report (name, size) without position

    @property
    def radius(self) -> float:
        """Radius of the circle that covers the hull: half the length (or the beam)."""
        sizes = [s for s in (self.length, self.beam) if s]
        return max(sizes) / 2.0 if sizes else DEFAULT_RADIUS_M

    @property
    def positioned(self) -> bool:
        return self.lat is not None and self.lon is not None


@dataclass
class WorldConfig:
    max_age_s: float = 180.0  # a silent track is dropped after this long
    manual_never_ages: bool = True


@dataclass
class World:
    """Own ship, lever arm and tracks; `anchor` is the fixed ramp without an own-ship fix."""

    anchor: RampFrame | None = None
    lever_arm: LeverArm = field(default_factory=LeverArm)
    config: WorldConfig = field(default_factory=WorldConfig)
    own: OwnShip = field(default_factory=OwnShip)
    tracks: dict[str, Track] = field(default_factory=dict)
    version: int = 0  # bumped on every change

    # --- updates ---------------------------------------------------------------------------
    def update_own(self, t: float, *, lat: float | None = None, lon: float | None = None,
                   heading_deg: float | None = None, course_deg: float | None = None,
                   speed: float | None = None) -> None:
        """Merge a partial own-ship report (GGA: position; HDT: heading; VTG: course, speed)."""
        changes: dict[str, float] = {"t": t}
        if lat is not None and lon is not None:
            changes.update(lat=lat, lon=lon, t_fix=t)
            jump = self._jump(t, lat, lon)
            if jump is not None:
                changes.update(jump_m=jump[0], jump_allowed_m=jump[1], t_jump=t)
        if heading_deg is not None:
            changes["heading_deg"] = heading_deg % 360.0
        if course_deg is not None:
            changes["course_deg"] = course_deg % 360.0
        if speed is not None:
            changes["speed"] = speed
        self.own = replace(self.own, **changes)
        self.version += 1

    def _jump(self, t: float, lat: float, lon: float) -> tuple[float, float] | None:
        """(distance, allowed) when a fix lies further from the last one than the ship's
        speed allows in the time between them, else None."""
        own = self.own
        if not own.has_fix or own.t_fix is None:
            return None
        assert own.lat is not None and own.lon is not None
        e, n, _ = pymap3d.geodetic2enu(lat, lon, 0.0, own.lat, own.lon, 0.0, deg=True)
        distance = math.hypot(float(e), float(n))
        dt = max(0.0, t - own.t_fix)
        allowed = JUMP_BASE_M + JUMP_FACTOR * max(own.speed or 0.0, JUMP_MIN_SPEED) * dt
        return (distance, allowed) if distance > allowed else None

    def update_track(self, t: float, track_id: str, source: Source, **fields: object) -> Track:
        """Merge a report into a track; a report with lat and lon is a position report."""
        old = self.tracks.get(track_id) or Track(id=track_id, source=source, t=t)
        values = {k: v for k, v in fields.items() if v is not None}
        if "course_deg" in values:
            values["course_deg"] = float(values["course_deg"]) % 360.0  # type: ignore[arg-type]
        if "lat" in values and "lon" in values:
            values["t"] = t
        elif not old.positioned:
            values["t_static"] = t
        new = replace(old, **values)
        self.tracks[track_id] = new
        self.version += 1
        return new

    def update_radar_target(self, t: float, number: int, range_m: float, bearing_deg: float,
                            speed: float, course_deg: float, *, relative: bool = False,
                            name: str | None = None) -> Track | None:
        """An ARPA target (TTM) from range and bearing off the own ship; None without a fix.

        `relative` bearings are from the own ship's heading; speed and course are taken
        as over ground (TTM reference T).
        """
        if not self.own.has_fix:
            return None
        if relative:
            if self.own.heading_deg is None:
                return None
            bearing_deg = bearing_deg + self.own.heading_deg
        lat, lon = self.own.position_at(t)
        b = math.radians(bearing_deg)
        tlat, tlon = offset_geodetic(lat, lon, range_m * math.sin(b), range_m * math.cos(b))
        return self.update_track(t, f"arpa:{number}", "arpa", lat=tlat, lon=tlon, speed=speed,
                                 course_deg=course_deg, name=name)

    def set_manual(self, t: float, obstacles: list[tuple[float, float, float, float, float]],
                   frame: RampFrame) -> None:
        """The scenario's obstacles (x, y, radius, vx, vy in `frame`) as `manual` tracks."""
        for key in [k for k, tr in self.tracks.items() if tr.source == "manual"]:
            del self.tracks[key]
        for i, (x, y, radius, vx, vy) in enumerate(obstacles):
            lat, lon = frame.to_geodetic(x, y)
            e, n = frame.ramp_to_enu(vx, vy)
            speed, course = enu_to_compass(float(e), float(n))
            self.tracks[f"manual:{i}"] = Track(
                id=f"manual:{i}", source="manual", lat=float(lat), lon=float(lon), speed=speed,
                course_deg=course, length=2.0 * radius, name=f"obstacle {i}", t=t)
        self.version += 1

    def expire(self, t: float) -> list[str]:
        """Drop tracks silent for longer than max_age_s; returns their ids."""
        gone = []
        for key, tr in self.tracks.items():
            if tr.source == "manual" and self.config.manual_never_ages:
                continue
            last = tr.t if tr.positioned else (tr.t_static or tr.t)
            if t - last > self.config.max_age_s:
                gone.append(key)
        for key in gone:
            del self.tracks[key]
        if gone:
            self.version += 1
        return gone

    # --- queries ---------------------------------------------------------------------------
    def ramp(self, t: float) -> RampPose | None:
        """The ramp pose at t: from the own ship if it has a fix, else the fixed anchor."""
        if self.own.has_fix:
            return ramp_pose(self.own, self.lever_arm, t)
        if self.anchor is not None:
            a = self.anchor
            return RampPose(a.lat, a.lon, a.ramp_bearing_deg)
        return None

    def targets(self, t: float) -> list[Target]:
        """Every positioned track predicted to t, in the ramp frame of t (vectorised): the
        `records.Target` the station serves (vx, vy over ground, rvx, rvy relative to the
        ramp, both in ramp axes)."""
        pose = self.ramp(t)
        tracks = [tr for tr in self.tracks.values() if tr.positioned]
        if pose is None or not tracks:
            return []
        frame = pose.frame
        lat = np.array([tr.lat for tr in tracks], dtype=float)
        lon = np.array([tr.lon for tr in tracks], dtype=float)
        age = t - np.array([tr.t for tr in tracks], dtype=float)
        course = np.radians([tr.course_deg for tr in tracks])
        speed = np.array([tr.speed for tr in tracks], dtype=float)
        ve, vn = speed * np.sin(course), speed * np.cos(course)
        x0, y0 = frame.to_ramp(lat, lon)
        vx, vy = frame.vector_to_ramp(ve, vn)
        x, y = x0 + vx * age, y0 + vy * age
        plat, plon = frame.to_geodetic(x, y)
        svx, svy = frame.vector_to_ramp(pose.ve, pose.vn)
        return [
            Target(
                id=tr.id, source=tr.source, mmsi=tr.mmsi, name=tr.name,
                lat=float(plat[i]), lon=float(plon[i]), x=float(x[i]), y=float(y[i]),
                vx=float(vx[i]), vy=float(vy[i]), rvx=float(vx[i] - svx),
                rvy=float(vy[i] - svy), radius=tr.radius, age_s=float(age[i]),
                speed=tr.speed, course_deg=tr.course_deg, heading_deg=tr.heading_deg,
                length=tr.length, ais_class=tr.ais_class,
                lost=tr.source != "manual" and float(age[i]) > LOST_AFTER_S,
            )
            for i, tr in enumerate(tracks)
        ]
