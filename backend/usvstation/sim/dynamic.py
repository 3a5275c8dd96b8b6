"""The simulated boat's default vehicle: the 3-DOF model steered by compensated AV-LOS.

It puts issue 3's pieces behind the `Vehicle` interface of sim/vehicle.py:
the vessel model (`dynamics.Vessel`, the Otter by default) in the scenario's
current and wind (and waves when asked), AV-LOS guidance with the
disturbance compensation of paper 000 section 3.1 (`CompensatedAVLOS`,
every 0.2 s) and the PID autopilot (every 0.05 s), as in the tracking bench.

The mission clock runs only while the boat tracks: hold and shore-assisted
guidance stop it, resume continues from where it stopped (AV-LOS then
speeds up to make up lost ground). Holding first lets the boat coast to
rest (below 0.3 m/s), then keeps station there: it steers back at low speed
when it drifts more than 3 m from where it stopped. The
mission is complete when the boat passes the last waypoint (for a recovery:
reaches the ramp end); it then stops its propellers and, on a recovery ramp,
is held there (the model stops moving; boat time goes on).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from usvstation.control import Autopilot
from usvstation.dynamics import Environment, ThrustCommand, Vessel, VesselState, otter
from usvstation.dynamics.params import VesselParams
from usvstation.guidance import CompensatedAVLOS, DisturbancePredictor, Trajectory
from usvstation.sim.vehicle import VehicleState, Waypoint, checked_mission, cross_track_error

CONTROL_PERIOD = 0.05  # s, autopilot and model
GUIDANCE_PERIOD = 0.2  # s, AV-LOS (paper 000 sec. 4.2 uses 0.2 s)
LOOKAHEAD = 8.0  # m, four Otter lengths (docs/tracking.md)
OVERRUN = 15.0  # m of path past the ramp end, so the boat drives on up the ramp
HOLD_RADIUS = 3.0  # m, station-keeping dead band
HOLD_SPEED = 0.8  # m/s, at most, when returning to the hold point
REST_SPEED = 0.3  # m/s, a holding boat has come to rest below this


@dataclass(frozen=True)
class _Command:
    heading: float
    speed: float


class DynamicVehicle:
    """A `Vehicle` simulated with the 3-DOF model, compensated AV-LOS and the autopilot."""

    def __init__(self, x: float, y: float, heading: float, *, speed: float = 0.0,
                 params: VesselParams | None = None, env: Environment | None = None,
                 accel: float = 0.5) -> None:
        self.params = params or otter()
        self.env = env or Environment.with_current(0.0, 0.0)
        self.accel = accel
        self.vessel = Vessel(self.params, VesselState(x, y, heading, speed))
        self.pilot = Autopilot(self.params)
        self._wps: list[Waypoint] = []
        self._guide: CompensatedAVLOS | None = None
        self._phase = "idle"  # idle | track | hold | guided | done | aborted
        self._hold_at = (x, y)
        self._settled = True  # a holding boat has come to rest at _hold_at
        self._tau = 0.0  # mission time
        self._pending = 0.0  # boat time not yet simulated (less than one control period)
        self._next_guidance = 0.0
        self._command: _Command | None = None
        self._guided = _Command(heading, 0.0)
        self._thrust = ThrustCommand(0.0, 0.0)
        self._segment = 0
        self._complete = False
        self._idle_time = 0.0  # boat time spent held on the ramp (the model is frozen)
        self._state = self._report()

    # --- Vehicle interface --------------------------------------------------------
    @property
    def state(self) -> VehicleState:
        return self._state

    @property
    def phase(self) -> str:
        return self._phase

    def set_mission(self, waypoints: Sequence[Waypoint]) -> None:
        self._wps = checked_mission(waypoints)
        self._guide, self._complete, self._segment = None, False, 0
        self._keep_station()

    def start(self) -> None:
        if len(self._wps) < 2:
            return
        traj = Trajectory.from_xyt([(w.x, w.y, w.t) for w in self._wps])
        self._guide = CompensatedAVLOS(
            traj, DisturbancePredictor(self.params, self.env), LOOKAHEAD,
            speed_max=self.params.top_speed, accel=self.accel, overrun=OVERRUN,
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

    def step(self, dt: float) -> None:
        if dt <= 0.0:
            return
        self._pending += dt
        while self._pending >= CONTROL_PERIOD:
            self._pending -= CONTROL_PERIOD
            self._control_step()
        self._state = self._report()

    # --- internals ----------------------------------------------------------------------
    def _keep_station(self) -> None:
        s = self.vessel.state
        self._hold_at, self._phase = (s.x, s.y), "hold" if self._guide else "idle"
        self._settled = math.hypot(*s.velocity) < REST_SPEED
        if self._complete:
            self._phase = "done"

    def _control_step(self) -> None:
        if self._phase == "done":  # recovered: the ramp holds the boat
            self._thrust = ThrustCommand(0.0, 0.0)
            self._idle_time += CONTROL_PERIOD
            return
        s = self.vessel.state
        command = self._steer(s)
        if command is None:
            self._thrust = ThrustCommand(0.0, 0.0)
            self.pilot.reset()
        else:
            self._thrust = self.pilot.update(command, s, CONTROL_PERIOD)
        self.vessel.step(self._thrust, self.env, CONTROL_PERIOD)
        if self._phase == "track":
            self._tau += CONTROL_PERIOD
            if self._passed_end():
                self._complete = True
                self._phase = "done"
                self._hold_at = (self.vessel.state.x, self.vessel.state.y)

    def _steer(self, s: VesselState) -> _Command | None:
        if self._phase == "track" and self._guide is not None:
            if self._command is None or self._tau >= self._next_guidance - 1e-9:
                cmd = self._guide.update(s, self._tau)
                self._segment = cmd.segment
                self._command = _Command(cmd.heading, cmd.speed)
                self._next_guidance = self._tau + GUIDANCE_PERIOD
            return self._command
        if self._phase == "guided":
            return self._guided
        if self._phase in ("hold", "idle"):
            if not self._settled:  # coast to rest, then hold where the boat stopped
                self._hold_at = (s.x, s.y)
                self._settled = math.hypot(*s.velocity) < REST_SPEED
                return None
            dx, dy = self._hold_at[0] - s.x, self._hold_at[1] - s.y
            dist = math.hypot(dx, dy)
            if dist <= HOLD_RADIUS:
                return None
            return _Command(math.atan2(dy, dx), min(HOLD_SPEED, 0.3 * dist))
        return None  # done (on the ramp) or aborted: propellers stopped

    def _passed_end(self) -> bool:
        """True once the boat is past the line through the last waypoint, across the last leg."""
        a, b = self._wps[-2], self._wps[-1]
        s = self.vessel.state
        lx, ly = b.x - a.x, b.y - a.y
        return (s.x - b.x) * lx + (s.y - b.y) * ly >= 0.0

    def _report(self) -> VehicleState:
        s = self.vessel.state
        vx, vy = s.velocity
        speed = math.hypot(vx, vy)
        full = self.params.thrusters.thrust_max
        index = min(self._segment + 1, max(len(self._wps) - 1, 0))
        if self._phase == "done":
            vx = vy = speed = 0.0
        return VehicleState(
            t=s.t + self._idle_time, x=s.x, y=s.y, heading=s.psi, speed=speed,
            course=math.atan2(vy, vx) if speed > 1e-6 else s.psi,
            yaw_rate=0.0 if self._phase == "done" else s.r,
            thrust_left=max(-1.0, min(1.0, self._thrust.left / full)),
            thrust_right=max(-1.0, min(1.0, self._thrust.right / full)),
            waypoint_index=index, cross_track_error=cross_track_error(self._wps, s.x, s.y, index),
            mission_complete=self._complete,
        )
