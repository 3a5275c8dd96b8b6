"""The simulated boat's default vehicle: the 3-DOF model steered by compensated AV-LOS.

It puts the tracking pieces behind the `Vehicle` interface of sim/vehicle.py:
the vessel model (`dynamics.Vessel`, the Otter by default) in the scenario's
current and wind (and waves when asked), a guidance law (compensated AV-LOS
by default, every 0.2 s) and an autopilot (every 0.05 s), as in the
tracking bench. Guidance and autopilot see only a `Measurement` (GNSS
position, COG/SOG, heading, yaw rate) and their own thrust; the drift they
compensate comes from an online `DriftObserver`, never from the simulator's
environment.

Sensors, not truth (issue 23): the measurement comes from the boat's sensors
(`sim.sensors.BoatSensors` with a named `SensorProfile`: GNSS noise, bias, latency and
outages, compass bias, noise and lag, gyro), and the hull may differ from the one its
observer and autopilot were tuned on (`HullMismatch`: the model steps the true hull, the
controllers keep `params`). `state` is what the boat measures (and so what its telemetry
says); `truth` is the true state, for the judge of a trial or a bench only. With a
`relative` GNSS (moving-baseline RTK) the fix is relative to the true ramp, which a sea
that knows it gives through `set_true_frame` (default: the frame the boat was told).

The mission clock runs only while the boat tracks: hold and shore-assisted
guidance stop it, resume continues from where it stopped (AV-LOS then
speeds up to make up lost ground). HOLD (and READY, before start) keeps
station on the point where the command came (`StationKeeper`: position
over ground, weathervaning into the estimated current); when the current
is beyond what the boat can hold, `notice` says so. The mission is complete
when the boat passes the last waypoint (for a recovery: reaches the ramp
end); it then stops its propellers and, on a recovery ramp, is held there
(the model stops moving; boat time goes on; on a moving ramp it goes where
the ramp goes).

A moving mother ship (`set_frame`, sim/frame.py): the vessel's physics stays
in the earth-fixed world frame (the water does not move with the ship); its
waypoints, guidance, station keeping and drift observer work in the
ship-fixed ramp frame, every fix mapped through the ramp's pose extrapolated
to that control step. The observer then learns the apparent current (the
real one less the ship's velocity), the planner's view of the same sea.
`state` stays in the world frame (what GNSS sees); its cross-track error is
the ramp frame's.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace

import numpy as np

from usvstation.control.select import CONTROLLERS, make_controller
from usvstation.dynamics import Environment, ThrustCommand, Vessel, VesselState, otter
from usvstation.dynamics.params import HullMismatch, VesselParams
from usvstation.geometry import angle_diff
from usvstation.guidance import Trajectory
from usvstation.guidance.approach import (
    ApproachGates,
    ArrivalLimits,
    RampApproach,
    escape_routes,
    standby_point,
)
from usvstation.guidance.compensation import CompensatedAVLOS, EstimatedDrift
from usvstation.guidance.observer import DriftObserver, Measurement
from usvstation.guidance.select import GUIDANCE_METHODS, make_guidance
from usvstation.guidance.station import StationKeeper
from usvstation.sim.frame import RampMotion
from usvstation.sim.sensors import BoatSensors, SensorProfile
from usvstation.sim.vehicle import VehicleState, Waypoint, checked_mission, leg_cross_track

CONTROL_PERIOD = 0.05  # s, autopilot and model
GUIDANCE_PERIOD = 0.2  # s, AV-LOS (paper 000 sec. 4.2 uses 0.2 s)
LOOKAHEAD = 8.0  # m, four Otter lengths (docs/tracking.md)
OVERRUN = 15.0  # m of path past the ramp end, so the boat drives on up the ramp
HOLD_RADIUS = 3.0  # m, what a holding boat keeps within (tests, integration)
OVER_CAPACITY = "current exceeds what the boat can hold: drifting"
APPROACH_SPEED_MAX = 1.8  # m/s along the axis (relative to the ramp) on the final approach
ESCAPE_SPEED = 1.5  # m/s over ground on a go-around's escape route
BACK_OFF_TO = 12.0  # m: a go-around closer to the ramp first backs away to here
BACK_OFF_SPEED = 0.8  # m/s astern over ground while backing away
ENTRY_MARGIN = 15.0  # m before the first gate: the approach line is joined from here
STRAIGHT_MARGIN = 5.0  # m: the approach takes over this far before the plan's final straight
AXIS_TOLERANCE = 1.0  # m off the ramp axis: a plan's point still on its final straight
PATH_SAMPLE_S = 1.0  # s between the samples of a path carried into the world frame


@dataclass(frozen=True)
class _Command:
    heading: float
    speed: float
    water_speed: float | None = None


class DynamicVehicle:
    """A `Vehicle` simulated with the 3-DOF model, compensated AV-LOS and the autopilot."""

    def __init__(self, x: float, y: float, heading: float, *, speed: float = 0.0,
                 params: VesselParams | None = None, env: Environment | None = None,
                 accel: float = 0.5, guidance: str = "avlos_comp",
                 controller: str = "pid", frame: RampMotion | None = None,
                 sensors: str | SensorProfile = "exact", hull: HullMismatch | None = None,
                 seed: int = 0, arrival: ArrivalLimits | None = None,
                 path_check: Callable[[Trajectory], bool] | None = None,
                 initial: VesselState | None = None) -> None:
        """At (x, y) heading `heading` making `speed` along it; with `frame` these are in
        the moving ramp frame (the start relative to the ship) and the vehicle tracks in it
        from the start. `params` is the hull the boat's controllers know; `hull` how the
        real one differs; `sensors` (a profile or its name) and `seed` what it measures.
        `arrival` (a recovery's ramp limits) turns on the final approach, its gates and
        the go-around; `path_check` must accept every path the boat makes up itself (the
        approach line, the escape route) before it is flown (None: no obstacles known).
        `initial` replaces the start state (a bench's steady motion; fixed frame only)."""
        if guidance not in GUIDANCE_METHODS:
            raise ValueError(f"guidance: unknown method {guidance!r}; "
                             f"available: {', '.join(GUIDANCE_METHODS)}")
        if controller not in CONTROLLERS:
            raise ValueError(f"controller: unknown {controller!r}; "
                             f"available: {', '.join(CONTROLLERS)}")
        self.params = params or otter()
        self.hull = hull or HullMismatch()
        self.true_params = self.hull.apply(self.params)
        self.sensors = BoatSensors(sensors, seed)
        self.env = env or Environment.with_current(0.0, 0.0)
        self.accel = accel
        self.guidance_method = guidance
        self.controller = controller
        motion = frame or RampMotion()
        if motion.identity:
            start = VesselState(x, y, heading, speed)
        else:  # the ramp-frame start over ground: turned, plus the ramp point's velocity
            wx, wy = motion.to_world(x, y)
            psi = heading + motion.theta
            px, py = motion.point_velocity(wx, wy)
            gx, gy = speed * math.cos(psi) + px, speed * math.sin(psi) + py
            c, s = math.cos(psi), math.sin(psi)
            start = VesselState(wx, wy, psi, gx * c + gy * s, -gx * s + gy * c)
        self.vessel = Vessel(self.true_params, initial or start)
        if speed > 0.0 and initial is None:
            trim = 0.5 * self.true_params.surge_drag(speed)
            self.vessel.set_initial_thrust(ThrustCommand(trim, trim))
        self.pilot = make_controller(controller, self.params)
        self.observer = DriftObserver(self.params)
        self.drift = EstimatedDrift(self.observer)
        self.keeper = StationKeeper(self.drift)
        self.keeper.hold_at(x, y)  # ramp frame
        self.arrival = arrival
        self.path_check = path_check
        self._wps: list[Waypoint] = []
        self._guide = None
        # idle | track | hold | guided | done | aborted | go_around | standby
        self._phase = "idle"
        self._approach: RampApproach | None = None
        self.gates = ApproachGates(arrival, self.params.top_speed) if arrival else None
        self.go_around: str | None = None  # why, while a go-around runs (GO_AROUND)
        self.go_arounds = 0
        self.bend_rejected = False  # the approach line failed path_check: the plan's kept
        self._escape = None  # the escape route's guidance
        self._standby: tuple[float, float] | None = None
        self._standby_on_plan: tuple[int, float] | None = None  # where on the plan it lies
        self._held_from: str | None = None  # the go-around phase a HOLD interrupted
        self._path: Trajectory | None = None  # the timed path being flown
        self._straight = 0.0  # length of its final straight along the ramp axis
        self._tau = 0.0  # mission time
        self._pending = 0.0  # boat time not yet simulated (less than one control period)
        self._next_guidance = 0.0
        self._command: _Command | None = None
        self._guided = _Command(heading, 0.0)
        # what the controllers commanded to get the propellers' initial shaft speeds
        nominal = self.params.thrusters
        self._thrust = ThrustCommand(*(nominal.thrust(n) for n in self.vessel.shaft_speeds))
        self._segment = 0
        self._complete = False
        self._idle_time = 0.0  # boat time spent held on the ramp (the model is frozen)
        self._clock = 0.0  # the vehicle's time: every dt stepped (BoatProtocol's boat time)
        self._motion = motion  # the ramp frame in the world frame (identity: fixed)
        self._on_ramp: tuple[float, float, float] | None = None  # ramp-frame x, y, psi
        self._true_ramp: RampMotion | None = None  # for a relative GNSS (None: _motion)
        self._fix = self.sensors.measure(self.vessel.state, 0.0, self._ramp_truth(0.0))
        self._meas = self._measure(0.0)
        self.observer.start(self._meas, (self._thrust.left, self._thrust.right))
        self._state = self._report()

    # --- Vehicle interface --------------------------------------------------------
    @property
    def state(self) -> VehicleState:
        """What the boat measures (its navigation solution), in the world frame."""
        return self._state

    @property
    def truth(self) -> VehicleState:
        """The true state (world frame): for the judge of a trial or a bench, never for
        the boat's own decisions."""
        return self._report(truth=True)

    sensed = True  # `state` is measured: the boat adds no error of its own to it

    @property
    def gnss_status(self) -> tuple[int, int, float]:
        """(GPS_FIX_TYPE, satellites, HDOP) as GPS_RAW_INT reports them (no fix in an
        outage)."""
        g = self.sensors.profile.gnss
        return (g.fix_type if self.sensors.fix_ok else 1), g.satellites, g.hdop

    @property
    def measurement(self) -> Measurement:
        """The latest navigation fix in the ramp frame (what guidance steered on)."""
        return self._meas

    @property
    def phase(self) -> str:
        return self._phase

    @property
    def notice(self) -> str | None:
        """A warning for the operator while station keeping cannot hold, else None."""
        if self._phase in ("hold", "idle", "standby") and self.keeper.over_capacity:
            return OVER_CAPACITY
        return None

    @property
    def approach(self) -> RampApproach | None:
        """The final approach's guidance while the boat flies it."""
        return self._approach

    @property
    def standby(self) -> tuple[float, float] | None:
        """The go-around's standby point (ramp frame) once chosen."""
        return self._standby

    @property
    def at_standby(self) -> bool:
        """Keeping station at the go-around's standby point (a new approach may begin)."""
        return self._phase == "standby" and self._standby is not None

    @property
    def committed(self) -> bool:
        """On the final approach inside its first gate: the boat keeps this approach (its
        gates decide arrival or go-around) and takes no new mission (a hot swap)."""
        a = self._approach
        return (self._phase == "track" and a is not None and a.state is not None
                and a.state.distance <= self.arrival.gates[0])

    def set_mission(self, waypoints: Sequence[Waypoint]) -> None:
        self._wps = checked_mission(waypoints)
        self._guide, self._complete, self._segment = None, False, 0
        self._keep_station()

    def start(self) -> None:
        if len(self._wps) < 2:
            return
        self._fly([(w.x, w.y, w.t) for w in self._wps])

    def _fly(self, rows: list[tuple[float, float, float]]) -> None:
        """Track the timed path `rows` (the mission, or a new approach) from its start."""
        traj = Trajectory.from_xyt(rows)
        self._guide = make_guidance(
            self.guidance_method, traj, self.params, self.drift, lookahead=LOOKAHEAD,
            accel=self.accel, overrun=OVERRUN, path_check=self.path_check,
        )
        self._path = traj
        self._straight = self._final_straight()
        self._tau, self._complete, self._command = 0.0, False, None
        self._approach, self._escape, self.go_around = None, None, None
        if self.gates is not None:
            self.gates.reset()
        self._next_guidance = 0.0
        self.pilot.reset()
        self._phase = "track"

    def hold(self) -> None:
        if self._phase in ("go_around", "standby"):
            self._held_from = self._phase
            self._phase = "hold"
            self.keeper.hold_at(self._meas.x, self._meas.y, heading=self._arrival_heading()
                                if self._held_from == "standby" else None)
            self.pilot.reset()
            return
        if self._phase in ("track", "guided", "idle", "done"):
            self._keep_station()

    def resume(self) -> None:
        if self._phase == "hold" and self._held_from is not None:
            self._phase, self._held_from = self._held_from, None  # back to the go-around
            if self._phase == "standby" and self._standby is not None:
                self.keeper.hold_at(*self._standby, heading=self._arrival_heading())
            self._command = None
            return
        if self._guide is not None and not self._complete and self._phase in ("hold", "guided"):
            held = self._phase == "hold"
            self._phase, self._command = "track", None
            self._next_guidance = self._tau
            if held and self._approach is not None:
                self._rejoin_approach()

    def _rejoin_approach(self) -> None:
        """RESUME after a HOLD (or a failsafe) on the final approach: the boat stopped and
        may have turned into the current, so the approach is joined anew where it is: the
        gates still ahead of it are checked (those less than JOIN_MARGIN inside skipped,
        never the last). Inside the last gate none is left: it goes on only from where it
        would arrive now (within the arrival offset of the axis, the hull within the
        arrival heading), else it goes around."""
        approach = self._approach
        s = self._meas
        distance, lateral = approach.locate(s)
        approach.restart()
        if distance > self.arrival.gates[-1]:
            self.gates.rejoin(distance)
            return
        heading = abs(angle_diff(s.psi - self.observer.compass_bias, approach.arrival))
        if abs(lateral) > self.arrival.offset or heading > self.arrival.heading:
            self._start_go_around(f"resumed {max(distance, 0.0):.1f} m out, {abs(lateral):.2f}"
                                  f" m and {math.degrees(heading):.1f} deg off the axis")

    def reapproach(self) -> str | None:
        """A new approach from the standby point after a go-around (the boat's own, RESUME):
        the plan flown on from the standby point when it lies on the plan (the escape route
        went back along it), else straight to the ramp end. None when it began, else why
        not (not at standby; the path is not clear of the obstacles the boat knows, at the
        times it would fly it)."""
        if not self.at_standby or not self._wps:
            return "go-around not at standby yet"
        rows = self._plan_from_standby()
        if not self._clear_timed(Trajectory.from_xyt([(x, y, t + self._clock)
                                                      for x, y, t in rows])):
            return "new approach blocked by an obstacle"
        self._fly(rows)
        return None

    def _plan_from_standby(self) -> list[tuple[float, float, float]]:
        """The new approach's timed path: the plan's own legs and times from the standby
        point on, or the straight line at the approach speed."""
        sx, sy = self._standby
        wps = self._wps
        if self._standby_on_plan is not None:
            i, f = self._standby_on_plan
            t0 = wps[i].t + f * (wps[i + 1].t - wps[i].t)
            rows = [(sx, sy, 0.0)]
            rows += [(w.x, w.y, w.t - t0) for w in wps[i + 1:] if w.t - t0 > 1e-3]
            if len(rows) >= 2:
                return rows
        gx, gy = wps[-1].x, wps[-1].y
        speed = max(self._approach_speed(), 0.5)
        return [(sx, sy, 0.0), (gx, gy, math.hypot(gx - sx, gy - sy) / speed)]

    def abort(self) -> None:
        self._wps, self._guide, self._phase = [], None, "aborted"
        self._approach, self._escape, self.go_around, self._held_from = None, None, None, None

    def set_guidance(self, heading: float, speed: float) -> None:
        self._guided = _Command(heading, max(0.0, min(speed, self.params.top_speed)))
        self._phase = "guided"

    def clear_guidance(self) -> None:
        if self._phase != "guided":
            return
        if self._guide is not None and not self._complete:
            self.resume()
        else:
            self._keep_station()

    @property
    def frame(self) -> RampMotion:
        return self._motion

    def set_true_frame(self, motion: RampMotion | None) -> None:
        """The ramp's true motion (vehicle clock), which a relative GNSS measures against
        (None: the frame the boat was told, `set_frame`)."""
        self._true_ramp = motion

    def set_frame(self, motion: RampMotion, *, reanchor: bool = False) -> None:
        """The ramp frame's motion in the world frame (times on the vehicle's clock, the
        sum of the steps' dt). Waypoints and hold points are ramp-frame points from now
        on; `reanchor` moves a hold point to where the boat is in the new frame (after a
        jump of the frame, e.g. frozen while the pose was stale, or back)."""
        self._motion = motion
        self._meas = self._measure(self._clock - self._pending)
        if reanchor and self._phase in ("hold", "idle"):
            self.keeper.hold_at(self._meas.x, self._meas.y)
        self._state = self._report()

    def in_ramp(self) -> VehicleState:
        """`state` as seen in the ramp frame of now (position, heading, velocity relative
        to the ramp)."""
        s = self._state
        if self._phase == "done":
            f = self._motion.at(self._clock)
            m = f.measure(Measurement(s.x, s.y, s.heading, s.speed, s.course, s.yaw_rate, s.t))
        else:
            m = self._meas  # the navigation fix, in the ramp frame of its own instant
        return replace(s, x=m.x, y=m.y, heading=m.psi, speed=m.sog, course=m.cog,
                       yaw_rate=m.r)

    def step(self, dt: float) -> None:
        if dt <= 0.0:
            return
        self._pending += dt
        self._clock += dt
        while self._pending >= CONTROL_PERIOD:
            self._pending -= CONTROL_PERIOD
            self._control_step(self._clock - self._pending - CONTROL_PERIOD)
        self._state = self._report()

    # --- internals ----------------------------------------------------------------------
    def _keep_station(self) -> None:
        s = self._meas
        # on the final approach the hull stays along the axis (in slack water)
        self.keeper.hold_at(s.x, s.y, heading=self._approach.arrival if self._approach
                            is not None and self._phase == "track" else None)
        self._phase = "hold" if self._guide else "idle"
        self.pilot.reset()
        if self._complete:
            self._phase = "done"

    def _ramp_truth(self, t: float) -> RampMotion:
        return (self._true_ramp or self._motion).at(t)

    def _measure(self, t: float) -> Measurement:
        """The latest fix in the ramp frame as the frame is at vehicle time t."""
        if self.sensors.relative:
            return self._fix
        return self._motion.at(t).measure(self._fix)

    def _control_step(self, t: float) -> None:
        if self._phase == "done":  # recovered: the ramp holds the boat
            self._thrust = ThrustCommand(0.0, 0.0)
            self._idle_time += CONTROL_PERIOD
            return
        self._fix = self.sensors.measure(self.vessel.state, t, self._ramp_truth(t))
        s = self._meas = self._measure(t)
        if self._reached_ramp(s):
            self._complete = True
            self._phase = "done"
            self._on_ramp = self._ramp_pose(t)
            self._thrust = ThrustCommand(0.0, 0.0)
            self._idle_time += CONTROL_PERIOD
            return
        self.observer.update(s, (self._thrust.left, self._thrust.right), CONTROL_PERIOD)
        command = self._steer(s)
        if command is None:
            self._thrust = ThrustCommand(0.0, 0.0)
            self.pilot.reset()
        else:
            self._thrust = self.pilot.update(command, s, CONTROL_PERIOD)
        self.vessel.step(self._thrust, self.env, CONTROL_PERIOD)
        if self._phase in ("track", "go_around"):
            self._tau += CONTROL_PERIOD

    def _ramp_pose(self, t: float) -> tuple[float, float, float]:
        """The true hull's ramp-frame x, y and heading (where the ramp holds it)."""
        m = self._ramp_truth(t).measure(Measurement.of(self.vessel.state))
        return m.x, m.y, m.psi

    def _steer(self, s: Measurement) -> _Command | None:
        if self._phase == "track" and self._guide is not None:
            if self._command is None or self._tau >= self._next_guidance - 1e-9:
                self._command = self._track(s)
                self._next_guidance = self._tau + GUIDANCE_PERIOD
            if self._phase == "track":
                return self._command
        if self._phase == "go_around":
            return self._escape_command(s)
        if self._phase == "guided":
            return self._guided
        if self._phase in ("hold", "idle", "standby"):
            c = self.keeper.update(s, s.t)
            return None if c.idle else _Command(c.heading, c.speed, c.water_speed)
        return None  # done (on the ramp) or aborted: propellers stopped

    # --- the final approach, its gates and the go-around (guidance/approach.py) -----------
    def _track(self, s: Measurement) -> _Command | None:
        if self.arrival is not None and self._approach is None and self._entering(s):
            self._begin_approach(s)
            if self._phase == "go_around":
                return None
        if self._unguarded(s):
            return None
        if self._approach is None:
            cmd = self._guide.update(s, self._tau)
            self._segment = cmd.segment
            return _Command(cmd.heading, cmd.speed, cmd.water_speed)
        cmd = self._approach.update(s, self._tau)
        gate = self.gates.check(self._approach.state, self._nav_ok())
        if gate is not None and not gate.passed:
            self._start_go_around(gate.reason)
            return None
        return _Command(cmd.heading, cmd.speed, cmd.water_speed)

    def _reached_ramp(self, s: Measurement) -> bool:
        """Past the ramp end on its final approach: the ramp holds it. Also in a HOLD that
        came too close to the ramp to stop short of it (under way at the ramp end, the
        ramp catches the boat whatever it was told)."""
        if self._phase not in ("track", "hold") or not self._passed_end(s):
            return False
        if self._phase == "hold":
            return self._approach is not None and self._held_from is None
        return not self._unguarded(s)

    def _unguarded(self, s: Measurement) -> bool:
        """The ramp guard of a recovery: the boat reaches the ramp only on its final
        approach, through its last gate. Within the last gate's distance of the ramp end
        (or past it) without the approach (a new mission swapped in close to the ramp, a
        plan that comes in from the side, a START there) it goes around instead; True
        then."""
        if self.arrival is None or self._approach is not None:
            return False
        goal = self._wps[-1]
        if math.hypot(s.x - goal.x, s.y - goal.y) > self.arrival.gates[-1] and \
                not self._passed_end(s):
            return False
        self._start_go_around("at the ramp without an approach")
        return True

    def _approach_speed(self) -> float:
        a, b = self._wps[-2], self._wps[-1]
        plan = math.hypot(b.x - a.x, b.y - a.y) / max(b.t - a.t, 1e-6)
        return min(plan, APPROACH_SPEED_MAX)

    def _arrival_heading(self) -> float:
        a, b = self._wps[-2], self._wps[-1]
        return math.atan2(b.y - a.y, b.x - a.x)

    def _new_approach(self, line_override: float | None = None) -> RampApproach:
        goal = (self._wps[-1].x, self._wps[-1].y)
        return RampApproach(goal, self._arrival_heading(), self.drift, self.arrival,
                            self._approach_speed(), 0.95 * self.params.top_speed,
                            compass_bias=lambda: self.observer.compass_bias,
                            line_override=line_override)

    def _entering(self, s: Measurement) -> bool:
        """True where the final approach takes over: the boat is on its path's final
        straight along the ramp axis (before it, the plan's path keeps it clear of what the
        station knows and it does not, such as traffic), before the ramp end, within the
        entry distance and not coming in from the side."""
        if self._path_left(s) > self._straight + STRAIGHT_MARGIN:
            return False  # (the cheap test first: a profile costs a little at every step)
        probe = self._new_approach()
        distance, lateral = probe.locate(s)
        prof = probe.profile()
        first = self.arrival.gates[0]
        wanted_first, _ = prof.at(first)
        entry = first + ENTRY_MARGIN + abs(wanted_first)
        if not self.arrival.gates[-1] < distance <= entry:
            return False  # (inside the last gate it is too late: the ramp guard acts)
        wanted, _ = prof.at(distance)
        # coming in from the side, the plan brings it round first
        return abs(lateral) <= abs(wanted) + max(3.0, 0.15 * distance)

    def _final_straight(self) -> float:
        """Length of the path's final straight: its last legs on the ramp axis (every point
        within AXIS_TOLERANCE of the line through the last waypoint along the last leg)."""
        tr = self._path
        a = tr.segment_heading(tr.segment_count - 1)
        gx, gy = tr.points[-1]
        length = 0.0
        for i in range(tr.segment_count - 1, -1, -1):
            ax, ay, _, _ = tr.segment(i)
            if abs(-(ax - gx) * math.sin(a) + (ay - gy) * math.cos(a)) > AXIS_TOLERANCE:
                break
            length += tr.segment_length(i)
        return length

    def _path_left(self, s: Measurement) -> float:
        """Path length from the boat's leg to the end of the path flown."""
        tr = self._path
        seg = min(self._segment, tr.segment_count - 1)
        _, _, bx, by = tr.segment(seg)
        left = math.hypot(bx - s.x, by - s.y)
        return left + sum(tr.segment_length(i) for i in range(seg + 1, tr.segment_count))

    def _begin_approach(self, s: Measurement) -> None:
        approach = self._new_approach()
        prof = approach.profile()
        distance, _ = approach.locate(s)
        g, a = approach.goal, approach.arrival
        c, sn = math.cos(a), math.sin(a)
        path = [(s.x, s.y)]
        for d in (0.75 * distance, 0.5 * distance, 0.25 * distance, 0.0):
            off, _ = prof.at(d)
            path.append((g[0] - d * c - off * sn, g[1] - d * sn + off * c))
        if not self._clear(path, prof.water_speed):
            self.bend_rejected = True  # keep to the plan's own final leg (the axis) ...
            approach = self._new_approach(line_override=0.0)
            first = self.arrival.gates[0]
            if abs(prof.at(first)[0]) > self.gates.cross_track_limit(first):
                # ... unless the drift carries it off the axis by more than a gate allows
                self._start_go_around("approach path blocked by an obstacle")
                return
        self._approach = approach
        self.gates.joined(distance)

    def _timed(self, points: list[tuple[float, float]], speed: float,
               start: float = 0.0) -> Trajectory:
        """`points` (ramp frame) flown at `speed` from time `start`."""
        rows, t = [(points[0][0], points[0][1], start)], start
        for (ax, ay), (bx, by) in itertools.pairwise(points):
            t += max(math.hypot(bx - ax, by - ay), 0.1) / max(speed, 0.3)
            rows.append((bx, by, t))
        return Trajectory.from_xyt(rows)

    def _clear(self, points: list[tuple[float, float]], speed: float) -> bool:
        """True when `points` (ramp frame), flown from now at `speed`, keep clear of every
        obstacle the boat knows (`path_check`: the scenario's circles, fixed or moving in
        the world frame, at the times of the vehicle's clock, which runs with the sea's).
        On a moving ramp the path is carried into the world frame with the ramp's motion
        as the boat knows it (sampled every PATH_SAMPLE_S)."""
        return self._clear_timed(self._timed(points, speed, self._clock))

    def _clear_timed(self, path: Trajectory) -> bool:
        """`_clear` for a timed path whose times are on the vehicle's clock."""
        if self.path_check is None:
            return True
        if not self._motion.identity:
            n = max(int((path.end_time - path.start_time) / PATH_SAMPLE_S), 1) + 1
            rows = []
            for t in np.linspace(path.start_time, path.end_time, n):
                x, y = path.position_at(np.array([t]))[0]
                rows.append((*self._motion.at(float(t)).to_world(float(x), float(y)), float(t)))
            path = Trajectory.from_xyt(rows)
        return self.path_check(path)

    def _nav_ok(self) -> bool:
        """An RTK-class fix, not dead-reckoned through an outage."""
        return (self.sensors.profile.gnss.fix_type >= 6 and self.sensors.fix_ok
                and self.sensors.fix_age < 1.0)

    def _start_go_around(self, reason: str) -> None:
        self.go_around = reason
        self.go_arounds += 1
        self._phase = "go_around"
        self._approach, self._escape, self._standby = None, None, None
        self.pilot.reset()

    def _escape_command(self, s: Measurement) -> _Command | None:
        """Back off from the ramp when close, then fly the first clear escape route to
        the standby point."""
        if self._escape is None:
            if self._backing_off(s):  # astern along the axis, the bow to the ramp
                a = self._arrival_heading()
                turn = max(math.cos(angle_diff(a, s.psi - self.observer.compass_bias)), 0.0)
                return _Command(a + self.observer.compass_bias, -BACK_OFF_SPEED * turn, None)
            self._plan_escape(s)
            if self._escape is None:
                return None  # holding (standby) where it stopped
        cmd = self._escape.update(s, self._tau)
        if self._escape.finished:
            self._phase = "standby"
            self.keeper.hold_at(*self._standby, heading=self._arrival_heading())
        return _Command(cmd.heading, cmd.speed, cmd.water_speed)

    def _backing_off(self, s: Measurement) -> bool:
        """True while a go-around close to the ramp must first back away from it."""
        a = self._arrival_heading()
        goal = self._wps[-1]
        return -((s.x - goal.x) * math.cos(a) + (s.y - goal.y) * math.sin(a)) < BACK_OFF_TO

    def _plan_escape(self, s: Measurement) -> None:
        goal = (self._wps[-1].x, self._wps[-1].y)
        standby = standby_point(goal, self._arrival_heading(), self.arrival)
        plan = [(w.x, w.y) for w in self._wps]
        for route in escape_routes((s.x, s.y), standby, plan, goal, self.arrival):
            if self._clear(route.points, ESCAPE_SPEED):
                self._standby, self._standby_on_plan = route.standby, route.on_plan
                self._escape = CompensatedAVLOS(self._timed(route.points, ESCAPE_SPEED,
                                                            self._tau),
                                                self.drift, LOOKAHEAD,
                                                speed_max=self.params.top_speed,
                                                arrive_radius=1.0, decide_at=-1.0)
                return
        self._standby, self._standby_on_plan = (s.x, s.y), None  # nowhere clear: stay
        self._phase = "standby"
        self.keeper.hold_at(s.x, s.y, heading=self._arrival_heading())

    def _passed_end(self, s: Measurement) -> bool:
        """True once the boat is past the line through the last waypoint, across the last leg."""
        a, b = self._wps[-2], self._wps[-1]
        lx, ly = b.x - a.x, b.y - a.y
        return (s.x - b.x) * lx + (s.y - b.y) * ly >= 0.0

    def _report(self, truth: bool = False) -> VehicleState:
        """The state in the world frame: measured (the navigation solution of the last
        control step) or, with `truth`, the true one."""
        s = self.vessel.state
        if truth:
            x, y, psi, r = s.x, s.y, s.psi, s.r
            vx, vy = s.velocity
        else:
            m = self._nav_world()
            x, y, psi, r = m.x, m.y, m.psi, m.r
            vx, vy = m.velocity
        full = self.params.thrusters.thrust_max
        index = min(self._segment + 1, max(len(self._wps) - 1, 0))
        f = self._motion.at(self._clock)
        if self._phase == "done":  # on the ramp: carried with it (still on a fixed one)
            rx, ry, rpsi = self._on_ramp if self._on_ramp is not None else (
                *f.to_ramp(x, y), psi - f.theta)
            x, y = f.to_world(rx, ry)
            psi, r = rpsi + f.theta, f.omega
            vx, vy = f.point_velocity(x, y)
        speed = math.hypot(vx, vy)
        rx, ry = f.to_ramp(x, y)
        return VehicleState(
            t=s.t + self._idle_time, x=x, y=y, heading=psi, speed=speed,
            course=math.atan2(vy, vx) if speed > 1e-6 else psi, yaw_rate=r,
            thrust_left=max(-1.0, min(1.0, self._thrust.left / full)),
            thrust_right=max(-1.0, min(1.0, self._thrust.right / full)),
            waypoint_index=index, cross_track_error=leg_cross_track(self._wps, rx, ry, index),
            mission_complete=self._complete,
        )

    def _nav_world(self) -> Measurement:
        """The navigation solution in the world frame."""
        if self.sensors.relative:
            return self._motion.at(self._meas.t).unmeasure(self._meas)
        return self._fix
