"""The vehicle interface the simulated boat drives, and a kinematic vehicle implementing it.

`Vehicle` is what sim/boat.py (the boat side of usv-link) needs from a boat model:
the 3-DOF dynamic model with AV-LOS guidance (issue 3) plugs in behind the same
interface. Everything is in one planar world frame (metres, the sim's ramp frame),
headings in radians anticlockwise from +x, times in seconds of boat time.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from itertools import pairwise
from typing import Protocol, runtime_checkable

import numpy as np

from usvstation.geometry import angle_diff, cross_track_error, position_at
from usvstation.sim.frame import RampMotion


@dataclass(frozen=True)
class Waypoint:
    """A mission waypoint in the world frame; position is linear in time between waypoints."""

    x: float
    y: float
    t: float  # s after the mission start
    speed: float  # m/s
    heading: float  # rad, anticlockwise from +x (segment leaving the waypoint)


@dataclass(frozen=True)
class VehicleState:
    """What the vehicle reports; the boat turns it into TELEMETRY."""

    t: float = 0.0  # boat time, s
    x: float = 0.0
    y: float = 0.0
    heading: float = 0.0  # rad, anticlockwise from +x
    speed: float = 0.0  # speed over ground, m/s
    course: float = 0.0  # course over ground, rad, anticlockwise from +x
    yaw_rate: float = 0.0  # rad/s, anticlockwise positive
    thrust_left: float = 0.0  # -1..1 of full thrust
    thrust_right: float = 0.0
    waypoint_index: int = 0  # waypoint being steered to
    cross_track_error: float = 0.0  # m, positive left of the track
    mission_complete: bool = False


@runtime_checkable
class Vehicle(Protocol):
    """A boat model the simulated boat can drive (sim/boat.py)."""

    @property
    def state(self) -> VehicleState:
        """What the boat knows of itself (measured); its telemetry reports this."""
        ...

    @property
    def truth(self) -> VehicleState:
        """The true state, for a trial's judge or a bench only."""
        ...

    def step(self, dt: float) -> None:
        """Advance boat time by dt seconds."""

    def set_mission(self, waypoints: Sequence[Waypoint]) -> None:
        """Replace the mission (not started: the vehicle keeps station until start())."""

    def start(self) -> None:
        """Begin the mission from its first waypoint."""

    def hold(self) -> None:
        """Keep station where the vehicle is; the mission clock stops."""

    def resume(self) -> None:
        """Continue the mission after hold()."""

    def abort(self) -> None:
        """Stop the thrusters and drop the mission."""

    def set_guidance(self, heading: float, speed: float) -> None:
        """Shore-assisted mode: steer `heading` (rad) at `speed` (m/s) until clear_guidance()."""

    def clear_guidance(self) -> None:
        """Leave shore-assisted mode and rejoin the mission."""


def checked_mission(waypoints: Sequence[Waypoint]) -> list[Waypoint]:
    """The waypoints as a list; ValueError unless their times increase."""
    wps = list(waypoints)
    if not wps or any(b.t <= a.t for a, b in pairwise(wps)):
        raise ValueError("a mission needs waypoints with increasing times")
    return wps


def leg_cross_track(wps: Sequence[Waypoint], x: float, y: float, i: int) -> float:
    """Cross-track error of (x, y) from the leg into waypoint i (m, positive left, as
    geometry.cross_track_error); 0 before the first leg, past the last, on a zero-length leg."""
    if i == 0 or i >= len(wps):
        return 0.0
    a, b = wps[i - 1], wps[i]
    if math.hypot(b.x - a.x, b.y - a.y) < 1e-9:
        return 0.0
    return cross_track_error(x, y, a.x, a.y, b.x, b.y)


class KinematicVehicle:
    """A kinematic stand-in for the dynamic model: follows the active mission exactly, with
    position linear in time between waypoints (DESIGN.md "Plan output", paper 000 eq. 9).

    Off the track (before start, after guidance) it first goes straight back to the
    mission's reference point at `rejoin_speed`, then follows the mission clock again.
    Thrust is a plausible derived figure (speed share plus a turn differential), not a model.

    With a moving ramp frame (`set_frame`, sim/frame.py) it moves in that frame exactly as
    it would in a fixed one, and `state` is mapped into the world frame (velocity over
    ground: its own relative to the ramp plus the ramp's).
    """

    def __init__(self, x: float = 0.0, y: float = 0.0, heading: float = 0.0, *,
                 speed_max: float = 3.0, rejoin_speed: float = 1.0) -> None:
        self._state = VehicleState(x=x, y=y, heading=heading, course=heading)
        self.speed_max = speed_max
        self.rejoin_speed = rejoin_speed
        self._wps: list[Waypoint] = []
        self._tau = 0.0  # mission clock, s
        self._phase = "idle"  # idle | track | rejoin | hold | guided | done | stopped
        self._guidance = (0.0, 0.0)
        self._clock = 0.0  # every dt stepped (BoatProtocol's boat time)
        self._motion = RampMotion()

    @property
    def state(self) -> VehicleState:
        """The state in the world frame (`_state` is in the ramp frame)."""
        f = self._motion.at(self._clock)
        s = self._state
        if f.identity:
            return s
        x, y = f.to_world(s.x, s.y)
        c, sn = math.cos(f.theta), math.sin(f.theta)
        rvx, rvy = s.speed * math.cos(s.course), s.speed * math.sin(s.course)
        px, py = f.point_velocity(x, y)
        gx, gy = c * rvx - sn * rvy + px, sn * rvx + c * rvy + py
        speed = math.hypot(gx, gy)
        heading = s.heading + f.theta
        return replace(s, x=x, y=y, heading=heading, speed=speed,
                       course=math.atan2(gy, gx) if speed > 1e-6 else heading,
                       yaw_rate=s.yaw_rate + f.omega)

    def set_frame(self, motion: RampMotion, *, reanchor: bool = False) -> None:
        """The ramp frame's motion in the world frame (times on the vehicle's clock). The
        vehicle keeps its ramp-frame position; with `reanchor` (the frame jumped) it keeps
        its world position instead."""
        if reanchor:
            w = self.state
            x, y = motion.at(self._clock).to_ramp(w.x, w.y)
            self._state = replace(self._state, x=x, y=y,
                                  heading=w.heading - motion.at(self._clock).theta)
        self._motion = motion

    sensed = False  # `state` is the truth: the boat adds its GPS error to its telemetry

    @property
    def truth(self) -> VehicleState:
        return self.state

    @property
    def phase(self) -> str:
        return self._phase

    def set_mission(self, waypoints: Sequence[Waypoint]) -> None:
        wps = checked_mission(waypoints)
        self._wps = wps
        self._tau = wps[0].t
        self._phase = "idle"
        self._state = replace(self._state, waypoint_index=0, mission_complete=False)

    def start(self) -> None:
        if not self._wps:
            raise ValueError("no mission to start")
        self._tau = self._wps[0].t
        self._phase = "rejoin"
        self._state = replace(self._state, mission_complete=False)

    def hold(self) -> None:
        if self._phase in ("track", "rejoin", "guided"):
            self._phase = "hold"

    def resume(self) -> None:
        if self._phase == "hold":
            self._phase = "rejoin"

    def abort(self) -> None:
        self._wps = []
        self._phase = "stopped"

    def set_guidance(self, heading: float, speed: float) -> None:
        if self._phase in ("track", "rejoin", "guided"):
            self._guidance = (heading, max(0.0, min(speed, self.speed_max)))
            self._phase = "guided"

    def clear_guidance(self) -> None:
        if self._phase == "guided":
            self._phase = "rejoin"

    # ---- motion

    def reference(self, tau: float) -> tuple[float, float, int]:
        """Mission position at mission time tau, and the index of the waypoint ahead."""
        wps = self._wps
        ts = [w.t for w in wps]
        if tau <= ts[0]:
            return wps[0].x, wps[0].y, 0
        if tau >= ts[-1]:
            return wps[-1].x, wps[-1].y, len(wps) - 1
        x, y = position_at(ts, [w.x for w in wps], [w.y for w in wps], tau)
        return x, y, int(np.searchsorted(ts, tau, side="right"))

    def step(self, dt: float) -> None:
        if dt <= 0:
            return
        self._clock += dt
        s = self._state
        x, y, heading, speed = s.x, s.y, s.heading, 0.0
        index, complete = s.waypoint_index, s.mission_complete
        if self._phase == "track":
            self._tau += dt
            x, y, index = self.reference(self._tau)
            speed = math.hypot(x - s.x, y - s.y) / dt
            if speed > 1e-6:
                heading = math.atan2(y - s.y, x - s.x)
            if self._tau >= self._wps[-1].t:
                self._phase, complete, speed = "done", True, 0.0
        elif self._phase == "rejoin":
            rx, ry, index = self.reference(self._tau)
            dist = math.hypot(rx - x, ry - y)
            v = max(self.rejoin_speed, self._wps[max(index - 1, 0)].speed)
            if dist <= v * dt:
                x, y = rx, ry
                self._phase = "track"
                speed = dist / dt
            else:
                heading = math.atan2(ry - y, rx - x)
                x += v * dt * math.cos(heading)
                y += v * dt * math.sin(heading)
                speed = v
        elif self._phase == "guided":
            heading, speed = self._guidance
            x += speed * dt * math.cos(heading)
            y += speed * dt * math.sin(heading)
        course = math.atan2(y - s.y, x - s.x) if speed > 1e-6 else s.course
        yaw_rate = angle_diff(heading, s.heading) / dt
        share = speed / self.speed_max
        diff = max(-0.5, min(0.5, yaw_rate))  # turn anticlockwise: right thruster harder
        left = max(-1.0, min(1.0, share - diff)) if speed > 0 else 0.0
        right = max(-1.0, min(1.0, share + diff)) if speed > 0 else 0.0
        xte = leg_cross_track(self._wps, x, y, index)
        self._state = VehicleState(
            t=s.t + dt, x=x, y=y, heading=heading, speed=speed, course=course,
            yaw_rate=yaw_rate, thrust_left=left, thrust_right=right, waypoint_index=index,
            cross_track_error=xte, mission_complete=complete,
        )
