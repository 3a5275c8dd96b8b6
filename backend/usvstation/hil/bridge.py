"""The HIL bridge: the vessel model run against the firmware's own thrust (sans-IO).

The firmware sends HIL_ACTUATOR_CONTROLS every 50 ms of its clock (time_usec = its
uptime; controls[0], [1] = left and right propeller, -1..1); the bridge holds the previous
command over the interval up to that instant, steps the 3-DOF vessel (dynamics.Vessel, the
Otter of the simulated boat, in the scenario's current and wind) to it, takes the new
command and answers with one HIL_GPS: the position with the GPS error model of the
simulated boat (a `PositionError`, sim/sensors.GpsNoise), the exact ground speed, course
and hull heading (as the simulated boat reports them), and UNIX time. Model time is the
firmware's clock, so a busy host slows the run down but never changes it; a firmware time
that goes backwards is a reset of the chip: the boat stays where it is.

A control value is the ESC's throttle: the propeller's shaft speed as a fraction of its
largest forward (or reverse) speed, so steady speed grows about linearly with it. Frames are
signed with the link key like the radio, under the boat's system id (the bridge speaks as
the boat's GNSS, MAV_COMP_ID_GPS); anything else is refused and counted.
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass, field
from typing import Any, Protocol

from usvstation.dynamics import Environment, ThrustCommand, Vessel, VesselState, otter
from usvstation.geo import RampFrame
from usvstation.link import wire
from usvstation.link.mavlink import usv_recovery as mav

GNSS_COMPONENT = mav.MAV_COMP_ID_GPS


class PositionError(Protocol):
    """A GPS error model: the position error of a fix dt seconds after the previous one."""

    fix_type: int
    satellites: int
    hdop: float

    def sample(self, dt: float) -> tuple[float, float]: ...


@dataclass
class BridgeStats:
    """What crossed the bridge: for the log and the judge, never for the firmware."""

    controls: int = 0  # HIL_ACTUATOR_CONTROLS taken
    fixes: int = 0  # HIL_GPS sent
    resets: int = 0  # firmware clock went backwards
    refused: Counter[str] = field(default_factory=Counter)
    firmware_time_s: float = 0.0
    thrust: tuple[float, float] = (0.0, 0.0)  # the latest controls


class HilBridge:
    """The vessel model on one side, the firmware's HIL link on the other (bytes in, out)."""

    def __init__(self, vessel: Vessel, env: Environment, frame: RampFrame, gps: PositionError,
                 *, boat_id: int = wire.BOAT_ID, key: bytes | None = None,
                 gnss_time: bool = True) -> None:
        """`gnss_time` False: the receiver has no UTC (HIL_GPS carries the firmware's own
        time since boot), so the boat's replay floor comes from its flash page alone."""
        self.vessel = vessel
        self.env = env
        self.frame = frame
        self.gps = gps
        self.boat_id = boat_id
        self.gnss_time = gnss_time
        self.codec = wire.Codec(boat_id, GNSS_COMPONENT, key)
        self.stats = BridgeStats()
        self._t: float | None = None  # firmware time of the last control (s)
        self._fix_t: float | None = None
        self._thrust = ThrustCommand(0.0, 0.0)

    @classmethod
    def for_scenario(cls, scenario: Any, gps: PositionError, *, boat_id: int = wire.BOAT_ID,
                     key: bytes | None = None, gnss_time: bool = True) -> HilBridge:
        """The Otter at rest at the scenario's start pose, in its current and wind, the ramp
        frame fixed at its origin (ValueError without an origin)."""
        if scenario.origin is None:
            raise ValueError(f"scenario {scenario.name} has no origin (lat, lon) for the GNSS")
        o, start = scenario.origin, scenario.start
        vessel = Vessel(otter(), VesselState(start.x, start.y, math.radians(start.heading_deg)))
        return cls(vessel, Environment.from_scenario(scenario.environment),
                   RampFrame(o.lat, o.lon, o.ramp_bearing_deg), gps, boat_id=boat_id, key=key,
                   gnss_time=gnss_time)

    @property
    def truth(self) -> VesselState:
        """The vessel's true state (ramp frame): for a judge, never sent to the boat."""
        return self.vessel.state

    def receive(self, data: bytes, unix_time: float) -> bytes:
        """Bytes from the firmware's USART2; returns the bytes to send back (HIL_GPS)."""
        msgs, refused = self.codec.feed(data)
        for r in refused:
            self.stats.refused[r.reason] += 1
        out = bytearray()
        for msg in msgs:
            if msg.get_type() == "HIL_ACTUATOR_CONTROLS" and msg.get_srcSystem() == self.boat_id:
                out += self._on_controls(msg, unix_time)
            else:
                self.stats.refused["not HIL_ACTUATOR_CONTROLS of the boat"] += 1
        return bytes(out)

    def _on_controls(self, msg: Any, unix_time: float) -> bytes:
        t = msg.time_usec * 1e-6
        if self._t is not None and t < self._t:
            self.stats.resets += 1
            self._fix_t = None
        elif self._t is not None and t > self._t:
            self.vessel.step(self._thrust, self.env, t - self._t)
        self._t = t
        left, right = (_clamp(float(c)) for c in msg.controls[:2])
        self._thrust = ThrustCommand(self._newtons(left), self._newtons(right))
        self.stats.controls += 1
        self.stats.firmware_time_s = t
        self.stats.thrust = (left, right)
        return self._fix(t, unix_time)

    def _newtons(self, throttle: float) -> float:
        """Thrust (N) of a propeller at a throttle: the shaft speed's fraction of its range."""
        th = self.vessel.params.thrusters
        return th.thrust(throttle * (th.n_max if throttle >= 0.0 else -th.n_min))

    def _fix(self, t: float, unix_time: float) -> bytes:
        s = self.vessel.state
        dx, dy = self.gps.sample(0.0 if self._fix_t is None else t - self._fix_t)
        self._fix_t = t
        lat, lon = self.frame.to_geodetic(s.x + dx, s.y + dy)
        compass = self.frame.heading_to_compass_deg
        cog = float(compass(math.degrees(s.course))) % 360.0
        hdg = float(compass(math.degrees(s.psi))) % 360.0
        speed = s.speed
        vn, ve = speed * math.cos(math.radians(cog)), speed * math.sin(math.radians(cog))
        gps = self.gps
        stamp = unix_time if self.gnss_time else t  # UTC, or time since boot without it
        msg = self.codec.mav.hil_gps_encode(
            int(stamp * 1e6), gps.fix_type, round(float(lat) * 1e7), round(float(lon) * 1e7),
            0, min(round(gps.hdop * 100), 0xFFFE), 0xFFFF, min(round(speed * 100), 0xFFFE),
            _cm(vn), _cm(ve), 0, round(cog * 100) % 36000, gps.satellites, 0,
            round(hdg * 100) % 36000 or 36000)  # yaw: 0 means unknown, north is 36000
        self.stats.fixes += 1
        return self.codec.encode(msg, wire.signing_time(unix_time))


def _clamp(v: float) -> float:
    return max(-1.0, min(1.0, v)) if math.isfinite(v) else 0.0


def _cm(v: float) -> int:
    return max(-32767, min(32767, round(v * 100)))
