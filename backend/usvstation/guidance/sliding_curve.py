"""Sliding-curve guidance (paper 002 sec. II.C, Table III).

The virtual target s slides along the path a distance delta ahead of the
boat's projection q on the current leg W_i -> W_i+1:

    R_u = |W_i - p|, theta = atan2(W_i+1 - W_i), theta_u = atan2(p - W_i),
    beta = theta - theta_u, R = R_u cos(beta), s = W_i + (R + delta)(cos theta, sin theta),
    psi_d = atan2(s - p).

Table III writes R = sqrt(R_u^2 - (R_u sin beta)^2) = |R_u cos beta|; the
signed projection is used so that a boat behind W_i is drawn to W_i, not past
it. When R + delta runs past W_i+1 the target continues along the following
legs, and the leg switches once the projection passes W_i+1. The speed is the
desired trajectory's speed at the current time, as for classic LOS.
"""

from __future__ import annotations

import math

from usvstation.guidance.los import GuidanceCommand, Pose, check_pose
from usvstation.guidance.trajectory import Trajectory


class SlidingCurveGuidance:
    """Carrot-style sliding-curve guidance of paper 002."""

    def __init__(self, trajectory: Trajectory, delta: float = 3.0, speed_max: float = 3.0,
                 arrive_radius: float = 0.5, overrun: float = 0.0) -> None:
        if not delta > 0.0:
            raise ValueError(f"guidance: delta must be > 0 (got {delta})")
        if not speed_max > 0.0:
            raise ValueError(f"guidance: speed_max must be > 0 (got {speed_max})")
        if overrun < 0.0:
            raise ValueError(f"guidance: overrun must be >= 0 (got {overrun})")
        self.trajectory = trajectory.extended(overrun) if overrun > 0.0 else trajectory
        self.delta = delta
        self.speed_max = speed_max
        self.arrive_radius = arrive_radius
        self.leg = 0
        self.finished = False

    def _projection(self, x: float, y: float) -> float:
        """Signed along-track distance R of the boat from W_i on leg i (Table III rows 4-8)."""
        ax, ay, bx, by = self.trajectory.segment(self.leg)
        r_u = math.hypot(x - ax, y - ay)
        theta = math.atan2(by - ay, bx - ax)
        theta_u = math.atan2(y - ay, x - ax)
        return r_u * math.cos(theta - theta_u)

    def update(self, pose: Pose, t: float) -> GuidanceCommand:
        check_pose(pose, t)
        tr = self.trajectory
        along = self._projection(pose.x, pose.y)
        while self.leg < tr.segment_count - 1 and along >= tr.segment_length(self.leg):
            self.leg += 1
            along = self._projection(pose.x, pose.y)
        arc = tr.arc_at(self.leg, 0.0) + max(along, 0.0) + self.delta
        seg, frac = tr.locate_arc(arc)
        sx, sy = tr.point_at(seg, frac)
        t_target = tr.time_at(seg, frac)
        end_x, end_y = tr.points[-1]
        last = tr.segment_count - 1
        if (seg == last and frac >= 1.0
                and math.hypot(end_x - pose.x, end_y - pose.y) <= self.arrive_radius):
            self.finished = True
        if self.leg == last and along >= tr.segment_length(last):
            self.finished = True  # past the last waypoint
        dist = math.hypot(sx - pose.x, sy - pose.y)
        heading = math.atan2(sy - pose.y, sx - pose.x) if dist > 1e-9 else pose.psi
        if self.finished:
            heading = tr.arrival_heading  # hold the last bearing
        if self.finished:
            return GuidanceCommand(heading, 0.0, (sx, sy), t_target, seg, True)
        speed = min(max(tr.speed_at(t), 0.0), self.speed_max)
        return GuidanceCommand(heading, speed, (sx, sy), t_target, seg)
