"""The simulated sea: a mother ship under way and scripted traffic, told to the station as a
ship's network would (NMEA 0183 own-ship sentences and AIS/ARPA over UDP).

`SeaModel` is pure: the true state of every ship at any time t (s since the sea started),
from the scenario's `origin`, `mother_ship` and `traffic` (scenario/ships.py), and the
sentences that report it (pynmea2 and pyais encode them). `SimulatedSea` hands them to a
sender at `rate_hz` of sea time (the clock's time scaled by `sim_speed`) and records the
truth: `UdpSender` puts them on a real UDP socket (`serve`: the ship's network), while in
simulated time they go straight to the world service.
"""

from __future__ import annotations

import asyncio
import contextlib
import math
import socket
import time
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import pynmea2
from pyais import encode_dict

from usvstation.clock import REAL_CLOCK, Clock
from usvstation.geo import RampFrame
from usvstation.scenario import Scenario
from usvstation.scenario.ships import MotherShip, TrafficShip
from usvstation.world.model import KNOT, compass_to_enu

STATIC_EVERY_S = 10.0  # AIS static reports (types 5 / 24)
TRUTH_KEPT = 36000


@dataclass(frozen=True)
class ShipTruth:
    """A ship's true state: ENU metres from the origin at t = 0, velocity, compass angles."""

    key: str
    east: float
    north: float
    ve: float
    vn: float
    course_deg: float
    speed: float
    heading_deg: float


Leg = tuple[float, float, float, float]  # (t_start, course at t_start deg, turn deg/s, speed)


def _legs(course_deg: float, speed: float, manoeuvres: list,
          turn_rate_deg_s: float | None = None) -> list[Leg]:
    """Legs from the initial motion and the timed manoeuvres: a new speed at once, a new
    course at once (`turn_rate_deg_s` None, as scripted traffic) or by a turn at that rate
    the shorter way round (the mother ship); a manoeuvre during a turn starts from where
    the turn had got to."""
    legs: list[Leg] = [(0.0, course_deg, 0.0, speed)]
    target = course_deg
    for m in manoeuvres:
        while len(legs) > 1 and legs[-1][0] > m.t:
            legs.pop()  # the end of a turn this manoeuvre interrupts
        _, _, _, _, course_now, speed_now = _integrate(legs, m.t)
        new_speed = speed_now if m.speed is None else m.speed
        if m.course_deg is not None:
            target = m.course_deg
        delta = (target - course_now + 180.0) % 360.0 - 180.0
        if turn_rate_deg_s is None or abs(delta) < 1e-9:
            legs.append((m.t, course_now + delta, 0.0, new_speed))
        else:
            rate = math.copysign(turn_rate_deg_s, delta)
            legs.append((m.t, course_now, rate, new_speed))
            legs.append((m.t + abs(delta) / turn_rate_deg_s, course_now + delta, 0.0, new_speed))
    return legs


def _integrate(legs: list[Leg], t: float) -> tuple[float, float, float, float, float, float]:
    """Displacement (e, n), velocity (ve, vn), course and speed at t along the legs (a turn
    at constant rate and speed sails a circular arc)."""
    e = n = 0.0
    course, speed = legs[0][1], legs[0][3]
    for i, (t0, c, rate, s) in enumerate(legs):
        if t0 > t:
            break
        t1 = legs[i + 1][0] if i + 1 < len(legs) else math.inf
        dt = min(t, t1) - t0
        if rate == 0.0:
            ve, vn = compass_to_enu(s, c)
            e, n = e + ve * dt, n + vn * dt
        else:
            w = math.radians(rate)
            c0, c1 = math.radians(c), math.radians(c + rate * dt)
            e += s / w * (math.cos(c0) - math.cos(c1))
            n += s / w * (math.sin(c1) - math.sin(c0))
        course, speed = c + rate * dt, s
    ve, vn = compass_to_enu(speed, course)
    return e, n, ve, vn, course % 360.0, speed


class SeaModel:
    """The true sea of a scenario (pure)."""

    def __init__(self, scenario: Scenario) -> None:
        if scenario.origin is None:
            raise ValueError("origin: the simulated sea needs a scenario with an origin")
        o = scenario.origin
        self.frame0 = RampFrame(o.lat, o.lon, o.ramp_bearing_deg)
        self.mother: MotherShip | None = scenario.mother_ship
        self.traffic: list[TrafficShip] = list(scenario.traffic)
        self._traffic_legs = [_legs(s.course_deg, s.speed, s.manoeuvres) for s in self.traffic]
        self._mother_legs: list[Leg] = []
        self._traffic_start = [tuple(float(v) for v in self.frame0.ramp_to_enu(s.start.x,
                                                                                s.start.y))
                               for s in self.traffic]
        self.heading_deg = 0.0  # the mother ship's heading at t = 0
        self._ship0 = (0.0, 0.0)
        if self.mother is not None:
            m = self.mother
            self.heading_deg = (o.ramp_bearing_deg - m.lever_arm.ramp_bearing_offset_deg) % 360.0
            self._mother_legs = _legs(m.course_deg, m.speed, m.manoeuvres, m.turn_rate_deg_s)
            # the ramp end is at the origin at t = 0: the ship's reference lies back along the arm
            ae, an = self._arm(self.heading_deg)
            self._ship0 = (-ae, -an)

    def _arm(self, heading_deg: float) -> tuple[float, float]:
        """The lever arm (ship's reference to the ramp end) in ENU at this heading."""
        assert self.mother is not None
        arm, h = self.mother.lever_arm, math.radians(heading_deg)
        return (arm.forward * math.sin(h) + arm.starboard * math.cos(h),
                arm.forward * math.cos(h) - arm.starboard * math.sin(h))

    def mother_at(self, t: float) -> ShipTruth | None:
        """The mother ship's reference point (ENU), velocity, course, speed and heading; its
        hull turns with its course."""
        if self.mother is None:
            return None
        e, n, ve, vn, course, speed = _integrate(self._mother_legs, t)
        heading = (self.heading_deg + course - self.mother.course_deg) % 360.0
        return ShipTruth("own", self._ship0[0] + e, self._ship0[1] + n, ve, vn, course, speed,
                         heading)

    def ramp_at(self, t: float) -> tuple[float, float]:
        """The ramp end's true ENU position at t (the origin when there is no mother ship)."""
        own = self.mother_at(t)
        if own is None:
            return 0.0, 0.0
        ae, an = self._arm(own.heading_deg)
        return own.east + ae, own.north + an

    def ramp_bearing_at(self, t: float) -> float:
        """The compass bearing of the ramp frame's +x axis at t."""
        own = self.mother_at(t)
        if own is None:
            return self.frame0.ramp_bearing_deg
        return (own.heading_deg + self.mother.lever_arm.ramp_bearing_offset_deg) % 360.0

    def ramp_velocity_at(self, t: float) -> tuple[float, float]:
        """The ramp end's ENU velocity at t: the ship's plus its turn's swing of the arm."""
        own = self.mother_at(t)
        if own is None:
            return 0.0, 0.0
        dt = 1e-3
        (e0, n0), (e1, n1) = self.ramp_at(t), self.ramp_at(t + dt)
        return (e1 - e0) / dt, (n1 - n0) / dt

    def traffic_at(self, t: float) -> list[ShipTruth]:
        out = []
        for ship, legs, (e0, n0) in zip(self.traffic, self._traffic_legs, self._traffic_start,
                                        strict=True):
            e, n, ve, vn, course, speed = _integrate(legs, t)
            out.append(ShipTruth(f"ais:{ship.mmsi}" if ship.report == "ais" else
                                 f"arpa:{self.traffic.index(ship) + 1}",
                                 e0 + e, n0 + n, ve, vn, course, speed, course))
        return out

    def traffic_in_ramp_frame(self, t: float) -> np.ndarray:
        """(N, 4) rows x, y, rvx, rvy of the traffic in the ship-fixed ramp frame at t."""
        ramp_e, ramp_n = self.ramp_at(t)
        mve, mvn = self.ramp_velocity_at(t)
        frame = RampFrame(self.frame0.lat, self.frame0.lon, self.ramp_bearing_at(t))
        rows = []
        for s in self.traffic_at(t):
            x, y = frame.enu_to_ramp(s.east - ramp_e, s.north - ramp_n)
            rvx, rvy = frame.vector_to_ramp(s.ve - mve, s.vn - mvn)
            rows.append((float(x), float(y), float(rvx), float(rvy)))
        return np.array(rows, dtype=float).reshape(-1, 4)

    def geodetic(self, east: float, north: float) -> tuple[float, float]:
        x, y = self.frame0.enu_to_ramp(east, north)
        lat, lon = self.frame0.to_geodetic(x, y)
        return float(lat), float(lon)

    # --- sentences ---------------------------------------------------------------------------
    def sentences(self, t: float, static: bool = False) -> list[str]:
        """Every sentence the ship's network carries at t (static AIS data when `static`)."""
        out: list[str] = []
        own = self.mother_at(t)
        stamp = time.strftime("%H%M%S.00", time.gmtime(t))
        if own is not None:
            lat, lon = self.geodetic(own.east, own.north)
            out.append(str(pynmea2.GGA("GP", "GGA", (
                stamp, _dm(lat, 2), "N" if lat >= 0 else "S", _dm(lon, 3),
                "E" if lon >= 0 else "W", "1", "12", "0.7", "5.0", "M", "0.0", "M", "", ""))))
            out.append(str(pynmea2.HDT("HE", "HDT", (f"{own.heading_deg:.1f}", "T"))))
            out.append(str(pynmea2.VTG("GP", "VTG", (
                f"{own.course_deg:.1f}", "T", "", "M", f"{own.speed / KNOT:.2f}", "N",
                f"{own.speed * 3.6:.2f}", "K", "A"))))
        for i, (ship, truth) in enumerate(zip(self.traffic, self.traffic_at(t), strict=True)):
            lat, lon = self.geodetic(truth.east, truth.north)
            if ship.report == "arpa":
                if own is None:
                    continue  # a radar target needs the radar's ship
                out.append(self._ttm(i + 1, own, truth, ship))
                continue
            kind = 1 if ship.ais_class == "A" else 18
            out += encode_dict({"type": kind, "mmsi": ship.mmsi, "lat": lat, "lon": lon,
                                "speed": round(truth.speed / KNOT, 1),
                                "course": round(truth.course_deg, 1),
                                "heading": round(truth.heading_deg) % 360},
                               talker_id="AI", sentence_type="VDM")
            if static:
                out += self._static(ship, i)
        return out

    @staticmethod
    def _ttm(number: int, own: ShipTruth, truth: ShipTruth, ship: TrafficShip) -> str:
        de, dn = truth.east - own.east, truth.north - own.north
        rng = math.hypot(de, dn) / 1852.0
        brg = math.degrees(math.atan2(de, dn)) % 360.0
        return str(pynmea2.TTM("RA", "TTM", (
            f"{number:02d}", f"{rng:.5f}", f"{brg:.2f}", "T", f"{truth.speed / KNOT:.2f}",
            f"{truth.course_deg:.2f}", "T", "", "", "N", ship.name, "T", "", "", "A")))

    @staticmethod
    def _static(ship: TrafficShip, i: int) -> list[str]:
        beam = ship.beam or max(1.0, ship.length / 3.0)
        dims = {"to_bow": round(ship.length / 2), "to_stern": round(ship.length / 2),
                "to_port": round(beam / 2), "to_starboard": round(beam / 2)}
        if ship.ais_class == "A":
            return encode_dict({"type": 5, "mmsi": ship.mmsi, "shipname": ship.name, **dims},
                               talker_id="AI", sentence_type="VDM", seq_id=i % 10)
        return [*encode_dict({"type": 24, "mmsi": ship.mmsi, "partno": 0,
                              "shipname": ship.name}, talker_id="AI", sentence_type="VDM"),
                *encode_dict({"type": 24, "mmsi": ship.mmsi, "partno": 1, **dims},
                             talker_id="AI", sentence_type="VDM")]


def _dm(value: float, width: int) -> str:
    """Degrees as NMEA ddmm.mmmmmm (6 decimals of a minute: 2 mm)."""
    a = abs(value)
    deg = int(a)
    minutes = round((a - deg) * 60.0, 6)
    if minutes >= 60.0:
        deg, minutes = deg + 1, 0.0
    return f"{deg:0{width}d}{minutes:09.6f}"


@dataclass
class TruthRecord:
    t: float
    ramp: tuple[float, float]
    ships: list[ShipTruth]


class UdpSender:
    """Sends each sentence as one UDP datagram to `addr`; a full or closed socket loses it,
    as a network would."""

    def __init__(self, addr: tuple[str, int]) -> None:
        self.addr = addr
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.setblocking(False)

    def __call__(self, data: bytes) -> None:
        with contextlib.suppress(OSError):
            self.sock.sendto(data, self.addr)

    def close(self) -> None:
        self.sock.close()


class SimulatedSea:
    """Hands the sea's sentences (CRLF-terminated bytes) to `send` and keeps the recent
    truth."""

    def __init__(self, scenario: Scenario, send: Callable[[bytes], None], rate_hz: float = 2.0,
                 sim_speed: float = 1.0, clock: Clock = REAL_CLOCK) -> None:
        self.model = SeaModel(scenario)
        self.send, self.rate_hz, self.sim_speed, self.clock = send, rate_hz, sim_speed, clock
        self.truth: deque[TruthRecord] = deque(maxlen=TRUTH_KEPT)
        self.sent = 0
        self.t0: float | None = None

    def now(self) -> float:
        """Sea time: seconds since the sea started, scaled by sim_speed."""
        return 0.0 if self.t0 is None else (self.clock.now() - self.t0) * self.sim_speed

    async def run(self, stop: asyncio.Event) -> None:
        self.t0 = self.clock.now()
        last_static = -math.inf
        while not stop.is_set():
            t = self.now()
            static = t - last_static >= STATIC_EVERY_S
            if static:
                last_static = t
            for line in self.model.sentences(t, static=static):
                self.send((line + "\r\n").encode("ascii"))
                self.sent += 1
            own = self.model.mother_at(t)
            self.truth.append(TruthRecord(t, self.model.ramp_at(t),
                                          [*([own] if own else []),
                                           *self.model.traffic_at(t)]))
            with contextlib.suppress(TimeoutError):
                await asyncio.wait_for(stop.wait(), 1.0 / (self.rate_hz * self.sim_speed))
