"""Independent check of a plan against its scenario (the validity rules of issue 2).

Written apart from the planner's own gates so that the two can catch each
other's mistakes: it reads only the stable plan format and the scenario.
"""

from __future__ import annotations

import itertools
import math
from typing import Any

from usvstation.scenario import Scenario

TOL = 1e-6
ARRIVAL_TOLERANCE_DEG = 10.0


def plan_violations(plan: dict[str, Any], scenario: Scenario) -> list[str]:
    """Every rule the plan breaks, as readable strings (empty when the plan is valid).

    Rules: starts at the start at t = 0 and ends at the goal; time increases;
    speeds within [speed_min, speed_max]; |dv|/dt <= accel_max on every
    segment; every turn <= turn_max_deg; the hull (half its length) never
    enters an obstacle circle at any time; a recovery arrives along the ramp
    axis (last segment within 10 degrees of heading 180).
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
    for i, w in enumerate(wps):
        if not v.speed_min - TOL <= w["speed"] <= v.speed_max + TOL:
            out.append(f"waypoint {i}: speed {w['speed']} outside [{v.speed_min}, {v.speed_max}]")
    for i, (a, b) in enumerate(itertools.pairwise(wps)):
        dt = b["t"] - a["t"]
        if dt <= 0.0:
            out.append(f"segment {i}: time does not increase ({a['t']} -> {b['t']})")
            continue
        if abs(b["speed"] - a["speed"]) / dt > v.accel_max * (1 + TOL) + TOL:
            out.append(f"segment {i}: |dv|/dt = {abs(b['speed'] - a['speed']) / dt:.4f} m/s^2 "
                       f"above {v.accel_max}")
    headings = [
        math.atan2(b["y"] - a["y"], b["x"] - a["x"]) for a, b in itertools.pairwise(wps)
    ]
    for i, (h0, h1) in enumerate(itertools.pairwise(headings)):
        turn = abs(math.degrees(math.remainder(h1 - h0, 2 * math.pi)))
        if turn > v.turn_max_deg + 1e-6:
            out.append(f"waypoint {i + 1}: turn {turn:.2f} deg above {v.turn_max_deg}")
    half_hull = v.length / 2.0
    for j, obs in enumerate(scenario.obstacles):
        for i, (a, b) in enumerate(itertools.pairwise(wps)):
            d = _closest_distance(a, b, obs.x, obs.y, obs.vx, obs.vy)
            if d < obs.radius + half_hull - TOL:
                out.append(f"segment {i}: hull within {d - obs.radius:.3f} m of obstacles[{j}]")
    if scenario.kind == "recovery":
        arrival = abs(math.degrees(math.remainder(headings[-1] - math.pi, 2 * math.pi)))
        if arrival > ARRIVAL_TOLERANCE_DEG + 1e-9:
            out.append(f"arrives {arrival:.2f} deg off the ramp axis")
    return out


def _closest_distance(a: dict, b: dict, ox: float, oy: float, ovx: float, ovy: float) -> float:
    """Least distance between the boat on segment a->b (linear in time) and a moving centre."""
    dt = b["t"] - a["t"]
    # relative position r(s) = r0 + s * dr for s in [0, 1]
    r0x = a["x"] - (ox + ovx * a["t"])
    r0y = a["y"] - (oy + ovy * a["t"])
    drx = (b["x"] - a["x"]) - ovx * dt
    dry = (b["y"] - a["y"]) - ovy * dt
    dd = drx * drx + dry * dry
    s = 0.0 if dd == 0.0 else min(1.0, max(0.0, -(r0x * drx + r0y * dry) / dd))
    return math.hypot(r0x + s * drx, r0y + s * dry)
