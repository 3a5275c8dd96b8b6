"""Timed trajectories: waypoints (x, y, t) with position linear in time between them.

This is the plan's own model (shared/DESIGN.md "Plan output"; the
average-velocity assumption of paper 000 eq. 9).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from usvstation.geometry import position_at


@dataclass(frozen=True, eq=False)
class Trajectory:
    """Waypoints `points` (N x 2, metres) reached at `times` (N, seconds, increasing)."""

    points: np.ndarray
    times: np.ndarray

    def __post_init__(self) -> None:
        pts = np.asarray(self.points, dtype=float)
        ts = np.asarray(self.times, dtype=float)
        if pts.ndim != 2 or pts.shape[1] != 2 or pts.shape[0] < 2:
            raise ValueError(f"trajectory: need at least 2 waypoints (x, y), got shape {pts.shape}")
        if ts.shape != (pts.shape[0],):
            raise ValueError(
                f"trajectory: {pts.shape[0]} waypoints but {ts.size} times"
            )
        if not (np.all(np.isfinite(pts)) and np.all(np.isfinite(ts))):
            raise ValueError("trajectory: waypoints and times must be finite")
        bad = np.flatnonzero(np.diff(ts) <= 0.0)
        if bad.size:
            i = int(bad[0])
            raise ValueError(
                f"trajectory: times must increase (waypoint {i + 1} at t = {ts[i + 1]:g} s "
                f"is not after waypoint {i} at t = {ts[i]:g} s)"
            )
        pts.setflags(write=False)
        ts.setflags(write=False)
        object.__setattr__(self, "points", pts)
        object.__setattr__(self, "times", ts)
        seg = np.diff(pts, axis=0)
        lengths = np.hypot(seg[:, 0], seg[:, 1])
        object.__setattr__(self, "_seg", seg)
        object.__setattr__(self, "_len", lengths)
        object.__setattr__(self, "_arc", np.concatenate([[0.0], np.cumsum(lengths)]))

    @classmethod
    def from_xyt(cls, rows: Iterable[Sequence[float]]) -> Trajectory:
        """From (x, y, t) rows."""
        arr = np.asarray(list(rows), dtype=float)
        if arr.ndim != 2 or arr.shape[1] != 3:
            raise ValueError("trajectory: expected rows of (x, y, t)")
        return cls(arr[:, :2], arr[:, 2])

    @classmethod
    def from_plan(cls, plan: Mapping[str, Any]) -> Trajectory:
        """From a plan dict's `waypoints` (stable plan output)."""
        try:
            rows = [(w["x"], w["y"], w["t"]) for w in plan["waypoints"]]
        except (KeyError, TypeError) as exc:
            raise ValueError(f"trajectory: plan waypoints need x, y and t ({exc})") from None
        return cls.from_xyt(rows)

    @property
    def segment_count(self) -> int:
        return self.points.shape[0] - 1

    @property
    def start_time(self) -> float:
        return float(self.times[0])

    @property
    def end_time(self) -> float:
        return float(self.times[-1])

    @property
    def length(self) -> float:
        return float(self._arc[-1])

    def segment(self, i: int) -> tuple[float, float, float, float]:
        """(ax, ay, bx, by) of segment i."""
        a, b = self.points[i], self.points[i + 1]
        return float(a[0]), float(a[1]), float(b[0]), float(b[1])

    def segment_length(self, i: int) -> float:
        return float(self._len[i])

    def segment_heading(self, i: int) -> float:
        """Heading of segment i; of the nearest non-degenerate one if it has no length."""
        order = [i, *range(i - 1, -1, -1), *range(i + 1, self.segment_count)]
        for j in order:
            if self._len[j] > 1e-12:
                return math.atan2(self._seg[j, 1], self._seg[j, 0])
        return 0.0

    @property
    def arrival_heading(self) -> float:
        """Heading of the last segment: the direction the boat should arrive in."""
        return self.segment_heading(self.segment_count - 1)

    def time_at(self, i: int, s: float) -> float:
        """Scheduled time of the point at fraction s of segment i."""
        t0, t1 = self.times[i], self.times[i + 1]
        return float(t0 + s * (t1 - t0))

    def point_at(self, i: int, s: float) -> tuple[float, float]:
        a, d = self.points[i], self._seg[i]
        return float(a[0] + s * d[0]), float(a[1] + s * d[1])

    def arc_at(self, i: int, s: float) -> float:
        """Path length from the start to the point at fraction s of segment i."""
        return float(self._arc[i] + s * self._len[i])

    def locate_arc(self, arc: float) -> tuple[int, float]:
        """(segment, fraction) of the point `arc` metres along the path, clamped to its ends."""
        if arc <= 0.0:
            return 0, 0.0
        if arc >= self._arc[-1]:
            return self.segment_count - 1, 1.0
        i = int(np.searchsorted(self._arc, arc, side="right")) - 1
        i = min(i, self.segment_count - 1)
        seg_len = self._len[i]
        return i, float((arc - self._arc[i]) / seg_len) if seg_len > 0 else 0.0

    def _segment_index(self, t: np.ndarray) -> np.ndarray:
        return np.clip(np.searchsorted(self.times, t, side="right") - 1, 0, self.segment_count - 1)

    def position_at(self, t: float | np.ndarray) -> np.ndarray:
        """Desired position at time(s) t; held at the ends outside [start, end]."""
        x, y = position_at(self.times, self.points[:, 0], self.points[:, 1],
                           np.asarray(t, dtype=float))
        return np.stack([x, y], axis=-1)

    def velocity_at(self, t: float) -> tuple[float, float]:
        """Desired velocity at time t (the segment's average velocity); zero outside the plan."""
        if t < self.times[0] or t > self.times[-1]:
            return 0.0, 0.0
        i = int(self._segment_index(np.asarray(t)))
        dt = self.times[i + 1] - self.times[i]
        return float(self._seg[i, 0] / dt), float(self._seg[i, 1] / dt)

    def speed_at(self, t: float) -> float:
        """The isochronous target speed: the desired trajectory's speed at time t.

        Before the start it is the first segment's, after the end the last
        segment's (a late boat keeps going rather than stopping short).
        """
        vx, vy = self.velocity_at(min(max(t, self.start_time), self.end_time))
        return math.hypot(vx, vy)

    def extended(self, length: float) -> Trajectory:
        """The trajectory continued `length` metres past its end, along its arrival heading,
        at the speed of its last segment (the boat keeps going onto the ramp)."""
        if not length > 0.0:
            raise ValueError(f"trajectory: extension length must be > 0 (got {length})")
        i = self.segment_count - 1
        dt = self.times[i + 1] - self.times[i]
        speed = max(self._len[i] / dt, 0.1)
        h = self.arrival_heading
        end = self.points[-1]
        extra = end + length * np.array([math.cos(h), math.sin(h)])
        return Trajectory(
            np.vstack([self.points, extra]),
            np.append(self.times, self.times[-1] + length / speed),
        )

    def replace_tail(self, from_arc: float, via: tuple[float, float]) -> Trajectory:
        """The path up to `from_arc` metres before the end, then straight to `via`, then the end.

        Only the last `from_arc` metres change: the point P of the path that
        far from the end is kept (at its scheduled time) and the path runs
        P -> via -> end, `via` timed in proportion to the distance along the
        new tail. Used to bend the final approach (see CompensatedAVLOS).
        """
        total = self.length
        arc = total - from_arc
        if not 0.0 < arc < total:
            raise ValueError(f"trajectory: tail length must be within (0, {total:g}) m")
        if not (math.isfinite(via[0]) and math.isfinite(via[1])):
            raise ValueError(f"trajectory: via point must be finite (got {via})")
        i, s = self.locate_arc(arc)
        px, py = self.point_at(i, s)
        t_p = self.time_at(i, s)
        end = self.points[-1]
        first = math.hypot(via[0] - px, via[1] - py)
        second = math.hypot(end[0] - via[0], end[1] - via[1])
        t_via = t_p + (self.end_time - t_p) * first / max(first + second, 1e-12)
        keep = i + 1
        pts = np.vstack([self.points[:keep], [[px, py]], [via], end[None, :]])
        ts = np.concatenate([self.times[:keep], [t_p, t_via, self.end_time]])
        # Drop a kept waypoint that coincides with P (P on a waypoint).
        if ts[keep] <= ts[keep - 1] + 1e-12:
            pts = np.delete(pts, keep, axis=0)
            ts = np.delete(ts, keep)
        return Trajectory(pts, ts)


class Schedule:
    """When each point of a trajectory's path is due: a monotone map between time and arc length.

    `exact` is the plan's own piecewise-linear time law. `feasible` replaces
    its instant speed changes by linear ramps of at most `accel` m/s^2
    centred on them (a box filter of the arc-length law over
    max|dv| / accel seconds), so a boat that can only ramp its speed (the
    paper's assumption) can follow it; away from the ramps it equals the
    plan, near them it differs by at most |dv| tau / 8 metres.
    """

    def __init__(self, times: np.ndarray, arcs: np.ndarray) -> None:
        self.times = np.asarray(times, dtype=float)
        self.arcs = np.maximum.accumulate(np.asarray(arcs, dtype=float))
        self.total = float(self.arcs[-1])
        if self.times.shape != self.arcs.shape or self.times.size < 2:
            raise ValueError("schedule: need matching time and arc arrays of 2 or more points")

    @classmethod
    def exact(cls, trajectory: Trajectory) -> Schedule:
        return cls(trajectory.times, trajectory._arc)

    @classmethod
    def feasible(cls, trajectory: Trajectory, accel: float, step: float = 0.01) -> Schedule:
        if not accel > 0.0:
            raise ValueError(f"schedule: accel must be > 0 (got {accel})")
        times, arcs = trajectory.times, trajectory._arc
        speeds = np.diff(arcs) / np.diff(times)
        jumps = np.abs(np.diff(np.concatenate([[0.0], speeds])))
        tau = float(jumps.max()) / accel
        n = round(tau / step)
        if n < 2:
            return cls.exact(trajectory)
        pad = (n // 2 + 1) * step
        grid = np.arange(times[0] - pad, times[-1] + pad + step / 2, step)
        # Before the plan the boat is at rest; after it, it carries on at the last
        # segment's speed (onto the ramp), so the schedule does not brake at the end.
        ext = np.arange(1, n + 1) * step
        grid_ext = np.concatenate([times[0] - pad - ext[::-1], grid, grid[-1] + ext])
        law = np.interp(grid_ext, times, arcs)
        after = grid_ext > times[-1]
        law[after] = arcs[-1] + speeds[-1] * (grid_ext[after] - times[-1])
        kernel = np.full(n, 1.0 / n)
        smooth = np.convolve(law, kernel, mode="same")[n:-n]
        return cls(grid, smooth)

    def time_at_arc(self, arc: float) -> float:
        """Scheduled time of the path point `arc` metres from the start (the first such time)."""
        arcs, times = self.arcs, self.times
        if arc <= arcs[0]:
            return float(times[0])
        if arc >= self.total:
            return float(times[-1])
        i = int(np.searchsorted(arcs, arc, side="left"))
        a0, a1 = arcs[i - 1], arcs[i]
        w = (arc - a0) / (a1 - a0) if a1 > a0 else 1.0
        return float(times[i - 1] + w * (times[i] - times[i - 1]))

    def speed_at_time(self, t: float) -> float:
        """Scheduled speed along the path at time t (zero outside the schedule)."""
        times = self.times
        if t < times[0] or t >= times[-1]:
            return 0.0
        i = min(int(np.searchsorted(times, t, side="right")) - 1, times.size - 2)
        return float((self.arcs[i + 1] - self.arcs[i]) / (times[i + 1] - times[i]))
