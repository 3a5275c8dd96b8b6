"""A mission as sent on the wire: plan waypoints (ramp frame, SI) to USV_MISSION_ITEMs and back.

Items carry WGS-84 lat/lon in 1e-7 degrees, t in ms from the mission start, speed in
cm/s, the compass course over ground of the leg leaving the waypoint and the compass
heading of the hull on it, in 0.01 degree (protocol/README.md "Mission"). The ranges
checked here are the boat's (`item_problem` is what both boats refuse with OUT_OF_RANGE).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from usvstation.geo import RampFrame
from usvstation.geometry import CDEG, CM, E7, MS
from usvstation.link.wire import MAX_MISSION_ITEMS, item_crc32

LAT_MAX_E7 = 90 * 10**7
LON_MAX_E7 = 180 * 10**7
SPEED_MAX_CMS = 3000
MIN_ITEMS = 2


class MissionError(ValueError):
    """A mission that cannot be sent or executed; the message names the waypoint and field."""


@dataclass(frozen=True)
class Origin:
    """The ramp-frame anchor the station converts with (not on the wire: items are geodetic)."""

    lat_e7: int
    lon_e7: int
    ramp_bearing_cdeg: int

    @classmethod
    def from_frame(cls, frame: RampFrame) -> Origin:
        return cls(E7.to_wire(frame.lat), E7.to_wire(frame.lon),
                   CDEG.to_wire(frame.ramp_bearing_deg))

    def to_frame(self) -> RampFrame:
        return RampFrame(E7.from_wire(self.lat_e7), E7.from_wire(self.lon_e7),
                         CDEG.from_wire(self.ramp_bearing_cdeg))


@dataclass(frozen=True)
class MissionItem:
    """One USV_MISSION_ITEM's values (integers as on the wire)."""

    mission_id: int
    seq: int
    lat: int  # 1e-7 deg
    lon: int
    t_ms: int
    speed_cms: int
    course_cdeg: int
    heading_cdeg: int

    @classmethod
    def from_msg(cls, msg: Any) -> MissionItem:
        return cls(msg.mission_id, msg.seq, msg.lat, msg.lon, msg.t_ms, msg.speed_cms,
                   msg.course_cdeg, msg.heading_cdeg)

    def as_dict(self) -> dict[str, int]:
        return {k: getattr(self, k) for k in self.__dataclass_fields__}


@dataclass(frozen=True)
class Mission:
    """A validated, wire-ready mission: id, items and the origin it was planned in."""

    mission_id: int
    items: tuple[MissionItem, ...]
    origin: Origin | None = None

    def __post_init__(self) -> None:
        validate_items(self.mission_id, self.items)

    @property
    def crc(self) -> int:
        return item_crc32(self.items)

    @property
    def count(self) -> int:
        return len(self.items)


def item_problem(it: Any) -> str | None:
    """Why one item's values are out of range, or None (the boat's per-item check)."""
    if not -LAT_MAX_E7 <= it.lat <= LAT_MAX_E7:
        return f"lat {it.lat} outside +-90 deg"
    if not -LON_MAX_E7 <= it.lon <= LON_MAX_E7:
        return f"lon {it.lon} outside +-180 deg"
    if it.speed_cms > SPEED_MAX_CMS:
        return f"speed_cms {it.speed_cms} above {SPEED_MAX_CMS}"
    if not 0 <= it.course_cdeg < 36000:
        return f"course_cdeg {it.course_cdeg} outside 0..35999"
    if not 0 <= it.heading_cdeg < 36000:
        return f"heading_cdeg {it.heading_cdeg} outside 0..35999"
    if it.seq == 0 and it.t_ms != 0:
        return f"t_ms {it.t_ms} of item 0 is not 0"
    return None


def sequence_problem(items: Sequence[Any]) -> tuple[int, str] | None:
    """(index, why) of the first item whose time does not increase, or None."""
    for i in range(1, len(items)):
        if items[i].t_ms <= items[i - 1].t_ms:
            return i, f"t_ms {items[i].t_ms} not after the previous item's {items[i - 1].t_ms}"
    return None


def validate_items(mission_id: int, items: Sequence[MissionItem]) -> None:
    """Raise MissionError unless the items form an executable mission."""
    if not 1 <= mission_id <= 0xFFFFFFFF:
        raise MissionError(f"mission_id must be 1..2^32-1, got {mission_id}")
    if not MIN_ITEMS <= len(items) <= MAX_MISSION_ITEMS:
        raise MissionError(f"a mission has {MIN_ITEMS}..{MAX_MISSION_ITEMS} waypoints, "
                           f"got {len(items)}")
    for i, it in enumerate(items):
        if it.seq != i or it.mission_id != mission_id:
            raise MissionError(f"waypoint {i}: seq/mission_id {it.seq}/{it.mission_id}, "
                               f"expected {i}/{mission_id}")
        problem = item_problem(it)
        if problem:
            raise MissionError(f"waypoint {i}: {problem}")
    bad = sequence_problem(items)
    if bad:
        raise MissionError(f"waypoint {bad[0]}: {bad[1]}")


def mission_from_plan(waypoints: Sequence[Mapping[str, Any]], frame: RampFrame,
                      mission_id: int) -> Mission:
    """Convert plan waypoints {x, y, t, speed, heading_deg} (ramp frame, DESIGN.md "Plan
    output") to a wire mission anchored at `frame`. Raises MissionError on bad input."""
    if not waypoints:
        raise MissionError("the plan has no waypoints")
    try:
        x, y, t, speed, heading_deg = (
            np.array([float(w[k]) for w in waypoints])
            for k in ("x", "y", "t", "speed", "heading_deg")
        )
    except (KeyError, TypeError, ValueError) as exc:
        raise MissionError(f"waypoints need numeric x, y, t, speed, heading_deg ({exc})") from None
    for name, arr in (("x", x), ("y", y), ("t", t), ("speed", speed), ("heading_deg", heading_deg)):
        bad = np.flatnonzero(~np.isfinite(arr))
        if bad.size:
            raise MissionError(f"waypoint {bad[0]}: {name} is not a finite number")
    if np.any(t < 0) or np.any(t * 1000 > 0xFFFFFFFF):
        raise MissionError(f"waypoint {int(np.argmax((t < 0) | (t * 1000 > 0xFFFFFFFF)))}: "
                           "t outside 0..4294967 s")
    if np.any(speed < 0) or np.any(speed * 100 > SPEED_MAX_CMS):
        i = int(np.argmax((speed < 0) | (speed * 100 > SPEED_MAX_CMS)))
        raise MissionError(f"waypoint {i}: speed {speed[i]} outside 0..{SPEED_MAX_CMS / 100} m/s")
    # course over ground of the leg leaving each waypoint (the last: its arrival heading)
    course = np.array(heading_deg, dtype=float)
    dx, dy = np.diff(x), np.diff(y)
    moving = np.hypot(dx, dy) > 1e-6
    course[:-1][moving] = np.degrees(np.arctan2(dy[moving], dx[moving]))
    lat, lon = frame.to_geodetic(x, y)
    compass_heading = np.atleast_1d(frame.heading_to_compass_deg(heading_deg))
    compass_course = np.atleast_1d(frame.heading_to_compass_deg(course))
    items = tuple(
        MissionItem(mission_id, i, E7.to_wire(la), E7.to_wire(lo), MS.to_wire(tt),
                    CM.to_wire(sp), CDEG.to_wire(cc), CDEG.to_wire(hd))
        for i, (la, lo, tt, sp, cc, hd) in enumerate(
            zip(np.atleast_1d(lat), np.atleast_1d(lon), t, speed, compass_course,
                compass_heading, strict=True))
    )
    return Mission(mission_id, items, Origin.from_frame(frame))


def plan_from_mission(mission: Mission, frame: RampFrame | None = None) -> list[dict[str, float]]:
    """The mission's waypoints back in the ramp frame of `frame` (default: its own origin)."""
    if frame is None:
        if mission.origin is None:
            raise MissionError("plan_from_mission needs a frame for a mission without origin")
        frame = mission.origin.to_frame()
    lat = E7.from_wire(np.array([it.lat for it in mission.items]))
    lon = E7.from_wire(np.array([it.lon for it in mission.items]))
    x, y = frame.to_ramp(lat, lon)
    cdeg = [it.heading_cdeg for it in mission.items]
    heading = frame.compass_to_heading_deg(CDEG.from_wire(cdeg))
    return [
        {"x": float(x[i]), "y": float(y[i]), "t": MS.from_wire(it.t_ms),
         "speed": CM.from_wire(it.speed_cms), "heading_deg": float(heading[i])}
        for i, it in enumerate(mission.items)
    ]


def distance_m(lat_e7: int, lon_e7: int, lat2_e7: int, lon2_e7: int) -> float:
    """Great-circle distance between two wire positions (haversine, WGS-84 mean radius)."""
    p1, p2 = math.radians(E7.from_wire(lat_e7)), math.radians(E7.from_wire(lat2_e7))
    dp, dl = p2 - p1, math.radians(E7.from_wire(lon2_e7 - lon_e7))
    a = math.sin(dp / 2) ** 2 + math.cos(p1) * math.cos(p2) * math.sin(dl / 2) ** 2
    return 2 * 6371008.8 * math.asin(min(1.0, math.sqrt(a)))
