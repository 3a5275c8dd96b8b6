"""The last 30 metres: approach guidance to the ramp, approach gates and the go-around
route (pure, no I/O; issue 24).

Approach line. With the drift c known from the observer, a boat that runs U through the
water with its hull within `end_heading` of the arrival heading psi_a crosses the water
diagonally: its ground velocity is v0 = U h(psi_a + delta0) + c, delta0 the crab it may
take at the end (into the cross current, at most `end_heading`). The approach line is
the straight line through the ramp end along v0: a boat on it arrives on the axis with
its hull along the axis. It is re-decided every guidance step with the drift known then.

Course-based integral LOS (Fossen 2021 ch. 12, ILOS with the integral state of Fossen
and Lekkas 2017): on the approach line, with cross-track error e (left of the line),

    chi_d = lambda - atan(e / Delta + k_i y_int),  y_int' = Delta e / ((e + kappa y_int)^2
    + Delta^2),

the look-ahead Delta shrinking with the distance to go (down to 2.5 m), so the boat keeps
correcting to the ramp end. The course chi_d is turned into a heading and a speed
through the water with the drift (`DriftModel.solve`): the course over ground is what is
steered; the integral removes what the drift estimate still has wrong.

Heading limit from what the boat can correct. At the ramp end the hull must be within
the arrival tolerance of the axis; farther out it may point away as long as it can turn
back in the time left: delta_max(d) = end_heading + turn_rate (d / v_along - lag), at most
`heading_max`. Held against it, the course cannot always be made good; the speed through
the water then changes (within `speed_min`..`speed_max`) so that the ground velocity
points where the course asks, which in a strong beam current is the stronger control.

Gates (`ApproachGates`): at fixed distances from the ramp end (scenario
`vessel.gates_m`, 30, 15 and 5 m by default) the approach is checked against limits
derived from the ramp tolerance and the vessel: navigation quality (an RTK-class fix,
not dead-reckoned), a feasible line (enough headway against the drift, a line angle the
hull can follow), cross-track error from the line, heading against what can still be
corrected, speed. A missed gate is a go-around.

Go-around (`escape_routes`): the escape route goes back along the plan's own path (legs
the planner checked against every obstacle the station knew) to where it lies `standby_m`
out from the ramp end, the standby point (for a plan with a long final straight: on the
axis); or, when that is not clear, straight to the standby point on the axis. The caller
checks each candidate against the obstacles it knows and flies the first clear one.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from usvstation.geometry import angle_diff, wrap_angle
from usvstation.guidance.compensation import DriftModel
from usvstation.guidance.los import GuidanceCommand, Pose, check_pose
from usvstation.guidance.trajectory import Trajectory


@dataclass(frozen=True)
class ArrivalLimits:
    """What the ramp accepts and where the approach is checked (SI units, radians)."""

    offset: float = 0.3  # m, lateral offset at the ramp end for an arrival
    heading: float = math.radians(5.0)  # heading error at the ramp end for an arrival
    contact_offset: float = 0.5  # m: a contact beyond this is a bad arrival
    contact_heading: float = math.radians(8.0)
    gates: tuple[float, ...] = (30.0, 15.0, 5.0)  # m from the ramp end, descending
    standby: float = 50.0  # m from the ramp end along the axis

    def __post_init__(self) -> None:
        if not 0.0 < self.offset < self.contact_offset:
            raise ValueError("arrival limits: need 0 < offset < contact_offset")
        if not 0.0 < self.heading < self.contact_heading < math.pi / 2:
            raise ValueError("arrival limits: need 0 < heading < contact_heading < 90 deg")
        if not self.gates or any(g <= 0.0 for g in self.gates) or \
                list(self.gates) != sorted(self.gates, reverse=True):
            raise ValueError("arrival limits: gates must be positive and descending")
        if self.standby <= self.gates[0]:
            raise ValueError("arrival limits: the standby point must lie beyond the first gate")

    @classmethod
    def from_vessel(cls, vessel) -> ArrivalLimits:
        """From a scenario's `vessel` (arrival_offset_m, arrival_heading_deg,
        contact_offset_m, contact_heading_deg, gates_m, standby_m)."""
        return cls(vessel.arrival_offset_m, math.radians(vessel.arrival_heading_deg),
                   vessel.contact_offset_m, math.radians(vessel.contact_heading_deg),
                   tuple(vessel.gates_m), vessel.standby_m)


@dataclass(frozen=True)
class ApproachLine:
    """The approach at one distance (angles relative to the arrival heading)."""

    angle: float  # lambda: the ground track's direction relative to the axis (rad)
    crab: float  # delta: the hull's offset from the axis there (rad)
    along: float  # ground speed along the axis (m/s)
    speed: float  # ground speed along the track (m/s)

    @property
    def feasible(self) -> bool:
        return self.along > MIN_HEADWAY


MIN_HEADWAY = 0.3  # m/s along the axis: below it the drift wins
FINAL_HEADWAY = 0.6  # m/s along the axis at least in the final phase
JOIN_MARGIN = 10.0  # m: a gate is checked only this far inside where the approach began
MAX_LINE_ANGLE = math.radians(50.0)  # a steeper track cannot be flown onto the ramp
PROFILE_STEP = 0.5  # m between the approach profile's samples
TURN_LAG = 2.0  # s the hull's heading lags its command (autopilot reference model)
FINAL_WINDOW = 5  # guidance steps (1 s) the final phase's predicted crossing is averaged


@dataclass(frozen=True)
class ApproachProfile:
    """The approach path of one guidance step: sampled every PROFILE_STEP m of distance
    to go, the lateral offset the boat must have there (`offset`, left of the axis) to
    drift onto the axis at the ramp end, and the track there (angle, crab, speeds)."""

    water_speed: float
    offset: np.ndarray
    angle: np.ndarray
    crab: np.ndarray
    along: np.ndarray
    speed: np.ndarray
    time: np.ndarray  # s to go on the profile from each sample

    def time_at(self, distance: float) -> float:
        steps = np.arange(len(self.time)) * PROFILE_STEP
        return float(np.interp(distance, steps, self.time, right=self.time[-1] + (
            distance - steps[-1]) / max(float(self.along[-1]), 0.3)))

    def at(self, distance: float) -> tuple[float, ApproachLine]:
        """(offset wanted, track) `distance` m out (beyond the samples: straight on)."""
        last = (len(self.offset) - 1) * PROFILE_STEP
        d = min(max(distance, 0.0), last)
        off = float(np.interp(d, np.arange(len(self.offset)) * PROFILE_STEP, self.offset))
        i = min(round(d / PROFILE_STEP), len(self.offset) - 1)
        if distance > last:
            off += (distance - last) * math.tan(float(self.angle[-1]))
        return off, ApproachLine(float(self.angle[i]), float(self.crab[i]),
                                 float(self.along[i]), float(self.speed[i]))

    @property
    def feasible(self) -> bool:
        return bool(np.all(self.along > MIN_HEADWAY)
                    and np.all(np.abs(self.angle) <= MAX_LINE_ANGLE))


def approach_line(drift: tuple[float, float], arrival: float, water_speed: float,
                  crab_limit: float) -> ApproachLine:
    """The track of a boat running `water_speed` through the water with its hull at most
    `crab_limit` off the arrival heading, crabbing into the cross drift as far as that
    allows."""
    cx, cy = drift
    ca = cx * math.cos(arrival) + cy * math.sin(arrival)
    cn = -cx * math.sin(arrival) + cy * math.cos(arrival)
    u = max(water_speed, 1e-6)
    crab = -math.asin(min(max(cn / u, -1.0), 1.0))
    crab = min(max(crab, -crab_limit), crab_limit)
    va = u * math.cos(crab) + ca
    vn = u * math.sin(crab) + cn
    return ApproachLine(math.atan2(vn, va), crab, va, math.hypot(va, vn))


@dataclass(frozen=True)
class ApproachState:
    """Where the boat is relative to the ramp and its approach (one guidance step)."""

    distance: float  # m to go along the axis (positive before the ramp end)
    lateral: float  # m left of the axis
    cross_track: float  # m left of the approach path
    line: ApproachLine  # the approach path's track here
    feasible: bool  # the whole approach can be flown against this drift
    heading_error: float  # estimated true heading - arrival heading (rad)
    heading_limit: float  # delta_max at this distance (rad)
    heading_reach: float  # delta_max where the boat will be `turn_lag` s later (rad)
    course: float  # measured course over ground (rad, ramp frame)
    sog: float
    final: bool = False  # cross_track is the crossing offset predicted beyond control
    yaw_rate: float = 0.0  # measured (rad/s)


class RampApproach:
    """Course-based ILOS onto the drift-aware approach path, re-decided every step.

    `drift` is the boat's drift model (EstimatedDrift); `compass_bias()` the observer's
    compass bias estimate (rad), so headings are limited as the hull truly points.
    The approach path: far out the hull may crab as far as it can still turn back
    (`heading_limit`), so the boat holds the axis; close in it must straighten, and the
    cross drift then carries it sideways, so the path bends away up-current: sampled
    back from the ramp end, offset(d) = -integral of v_n / v_a, with the hull at the
    design crab (the limit less `margin`, which is left for the correction).
    """

    def __init__(self, goal: tuple[float, float], arrival: float, drift: DriftModel,
                 limits: ArrivalLimits, speed: float, speed_max: float,
                 speed_min: float = 0.6, compass_bias=lambda: 0.0,
                 end_fraction: float = 0.6, margin: float = math.radians(1.5),
                 turn_rate: float = math.radians(10.0), final_s: float = 5.0,
                 heading_max: float = math.radians(50.0), lookahead_max: float = 5.0,
                 lookahead_min: float = 2.5, ki_ratio: float = 0.1, kappa: float = 2.0,
                 integral_zone: float = 0.5, reach: float = 120.0,
                 line_override: float | None = None) -> None:
        self.goal = goal
        self.arrival = arrival
        self.drift = drift
        self.limits = limits
        self.speed = speed  # wanted along the axis, over ground (relative to the ramp)
        self.speed_max = speed_max
        self.speed_min = speed_min
        self.compass_bias = compass_bias
        self.end_heading = end_fraction * limits.heading
        self.margin = margin
        self.turn_rate = turn_rate
        self.final_s = final_s
        self.heading_max = heading_max
        self.lookahead_max = lookahead_max
        self.lookahead_min = lookahead_min
        self.ki_ratio = ki_ratio
        self.kappa = kappa
        self.integral_zone = integral_zone
        self.reach = reach
        self.line_override = line_override  # a fixed track angle (the plan's axis), or None
        self.y_int = 0.0
        self.final = False  # in the final phase (the hull held along the axis)
        self._recent: list[float] = []  # the final phase's predicted crossing offsets
        self._last_t: float | None = None
        self.state: ApproachState | None = None

    def speed_for(self, drift: tuple[float, float]) -> float:
        """Water speed on the approach: what makes good `speed` along the axis against the
        drift along it, or more where the cross drift needs it to be held with at most
        0.8 x `heading_max` of crab; within the speed range (0.8 x the top for reserve)."""
        cx, cy = drift
        ca = cx * math.cos(self.arrival) + cy * math.sin(self.arrival)
        cn = abs(-cx * math.sin(self.arrival) + cy * math.cos(self.arrival))
        return min(max(self.speed - ca, cn / math.sin(0.8 * self.heading_max),
                       self.speed_min), 0.8 * self.speed_max)

    def heading_limit(self, distance: float, along: float) -> float:
        """delta_max: how far from the axis the hull may point `distance` m out: within
        `end_heading` for the last `final_s` seconds, then widening by what it can turn
        back at `turn_rate`."""
        to_go = max(distance, 0.0) / max(along, 0.5)
        return min(self.end_heading + self.turn_rate * max(to_go - self.final_s, 0.0),
                   self.heading_max)

    def restart(self) -> None:
        """Fly on from rest (after a HOLD): the integral and the final phase start anew."""
        self.y_int, self.final, self._last_t, self._recent = 0.0, False, None, []

    def profile(self) -> ApproachProfile:
        """The approach path for the drift known now (sampled out to `reach` m)."""
        drift = self.drift.drift(self.arrival, self.speed)
        u = self.speed_for(drift)
        ca = drift[0] * math.cos(self.arrival) + drift[1] * math.sin(self.arrival)
        cn = -drift[0] * math.sin(self.arrival) + drift[1] * math.cos(self.arrival)
        d = np.arange(int(self.reach / PROFILE_STEP) + 1) * PROFILE_STEP
        needed = -math.asin(min(max(cn / u, -1.0), 1.0))
        end_design = max(self.end_heading - self.margin, 0.3 * self.limits.heading)
        # time to go at each sample: first guessed with the hull crabbing as needed (up to
        # heading_max), then from the along-axis speed of the crab the schedule allows
        along = np.full_like(d, u * math.cos(min(abs(needed), self.heading_max)) + ca)
        for _ in range(2):
            to_go = np.concatenate(([0.0], np.cumsum(PROFILE_STEP / np.maximum(
                along[1:], 0.3))))
            # the hull follows the limit TURN_LAG seconds late: it is where the limit was
            limit = np.minimum(self.end_heading + self.turn_rate * np.maximum(
                to_go + TURN_LAG - self.final_s, 0.0), self.heading_max)
            design = np.maximum(limit - self.margin, end_design)
            crab = np.clip(needed, -design, design)
            along = u * np.cos(crab) + ca
        lateral = u * np.sin(crab) + cn
        angle = np.arctan2(lateral, along)
        if self.line_override is not None:
            angle = np.full_like(angle, self.line_override)
        offset = np.concatenate(([0.0], -np.cumsum(PROFILE_STEP * np.tan(angle[:-1]))))
        return ApproachProfile(u, offset, angle, crab, along, np.hypot(along, lateral), to_go)

    def locate(self, pose: Pose) -> tuple[float, float]:
        """(distance to go along the axis, lateral offset left of the axis)."""
        c, s = math.cos(self.arrival), math.sin(self.arrival)
        dx, dy = pose.x - self.goal[0], pose.y - self.goal[1]
        return -(dx * c + dy * s), -dx * s + dy * c

    def update(self, pose: Pose, t: float) -> GuidanceCommand:
        check_pose(pose, t)
        dt = 0.0 if self._last_t is None else max(t - self._last_t, 0.0)
        self._last_t = t
        prof = self.profile()
        distance, lateral = self.locate(pose)
        wanted, line = prof.at(distance)
        lam = line.angle
        e = (lateral - wanted) * math.cos(lam)  # left of the approach path
        delta = min(max(0.25 * distance, self.lookahead_min), self.lookahead_max)
        if abs(e) < self.integral_zone:  # integrate near the path only: no wind-up
            self.y_int += dt * delta * e / ((e + self.kappa * self.y_int) ** 2 + delta * delta)
        kp = 1.0 / delta
        chi = wrap_angle(self.arrival + lam - math.atan(kp * e + self.ki_ratio * kp * self.y_int))
        sol = self.drift.solve(line.speed * math.cos(chi), line.speed * math.sin(chi),
                               self.arrival)
        bias = self.compass_bias()
        sog = getattr(pose, "sog", 0.0)
        course = getattr(pose, "cog", pose.psi)
        along_now = max(sog * math.cos(angle_diff(course, self.arrival)), line.along)
        limit = self.heading_limit(distance, along_now)
        off = angle_diff(sol.heading, self.arrival)
        heading, water = sol.heading, sol.water_speed
        if abs(off) > limit:
            heading = wrap_angle(self.arrival + math.copysign(limit, off))
            water = self._speed_for(chi, heading, water)
        if prof.time_at(distance) <= self.final_s:
            delta, water, e = self._final(distance, lateral, sog, course, prof.water_speed)
            heading = wrap_angle(self.arrival + delta)
            self.final = True
            # the gates judge the crossing predicted over the last second, not one noisy step
            self._recent = [*self._recent[-(FINAL_WINDOW - 1):], e]
            e = sum(self._recent) / len(self._recent)
        reach = self.heading_limit(distance + TURN_LAG * along_now, along_now)
        self.state = ApproachState(distance, lateral, e, line, prof.feasible,
                                   angle_diff(pose.psi - bias, self.arrival), limit, reach,
                                   course, sog, self.final, getattr(pose, "r", 0.0))
        cx, cy = self.drift.drift(heading, water)
        surge = water + cx * math.cos(heading) + cy * math.sin(heading)
        return GuidanceCommand(wrap_angle(heading + bias), max(surge, 0.0), self.goal, t, 0,
                               False, min(water, self.speed_max))

    def _final(self, distance: float, lateral: float, sog: float, course: float,
               nominal: float) -> tuple[float, float, float]:
        """The final phase: the hull within `end_heading` of the axis, the crossing point
        predicted and put on the axis by choosing the crab and the speed through the water
        (re-solved every step, from where the boat will be `TURN_LAG` s on). Returns
        (crab, water speed, predicted crossing offset left over, m)."""
        cx, cy = self.drift.drift(self.arrival, nominal)
        ca = cx * math.cos(self.arrival) + cy * math.sin(self.arrival)
        cn = -cx * math.sin(self.arrival) + cy * math.cos(self.arrival)
        rel = angle_diff(course, self.arrival)
        va_m, vn_m = sog * math.cos(rel), sog * math.sin(rel)
        lag = min(TURN_LAG, 0.5 * distance / max(va_m, 0.5))
        y, d = lateral + vn_m * lag, max(distance - va_m * lag, 0.5)
        k = -y / d  # the lateral / along speed ratio that crosses on the axis
        h = self.end_heading
        return self._final_solve(y, d, k, h, ca, cn, nominal)

    def _final_solve(self, y: float, d: float, k: float, h: float, ca: float, cn: float,
                     nominal: float) -> tuple[float, float, float]:
        """The crab and water speed that put the predicted crossing on the axis with the
        drift estimate, and the offset left over."""
        crab0 = min(max(-math.asin(min(max(cn / max(nominal, 1e-6), -1.0), 1.0)),
                        -(h - self.margin)), h - self.margin)

        def residual(crab: float, u: float) -> float:
            va = u * math.cos(crab) + ca
            vn = u * math.sin(crab) + cn
            return y + d * vn / va if va > MIN_HEADWAY else math.copysign(math.inf, vn)

        # never so slow that the drift along the axis stops it short of the ramp
        slowest = min(max(self.speed_min, FINAL_HEADWAY - ca), self.speed_max)
        den = math.sin(crab0) - k * math.cos(crab0)
        if abs(den) > 1e-9:
            u = (k * ca - cn) / den
            if slowest <= u <= self.speed_max:
                return crab0, u, 0.0
        best = min((slowest, self.speed_max), key=lambda u: abs(residual(crab0, u)))
        lo, hi = -h, h
        f_lo, f_hi = residual(lo, best), residual(hi, best)
        if f_lo * f_hi > 0.0:
            crab = lo if abs(f_lo) < abs(f_hi) else hi
            return crab, best, residual(crab, best)
        for _ in range(30):  # bisection: the crossing moves monotonically with the crab
            mid = 0.5 * (lo + hi)
            if residual(mid, best) * f_lo > 0.0:
                lo, f_lo = mid, residual(mid, best)
            else:
                hi = mid
        return 0.5 * (lo + hi), best, 0.0

    def _speed_for(self, chi: float, heading: float, fallback: float) -> float:
        """The water speed that, at `heading`, turns the ground velocity onto course chi
        (or the nearest within the speed range)."""
        cx, cy = self.drift.drift(heading, fallback)
        hx, hy = math.cos(heading), math.sin(heading)
        kx, ky = math.cos(chi), math.sin(chi)
        den = hx * ky - hy * kx  # cross(h(heading), h(chi))
        if abs(den) < 1e-6:
            return fallback
        u = -(cx * ky - cy * kx) / den
        if (u * hx + cx) * kx + (u * hy + cy) * ky <= 0.0:  # would run away from the course
            return fallback
        return min(max(u, self.speed_min), self.speed_max)


@dataclass(frozen=True)
class GateResult:
    gate: float  # m
    passed: bool
    reason: str  # empty when passed


class ApproachGates:
    """The approach gates of `limits`, each checked once as the boat crosses it."""

    def __init__(self, limits: ArrivalLimits, speed_max: float) -> None:
        self.limits = limits
        self.speed_max = speed_max
        self.passed: list[float] = []
        self.skipped: list[float] = []
        self._next = 0

    def reset(self) -> None:
        self.passed, self.skipped, self._next = [], [], 0

    def rejoin(self, distance: float, margin: float = JOIN_MARGIN) -> None:
        """The approach is joined anew `distance` m out (after a HOLD): the gates still
        ahead are checked again as the boat crosses them (those less than `margin` m
        inside skipped, as at a first join); the caller goes around when none is ahead."""
        gates = self.limits.gates
        self.passed = [g for g in self.passed if g >= distance]
        self.skipped = [g for g in self.skipped if g >= distance]
        self._next = next((i for i, g in enumerate(gates) if g < distance), len(gates))
        self.joined(distance, margin)

    def joined(self, distance: float, margin: float = JOIN_MARGIN) -> None:
        """The approach begins `distance` m out: gates less than `margin` m inside it
        cannot be met yet (the plan joins the axis late) and are skipped."""
        gates = self.limits.gates
        while self._next < len(gates) - 1 and gates[self._next] > distance - margin:
            self.skipped.append(gates[self._next])
            self._next += 1

    def cross_track_limit(self, gate: float, final: bool = False) -> float:
        """Cross-track error allowed at `gate` m: the arrival offset near the ramp,
        widening with the distance left to correct it; in the final phase the crossing
        offset the boat predicts it cannot take out must stay within the arrival
        tolerance (a bad contact is 0.2 m farther still)."""
        if final:
            return self.limits.offset
        return self.limits.offset * (0.5 + gate / 4.0)

    def check(self, st: ApproachState, nav_ok: bool) -> GateResult | None:
        """The result of the gate the boat has just crossed, or None (no gate crossed)."""
        gates = self.limits.gates
        if self._next >= len(gates) or st.distance > gates[self._next]:
            return None
        gate = gates[self._next]
        while self._next < len(gates) and st.distance <= gates[self._next]:
            self._next += 1  # a boat that crossed two at once is checked once
        reason = self._problem(gate, st, nav_ok)
        if not reason:
            self.passed.append(gate)
        return GateResult(gate, not reason, reason)

    def _problem(self, gate: float, st: ApproachState, nav_ok: bool) -> str:
        g = f"gate {gate:g} m"
        if not nav_ok:
            return f"{g}: no RTK-class fix"
        line = st.line
        if not st.feasible:
            return f"{g}: drift too strong for an approach"
        e_max = self.cross_track_limit(gate, st.final)
        if abs(st.cross_track) > e_max:
            return f"{g}: cross-track {abs(st.cross_track):.2f} m > {e_max:.2f} m"
        h_max = st.heading_reach + math.radians(2.0)
        # where the heading will be once the turn the boat is in has taken effect
        ahead = st.heading_error + st.yaw_rate * TURN_LAG
        if abs(st.heading_error) > h_max and abs(ahead) > h_max:
            return (f"{g}: heading off {math.degrees(abs(st.heading_error)):.1f} deg > "
                    f"{math.degrees(h_max):.1f} deg")
        if st.sog > 1.3 * line.speed + 0.5 or st.sog < 0.3:
            return f"{g}: speed {st.sog:.2f} m/s"
        return ""


def standby_point(goal: tuple[float, float], arrival: float,
                  limits: ArrivalLimits) -> tuple[float, float]:
    """The standby point: `limits.standby` m out from the ramp end along the axis."""
    return (goal[0] - limits.standby * math.cos(arrival),
            goal[1] - limits.standby * math.sin(arrival))


@dataclass(frozen=True)
class EscapeRoute:
    """A go-around route: `points` from the boat to the standby point (the last one);
    `on_plan` = (segment, fraction) where that point lies on the plan's path (the new
    approach flies the plan on from there), None when it is off the plan."""

    points: list[tuple[float, float]]
    on_plan: tuple[int, float] | None = None

    @property
    def standby(self) -> tuple[float, float]:
        return self.points[-1]


def escape_routes(position: tuple[float, float], standby: tuple[float, float],
                  plan: Sequence[tuple[float, float]], goal: tuple[float, float],
                  limits: ArrivalLimits) -> list[EscapeRoute]:
    """Candidate go-around routes from `position`, best first: back along the plan's path
    (`plan`, its waypoints from the start: legs the planner checked against every obstacle
    the station knew) from the leg nearest the boat to where the path first lies
    `limits.standby` m from the ramp end (or to its start), which is then the standby
    point; else straight to the standby point on the axis (`standby`)."""
    routes = []
    pts = np.asarray(plan, dtype=float)
    if len(pts) >= 2:
        here = np.asarray(position, dtype=float)
        a, b = pts[:-1], pts[1:]
        ab = b - a
        w = np.clip(np.einsum("ij,ij->i", here - a, ab) / np.maximum(
            np.einsum("ij,ij->i", ab, ab), 1e-12), 0.0, 1.0)
        k = int(np.argmin(np.hypot(*(a + w[:, None] * ab - here).T)))
        back, on_plan = [position], (0, 0.0)
        g = np.asarray(goal, dtype=float)
        for i in range(k, -1, -1):  # leg i from pts[i] to pts[i + 1], walked backwards
            end = float(np.hypot(*(pts[i] - g)))
            if end >= limits.standby:
                start = a[i] + (w[k] if i == k else 1.0) * ab[i]
                f = _crossing(start, pts[i], g, limits.standby)
                p = start + f * (pts[i] - start)
                back.append((float(p[0]), float(p[1])))
                frac = (w[k] if i == k else 1.0) * (1.0 - f)
                on_plan = (i, float(frac))
                break
            back.append((float(pts[i][0]), float(pts[i][1])))
        routes.append(EscapeRoute(back, on_plan))
    routes.append(EscapeRoute([position, standby]))
    return routes


def _crossing(p: np.ndarray, q: np.ndarray, g: np.ndarray, radius: float) -> float:
    """The fraction along p -> q where the distance from g first reaches `radius` (q lies
    at or beyond it)."""
    d = q - p
    m = p - g
    qa, qb, qc = float(d @ d), 2.0 * float(m @ d), float(m @ m) - radius * radius
    if qc >= 0.0 or qa < 1e-12:
        return 0.0
    return min(max((-qb + math.sqrt(max(qb * qb - 4 * qa * qc, 0.0))) / (2 * qa), 0.0), 1.0)


def obstacle_check(obstacles: Sequence, half_length: float,
                   samples_per_s: float = 5.0) -> Callable[[Trajectory], bool] | None:
    """A path check against moving circles (anything with x, y, radius, vx, vy: a scenario's
    obstacles, at x + vx t, y + vy t at plan time t): True when the hull (`half_length`
    around its centre) keeps clear of every circle all along the timed path. None when
    there are no obstacles."""
    if not obstacles:
        return None
    ox = np.array([o.x for o in obstacles])
    oy = np.array([o.y for o in obstacles])
    ovx = np.array([o.vx for o in obstacles])
    ovy = np.array([o.vy for o in obstacles])
    reach = np.array([o.radius for o in obstacles]) + half_length

    def check(tr: Trajectory) -> bool:
        n = max(int((tr.end_time - tr.start_time) * samples_per_s), 2) + 1
        ts = np.linspace(tr.start_time, tr.end_time, n)
        pos = tr.position_at(ts)
        dx = pos[:, 0:1] - (ox[None, :] + ovx[None, :] * ts[:, None])
        dy = pos[:, 1:2] - (oy[None, :] + ovy[None, :] * ts[:, None])
        return bool(np.all(np.hypot(dx, dy) > reach[None, :]))

    return check
