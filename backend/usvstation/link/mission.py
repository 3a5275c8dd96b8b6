"""A mission as sent on the wire: plan waypoints (ramp frame, SI) to MISSION_ITEMs and back.

Items carry WGS-84 lat/lon in 1e-7 degrees, t in ms, speed in cm/s and the compass
heading of the segment leaving the waypoint in 0.01 degree (protocol/README.md).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from usvstation.geo import RampFrame
from usvstation.link import messages as m
from usvstation.link.codec import mission_crc32

LAT_MAX_E7 = 90 * 10**7
LON_MAX_E7 = 180 * 10**7


class MissionError(ValueError):
    """A mission that cannot be sent or executed; the message names the waypoint and field."""


@dataclass(frozen=True)
class Origin:
    """The ramp-frame origin on the wire: ramp end lat/lon (1e-7 deg), +x bearing (0.01 deg)."""

    lat_e7: int
    lon_e7: int
    ramp_bearing_cdeg: int

    @classmethod
    def from_frame(cls, frame: RampFrame) -> Origin:
        return cls(round(frame.lat * 1e7), round(frame.lon * 1e7),
                   round(frame.ramp_bearing_deg % 360.0 * 100) % 36000)

    def to_frame(self) -> RampFrame:
        return RampFrame(self.lat_e7 / 1e7, self.lon_e7 / 1e7, self.ramp_bearing_cdeg / 100)

    def as_tuple(self) -> tuple[int, int, int]:
        return (self.lat_e7, self.lon_e7, self.ramp_bearing_cdeg)


@dataclass(frozen=True)
class Mission:
    """A verified, wire-ready mission: its id, origin and items (MissionItem messages)."""

    mission_id: int
    origin: Origin
    items: tuple[m.MissionItem, ...]

    def __post_init__(self) -> None:
        validate_items(self.mission_id, self.items)

    @property
    def crc(self) -> int:
        return mission_crc32(self.origin.as_tuple(), self.items)

    @property
    def count(self) -> int:
        return len(self.items)

    def begin(self) -> m.MissionBegin:
        return m.MissionBegin(self.mission_id, self.count, self.crc, *self.origin.as_tuple())

    def end(self) -> m.MissionEnd:
        return m.MissionEnd(self.mission_id, self.count, self.crc)


def validate_items(mission_id: int, items: Sequence[m.MissionItem]) -> None:
    """Raise MissionError unless the items form an executable mission (README "Mission")."""
    if not 1 <= mission_id <= 0xFFFF:
        raise MissionError(f"mission_id must be 1..65535, got {mission_id}")
    if not 1 <= len(items) <= m.MAX_MISSION_ITEMS:
        raise MissionError(f"a mission has 1..{m.MAX_MISSION_ITEMS} waypoints, got {len(items)}")
    prev_t = -1
    for i, it in enumerate(items):
        problem = item_problem(it)
        if it.index != i or it.mission_id != mission_id:
            problem = f"index/mission_id {it.index}/{it.mission_id}, expected {i}/{mission_id}"
        elif problem is None and it.t_ms <= prev_t:
            problem = f"t_ms {it.t_ms} not after the previous waypoint's {prev_t}"
        if problem:
            raise MissionError(f"waypoint {i}: {problem}")
        prev_t = it.t_ms


def item_problem(it: m.MissionItem) -> str | None:
    """Why a single item is out of range, or None (the boat's per-item check, BAD_ITEM)."""
    if not -LAT_MAX_E7 <= it.lat_e7 <= LAT_MAX_E7:
        return f"lat_e7 {it.lat_e7} outside +-90 deg"
    if not -LON_MAX_E7 <= it.lon_e7 <= LON_MAX_E7:
        return f"lon_e7 {it.lon_e7} outside +-180 deg"
    if not 0 <= it.heading_cdeg < 36000:
        return f"heading_cdeg {it.heading_cdeg} outside 0..35999"
    return None


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
    if np.any(speed < 0) or np.any(speed * 100 > 0xFFFF):
        i = int(np.argmax((speed < 0) | (speed * 100 > 0xFFFF)))
        raise MissionError(f"waypoint {i}: speed {speed[i]} outside 0..655.35 m/s")
    lat, lon = frame.to_geodetic(x, y)
    compass = frame.heading_to_compass_deg(heading_deg)
    items = tuple(
        m.MissionItem(mission_id, i, round(la * 1e7), round(lo * 1e7), round(tt * 1000),
                      round(sp * 100), round(hd * 100) % 36000)
        for i, (la, lo, tt, sp, hd) in enumerate(
            zip(np.atleast_1d(lat), np.atleast_1d(lon), t, speed, compass, strict=True))
    )
    return Mission(mission_id, Origin.from_frame(frame), items)


def plan_from_mission(mission: Mission, frame: RampFrame | None = None) -> list[dict[str, float]]:
    """The mission's waypoints back in the ramp frame of `frame` (default: its own origin)."""
    frame = frame or mission.origin.to_frame()
    lat = np.array([it.lat_e7 / 1e7 for it in mission.items])
    lon = np.array([it.lon_e7 / 1e7 for it in mission.items])
    x, y = frame.to_ramp(lat, lon)
    heading = frame.compass_to_heading_deg([it.heading_cdeg / 100 for it in mission.items])
    return [
        {"x": float(x[i]), "y": float(y[i]), "t": it.t_ms / 1000, "speed": it.speed_cms / 100,
         "heading_deg": float(heading[i])}
        for i, it in enumerate(mission.items)
    ]
