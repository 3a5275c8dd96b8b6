"""Exact check of a plan against its scenario (the validity rules of issues 2 and 12).

Written apart from the planner's own gates so that the two can catch each
other's mistakes: it reads only the stable plan format and the scenario.
Every planner's output goes through `plan_violations` before it leaves.

Clearance is the water between the hull and the obstacle: the hull is a
circle of half the vessel length around the boat's centre, so a segment is
clear of an obstacle of radius R when the centre-to-centre distance stays
above R + D_USV / 2 at every instant (eq. 9 solved exactly: closest approach
of two linear motions). Touching is a collision.

Timing margin (issue 12): the boat may run up to `time_margin_s` early or
late anywhere on the plan. A moving obstacle is then swept over
[t - m, t + m]; the relative position boat - obstacle over a segment and a
shift d in [-m, m] is affine in (tau, d), so its least norm is the distance
from the origin to a parallelogram, computed exactly.
"""

from __future__ import annotations

import itertools
import math
from typing import Any

import numpy as np

from usvstation.geometry import angle_diff
from usvstation.planning import kernel_geom
from usvstation.planning.hull import outline_clearance
from usvstation.scenario import Scenario

TOL = 1e-6
ARRIVAL_TOLERANCE_DEG = 10.0
MOVING_START_SPEED = 0.5  # m/s: from this start speed on, the start heading binds the first leg


def plan_violations(plan: dict[str, Any], scenario: Scenario) -> list[str]:
    """Every rule the plan breaks, as readable strings (empty when the plan is valid).

    Rules: starts at the start at t = 0 and ends at the goal; time increases;
    ground speeds within [speed_min, speed_max] without a current; the speed
    through the water (ground velocity minus current) within [speed_min,
    speed_max] at both ends of every segment, the hull making way forward;
    |dv|/dt <= accel_max on every segment; every turn <= turn_max_deg, and the
    first leg within turn_max_deg of the start heading when the boat moves
    (start speed >= 0.5 m/s); the hull never touches an obstacle circle; with
    the timing margin, not even when early or late by up to time_margin_s;
    a recovery arrives along the ramp axis (last segment within 10 degrees of
    heading 180); the hull never touches the mother ship's hull while the boat's
    centre is outside the approach corridor (planning/hull.py).
    """
    wps = plan["waypoints"]
    v = scenario.vessel
    out: list[str] = []
    if len(wps) < 2:
        return ["fewer than two waypoints"]
    first, last = wps[0], wps[-1]
    if abs(first["x"] - scenario.start.x) > TOL or abs(first["y"] - scenario.start.y) > TOL:
        out.append(f"does not start at the start ({first['x']}, {first['y']})")
    if abs(first["t"]) > TOL:
        out.append(f"starts at t = {first['t']}, not 0")
    if abs(last["x"] - scenario.goal.x) > TOL or abs(last["y"] - scenario.goal.y) > TOL:
        out.append(f"does not end at the goal ({last['x']}, {last['y']})")
    cur = current_vector(scenario)
    if cur == (0.0, 0.0):
        for i, w in enumerate(wps):
            if not v.speed_min - TOL <= w["speed"] <= v.speed_max + TOL:
                out.append(
                    f"waypoint {i}: speed {w['speed']} outside [{v.speed_min}, {v.speed_max}]"
                )
    for i, (a, b) in enumerate(itertools.pairwise(wps)):
        dt = b["t"] - a["t"]
        if dt <= 0.0:
            out.append(f"segment {i}: time does not increase ({a['t']} -> {b['t']})")
            continue
        if abs(b["speed"] - a["speed"]) / dt > v.accel_max * (1 + TOL) + TOL:
            out.append(f"segment {i}: |dv|/dt = {abs(b['speed'] - a['speed']) / dt:.4f} m/s^2 "
                       f"above {v.accel_max}")
    if out:
        return out
    headings = [
        math.atan2(b["y"] - a["y"], b["x"] - a["x"]) for a, b in itertools.pairwise(wps)
    ]
    for i, (h0, h1) in enumerate(itertools.pairwise(headings)):
        turn = abs(math.degrees(angle_diff(h1, h0)))
        if turn > v.turn_max_deg + 1e-6:
            out.append(f"waypoint {i + 1}: turn {turn:.2f} deg above {v.turn_max_deg}")
    turn0 = first_turn_deg(plan, scenario)
    if turn0 is not None and turn0 > v.turn_max_deg + 1e-6:
        out.append(f"first leg turns {turn0:.2f} deg from the start heading, "
                   f"above {v.turn_max_deg}")
    if cur != (0.0, 0.0):
        for i, (lo, hi, fwd) in enumerate(water_speeds(plan, scenario)):
            if lo < v.speed_min - 1e-4 or hi > v.speed_max + 1e-4 or not fwd:
                out.append(f"segment {i}: speed through the water {lo:.3f}-{hi:.3f} m/s outside "
                           f"[{v.speed_min}, {v.speed_max}]" + ("" if fwd else " or astern"))
    clear = clearance_matrix(plan, scenario) if scenario.obstacles else np.zeros((0, 0))
    for i, j in zip(*np.nonzero(clear <= TOL), strict=True):
        out.append(f"segment {i}: hull {clear[i, j]:.3f} m from obstacles[{j}] "
                   "(touching or inside)")
    ship = outline_clearance(scenario, np.array([w["x"] for w in wps]),
                             np.array([w["y"] for w in wps]))
    if ship is not None and ship <= TOL:
        out.append(f"hull {ship:.3f} m from the mother ship's hull outside the approach "
                   "corridor (touching or inside)")
    if v.time_margin_s > 0.0:
        swept = clearances(plan, scenario, margin_s=v.time_margin_s, moving_only=True)
        for (i, j), c in swept.items():
            if c <= TOL and clear[i, j] > TOL:
                out.append(f"segment {i}: hull within {c:.3f} m of obstacles[{j}] when "
                           f"{v.time_margin_s:g} s early or late")
    if scenario.kind == "recovery":
        arrival = abs(math.degrees(angle_diff(headings[-1], math.pi)))
        if arrival > ARRIVAL_TOLERANCE_DEG + 1e-9:
            out.append(f"arrives {arrival:.2f} deg off the ramp axis")
    return out


def current_vector(scenario: Scenario) -> tuple[float, float]:
    """The current's velocity (m/s) in the ramp frame; (0, 0) without one."""
    env = scenario.environment
    if env.current_speed == 0.0:
        return (0.0, 0.0)
    a = math.radians(env.current_dir_deg)
    return (env.current_speed * math.cos(a), env.current_speed * math.sin(a))


def first_turn_deg(plan: dict[str, Any], scenario: Scenario) -> float | None:
    """Turn from the start heading onto the first leg, degrees (None when the boat is still)."""
    if scenario.start.speed < MOVING_START_SPEED:
        return None
    wps = plan["waypoints"]
    course = math.atan2(wps[1]["y"] - wps[0]["y"], wps[1]["x"] - wps[0]["x"])
    hull = _water_heading(course, wps[0]["speed"], current_vector(scenario))
    return abs(math.degrees(angle_diff(hull, math.radians(scenario.start.heading_deg))))


def _water_heading(course: float, speed: float, cur: tuple[float, float]) -> float:
    wx, wy = speed * math.cos(course) - cur[0], speed * math.sin(course) - cur[1]
    return course if wx == 0.0 and wy == 0.0 else math.atan2(wy, wx)


def water_speeds(plan: dict[str, Any], scenario: Scenario) -> list[tuple[float, float, bool]]:
    """Per segment: (least, greatest) speed through the water at its two ends, and whether the
    hull makes way forward along the track (through-water velocity has a positive component
    along the course)."""
    cx, cy = current_vector(scenario)
    out = []
    for a, b in itertools.pairwise(plan["waypoints"]):
        dx, dy = b["x"] - a["x"], b["y"] - a["y"]
        n = math.hypot(dx, dy) or 1.0
        ux, uy = dx / n, dy / n
        speeds, fwd = [], True
        for s in (a["speed"], b["speed"]):
            wx, wy = s * ux - cx, s * uy - cy
            speeds.append(math.hypot(wx, wy))
            fwd &= wx * ux + wy * uy > 0.0
        out.append((min(speeds), max(speeds), fwd))
    return out


def clearances(
    plan: dict[str, Any], scenario: Scenario, margin_s: float = 0.0, moving_only: bool = False
) -> dict[tuple[int, int], float]:
    """Water between hull and obstacle, m, for every (segment, obstacle): negative inside.

    With `margin_s` > 0 each moving obstacle is swept over [t - margin_s, t + margin_s].
    """
    obs = scenario.obstacles
    if not obs:
        return {}
    wps = plan["waypoints"]
    half_hull = scenario.vessel.length / 2.0
    if margin_s <= 0.0:
        d = clearance_matrix(plan, scenario)
        cols = [j for j, o in enumerate(obs) if o.moving or not moving_only]
        return {(i, j): float(d[i, j]) for i in range(d.shape[0]) for j in cols}
    cols = [j for j, o in enumerate(obs) if o.moving or not moving_only]
    if kernel_geom.AVAILABLE:  # closest_distance of every pair in one compiled call
        x, y, t = (np.array([w[k] for w in wps], dtype=float) for k in ("x", "y", "t"))
        sel = [obs[j] for j in cols]
        centre = np.array([[o.x, o.y] for o in sel], dtype=float).reshape(-1, 2)
        velocity = np.array([[o.vx, o.vy] for o in sel], dtype=float).reshape(-1, 2)
        margin = np.array([margin_s if o.moving else 0.0 for o in sel], dtype=float)
        dist = kernel_geom.swept_clearances(x, y, t, centre, velocity, margin)
        return {(i, j): float(dist[i, k]) - obs[j].radius - half_hull
                for k, j in enumerate(cols) for i in range(dist.shape[0])}
    out: dict[tuple[int, int], float] = {}
    for j in cols:
        o = obs[j]
        m = margin_s if o.moving else 0.0
        for i, (a, b) in enumerate(itertools.pairwise(wps)):
            dist = closest_distance(a, b, o.x, o.y, o.vx, o.vy, m)
            out[(i, j)] = dist - o.radius - half_hull
    return out


def clearance_matrix(plan: dict[str, Any], scenario: Scenario) -> np.ndarray:
    """(segments, obstacles) water between hull and obstacle on time, m (closest approach of
    two linear motions, exact)."""
    wps = plan["waypoints"]
    x = np.array([w["x"] for w in wps], dtype=float)
    y = np.array([w["y"] for w in wps], dtype=float)
    t = np.array([w["t"] for w in wps], dtype=float)
    obs = scenario.obstacles
    ox = np.array([o.x for o in obs])[None, :]
    oy = np.array([o.y for o in obs])[None, :]
    vx = np.array([o.vx for o in obs])[None, :]
    vy = np.array([o.vy for o in obs])[None, :]
    r = np.array([o.radius for o in obs])[None, :] + scenario.vessel.length / 2.0
    t0, t1 = t[:-1, None], t[1:, None]
    r0x, r0y = x[:-1, None] - (ox + vx * t0), y[:-1, None] - (oy + vy * t0)
    drx = (x[1:, None] - x[:-1, None]) - vx * (t1 - t0)
    dry = (y[1:, None] - y[:-1, None]) - vy * (t1 - t0)
    dd = drx * drx + dry * dry
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(dd > 0.0, -(r0x * drx + r0y * dry) / dd, 0.0)
    s = np.clip(s, 0.0, 1.0)
    return np.hypot(r0x + s * drx, r0y + s * dry) - r


def hull_clearance(plan: dict[str, Any], scenario: Scenario) -> float | None:
    """Least water between hull and any obstacle circle over the plan, m (None: no obstacles)."""
    if not scenario.obstacles:
        return None
    if kernel_geom.AVAILABLE:  # clearance_matrix's least entry in one compiled pass
        wps, obs = plan["waypoints"], scenario.obstacles
        x, y, t = (np.array([w[k] for w in wps], dtype=float) for k in ("x", "y", "t"))
        centre = np.array([[o.x, o.y] for o in obs], dtype=float)
        velocity = np.array([[o.vx, o.vy] for o in obs], dtype=float)
        r = np.array([o.radius for o in obs]) + scenario.vessel.length / 2.0
        return float(kernel_geom.hull_clearance(x, y, t, centre, velocity, r))
    return float(clearance_matrix(plan, scenario).min())


def closest_distance(
    a: dict, b: dict, ox: float, oy: float, ovx: float, ovy: float, margin_s: float = 0.0
) -> float:
    """Least distance between the boat on segment a->b (linear in time) and a moving centre,
    the centre taken at any time shift d in [-margin_s, margin_s]."""
    dt = b["t"] - a["t"]
    # relative position r(s, d) = r0 + s * dr + d * q, s in [0, 1], d in [-m, m]
    r0x = a["x"] - (ox + ovx * a["t"])
    r0y = a["y"] - (oy + ovy * a["t"])
    drx = (b["x"] - a["x"]) - ovx * dt
    dry = (b["y"] - a["y"]) - ovy * dt
    if margin_s <= 0.0 or (ovx == 0.0 and ovy == 0.0):
        return _point_segment(0.0, 0.0, r0x, r0y, r0x + drx, r0y + dry)
    qx, qy = -ovx * margin_s, -ovy * margin_s
    # parallelogram with corners r0 -/+ q and r0 + dr -/+ q
    corners = [(r0x - qx, r0y - qy), (r0x + drx - qx, r0y + dry - qy),
               (r0x + drx + qx, r0y + dry + qy), (r0x + qx, r0y + qy)]
    if _contains_origin(corners):
        return 0.0
    return min(
        _point_segment(0.0, 0.0, *corners[k], *corners[(k + 1) % 4]) for k in range(4)
    )


def _point_segment(px: float, py: float, ax: float, ay: float, bx: float, by: float) -> float:
    dx, dy = bx - ax, by - ay
    dd = dx * dx + dy * dy
    s = 0.0 if dd == 0.0 else min(1.0, max(0.0, ((px - ax) * dx + (py - ay) * dy) / dd))
    return math.hypot(ax + s * dx - px, ay + s * dy - py)


def _contains_origin(corners: list[tuple[float, float]]) -> bool:
    """Origin strictly inside a convex quadrilateral (either orientation, may be degenerate)."""
    signs = []
    for k in range(4):
        (ax, ay), (bx, by) = corners[k], corners[(k + 1) % 4]
        signs.append((bx - ax) * (0.0 - ay) - (by - ay) * (0.0 - ax))
    return all(s > 0.0 for s in signs) or all(s < 0.0 for s in signs)
