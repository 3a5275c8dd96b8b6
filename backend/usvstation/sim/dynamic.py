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

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace

from usvstation.control.select import CONTROLLERS, make_controller
from usvstation.dynamics import Environment, ThrustCommand, Vessel, VesselState, otter
from usvstation.dynamics.params import HullMismatch, VesselParams
from usvstation.guidance import Trajectory
from usvstation.guidance.compensation import EstimatedDrift
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
                 seed: int = 0) -> None:
        """At (x, y) heading `heading` making `speed` along it; with `frame` these are in
        the moving ramp frame (the start relative to the ship) and the vehicle tracks in it
        from the start. `params` is the hull the boat's controllers know; `hull` how the
        real one differs; `sensors` (a profile or its name) and `seed` what it measures."""
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
        self.vessel = Vessel(self.true_params, start)
        if speed > 0.0:
            trim = 0.5 * self.true_params.surge_drag(speed)
            self.vessel.set_initial_thrust(ThrustCommand(trim, trim))
        self.pilot = make_controller(controller, self.params)
        self.observer = DriftObserver(self.params)
        self.drift = EstimatedDrift(self.observer)
        self.keeper = StationKeeper(self.drift)
        self.keeper.hold_at(x, y)  # ramp frame
        self._wps: list[Waypoint] = []
        self._guide = None
        self._phase = "idle"  # idle | track | hold | guided | done | aborted
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
        if self._phase in ("hold", "idle") and self.keeper.over_capacity:
            return OVER_CAPACITY
        return None

    def set_mission(self, waypoints: Sequence[Waypoint]) -> None:
        self._wps = checked_mission(waypoints)
        self._guide, self._complete, self._segment = None, False, 0
        self._keep_station()

    def start(self) -> None:
        if len(self._wps) < 2:
            return
        traj = Trajectory.from_xyt([(w.x, w.y, w.t) for w in self._wps])
        self._guide = make_guidance(
            self.guidance_method, traj, self.params, self.drift, lookahead=LOOKAHEAD,
            accel=self.accel, overrun=OVERRUN,
        )
        self._tau, self._complete, self._command = 0.0, False, None
        self._next_guidance = 0.0
        self.pilot.reset()
        self._phase = "track"

    def hold(self) -> None:
        if self._phase in ("track", "guided", "idle", "done"):
            self._keep_station()

    def resume(self) -> None:
        if self._guide is not None and not self._complete and self._phase in ("hold", "guided"):
            self._phase, self._command = "track", None
            self._next_guidance = self._tau

    def abort(self) -> None:
        self._wps, self._guide, self._phase = [], None, "aborted"

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
        self.keeper.hold_at(s.x, s.y)
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
        if self._phase == "track" and self._passed_end(s):
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
        if self._phase == "track":
            self._tau += CONTROL_PERIOD

    def _ramp_pose(self, t: float) -> tuple[float, float, float]:
        """The true hull's ramp-frame x, y and heading (where the ramp holds it)."""
        m = self._ramp_truth(t).measure(Measurement.of(self.vessel.state))
        return m.x, m.y, m.psi

    def _steer(self, s: Measurement) -> _Command | None:
        if self._phase == "track" and self._guide is not None:
            if self._command is None or self._tau >= self._next_guidance - 1e-9:
                cmd = self._guide.update(s, self._tau)
                self._segment = cmd.segment
                self._command = _Command(cmd.heading, cmd.speed, cmd.water_speed)
                self._next_guidance = self._tau + GUIDANCE_PERIOD
            return self._command
        if self._phase == "guided":
            return self._guided
        if self._phase in ("hold", "idle"):
            c = self.keeper.update(s, s.t)
            return None if c.idle else _Command(c.heading, c.speed, c.water_speed)
        return None  # done (on the ramp) or aborted: propellers stopped

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
