"""Classic LOS and AV-LOS guidance (paper 000 sec. 3.3, Fig. 9, eq. 13).

Both look ahead to where a circle of radius R around the boat crosses the
path. Following Fig. 9b, the crossing nearer the end of the current segment is
taken; when the end of the segment lies inside the circle the next segment is
searched too, and once the look-ahead point moves onto a later segment the
earlier ones are dropped. A boat farther than R from its segment steers to the
nearest point of it.

Classic LOS commands the heading to the look-ahead point and the desired
trajectory's speed at the current time (its "isochronous target speed").
AV-LOS commands the same heading and the speed R / dT that reaches the
look-ahead point at its scheduled time (eq. 13), saturated.

`overrun` metres of path are added past the end along the arrival heading
(the boat drives on up the ramp instead of circling the last waypoint).

All guidance objects are driven step by step: `update(pose, t)` with any pose
object having x, y and psi attributes (e.g. dynamics.VesselState).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Protocol

from usvstation.guidance.geometry import circle_segment_intersections, project_on_segment
from usvstation.guidance.trajectory import Schedule, Trajectory


class Pose(Protocol):
    x: float
    y: float
    psi: float


@dataclass(frozen=True)
class GuidanceCommand:
    """What the guidance asks of the autopilot.

    heading (rad, ramp frame); speed (m/s, over ground along the heading);
    target the look-ahead point and target_time its scheduled time;
    finished once the end of the trajectory is reached.
    """

    heading: float
    speed: float
    target: tuple[float, float]
    target_time: float
    segment: int
    finished: bool = False
    water_speed: float | None = None  # m/s through the water, when the guidance knows it


def check_pose(pose: Pose, t: float) -> None:
    """ValueError naming the field unless the pose and the time are finite numbers."""
    for name in ("x", "y", "psi"):
        value = getattr(pose, name)
        if not math.isfinite(value):
            raise ValueError(f"guidance: pose {name} must be finite (got {value})")
    if not math.isfinite(t):
        raise ValueError(f"guidance: time must be finite (got {t})")


@dataclass(frozen=True)
class Lookahead:
    segment: int
    fraction: float
    x: float
    y: float
    distance: float  # from the boat to the look-ahead point
    on_circle: bool  # False: the boat is off the path by more than R


class LookaheadTracker:
    """Finds the look-ahead point of Fig. 9b and remembers the current segment."""

    def __init__(self, trajectory: Trajectory, radius: float) -> None:
        if not radius > 0.0:
            raise ValueError(f"guidance: look-ahead radius must be > 0 (got {radius})")
        self.trajectory = trajectory
        self.radius = radius
        self.segment = 0

    def reset(self) -> None:
        self.segment = 0

    def find(self, x: float, y: float) -> Lookahead:
        tr, radius = self.trajectory, self.radius
        last = tr.segment_count - 1
        # Along-track switching: a boat past the end of its leg (measured along
        # the leg) is on the next one, whether or not its circle reaches it.
        # Without this a boat that overshoots a hairpin by more than R orbits.
        while self.segment < last and self._along(self.segment, x, y) >= 1.0:
            self.segment += 1
        best: tuple[int, float] | None = None
        j = self.segment
        while j <= last:
            ax, ay, bx, by = tr.segment(j)
            hits = circle_segment_intersections(x, y, radius, ax, ay, bx, by)
            if hits:
                best = (j, hits[-1])
            end_inside = math.hypot(bx - x, by - y) <= radius
            if not end_inside:
                break
            if j == last:
                best = (last, 1.0)
            j += 1
        if best is None:
            # Off the path by more than R: aim R ahead of the nearest point, so
            # the boat closes the path at an angle instead of circling a point.
            j = self.segment
            ax, ay, bx, by = tr.segment(j)
            s = project_on_segment(x, y, ax, ay, bx, by)
            seg, frac = tr.locate_arc(tr.arc_at(j, s) + radius)
            px, py = tr.point_at(seg, frac)
            return Lookahead(seg, frac, px, py, math.hypot(px - x, py - y), False)
        j, s = best
        self.segment = j
        px, py = tr.point_at(j, s)
        return Lookahead(j, s, px, py, math.hypot(px - x, py - y), True)

    def _along(self, j: int, x: float, y: float) -> float:
        """Unclamped along-track fraction of (x, y) on segment j."""
        ax, ay, bx, by = self.trajectory.segment(j)
        dx, dy = bx - ax, by - ay
        a = dx * dx + dy * dy
        if a == 0.0:
            return 1.0
        return ((x - ax) * dx + (y - ay) * dy) / a

    def past_end(self, x: float, y: float) -> bool:
        """True once (x, y) is past the end of the last segment, measured along it."""
        last = self.trajectory.segment_count - 1
        return self.segment == last and self._along(last, x, y) >= 1.0


class _LineOfSight:
    """Shared heading law: steer at the look-ahead point."""

    def __init__(self, trajectory: Trajectory, lookahead: float, speed_max: float,
                 arrive_radius: float, overrun: float) -> None:
        if not speed_max > 0.0:
            raise ValueError(f"guidance: speed_max must be > 0 (got {speed_max})")
        if overrun < 0.0:
            raise ValueError(f"guidance: overrun must be >= 0 (got {overrun})")
        if overrun > 0.0:
            trajectory = trajectory.extended(overrun)
        self.trajectory = trajectory
        self.tracker = LookaheadTracker(trajectory, lookahead)
        self.speed_max = speed_max
        self.arrive_radius = arrive_radius
        self.finished = False

    @property
    def lookahead(self) -> float:
        return self.tracker.radius

    def _look(self, pose: Pose, t: float = 0.0) -> tuple[Lookahead, float, float]:
        check_pose(pose, t)
        la = self.tracker.find(pose.x, pose.y)
        tr = self.trajectory
        at_end = la.segment == tr.segment_count - 1 and la.fraction >= 1.0
        if (at_end and la.distance <= self.arrive_radius) or self.tracker.past_end(pose.x, pose.y):
            self.finished = True
        if self.finished:  # past the last waypoint: hold the last bearing
            heading = tr.arrival_heading
        else:
            heading = math.atan2(la.y - pose.y, la.x - pose.x) if la.distance > 1e-9 else pose.psi
        return la, heading, tr.time_at(la.segment, la.fraction)

    def _command(self, la: Lookahead, heading: float, speed: float, t_la: float) -> GuidanceCommand:
        if self.finished:
            return GuidanceCommand(heading, 0.0, (la.x, la.y), t_la, la.segment, True)
        speed = min(max(speed, 0.0), self.speed_max)
        return GuidanceCommand(heading, speed, (la.x, la.y), t_la, la.segment)


class LOSGuidance(_LineOfSight):
    """Classic LOS (Fig. 9a) with the isochronous target speed."""

    def __init__(self, trajectory: Trajectory, lookahead: float = 3.0, speed_max: float = 3.0,
                 arrive_radius: float = 0.5, overrun: float = 0.0) -> None:
        super().__init__(trajectory, lookahead, speed_max, arrive_radius, overrun)

    def update(self, pose: Pose, t: float) -> GuidanceCommand:
        la, heading, t_la = self._look(pose, t)
        return self._command(la, heading, self.trajectory.speed_at(t), t_la)


def avlos_speed(distance: float, time_to_target: float, speed_max: float,
                speed_min: float = 0.0) -> float:
    """Paper 000 eq. 13: the speed R / dT that reaches the look-ahead point on schedule.

    Late (dT small or already past) asks for more speed, early for less;
    the result is saturated to [speed_min, speed_max].
    """
    if time_to_target <= 0.0:
        return speed_max
    return min(max(distance / time_to_target, speed_min), speed_max)


def limit_correction(speed: float, scheduled_speed: float, distance: float,
                     time_to_target: float, accel: float) -> float:
    """Cap eq. 13's departure from the scheduled speed to what the boat can take back.

    With e the distance the boat is ahead of schedule (behind: e < 0), a
    speed correction larger than sqrt(2 a |e|) cannot be undone by braking
    (or speeding up) at `accel` before the error is gone, so the boat would
    overshoot the schedule; the correction is held to that bound.
    """
    if time_to_target <= 0.0 or scheduled_speed <= 0.05:
        return speed
    ahead = (time_to_target - distance / scheduled_speed) * scheduled_speed
    cap = math.sqrt(2.0 * accel * abs(ahead))
    return scheduled_speed + min(max(speed - scheduled_speed, -cap), cap)


class AVLOSGuidance(_LineOfSight):
    """Average-velocity LOS (paper 000 eq. 13, Fig. 9b).

    With `accel` (m/s^2) two refinements for a boat whose speed can only
    ramp: the look-ahead point's due time comes from the plan's
    acceleration-feasible schedule (Schedule.feasible), and the eq. 13
    correction is capped by limit_correction. accel=None is eq. 13 alone.
    """

    def __init__(self, trajectory: Trajectory, lookahead: float = 3.0, speed_max: float = 3.0,
                 speed_min: float = 0.0, accel: float | None = None,
                 arrive_radius: float = 0.5, overrun: float = 0.0) -> None:
        super().__init__(trajectory, lookahead, speed_max, arrive_radius, overrun)
        self.speed_min = speed_min
        self.accel = accel
        tr = self.trajectory
        self.schedule = Schedule.feasible(tr, accel) if accel else Schedule.exact(tr)

    def velocity(self, pose: Pose, t: float) -> tuple[Lookahead, float, float, float]:
        """(look-ahead, heading, AV-LOS speed, look-ahead due time) at time t."""
        la, heading, _ = self._look(pose, t)
        t_la = self.schedule.time_at_arc(self.trajectory.arc_at(la.segment, la.fraction))
        dt = t_la - t
        speed = avlos_speed(la.distance, dt, self.speed_max, self.speed_min)
        if self.accel:
            v_sched = self.schedule.speed_at_time(t_la - 1e-9)
            speed = limit_correction(speed, v_sched, la.distance, dt, self.accel)
            speed = min(max(speed, self.speed_min), self.speed_max)
        return la, heading, speed, t_la

    def update(self, pose: Pose, t: float) -> GuidanceCommand:
        la, heading, speed, t_la = self.velocity(pose, t)
        return self._command(la, heading, speed, t_la)
