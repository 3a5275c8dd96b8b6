"""Disturbance compensation for AV-LOS (paper 000 sec. 3.1 and 3.3).

The paper feeds the predicted current and wave effect into AV-LOS. Here the
prediction is a drift velocity: on a boat, the online estimate of
`DriftObserver` (`EstimatedDrift`: current plus steady crab, from the
boat's own sensors); for comparison only, `DisturbancePredictor` computes it
from the simulator's environment (the current, which acts through the
relative velocity, plus the steady sway the wave drift force, eq. 3-5, and
the wind force, paper 002 eq. 24, push the hull to against its own sway
damping). AV-LOS asks for a velocity over ground; the compensated heading is
the one whose water velocity plus the drift points the right way, the speed
command is the wanted ground velocity's component along that heading, and
the speed through the water goes to the autopilot as drag feed-forward.

Arrival: holding a line across a current needs a crab angle (at 2.4 m/s a
0.3 m/s cross current needs 7 deg), but the ramp wants the hull aligned. So
near the end the last `approach_length` metres are bent once, with the drift
known then: the boat comes in on a line through the goal, from up-current,
along which the crab it needs is a fraction of the tolerance; there it
steers for the goal with feedback on its measured course over ground, and
its heading command is held within the tolerance of the arrival heading;
the drift then carries it onto the axis at the goal.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

from usvstation.dynamics.environment import Environment, wave_drift_force, wind_force
from usvstation.dynamics.params import VesselParams
from usvstation.geometry import angle_diff, wrap_angle
from usvstation.guidance.los import (
    AVLOSGuidance,
    GuidanceCommand,
    LookaheadTracker,
    Pose,
    check_pose,
)
from usvstation.guidance.observer import DriftObserver
from usvstation.guidance.trajectory import Schedule, Trajectory


@dataclass(frozen=True)
class Compensation:
    """A solved compensation: heading, surge over ground, speed through the water, ground speed.

    `ground_speed` is what is actually made good along the wanted direction:
    less than asked when the boat cannot make it against the drift
    (`limited`), negative when the drift sets it back along the line.
    """

    heading: float
    surge: float
    water_speed: float
    ground_speed: float
    limited: bool = False


class DriftModel:
    """Base of the drift predictors: the compensation of paper 000 sec. 3.1 on a drift model.

    Subclasses give `drift(psi, speed)`, the earth-frame velocity the
    environment adds to a boat at heading psi making `speed` through the water.
    `water_speed_max` is the most the boat can run through the water.
    """

    water_speed_max: float = math.inf

    def drift(self, psi: float, speed: float) -> tuple[float, float]:  # pragma: no cover
        raise NotImplementedError

    def solve(self, vx: float, vy: float, psi_guess: float, iterations: int = 4) -> Compensation:
        """Heading and speeds that make good the ground velocity (vx, vy), or the most of it.

        With drift c and wanted direction d, the water velocity is w = s d - c.
        When |w| would exceed `water_speed_max` U the boat keeps the line and
        slows along it: s = c.d + sqrt(U^2 - (c x d)^2) (or, carried along
        faster than asked, makes good c.d - sqrt(...)). A cross drift above
        U cannot be held: the boat then heads straight into it.
        """
        for value, name in ((vx, "vx"), (vy, "vy"), (psi_guess, "psi")):
            if not math.isfinite(value):
                raise ValueError(f"compensation: {name} must be finite (got {value})")
        speed = math.hypot(vx, vy)
        if speed > 1e-9:
            ux, uy = vx / speed, vy / speed
        else:
            ux, uy = math.cos(psi_guess), math.sin(psi_guess)
        psi = psi_guess if speed < 1e-6 else math.atan2(vy, vx)
        cap = self.water_speed_max
        s, limited = speed, False
        wx = wy = 0.0
        for _ in range(iterations):
            cx, cy = self.drift(psi, math.hypot(wx, wy) if (wx or wy) else speed)
            along = cx * ux + cy * uy
            cross = -cx * uy + cy * ux
            s, limited = speed, False
            if math.isfinite(cap):
                if abs(cross) >= cap:
                    s, limited = along, True  # cannot hold the line: all into the cross drift
                    wx, wy = cap * uy * math.copysign(1.0, cross), -cap * ux * math.copysign(
                        1.0, cross)
                    psi = math.atan2(wy, wx)
                    continue
                reach = math.sqrt(cap * cap - cross * cross)
                if s > along + reach:  # cannot make it good: slow along the line
                    s, limited = along + reach, True
                elif s < along - reach:  # carried along faster than asked: brake
                    s, limited = along - reach, True
            wx, wy = s * ux - cx, s * uy - cy
            if math.hypot(wx, wy) < 0.05:
                break
            psi = math.atan2(wy, wx)
        ground_x, ground_y = wx + cx, wy + cy
        c, sn = math.cos(psi), math.sin(psi)
        surge = ground_x * c + ground_y * sn
        water = max(wx * c + wy * sn, 0.0)
        return Compensation(wrap_angle(psi), surge, water, s, limited)

    def compensate(self, vx: float, vy: float, psi_guess: float,
                   iterations: int = 4) -> tuple[float, float]:
        """(heading, surge speed over ground) that give the ground velocity (vx, vy)."""
        sol = self.solve(vx, vy, psi_guess, iterations)
        return sol.heading, max(sol.surge, 0.0)

    def crab_angle(self, heading: float, speed: float) -> float:
        """Heading minus course needed to make good `speed` along `heading` (rad)."""
        psi, _ = self.compensate(speed * math.cos(heading), speed * math.sin(heading), heading)
        return angle_diff(psi, heading)


class DisturbancePredictor(DriftModel):
    """Drift predicted from a known environment (current, waves, wind): the oracle.

    A boat does not know its environment; this is kept for the comparison
    rows (`current_source: "oracle"`) and for planning-side predictions.
    The boat uses `EstimatedDrift`.
    """

    def __init__(self, params: VesselParams, env: Environment,
                 water_speed_max: float | None = None) -> None:
        self.params = params
        self.env = env
        self.water_speed_max = water_speed_max if water_speed_max is not None else math.inf

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


class EstimatedDrift(DriftModel):
    """Drift from an online `DriftObserver`: what a boat can know (no oracle)."""

    def __init__(self, observer: DriftObserver, water_speed_max: float | None = None) -> None:
        self.observer = observer
        top = observer.params.top_speed
        self.water_speed_max = water_speed_max if water_speed_max is not None else 0.95 * top

    def drift(self, psi: float, speed: float) -> tuple[float, float]:
        return self.observer.estimate


COURSE_GAIN = 1.0  # course error (bearing to goal - COG) added to the compensated heading


class CompensatedAVLOS(AVLOSGuidance):
    """AV-LOS with the disturbance compensation of paper 000 sec. 3.1 and a crab-limited arrival.

    `predictor` is any `DriftModel`: `EstimatedDrift` on a boat (its
    observer's estimate changes as the boat goes), `DisturbancePredictor`
    for the oracle comparison. When the boat is `decide_at` metres of path
    from the end, the last `approach_length` metres are bent (once) onto a
    line through the goal from up-current, built for `approach_crab` x the
    tolerance of crab with the drift known then; `path_check` (if given)
    must accept the bent path, else the plan's path is kept. On the bent
    approach the boat steers for the goal itself (so any lateral error left
    is taken out before the ramp) and its heading command stays within
    0.9 x `arrival_tolerance` of the arrival heading.
    """

    def __init__(self, trajectory: Trajectory, predictor: DriftModel,
                 lookahead: float = 3.0, speed_max: float = 3.0, speed_min: float = 0.0,
                 accel: float | None = None, arrival_tolerance: float = math.radians(5.0),
                 approach_length: float = 12.0, approach_crab: float = 0.3,
                 overrun: float = 0.0, arrive_radius: float = 0.5,
                 decide_at: float | None = None,
                 path_check: Callable[[Trajectory], bool] | None = None) -> None:
        if not 0.0 < arrival_tolerance < math.pi / 2:
            raise ValueError("guidance: arrival_tolerance must be within (0, pi/2) rad")
        self.predictor = predictor
        self.plan = trajectory
        self.arrival_heading = trajectory.arrival_heading
        self.arrival_tolerance = arrival_tolerance
        self.approach_length = approach_length
        self.approach_crab_fraction = approach_crab
        self.decide_at = decide_at if decide_at is not None else approach_length + 2 * lookahead
        self.path_check = path_check
        self.goal = (float(trajectory.points[-1][0]), float(trajectory.points[-1][1]))
        self.arrival_speed = min(_last_segment_speed(trajectory), speed_max)
        self.approach_crab = 0.0
        self.approach_segment: int | None = None
        self.bend_decided = False
        self.bend_rejected = False
        self._overrun = overrun
        super().__init__(trajectory, lookahead, speed_max, speed_min, accel,
                         arrive_radius=arrive_radius, overrun=overrun)

    def _decide_bend(self, pose: Pose) -> None:
        """Bend the final approach with the drift known now (once, near the end)."""
        self.bend_decided = True
        bent, crab = _bend_final_approach(
            self.plan, self.predictor, self.arrival_speed,
            self.approach_crab_fraction * self.arrival_tolerance, self.approach_length,
        )
        self.approach_crab = crab
        if bent is self.plan:
            return
        if self.path_check is not None and not self.path_check(bent):
            self.bend_rejected = True
            return
        tr = bent.extended(self._overrun) if self._overrun > 0.0 else bent
        segment = self.tracker.segment
        self.trajectory = tr
        self.tracker = LookaheadTracker(tr, self.tracker.radius)
        self.tracker.segment = min(segment, tr.segment_count - 1)
        self.schedule = Schedule.feasible(tr, self.accel) if self.accel else Schedule.exact(tr)
        self.approach_segment = bent.segment_count - 1

    def update(self, pose: Pose, t: float) -> GuidanceCommand:
        check_pose(pose, t)
        if not self.bend_decided:
            gx, gy = self.goal
            if math.hypot(gx - pose.x, gy - pose.y) <= self.decide_at:
                self._decide_bend(pose)
        la, heading, speed, t_la = self.velocity(pose, t)
        if self.finished:
            return self._command(la, heading, speed, t_la)
        approach = self.approach_segment is not None and self._on_approach(pose)
        along = 0.0
        if approach:
            gx, gy = self.goal
            along = (gx - pose.x) * math.cos(self.arrival_heading) + (
                gy - pose.y) * math.sin(self.arrival_heading)
            if along > 1.0:
                heading = math.atan2(gy - pose.y, gx - pose.x)
        sol = self.predictor.solve(speed * math.cos(heading), speed * math.sin(heading), pose.psi)
        psi = sol.heading
        cog, sog = getattr(pose, "cog", None), getattr(pose, "sog", 0.0)
        if approach and cog is not None and sog > 0.5 and along > 1.0:
            # Course feedback on the measured COG on top of the compensation:
            # point the track made good at the goal, whatever error the drift
            # estimate still has.
            psi = wrap_angle(psi + COURSE_GAIN * angle_diff(heading, cog))
        if approach:
            limit = 0.9 * self.arrival_tolerance
            off = angle_diff(psi, self.arrival_heading)
            psi = wrap_angle(self.arrival_heading + min(max(off, -limit), limit))
        cmd = self._command(la, psi, max(sol.surge, 0.0), t_la)
        return replace(cmd, water_speed=min(sol.water_speed, self.speed_max))

    def _on_approach(self, pose: Pose) -> bool:
        """True once the boat is past the start of the bent approach line."""
        ax, ay, bx, by = self.trajectory.segment(self.approach_segment)
        return (pose.x - ax) * (bx - ax) + (pose.y - ay) * (by - ay) > 0.0


def _last_segment_speed(trajectory: Trajectory) -> float:
    i = trajectory.segment_count - 1
    return trajectory.segment_length(i) / (trajectory.times[i + 1] - trajectory.times[i])


def _bend_final_approach(
    trajectory: Trajectory, predictor: DriftModel, speed: float, crab: float,
    length: float,
) -> tuple[Trajectory, float]:
    """The trajectory with only its last `length` metres replaced by a drift-aware approach.

    The approach line runs through the goal from up-current, `approach` =
    2/3 of `length` long, built so that the crab the boat needs on it is
    `crab`; it joins the plan's path `length` metres before the end. Returns
    (trajectory, crab angle the boat will hold on the approach); the
    trajectory comes back unchanged when the full crab is within `crab`.
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
    if norm < 1e-6:
        return trajectory, needed
    ex, ey = trajectory.points[-1]
    approach = 2.0 * length / 3.0
    via = (float(ex - approach * gx / norm), float(ey - approach * gy / norm))
    return trajectory.replace_tail(length, via), hold
