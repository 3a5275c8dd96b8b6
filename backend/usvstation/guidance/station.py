"""Station keeping on GNSS position with the drift observer (pure, no I/O).

A boat told to HOLD must stay where it is in a current, so "at rest" means
at rest over ground at the hold point, not a low speed over ground. The law
asks for a ground velocity back to the hold point, a PI on the position error,

    v_d = sat(k e + k_i int(e), v_max),

and turns it into a heading and speed through the water with the drift
estimate c: the water velocity it needs is w = v_d - c. In a current (estimate above
`weathervane_current`) the boat weathervanes: bow into w; when w comes round behind it
(more than 135 deg off the bow: a current that reversed, or the point behind it), stern
into it with astern thrust, which a twin-screw boat can give at once, within the astern
capacity; it turns its bow back into the current at slack water (or when astern power
is not enough), so in a steady current it may hold bow or stern first. The heading
follows the current as it turns, instead of being caught broadside. In slack water it
turns towards the point before it goes (`EstimatedDrift.solve`, the speed scaled by the
cosine of the heading still to turn) and, close to it, keeps its heading and stops its
propellers; given a heading to hold (a standby point facing the ramp, a HOLD on the final
approach), it turns to it and holds the point ahead or astern along it while the point
lies within 1 m of that line, and stops its propellers once it points within 5 deg.

`over_capacity` is true when the boat cannot hold: the estimated drift needs more than
`capacity` x the top speed through the water; or the boat, having held its point (at
rest there), is more than `radius` (2 m) off it (it clears within half of that); or a
current above 60 % of its top speed comes from more than 60 deg off the way it must
head (it is still turning to meet it and drifts meanwhile). The simulated boat reports
it in a STATUSTEXT and the USV_MISSION_STATE flags.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from usvstation.geometry import angle_diff, wrap_angle
from usvstation.guidance.compensation import EstimatedDrift
from usvstation.guidance.los import GuidanceCommand, Pose, check_pose


@dataclass(frozen=True)
class StationCommand:
    """Heading (rad), surge over ground and speed through the water (m/s) for the autopilot."""

    heading: float
    speed: float
    water_speed: float | None
    idle: bool  # propellers may stop: in slack water at the point


STRONG_CURRENT = 0.6  # of the top speed: a current the boat cannot ride out broadside
ASTERN_TURN = math.radians(135.0)  # a current this far round behind the bow: met astern
HELD_SPEED = 0.3  # m/s over ground: at the point and this slow, the boat holds it
BROADSIDE = math.radians(60.0)  # heading still to turn before the boat meets the current
ALIGNED = math.radians(5.0)  # a held heading this close: the propellers may stop


class StationKeeper:
    """Hold a point with the drift estimate: position loop -> compensation -> autopilot."""

    def __init__(self, drift: EstimatedDrift, gain: float = 0.5, speed_max: float = 1.0,
                 idle_speed: float = 0.15, capacity: float = 0.9,
                 weathervane_current: float = 0.15, integral_gain: float = 0.02,
                 radius: float = 2.0, astern_share: float = 0.6,
                 max_offset: float = math.radians(60.0)) -> None:
        if not gain > 0.0 or not speed_max > 0.0:
            raise ValueError("station keeping: gain and speed_max must be > 0")
        self.drift = drift
        self.gain = gain
        self.speed_max = speed_max
        self.idle_speed = idle_speed
        self.capacity = capacity
        self.weathervane_current = weathervane_current
        self.integral_gain = integral_gain
        self.radius = radius
        self.astern_share = astern_share  # of the top speed: what astern thrust can hold
        self.max_offset = max_offset
        self.point: tuple[float, float] | None = None
        self.heading: float | None = None  # the bow's way in slack water (None: free)
        self.astern = False
        self.off_point = False
        # the current is strong and the boat must still turn far to meet it: it drifts
        self.turning_in_strong_current = False
        self._integral = (0.0, 0.0)
        self._last_t: float | None = None
        self._held = False

    def hold_at(self, x: float, y: float, heading: float | None = None) -> None:
        """Hold (x, y); with `heading`, in slack water the bow points that way (a standby
        point facing the ramp), the point held by going ahead or astern along it."""
        if not (math.isfinite(x) and math.isfinite(y)):
            raise ValueError(f"station keeping: hold point must be finite (got {x}, {y})")
        if heading is not None and not math.isfinite(heading):
            raise ValueError(f"station keeping: heading must be finite (got {heading})")
        self.point = (x, y)
        self.heading = heading
        self._integral, self._last_t, self.off_point = (0.0, 0.0), None, False
        self.turning_in_strong_current = False
        self._held = False  # it has been at the point since hold_at

    @property
    def over_capacity(self) -> bool:
        top = self.drift.observer.params.top_speed
        return self.drift.observer.speed > self.capacity * top or self.off_point or \
            self.turning_in_strong_current

    def update(self, pose: Pose, t: float) -> StationCommand:
        check_pose(pose, t)
        if self.point is None:
            self.point = (pose.x, pose.y)
        dt = 0.0 if self._last_t is None else min(max(t - self._last_t, 0.0), 1.0)
        self._last_t = t
        dx, dy = self.point[0] - pose.x, self.point[1] - pose.y
        dist = math.hypot(dx, dy)
        if dist < 0.5 * self.radius:
            self.off_point = False
            # it holds once it is there and at rest over ground (coming to the point under
            # way, its overshoot is not the current's doing)
            self._held = self._held or getattr(pose, "sog", 0.0) < HELD_SPEED
        elif dist > self.radius and self._held:
            self.off_point = True
        ix, iy = self._integral
        if dist < self.radius:  # integrate near the point only (no wind-up out of reach)
            ix, iy = ix + dx * dt, iy + dy * dt
            cap = self.speed_max / max(self.integral_gain, 1e-9)
            norm = math.hypot(ix, iy)
            if norm > cap:
                ix, iy = ix * cap / norm, iy * cap / norm
        self._integral = (ix, iy)
        vx = self.gain * dx + self.integral_gain * ix
        vy = self.gain * dy + self.integral_gain * iy
        speed = math.hypot(vx, vy)
        if speed > self.speed_max:
            vx, vy = vx * self.speed_max / speed, vy * self.speed_max / speed
        cx, cy = self.drift.observer.fast  # react to a changing current within a second
        if math.hypot(*self.drift.observer.estimate) < self.weathervane_current:
            if self.heading is not None and \
                    abs(-dx * math.sin(self.heading) + dy * math.cos(self.heading)) \
                    <= 0.5 * self.radius:
                return self._along(vx, vy, pose.psi)
            sol = self.drift.solve(vx, vy, pose.psi)
            if sol.water_speed < self.idle_speed and math.hypot(vx, vy) < self.idle_speed:
                return StationCommand(pose.psi, 0.0, None, True)
            # turn first, then go: running on while the bow swings round orbits the point
            ahead = max(math.cos(angle_diff(sol.heading, pose.psi)), 0.0)
            return StationCommand(sol.heading, sol.surge * ahead, sol.water_speed * ahead, False)
        # Weathervane: bow (or stern) into the water velocity it needs.
        top = self.drift.observer.params.top_speed
        astern_cap = self.astern_share * top
        astern_ok = math.hypot(cx, cy) <= 0.9 * astern_cap
        wx, wy = vx - cx, vy - cy
        bow = math.atan2(wy, wx)
        stern = wrap_angle(bow + math.pi)
        turn_bow = abs(angle_diff(bow, pose.psi))
        if not astern_ok or math.hypot(cx, cy) < self.weathervane_current:
            self.astern = False  # beyond astern power, or slack: the bow again
        elif not self.astern:  # what it must meet came round behind it: stern first
            self.astern = turn_bow > ASTERN_TURN
        psi = stern if self.astern else bow
        self.turning_in_strong_current = (
            math.hypot(cx, cy) > STRONG_CURRENT * top
            and abs(angle_diff(psi, pose.psi)) > BROADSIDE)
        # what the propellers can give that way: the pursuit of the point shrinks first
        cap = astern_cap if self.astern else 0.95 * top
        shrink = _within(vx, vy, cx, cy, cap)
        wx, wy = shrink * vx - cx, shrink * vy - cy
        c, s = math.cos(psi), math.sin(psi)
        water = wx * c + wy * s  # negative: astern
        surge = water + cx * c + cy * s
        return StationCommand(psi, surge, water, False)

    def _along(self, vx: float, vy: float, psi: float) -> StationCommand:
        """Slack water, the point (nearly) ahead or astern: keep the bow on `heading` and go
        ahead or astern along it (turning first); idle there once it points that way."""
        h = self.heading
        along = vx * math.cos(h) + vy * math.sin(h)
        off = abs(angle_diff(h, psi))
        if abs(along) < self.idle_speed and off < ALIGNED:
            return StationCommand(psi, 0.0, None, True)
        along *= max(math.cos(off), 0.0)
        return StationCommand(h, along, along, False)

    def command(self, pose: Pose, t: float) -> GuidanceCommand:
        """The same as a GuidanceCommand (for a TrackingLoop); `finished` is never set."""
        c = self.update(pose, t)
        point = self.point or (pose.x, pose.y)
        return GuidanceCommand(c.heading, c.speed, point, t, 0, False, c.water_speed)


def _within(vx: float, vy: float, cx: float, cy: float, cap: float) -> float:
    """The largest s in [0, 1] with |s v - c| <= cap (0 when even -c exceeds it)."""
    if math.hypot(vx - cx, vy - cy) <= cap:
        return 1.0
    if math.hypot(cx, cy) >= cap:
        return 0.0
    lo, hi = 0.0, 1.0
    for _ in range(20):
        mid = 0.5 * (lo + hi)
        if math.hypot(mid * vx - cx, mid * vy - cy) <= cap:
            lo = mid
        else:
            hi = mid
    return lo
