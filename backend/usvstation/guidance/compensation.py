"""Disturbance compensation for AV-LOS (paper 000 sec. 3.1 and 3.3).

The paper feeds the predicted current and wave effect into AV-LOS. Here the
prediction is the drift velocity the environment gives the hull: the current
itself (it acts through the relative velocity) plus the steady sway the wave
drift force (eq. 3-5) and the wind force (paper 002 eq. 24) push it to
against the hull's own sway damping. AV-LOS asks for a velocity over ground;
the compensated heading is the one whose water velocity plus that drift
points the right way, and the speed command is the wanted ground velocity's
component along that heading.

Arrival: holding a line across a current needs a crab angle (at 3 m/s a
0.3 m/s cross current alone needs 5.7 deg), but the ramp wants the hull
aligned. So the last `approach_length` metres are bent: the boat comes in on
a line through the goal, from up-current, along which the crab it needs is
half the tolerance, and there its heading command is held within the
tolerance of the arrival heading; the drift then carries it onto the axis at
the goal.
"""

from __future__ import annotations

import math

from usvstation.dynamics.environment import Environment, wave_drift_force, wind_force
from usvstation.dynamics.params import VesselParams
from usvstation.guidance.angles import angle_diff, wrap_angle
from usvstation.guidance.los import AVLOSGuidance, GuidanceCommand, Pose
from usvstation.guidance.trajectory import Trajectory


class DisturbancePredictor:
    """Predicted drift of a vessel in an environment (known current, waves and wind)."""

    def __init__(self, params: VesselParams, env: Environment) -> None:
        self.params = params
        self.env = env

    def force(self, psi: float, speed: float) -> tuple[float, float]:
        """Predicted wave drift + wind force (N, body x and y) at heading psi, surge `speed`."""
        fx = fy = 0.0
        if self.env.waves is not None:
            f = wave_drift_force(self.params, self.env.waves, psi)
            fx, fy = fx + float(f[0]), fy + float(f[1])
        if self.env.wind is not None:
            f = wind_force(self.params, self.env.wind, psi, speed, 0.0)
            fx, fy = fx + float(f[0]), fy + float(f[1])
        return fx, fy

    def drift(self, psi: float, speed: float) -> tuple[float, float]:
        """Earth-frame velocity (m/s) the environment adds to a boat at heading psi, surge `speed`.

        The current, plus the steady surge change and sway the wave and wind
        forces cause against the hull's damping at that speed.
        """
        cx, cy = self.env.current
        fx, fy = self.force(psi, speed)
        p = self.params
        slope = p.linear_damping[0] + 2.0 * p.quadratic_damping[0] * abs(speed)
        surge = fx / slope if slope > 0.0 else 0.0
        slip = p.sway_drift_speed(fy)
        c, s = math.cos(psi), math.sin(psi)
        return cx + c * surge - s * slip, cy + s * surge + c * slip

    def compensate(self, vx: float, vy: float, psi_guess: float,
                   iterations: int = 4) -> tuple[float, float]:
        """(heading, surge speed over ground) that give the ground velocity (vx, vy)."""
        speed = math.hypot(vx, vy)
        psi = psi_guess if speed < 1e-6 else math.atan2(vy, vx)
        for _ in range(iterations):
            # Fixed point: the water velocity is the wanted velocity minus the drift.
            dx, dy = self.drift(psi, speed)
            wx, wy = vx - dx, vy - dy
            if math.hypot(wx, wy) < 0.05:
                break
            psi = math.atan2(wy, wx)
        surge = max(vx * math.cos(psi) + vy * math.sin(psi), 0.0)
        return wrap_angle(psi), surge

    def crab_angle(self, heading: float, speed: float) -> float:
        """Heading minus course needed to make good `speed` along `heading` (rad)."""
        psi, _ = self.compensate(speed * math.cos(heading), speed * math.sin(heading), heading)
        return angle_diff(psi, heading)


class CompensatedAVLOS(AVLOSGuidance):
    """AV-LOS with the disturbance compensation of paper 000 sec. 3.1 and a crab-limited arrival.

    On the bent approach line the boat steers for the goal itself (so any
    lateral error left is taken out before the ramp) and its heading command
    stays within 0.9 x `arrival_tolerance` of the arrival heading.
    `approach_crab` is the fraction of the tolerance the approach line is
    built for.
    """

    def __init__(self, trajectory: Trajectory, predictor: DisturbancePredictor,
                 lookahead: float = 3.0, speed_max: float = 3.0, speed_min: float = 0.0,
                 accel: float | None = None, arrival_tolerance: float = math.radians(5.0),
                 approach_length: float = 12.0, approach_crab: float = 0.5,
                 overrun: float = 0.0, arrive_radius: float = 0.5) -> None:
        if not 0.0 < arrival_tolerance < math.pi / 2:
            raise ValueError("guidance: arrival_tolerance must be within (0, pi/2) rad")
        self.predictor = predictor
        self.arrival_heading = trajectory.arrival_heading
        self.arrival_tolerance = arrival_tolerance
        self.goal = (float(trajectory.points[-1][0]), float(trajectory.points[-1][1]))
        arrival_speed = min(_last_segment_speed(trajectory), speed_max)
        bent, self.approach_crab = _bend_final_approach(
            trajectory, predictor, arrival_speed, approach_crab * arrival_tolerance,
            approach_length,
        )
        self.approach_segment = bent.segment_count - 1 if bent is not trajectory else None
        super().__init__(bent, lookahead, speed_max, speed_min, accel,
                         arrive_radius=arrive_radius, overrun=overrun)

    def update(self, pose: Pose, t: float) -> GuidanceCommand:
        la, heading, speed, t_la = self.velocity(pose, t)
        if self.finished:
            return self._command(la, heading, speed, t_la)
        approach = self.approach_segment is not None and self._on_approach(pose)
        if approach:
            gx, gy = self.goal
            along = (gx - pose.x) * math.cos(self.arrival_heading) + (
                gy - pose.y) * math.sin(self.arrival_heading)
            if along > 1.0:
                heading = math.atan2(gy - pose.y, gx - pose.x)
        psi, surge = self.predictor.compensate(
            speed * math.cos(heading), speed * math.sin(heading), pose.psi,
        )
        if approach:
            limit = 0.9 * self.arrival_tolerance
            off = angle_diff(psi, self.arrival_heading)
            psi = wrap_angle(self.arrival_heading + min(max(off, -limit), limit))
        return self._command(la, psi, surge, t_la)

    def _on_approach(self, pose: Pose) -> bool:
        """True once the boat is past the start of the bent approach line."""
        ax, ay, bx, by = self.trajectory.segment(self.approach_segment)
        return (pose.x - ax) * (bx - ax) + (pose.y - ay) * (by - ay) > 0.0


def _last_segment_speed(trajectory: Trajectory) -> float:
    i = trajectory.segment_count - 1
    return trajectory.segment_length(i) / (trajectory.times[i + 1] - trajectory.times[i])


def _bend_final_approach(
    trajectory: Trajectory, predictor: DisturbancePredictor, speed: float, crab: float,
    length: float,
) -> tuple[Trajectory, float]:
    """The trajectory with its last `length` metres replaced by a drift-aware approach line.

    Returns (trajectory, crab angle the boat will hold on the approach). The
    trajectory is returned unchanged when the full crab is within `crab`.
    """
    arrival = trajectory.arrival_heading
    needed = predictor.crab_angle(arrival, speed)
    if abs(needed) <= crab or length >= trajectory.length or speed <= 0.0:
        return trajectory, needed
    hold = math.copysign(crab, needed)
    psi = arrival + hold
    # The boat runs `speed` through the water; the drift adds to it.
    dx, dy = predictor.drift(psi, speed)
    gx, gy = speed * math.cos(psi) + dx, speed * math.sin(psi) + dy
    norm = math.hypot(gx, gy)
    ex, ey = trajectory.points[-1]
    via = (float(ex - length * gx / norm), float(ey - length * gy / norm))
    return trajectory.replace_tail(length, via), hold
