"""An independent plan checker for the benchmarks (issue 12), apart from the planner's own.

The planner's validator (planning/validate.py) solves closest approaches
exactly; this one samples. It replays the plan as the boat would sail it
(position linear in time on each segment), samples every segment densely in
time and every moving obstacle over a grid of timing errors, and reports
the water between hull and obstacle it saw, the first turn from the start
heading, and the speed through the water (segment's average ground velocity
minus the current). Sampling can only over-estimate clearance by at most
the distance travelled between two samples, which `STEP_M` bounds.

The mother ship's hull (issue 27): every sample whose centre lies outside the
approach corridor (x >= 0, |y| <= ramp_width / 2 + x tan 10 deg) must keep
the boat's hull circle off the ship's polygon, and no sample may lie inside
the polygon; the polygon is rebuilt here from the scenario's fields.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from usvstation.geometry import angle_diff
from usvstation.scenario import Scenario

STEP_M = 0.02  # largest relative movement between two samples, m
SHIFT_STEP_S = 0.1  # timing errors sampled every 0.1 s over [-margin, margin]
ANGLE_TOL_DEG = 0.01
SPEED_TOL = 0.01


@dataclass
class CheckReport:
    """What the checker saw; `problems` empty means the plan passes."""

    clearance_m: float | None = None  # hull-to-obstacle water on time
    clearance_margin_m: float | None = None  # the same, early or late by up to time_margin_s
    ship_clearance_m: float | None = None  # hull-to-mother-ship water outside the corridor
    first_turn_deg: float | None = None
    water_speed_range: tuple[float, float] | None = None
    problems: list[str] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return not self.problems


def check_plan(plan: dict[str, Any], scenario: Scenario,
               time_margin_s: float | None = None) -> CheckReport:
    """Check a plan in the stable format against its scenario by dense sampling."""
    rep = CheckReport()
    v = scenario.vessel
    wps = plan["waypoints"]
    x = np.array([w["x"] for w in wps], dtype=float)
    y = np.array([w["y"] for w in wps], dtype=float)
    t = np.array([w["t"] for w in wps], dtype=float)
    if len(wps) < 2 or np.any(np.diff(t) <= 0.0):
        rep.problems.append("fewer than two waypoints or time not increasing")
        return rep
    if math.hypot(x[0] - scenario.start.x, y[0] - scenario.start.y) > 1e-3 or abs(t[0]) > 1e-6:
        rep.problems.append("does not start at the start at t = 0")
    if math.hypot(x[-1] - scenario.goal.x, y[-1] - scenario.goal.y) > 1e-3:
        rep.problems.append("does not end at the goal")
    env = scenario.environment
    ca = math.radians(env.current_dir_deg)
    cur = np.array([env.current_speed * math.cos(ca), env.current_speed * math.sin(ca)])
    dt = np.diff(t)
    ground = np.column_stack([np.diff(x), np.diff(y)]) / dt[:, None]
    water = ground - cur
    ws = np.hypot(water[:, 0], water[:, 1])
    rep.water_speed_range = (float(ws.min()), float(ws.max()))
    if ws.min() < v.speed_min - SPEED_TOL or ws.max() > v.speed_max + SPEED_TOL:
        rep.problems.append(
            f"speed through the water {ws.min():.3f}-{ws.max():.3f} m/s outside "
            f"[{v.speed_min}, {v.speed_max}]")
    course = np.arctan2(ground[:, 1], ground[:, 0])
    turns = np.degrees(np.abs(np.angle(np.exp(1j * np.diff(course)))))
    if turns.size and turns.max() > v.turn_max_deg + ANGLE_TOL_DEG:
        rep.problems.append(f"turn of {turns.max():.2f} deg above {v.turn_max_deg}")
    if scenario.start.speed >= 0.5:
        # the hull as the boat leaves the start: its waypoint speed along the first course
        u0 = ground[0] / max(float(np.hypot(*ground[0])), 1e-12)
        w0 = wps[0]["speed"] * u0 - cur
        hull0 = math.atan2(w0[1], w0[0])
        d = math.degrees(abs(angle_diff(hull0, math.radians(scenario.start.heading_deg))))
        rep.first_turn_deg = d
        if d > v.turn_max_deg + ANGLE_TOL_DEG:
            rep.problems.append(f"first turn {d:.2f} deg above {v.turn_max_deg}")
    if scenario.kind == "recovery":
        off = math.degrees(abs(angle_diff(course[-1], math.pi)))
        if off > 10.0 + ANGLE_TOL_DEG:
            rep.problems.append(f"arrives {off:.2f} deg off the ramp axis")
    if scenario.obstacles:
        margin = v.time_margin_s if time_margin_s is None else time_margin_s
        rep.clearance_m = _sampled_clearance(x, y, t, scenario, 0.0)
        if rep.clearance_m <= 0.0:
            rep.problems.append(f"hull {rep.clearance_m:.3f} m from an obstacle (collision)")
        if margin > 0.0 and any(o.moving for o in scenario.obstacles):
            rep.clearance_margin_m = _sampled_clearance(x, y, t, scenario, margin)
            if rep.clearance_margin_m <= 0.0:
                rep.problems.append(
                    f"hull {rep.clearance_margin_m:.3f} m from a moving obstacle when up to "
                    f"{margin:g} s early or late")
    ship = scenario.mother_ship
    if ship is not None and (ship.beam is not None or ship.outline is not None):
        rep.ship_clearance_m = _sampled_ship_clearance(x, y, scenario)
        if rep.ship_clearance_m is not None and rep.ship_clearance_m <= 0.0:
            rep.problems.append(f"hull {rep.ship_clearance_m:.3f} m from the mother ship's hull "
                                "outside the approach corridor (collision)")
    return rep


def _sampled_ship_clearance(x: np.ndarray, y: np.ndarray, scenario: Scenario) -> float | None:
    """Least water between the boat's hull circle and the ship's polygon over samples
    `STEP_M` apart outside the corridor (negative inside the polygon)."""
    ship = scenario.mother_ship
    assert ship is not None
    if ship.outline is not None:
        poly = np.array(ship.outline, dtype=float)
    else:
        assert ship.beam is not None
        b = ship.beam / 2.0
        poly = np.array([[0.0, b], [-ship.length, b], [-ship.length, -b], [0.0, -b]])
    length = np.hypot(np.diff(x), np.diff(y))
    n = np.maximum(np.ceil(length / STEP_M).astype(int), 1)
    px = np.concatenate([np.linspace(x[i], x[i + 1], n[i] + 1) for i in range(len(n))])
    py = np.concatenate([np.linspace(y[i], y[i + 1], n[i] + 1) for i in range(len(n))])
    out = ~((px >= 0.0) & (np.abs(py) <= ship.ramp_width / 2.0
                           + px * math.tan(math.radians(10.0))))
    px, py = px[out], py[out]
    if px.size == 0:
        return None
    a, b = poly, np.roll(poly, -1, axis=0)
    best = np.full(px.size, np.inf)
    crossings = np.zeros(px.size, dtype=int)
    for (ax, ay), (bx, by) in zip(a, b, strict=True):
        ex, ey = bx - ax, by - ay
        s = np.clip(((px - ax) * ex + (py - ay) * ey) / max(ex * ex + ey * ey, 1e-18), 0, 1)
        best = np.minimum(best, np.hypot(px - ax - s * ex, py - ay - s * ey))
        if ay != by:
            xs = ax + (py - ay) * ex / ey
            crossings += ((ay > py) != (by > py)) & (px < xs)
    d = np.where(crossings % 2 == 1, -best, best) - scenario.vessel.length / 2.0
    return float(d.min())


def _sampled_clearance(x: np.ndarray, y: np.ndarray, t: np.ndarray, scenario: Scenario,
                       margin_s: float) -> float:
    obs = [o for o in scenario.obstacles if o.moving or margin_s <= 0.0]
    ox = np.array([o.x for o in obs])
    oy = np.array([o.y for o in obs])
    ovx = np.array([o.vx for o in obs])
    ovy = np.array([o.vy for o in obs])
    rad = np.array([o.radius for o in obs]) + scenario.vessel.length / 2.0
    moving = (ovx != 0.0) | (ovy != 0.0)
    n_shift = math.ceil(2 * margin_s / SHIFT_STEP_S) + 1 if margin_s > 0 else 1
    shifts = np.linspace(-margin_s, margin_s, n_shift) if margin_s > 0 else np.zeros(1)
    best = math.inf
    rel_speed = float(np.max(np.hypot(ovx, ovy), initial=0.0))
    for i in range(len(x) - 1):
        seg_t = t[i + 1] - t[i]
        sp = math.hypot(x[i + 1] - x[i], y[i + 1] - y[i]) / seg_t
        n = max(2, math.ceil(seg_t * (sp + rel_speed) / STEP_M) + 1)
        n = min(n, 20_000)
        s = np.linspace(0.0, 1.0, n)
        px = x[i] + s * (x[i + 1] - x[i])
        py = y[i] + s * (y[i + 1] - y[i])
        pt = t[i] + s * seg_t
        for d in shifts:
            tt = pt[:, None] + np.where(moving, d, 0.0)[None, :]
            dx = px[:, None] - (ox + ovx * tt)
            dy = py[:, None] - (oy + ovy * tt)
            best = min(best, float(np.min(np.hypot(dx, dy) - rad)))
    return best
