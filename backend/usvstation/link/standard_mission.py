"""A usv-link mission as a standard MAVLink mission (MISSION_ITEM_INT items), and back.

What any ground station and any stock autopilot understand (docs/link.md "Standard
MAVLink"): one MAV_CMD_NAV_WAYPOINT per waypoint (MAV_FRAME_GLOBAL_RELATIVE_ALT, lat/lon in
1e-7 degrees, altitude 0), each but the last followed by a MAV_CMD_DO_CHANGE_SPEED whose
param2 is the leg's planned speed over ground: its length over its duration, the mean of
its end speeds in plans that follow paper 000's eq. 11 (`leg_speed`). So 2n - 1 items for
n waypoints. The timing itself (t_ms), the course and the hull heading have no place in a
standard mission: a usv-link 2 boat keeps them in the dialect, a stock autopilot sails
the legs at their speeds (AUTO) or follows the station's timed position targets (GUIDED).

An ArduPilot vehicle keeps its home position in item 0 and overwrites whatever is
uploaded there, so `home=True` puts a copy of waypoint 0 in front (2n items) and the
comparison skips it.

Pure: no I/O; the boats (sim/boat.py, the C boat's `usv_std_*`) answer reads with these
items and the station (link/standard.py) uploads and compares them.
"""

from __future__ import annotations

import itertools
import math
import struct
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from usvstation.link.mavlink import usv_recovery as mav

NAV_WAYPOINT = mav.MAV_CMD_NAV_WAYPOINT
DO_CHANGE_SPEED = mav.MAV_CMD_DO_CHANGE_SPEED
WAYPOINT_FRAME = mav.MAV_FRAME_GLOBAL_RELATIVE_ALT
COMMAND_FRAME = mav.MAV_FRAME_MISSION
SPEED_GROUND = 1.0  # DO_CHANGE_SPEED param1: ground speed
THROTTLE_UNCHANGED = -1.0  # DO_CHANGE_SPEED param3
SPEED_TOLERANCE = 0.01  # m/s: a leg speed read back may differ by float32 rounding only

_WGS84_A = 6378137.0
_WGS84_E2 = 6.69437999014e-3
_F32 = struct.Struct("<f")


def f32(v: float) -> float:
    """`v` as a float32 field carries it (what a MAVLink param holds)."""
    return _F32.unpack(_F32.pack(v))[0] if math.isfinite(v) else v


def leg_length_m(lat1_e7: int, lon1_e7: int, lat2_e7: int, lon2_e7: int) -> float:
    """Length of a leg between two wire positions on the WGS-84 ellipsoid: the meridian and
    prime-vertical radii of curvature at the mid latitude (the local tangent plane the
    ramp frame uses, geo.py, to 1e-6 over a recovery's legs)."""
    phi = math.radians((lat1_e7 + lat2_e7) * 0.5e-7)
    w = 1.0 - _WGS84_E2 * math.sin(phi) ** 2
    meridian = _WGS84_A * (1.0 - _WGS84_E2) / (w * math.sqrt(w))
    normal = _WGS84_A / math.sqrt(w)
    dn = math.radians((lat2_e7 - lat1_e7) * 1e-7) * meridian
    de = math.radians((lon2_e7 - lon1_e7) * 1e-7) * normal * math.cos(phi)
    return math.hypot(dn, de)


def leg_speed(a: Any, b: Any) -> float:
    """The planned speed (m/s) of the leg from item a to item b (lat, lon, t_ms, speed_cms):
    its length over its duration. A plan that follows paper 000's eq. 11 (dT = 2 L /
    (v_a + v_b), every planner here does) gives the same as the mean of its end speeds,
    which the wire carries to 1 cm/s where the 1e-7 degree positions make the length
    over a short leg less exact: then that mean; otherwise length / duration."""
    dt = (b.t_ms - a.t_ms) / 1000.0
    if dt <= 0:
        return 0.0
    geometric = leg_length_m(a.lat, a.lon, b.lat, b.lon) / dt
    mean = (a.speed_cms + b.speed_cms) / 200.0
    # the wire's rounding: 1e-7 deg at each end (about 1.6 cm together), 1 ms, 1 cm/s
    tolerance = 0.01 + (0.02 + 0.001 * geometric) / dt
    return mean if abs(mean - geometric) <= tolerance else geometric


def leg_speeds(items: Sequence[Any]) -> list[float]:
    """Planned speed of each leg of timed items (`leg_speed`)."""
    return [leg_speed(a, b) for a, b in itertools.pairwise(items)]


@dataclass(frozen=True)
class StandardItem:
    """One MISSION_ITEM_INT's values (params as the float32 the frame carries)."""

    seq: int
    frame: int
    command: int
    param1: float
    param2: float
    param3: float
    param4: float
    x: int
    y: int
    z: float = 0.0
    autocontinue: int = 1

    @classmethod
    def from_msg(cls, m: Any) -> StandardItem:
        return cls(m.seq, m.frame, m.command, m.param1, m.param2, m.param3, m.param4,
                   m.x, m.y, m.z, m.autocontinue)

    def fields(self) -> tuple[int, int, float, float, float, float, int, int, float]:
        """The values a copy must keep (float32-rounded): seq and autocontinue aside."""
        return (self.frame, self.command, f32(self.param1), f32(self.param2),
                f32(self.param3), f32(self.param4), self.x, self.y, f32(self.z))

    def as_dict(self) -> dict[str, float]:
        return {k: getattr(self, k) for k in self.__dataclass_fields__}


def waypoint_item(seq: int, lat_e7: int, lon_e7: int) -> StandardItem:
    return StandardItem(seq, WAYPOINT_FRAME, NAV_WAYPOINT, 0.0, 0.0, 0.0, 0.0, lat_e7, lon_e7)


def speed_item(seq: int, speed: float) -> StandardItem:
    return StandardItem(seq, COMMAND_FRAME, DO_CHANGE_SPEED, SPEED_GROUND, f32(speed),
                        THROTTLE_UNCHANGED, 0.0, 0, 0)


def standard_items(items: Sequence[Any], home: bool = False) -> tuple[StandardItem, ...]:
    """The standard mission of timed items (MissionItem: lat, lon, t_ms): NAV_WAYPOINT, then
    DO_CHANGE_SPEED with the leg's speed, for each waypoint (none after the last); with
    `home`, waypoint 0 once more in front as item 0 (ArduPilot's home slot)."""
    out: list[StandardItem] = []
    if home and items:
        out.append(waypoint_item(0, items[0].lat, items[0].lon))
    speeds = leg_speeds(items)
    for i, it in enumerate(items):
        out.append(waypoint_item(len(out), it.lat, it.lon))
        if i < len(speeds):
            out.append(speed_item(len(out), speeds[i]))
    return tuple(out)


def standard_count(n_waypoints: int, home: bool = False) -> int:
    """Items of the standard mission of n waypoints (0 for none)."""
    return 0 if n_waypoints == 0 else 2 * n_waypoints - 1 + int(home)


@dataclass(frozen=True)
class StandardWaypoint:
    """A waypoint as a standard mission holds it: where, and the speed of the leg after it
    (None for the last, or where no DO_CHANGE_SPEED follows)."""

    lat_e7: int
    lon_e7: int
    leg_speed: float | None


def waypoints_of(items: Sequence[StandardItem], home: bool = False) -> list[StandardWaypoint]:
    """The waypoints of a standard mission (any GCS's: other DO items are skipped; a
    DO_CHANGE_SPEED applies to the leg after the waypoint before it)."""
    out: list[StandardWaypoint] = []
    for it in items[1:] if home else items:
        if it.command == NAV_WAYPOINT:
            out.append(StandardWaypoint(it.x, it.y, None))
        elif it.command == DO_CHANGE_SPEED and out and it.param2 >= 0:
            last = out[-1]
            out[-1] = StandardWaypoint(last.lat_e7, last.lon_e7, it.param2)
    return out


def first_difference(sent: Sequence[StandardItem], held: Sequence[StandardItem],
                     home: bool = False) -> str | None:
    """Why the vehicle's copy `held` is not the mission `sent` (the first difference, one
    sentence), or None when it is (item 0 aside with `home`: the vehicle's home)."""
    if len(held) != len(sent):
        return f"the vehicle holds {len(held)} items, {len(sent)} were sent"
    for a, b in zip(sent, held, strict=True):
        if home and a.seq == 0:
            continue
        if b.seq != a.seq or a.fields() != b.fields():
            return (f"item {a.seq} differs: sent {_describe(a)}, the vehicle holds "
                    f"{_describe(b)}")
    return None


def _describe(it: StandardItem) -> str:
    if it.command == NAV_WAYPOINT:
        return f"NAV_WAYPOINT {it.x * 1e-7:.7f}, {it.y * 1e-7:.7f}"
    if it.command == DO_CHANGE_SPEED:
        return f"DO_CHANGE_SPEED {it.param2:.3f} m/s"
    return f"command {it.command}"


# ----------------------------------------------------------------------------- the boats' side

ROVER_HOLD, ROVER_LOITER, ROVER_AUTO = 4, 5, 10  # ArduPilot Rover's numbers and names
STATE_MODES = {0: ROVER_HOLD, 1: ROVER_LOITER, 2: ROVER_AUTO, 3: ROVER_LOITER,
               4: ROVER_LOITER, 5: ROVER_HOLD, 6: ROVER_LOITER, 7: ROVER_AUTO}
"""A usv-link 2 boat's state (USV_BOAT_STATE) as the HEARTBEAT custom_mode a ground station
names: a SURFACE_BOAT's custom modes are read with ArduPilot Rover's table (pymavlink,
MAVProxy, Mission Planner), where HOLD stops the motors, LOITER keeps station and AUTO
follows the mission. IDLE and ABORTED: HOLD; READY, HOLD, DONE and FAILSAFE (keeping
station): LOITER; RUNNING and GO_AROUND (the boat flies its escape route and standby on
its own): AUTO. The state itself is in USV_MISSION_STATE."""

MISSION_STATES = {0: mav.MISSION_STATE_NO_MISSION, 1: mav.MISSION_STATE_NOT_STARTED,
                  2: mav.MISSION_STATE_ACTIVE, 3: mav.MISSION_STATE_PAUSED,
                  4: mav.MISSION_STATE_COMPLETE, 5: mav.MISSION_STATE_NO_MISSION,
                  6: mav.MISSION_STATE_PAUSED, 7: mav.MISSION_STATE_ACTIVE}
"""The boat state as MISSION_CURRENT.mission_state (IDLE and ABORTED hold no mission)."""


def standard_mode(state: int) -> int:
    """HEARTBEAT.custom_mode for a boat state (a state this table does not know: AUTO)."""
    return STATE_MODES.get(state, ROVER_AUTO)


def standard_armed(state: int) -> bool:
    """HEARTBEAT's SAFETY_ARMED: the propellers drive a mission (RUNNING, HOLD, FAILSAFE,
    GO_AROUND)."""
    return state in (2, 3, 6, 7)


def nav_seq(waypoint: int, home: bool = False) -> int:
    """The mission item of waypoint `waypoint` (its NAV_WAYPOINT)."""
    return 2 * waypoint + int(home)
