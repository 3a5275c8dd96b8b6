"""Where the IGA's leg begins: the start itself, or the end of a turning run-out (issue 12).

The IGA's encoding steps towards the goal along the planning frame's x axis
(eq. 10), so its first leg cannot leave a boat that points away, and a
recovery cannot start within a few metres of the ramp or behind it. Such a
start gets a prefix: short legs at about constant speed through the water, the
course over ground turning by at most 0.6 turn_max per waypoint (the hull crabs
into a current), first out to sea (recoveries
that start too close in, behind or beside the ramp) and then round towards
the goal until the remaining turn is small. The IGA plans the rest from the
prefix's end, its first leg bound to the prefix's last course. Prefix legs
are checked against the inflated (and time-swept) obstacles exactly (eq. 9).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from usvstation.geometry import angle_diff
from usvstation.planning.hull import keepout_circles
from usvstation.planning.problem import StartState, sweep_moving
from usvstation.planning.validate import MOVING_START_SPEED, current_vector
from usvstation.planning.xyt import ObstacleField
from usvstation.scenario import Scenario
from usvstation.scenario.options import IGAOptions

MAX_PREFIX_LEGS = 24
ALIGNED = math.radians(60.0)  # a start course within this of the goal needs no prefix


@dataclass(frozen=True)
class Prefix:
    """Waypoints from the start to where the IGA takes over (scenario frame, eq. 11 times)."""

    x: list[float]
    y: list[float]
    t: list[float]
    v: list[float]  # ground speed at each waypoint
    end: StartState

    @property
    def legs(self) -> int:
        return len(self.x) - 1


def start_state(scenario: Scenario) -> StartState:
    """The scenario's start; its heading binds the first leg when the boat moves.

    `start.speed` is the boat's speed over ground (in the scenario's frame: with a moving
    ramp, relative to the ramp) and the plan starts from it: the first waypoint's speed is
    that speed and the first leg reaches the next within accel_max (eq. 12's G_acc). Its
    course over ground follows from the hull heading, that speed and the current
    (`start_motion`). Only a start whose speed over ground the boat cannot keep on that
    course within [speed_min, speed_max] through the water (a boat the current sets back,
    its ground velocity with no component along its hull: it is planned along its hull
    heading) starts from the nearest speed the course admits, and the plan says so.
    """
    s, v = scenario.start, scenario.vessel
    h = math.radians(s.heading_deg)
    cx, cy = current_vector(scenario)
    moving = s.speed >= MOVING_START_SPEED
    _, course = start_motion(scenario)
    speed = float(np.clip(s.speed, v.speed_min, v.speed_max))
    if not moving and (cx, cy) == (0.0, 0.0):
        return StartState(s.x, s.y, h, speed, bound=False, course=course)
    lo, hi = ground_window(course, cx, cy, v.speed_min, v.speed_max, slack=0.0)
    if lo <= hi:
        speed = float(np.clip(speed, lo, hi))
    return StartState(s.x, s.y, h, speed, bound=moving, course=course)


def start_motion(scenario: Scenario) -> tuple[float, float]:
    """(speed through the water, course the first leg is bound around) of the scenario's
    start, from its hull heading, its speed over ground and the current.

    The speed through the water w solves |w u + c| = s (u the hull's unit vector, c the
    current, s the speed over ground): of its roots w >= 0, the largest within [speed_min,
    speed_max] (the boat making way along its hull), else the largest; without a root (a
    cross current faster than s) the w nearest one. The course is the course over ground,
    or the hull heading when the current sets the boat back (`start_course`).
    """
    s, v = scenario.start, scenario.vessel
    h = math.radians(s.heading_deg)
    cx, cy = current_vector(scenario)
    water = water_speed_for(h, s.speed, cx, cy, v.speed_min, v.speed_max)
    return water, start_course(h, water, cx, cy)


def water_speed_for(heading: float, ground_speed: float, cx: float, cy: float,
                    speed_min: float, speed_max: float) -> float:
    """Speed through the water of a hull at `heading` making `ground_speed` over ground in
    the current (c): the root w >= 0 of w^2 + 2 w u.c + |c|^2 - s^2 = 0 as `start_motion`
    chooses it."""
    if (cx, cy) == (0.0, 0.0):
        return ground_speed
    along = math.cos(heading) * cx + math.sin(heading) * cy
    disc = along * along - (cx * cx + cy * cy) + ground_speed * ground_speed
    if disc < 0.0:
        return max(0.0, -along)
    roots = [w for w in (-along + math.sqrt(disc), -along - math.sqrt(disc)) if w >= 0.0]
    if not roots:
        return 0.0
    inside = [w for w in roots if speed_min <= w <= speed_max]
    return max(inside or roots)


def ground_window(course: float, cx: float, cy: float, speed_min: float,
                  speed_max: float, slack: float = 0.01) -> tuple[float, float]:
    """Ground speeds along `course` within [speed_min, speed_max] whose speed through the
    water (ground velocity minus current) lies in [speed_min, speed_max] too, with `slack`
    (1 %) at both ends in a current (lo > hi: none)."""
    if (cx, cy) == (0.0, 0.0):
        return speed_min, speed_max
    ux, uy = math.cos(course), math.sin(course)
    along, across = ux * cx + uy * cy, ux * cy - uy * cx
    lo_w, hi_w = (1.0 + slack) * speed_min, (1.0 - slack) * speed_max
    if across * across >= hi_w * hi_w:
        return 1.0, 0.0
    lo = along + math.sqrt(max(lo_w * lo_w - across * across, 0.0))
    hi = along + math.sqrt(hi_w * hi_w - across * across)
    return max(lo, speed_min), min(hi, speed_max)


def start_course(heading: float, water_speed: float, cx: float, cy: float) -> float:
    """The course the first leg is bound around: the course over ground, or the hull
    heading when the current sets the boat back (no ground way along its hull)."""
    gx, gy = water_speed * math.cos(heading) + cx, water_speed * math.sin(heading) + cy
    if gx * math.cos(heading) + gy * math.sin(heading) <= 0.0:
        return heading
    return ground_course(heading, water_speed, cx, cy)


def ground_course(heading: float, water_speed: float, cx: float, cy: float) -> float:
    """Course over ground of a hull at `heading` making `water_speed` in the current; the
    heading itself when the current holds the boat (almost) still over ground."""
    gx, gy = water_speed * math.cos(heading) + cx, water_speed * math.sin(heading) + cy
    return heading if math.hypot(gx, gy) < 0.1 else math.atan2(gy, gx)


def x_needed(opts: IGAOptions) -> float:
    """A recovery's leg needs its start at least this far out along the ramp axis, m."""
    return opts.approach_length + 2.0 * opts.d_sl + 5.0


def needs_prefix(scenario: Scenario, opts: IGAOptions) -> bool:
    s = scenario.start
    if scenario.kind == "recovery" and s.x < x_needed(opts):
        return True
    if s.speed < MOVING_START_SPEED:
        return False
    _, course = start_motion(scenario)
    bearing = math.atan2(scenario.goal.y - s.y, scenario.goal.x - s.x)
    return abs(angle_diff(course, bearing)) > ALIGNED


def prefixes(scenario: Scenario, opts: IGAOptions, margin: float) -> list[Prefix]:
    """Collision-free run-outs for a start the IGA cannot leave directly, shortest first."""
    field = _field(scenario, margin)
    out: list[Prefix] = []
    for scale in LEG_SCALES:  # shorter legs turn in less water (beside a ship's hull)
        for side in (1.0, -1.0):
            p = _steer(scenario, opts, side, scale)
            if p is not None and _free(p, field):
                out.append(p)
        if out:
            break
    return sorted(out, key=lambda p: p.end.t)


LEG_SCALES = (1.0, 0.5, 0.25)  # leg lengths tried, in multiples of the usual one


def _steer(scenario: Scenario, opts: IGAOptions, side: float,
           scale: float = 1.0) -> Prefix | None:
    """Legs whose course over ground turns by at most 0.6 turn_max per waypoint; each leg's
    ground speed is the one that makes `water` m/s through the water on it, and every
    waypoint's speed lies in the through-water window of both legs that meet there."""
    v = scenario.vessel
    s = scenario.start
    cx, cy = current_vector(scenario)
    drift = math.hypot(cx, cy)
    start_water, start_k = start_motion(scenario)
    water = float(np.clip(max(start_water, 1.0), v.speed_min, v.speed_max))
    if drift >= 0.8 * water:  # make way against the current in every direction
        water = max(water, min(0.95 * v.speed_max, drift / 0.8))
    step = 0.6 * math.radians(v.turn_max_deg)
    leg = scale * max(3.0, 2.0 * v.length, 2.0 * water, 4.0 * drift)
    moving = s.speed >= MOVING_START_SPEED
    k = start_k if moving else None
    x, y = s.x, s.y
    recovery = scenario.kind == "recovery"
    x_out = x_needed(opts) + 0.5 * abs(s.y) if recovery and s.x < x_needed(opts) else None
    xs, ys, courses = [x], [y], []
    first_water = water
    for _ in range(MAX_PREFIX_LEGS):
        if x_out is not None and x < x_out:
            target = 0.0
        else:
            x_out = None
            target = math.atan2(scenario.goal.y - y, scenario.goal.x - x)
            if k is not None and abs(angle_diff(k, target)) <= step / 2:
                break
        if k is None:
            k = target
        elif not courses:
            # the first leg turns the hull (the rule binds the hull, not the course)
            h = math.radians(s.heading_deg)
            err = angle_diff(_crab(target, water, cx, cy), h)
            turn = err if abs(err) <= step else (
                side if abs(err) > math.pi - step else math.copysign(1.0, err)) * step
            first_water = _water_within(h + turn, water, cx, cy, v.speed_min, v.speed_max)
            k = ground_course(h + turn, first_water, cx, cy)
        else:
            err = angle_diff(target, k)
            if abs(err) <= step:
                k = target
            else:
                k += (side if abs(err) > math.pi - step else math.copysign(1.0, err)) * step
        run = leg
        if x_out is not None and k == target:
            run = max(leg, min(x_out - x, 200.0))  # straight out in one leg
        x, y = x + math.cos(k) * run, y + math.sin(k) * run
        xs.append(x)
        ys.append(y)
        courses.append(k)
    else:
        return None
    if len(xs) == 1:
        return None
    waters = [first_water] + [water] * (len(courses) - 1)
    legs = [math.hypot(xs[i + 1] - xs[i], ys[i + 1] - ys[i]) for i in range(len(xs) - 1)]
    speeds = _joint_speeds(courses, waters, cx, cy, v.speed_min, v.speed_max,
                           start_state(scenario).speed, legs, v.accel_max)
    if speeds is None:
        return None
    t = [0.0]
    for i, d in enumerate(legs):
        t.append(t[-1] + 2.0 * d / (speeds[i] + speeds[i + 1]))
    kk, g = courses[-1], speeds[-1]
    hull = math.atan2(g * math.sin(kk) - cy, g * math.cos(kk) - cx)
    end = StartState(xs[-1], ys[-1], hull, g, t[-1], bound=True, course=kk)
    return Prefix(xs, ys, t, speeds, end)


def _crab(course: float, water: float, cx: float, cy: float) -> float:
    """Hull heading that makes good `course` over ground at `water` m/s in the current."""
    across = -cx * math.sin(course) + cy * math.cos(course)
    return course - math.asin(max(-1.0, min(1.0, across / water)))


def _water_within(hull: float, water: float, cx: float, cy: float, speed_min: float,
                  speed_max: float) -> float:
    """The most speed through the water, at most `water`, at which a hull at `hull` goes no
    faster than 0.99 speed_max over ground (running with the current)."""
    along = math.cos(hull) * cx + math.sin(hull) * cy
    disc = along * along - (cx * cx + cy * cy) + (0.99 * speed_max) ** 2
    if (cx, cy) == (0.0, 0.0) or disc < 0.0:
        return water
    return float(np.clip(-along + math.sqrt(disc), 1.01 * speed_min, water))


def _joint_speeds(courses: list[float], waters: list[float], cx: float, cy: float,
                  speed_min: float, speed_max: float, start: float, legs: list[float],
                  accel_max: float) -> list[float] | None:
    """Ground speed at every prefix waypoint (eq. 11's v_i): the start's own speed over
    ground (moved into the first leg's window only where that window excludes it), then the
    one that makes waters[i] through the water on the leg it starts, moved into the window
    of both adjacent legs and within accel_max of the previous waypoint's speed over the leg
    between them; None where these do not meet."""
    def wanted(i: int) -> float:
        k, water = courses[i], waters[i]
        along = math.cos(k) * cx + math.sin(k) * cy
        across = math.cos(k) * cy - math.sin(k) * cx
        return along + math.sqrt(max(water * water - across * across, 0.0))

    windows = [ground_window(k, cx, cy, speed_min, speed_max) for k in courses]
    lo, hi = ground_window(courses[0], cx, cy, speed_min, speed_max, slack=0.0)
    if lo > hi:
        return None
    out = [float(np.clip(start, lo, hi))]
    for i in range(1, len(courses) + 1):
        near = windows[i - 1:i + 1]
        lo, hi = max(w[0] for w in near), min(w[1] for w in near)
        reach = 2.0 * accel_max * legs[i - 1] * (1.0 - 1e-9)  # |v1^2 - v0^2| <= 2 a L
        lo = max(lo, math.sqrt(max(out[-1] ** 2 - reach, 0.0)))
        hi = min(hi, math.sqrt(out[-1] ** 2 + reach))
        if lo > hi:
            return None
        out.append(float(np.clip(wanted(min(i, len(courses) - 1)), lo, hi)))
    return out


def _field(scenario: Scenario, margin: float) -> ObstacleField:
    obs = scenario.obstacles
    centre = np.array([[o.x, o.y] for o in obs], dtype=float).reshape(-1, 2)
    velocity = np.array([[o.vx, o.vy] for o in obs], dtype=float).reshape(-1, 2)
    radius = np.array([o.radius for o in obs], dtype=float)
    c, w, r, infl, src = sweep_moving(centre, velocity, radius, radius + margin,
                                      scenario.vessel.time_margin_s)
    ship_c, ship_r = keepout_circles(scenario, margin)  # the mother ship's hull (hull.py)
    return ObstacleField(np.vstack([c, ship_c]), np.vstack([w, np.zeros_like(ship_c)]),
                         np.concatenate([r, np.zeros_like(ship_r)]),
                         np.concatenate([infl, ship_r]),
                         np.concatenate([src, np.full(ship_r.size, -1)]))


def _free(p: Prefix, field: ObstacleField) -> bool:
    if field.count == 0:
        return True
    x, y, t = (np.asarray(a) for a in (p.x, p.y, p.t))
    return not bool(field.hits(x[:-1], y[:-1], t[:-1], x[1:], y[1:], t[1:]).any())
