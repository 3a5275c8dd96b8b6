"""Seeded random scenarios of the kinds the planner must handle (issue 2, "Done when").

Recoveries: start 50-140 m out within +-45 degrees of the ramp axis, 3-9
obstacles of radius 1-4 m spread around the direct line, about a third of
them moving at up to 0.8 m/s, current up to 0.3 m/s. Transits: a 400 m x
400 m area crossed corner to corner, with large islands and ships faster
than the boat crossing the route.
"""

from __future__ import annotations

import math

import numpy as np

from usvstation.geometry import inflated_radius
from usvstation.scenario import Obstacle, Scenario, ScenarioError, Vessel, parse_scenario

_ORIGIN = {"lat": 30.5135, "lon": 114.4182, "ramp_bearing_deg": 90.0}


def random_recovery(seed: int) -> Scenario:
    """A random recovery scenario; the same seed gives the same scenario."""
    rng = np.random.default_rng(seed)
    vessel = Vessel()
    while True:
        _, sx, sy = _out_at_sea(rng, 50.0, 140.0, 45.0)
        obstacles = []
        for _ in range(int(rng.integers(3, 10))):
            frac = rng.uniform(0.1, 0.9)
            moving = rng.random() < 1.0 / 3.0
            speed = rng.uniform(0.1, 0.8) if moving else 0.0
            course = rng.uniform(0.0, 2.0 * math.pi)
            obstacles.append({
                "x": round(sx * frac + rng.normal(0.0, 4.0), 2),
                "y": round(sy * frac + rng.normal(0.0, 10.0), 2),
                "radius": round(rng.uniform(1.0, 4.0), 2),
                "vx": round(speed * math.cos(course), 3),
                "vy": round(speed * math.sin(course), 3),
            })
        obstacles = _clear_of(obstacles, [(sx, sy), (0.0, 0.0)], vessel)
        heading = math.degrees(math.atan2(-sy, -sx)) + rng.uniform(-30.0, 30.0)
        data = {
            "name": f"random-recovery-{seed}",
            "kind": "recovery",
            "origin": _ORIGIN,
            "start": {"x": round(sx, 2), "y": round(sy, 2), "heading_deg": round(heading % 360, 2),
                      "speed": round(rng.uniform(0.5, 1.5), 2)},
            "goal": {"x": 0.0, "y": 0.0},
            "obstacles": obstacles,
            "vessel": vessel.model_dump(),
            "environment": _environment(rng),
        }
        try:
            return parse_scenario(data)
        except ScenarioError:  # pragma: no cover - _clear_of keeps start and goal free
            continue


def random_transit(seed: int) -> Scenario:
    """A 400 m x 400 m transit with large islands and ships faster than the boat."""
    rng = np.random.default_rng(seed)
    vessel = Vessel()
    sx, sy = rng.uniform(-190, -160), rng.uniform(-190, -160)
    gx, gy = rng.uniform(160, 190), rng.uniform(160, 190)
    obstacles = []
    for _ in range(int(rng.integers(3, 7))):  # islands
        x, y = rng.uniform(-150, 150, size=2)
        obstacles.append({"x": round(x, 1), "y": round(y, 1),
                          "radius": round(rng.uniform(15.0, 45.0), 1), "vx": 0.0, "vy": 0.0})
    route = math.atan2(gy - sy, gx - sx)
    length = math.hypot(gx - sx, gy - sy)
    for _ in range(int(rng.integers(2, 4))):  # ships crossing the route
        frac, t_cross = rng.uniform(0.2, 0.8), rng.uniform(30.0, 160.0)
        px, py = sx + frac * length * math.cos(route), sy + frac * length * math.sin(route)
        course = route + math.pi / 2 * rng.choice([-1.0, 1.0]) + math.radians(rng.uniform(-40, 40))
        speed = rng.uniform(vessel.speed_max + 0.5, vessel.speed_max + 3.0)
        vx, vy = speed * math.cos(course), speed * math.sin(course)
        obstacles.append({"x": round(px - vx * t_cross, 1), "y": round(py - vy * t_cross, 1),
                          "radius": round(rng.uniform(4.0, 8.0), 1),
                          "vx": round(vx, 3), "vy": round(vy, 3)})
    obstacles = _clear_of(obstacles, [(sx, sy), (gx, gy)], vessel)
    data = {
        "name": f"random-transit-{seed}",
        "kind": "transit",
        "origin": _ORIGIN,
        "start": {"x": round(sx, 1), "y": round(sy, 1),
                  "heading_deg": round(math.degrees(route) % 360, 1), "speed": 1.0},
        "goal": {"x": round(gx, 1), "y": round(gy, 1)},
        "obstacles": obstacles,
        "vessel": vessel.model_dump(),
        "environment": _environment(rng),
    }
    return parse_scenario(data)


def _out_at_sea(rng: np.random.Generator, near: float, far: float,
                half_angle_deg: float) -> tuple[float, float, float]:
    """A recovery's start: `near` to `far` m from the ramp end at a bearing within
    +-`half_angle_deg` of the ramp axis; its distance and ramp-frame x, y."""
    dist = rng.uniform(near, far)
    bearing = math.radians(rng.uniform(-half_angle_deg, half_angle_deg))
    return dist, dist * math.cos(bearing), dist * math.sin(bearing)


def _clear_of(
    obstacles: list[dict], points: list[tuple[float, float]], vessel: Vessel
) -> list[dict]:
    """Drop obstacles whose inflated circle (eq. 7) covers a point at t = 0, with a 1 m margin."""
    length, r_c = vessel.length, vessel.compensation_radius
    return [
        o for o in obstacles
        if all(math.hypot(o["x"] - px, o["y"] - py)
               > inflated_radius(Obstacle(**o).radius, length, r_c) + 1.0
               for px, py in points)
    ]


def _environment(rng: np.random.Generator) -> dict:
    return {"current_speed": round(rng.uniform(0.0, 0.3), 3),
            "current_dir_deg": round(rng.uniform(0.0, 360.0), 1),
            "wind_speed": round(rng.uniform(0.0, 8.0), 1),
            "wind_dir_deg": round(rng.uniform(0.0, 360.0), 1)}


# --- hidden families (issue 12): the kinds of scenario the planner was stress-tested on -------

def pointing_away(seed: int) -> Scenario:
    """A random recovery whose boat points away from the ramp (90-180 deg off), under way."""
    rng = np.random.default_rng(10_000 + seed)
    data = random_recovery(seed).model_dump()
    s = data["start"]
    bearing = math.degrees(math.atan2(-s["y"], -s["x"]))
    off = rng.uniform(90.0, 180.0) * rng.choice([-1.0, 1.0])
    s["heading_deg"] = round((bearing + off) % 360.0, 2)
    s["speed"] = round(rng.uniform(1.0, 2.5), 2)
    data["name"] = f"pointing-away-{seed}"
    return parse_scenario(data)


def strong_current(seed: int) -> Scenario:
    """A random recovery in a current of 0.5-1 m/s from any direction."""
    rng = np.random.default_rng(20_000 + seed)
    data = random_recovery(seed).model_dump()
    data["environment"]["current_speed"] = round(rng.uniform(0.5, 1.0), 3)
    data["environment"]["current_dir_deg"] = round(rng.uniform(0.0, 360.0), 1)
    data["name"] = f"strong-current-{seed}"
    return parse_scenario(data)


def crossing_ships(seed: int) -> Scenario:
    """A recovery with 1-3 ships at 1.5-3x the boat's top speed crossing, meeting head-on or
    overtaking near the direct line, timed to be there around when the boat is."""
    rng = np.random.default_rng(30_000 + seed)
    vessel = Vessel()
    dist, sx, sy = _out_at_sea(rng, 60.0, 140.0, 30.0)
    obstacles = []
    for _ in range(int(rng.integers(1, 4))):
        frac = rng.uniform(0.25, 0.85)
        px, py = sx * frac, sy * frac
        t_meet = (1 - frac) * dist / 1.5 + rng.uniform(-8.0, 8.0)  # boat at about 1.5 m/s
        kind = rng.choice(["crossing", "head-on", "overtaking"])
        route = math.atan2(-sy, -sx)
        course = {"crossing": route + math.pi / 2 * rng.choice([-1.0, 1.0]),
                  "head-on": route + math.pi, "overtaking": route}[kind]
        course += math.radians(rng.uniform(-20.0, 20.0))
        speed = rng.uniform(1.5, 3.0) * vessel.speed_max
        vx, vy = speed * math.cos(course), speed * math.sin(course)
        obstacles.append({"x": round(px - vx * max(t_meet, 1.0), 2),
                          "y": round(py - vy * max(t_meet, 1.0), 2),
                          "radius": round(rng.uniform(2.0, 5.0), 2),
                          "vx": round(vx, 3), "vy": round(vy, 3)})
    obstacles = _clear_of(obstacles, [(sx, sy), (0.0, 0.0)], vessel)
    return parse_scenario({
        "name": f"crossing-ships-{seed}", "origin": _ORIGIN,
        "start": {"x": round(sx, 2), "y": round(sy, 2),
                  "heading_deg": round(math.degrees(math.atan2(-sy, -sx)) % 360, 2),
                  "speed": 1.0},
        "obstacles": obstacles, "vessel": vessel.model_dump(),
        "environment": _environment(rng),
    })


def behind_ramp(seed: int) -> Scenario:
    """A recovery starting behind the ramp (x < 0, off to a side) or beside it (x < 5 m)."""
    rng = np.random.default_rng(40_000 + seed)
    vessel = Vessel()
    sx = rng.uniform(-40.0, 5.0)
    sy = rng.uniform(10.0, 60.0) * rng.choice([-1.0, 1.0])
    moving = rng.random() < 0.5
    return parse_scenario({
        "name": f"behind-ramp-{seed}", "origin": _ORIGIN,
        "start": {"x": round(sx, 2), "y": round(sy, 2),
                  "heading_deg": round(rng.uniform(0.0, 360.0), 1),
                  "speed": round(rng.uniform(0.5, 2.0), 2) if moving else 0.0},
        "obstacles": [], "vessel": vessel.model_dump(), "environment": _environment(rng),
    })


def long_wall(seed: int) -> Scenario:
    """A recovery behind a wall of touching circles 100-250 m long across the approach."""
    rng = np.random.default_rng(50_000 + seed)
    vessel = Vessel()
    sx, sy = rng.uniform(80.0, 140.0), rng.uniform(-20.0, 20.0)
    wx = rng.uniform(0.35, 0.65) * sx
    length = rng.uniform(100.0, 250.0)
    centre = rng.uniform(-0.3, 0.3) * length
    r = 2.0
    ys = np.arange(centre - length / 2, centre + length / 2 + 1e-9, 1.5 * r)
    obstacles = [{"x": round(wx, 2), "y": round(float(y), 2), "radius": r} for y in ys]
    obstacles = _clear_of(obstacles, [(sx, sy), (0.0, 0.0)], vessel)
    return parse_scenario({
        "name": f"long-wall-{seed}", "origin": _ORIGIN,
        "start": {"x": round(sx, 2), "y": round(sy, 2), "heading_deg": 180.0, "speed": 1.0},
        "obstacles": obstacles, "vessel": vessel.model_dump(), "environment": _environment(rng),
    })


def dense_field(seed: int, count: int = 500) -> Scenario:
    """A recovery through `count` small obstacles (a tenth of them drifting) over 300 x 300 m."""
    rng = np.random.default_rng(60_000 + seed)
    vessel = Vessel()
    sx, sy = rng.uniform(100.0, 150.0), rng.uniform(-30.0, 30.0)
    obstacles = []
    for _ in range(count):
        moving = rng.random() < 0.1
        speed, course = (rng.uniform(0.1, 0.5), rng.uniform(0, 2 * math.pi)) if moving else (0, 0)
        obstacles.append({"x": round(rng.uniform(10.0, 300.0), 2),
                          "y": round(rng.uniform(-150.0, 150.0), 2),
                          "radius": round(rng.uniform(0.3, 1.0), 2),
                          "vx": round(speed * math.cos(course), 3),
                          "vy": round(speed * math.sin(course), 3)})
    obstacles = _clear_of(obstacles, [(sx, sy), (0.0, 0.0)], vessel)
    return parse_scenario({
        "name": f"dense-field-{seed}", "origin": _ORIGIN,
        "start": {"x": round(sx, 2), "y": round(sy, 2), "heading_deg": 180.0, "speed": 1.0},
        "obstacles": obstacles, "vessel": vessel.model_dump(), "environment": _environment(rng),
    })


def alongside(seed: int) -> Scenario:
    """A recovery from beside the mother ship's hull, abeam of it (behind the ramp's beam):
    a 40-80 m ship of 8-16 m beam, the boat 3-30 m off either side, any heading, still or
    under way, 0-4 small obstacles out at sea, a current up to 0.3 m/s (issue 27)."""
    rng = np.random.default_rng(70_000 + seed)
    vessel = Vessel()
    length, beam = round(rng.uniform(40.0, 80.0), 1), round(rng.uniform(8.0, 16.0), 1)
    side = rng.choice([-1.0, 1.0])
    sx = rng.uniform(-length + 3.0, -2.0)
    sy = side * (beam / 2.0 + rng.uniform(3.0, 30.0))
    obstacles = [{"x": round(rng.uniform(15.0, 80.0), 2), "y": round(rng.uniform(-40.0, 40.0), 2),
                  "radius": round(rng.uniform(0.5, 2.0), 2)}
                 for _ in range(int(rng.integers(0, 5)))]
    obstacles = _clear_of(obstacles, [(sx, sy), (0.0, 0.0)], vessel)
    moving = rng.random() < 0.6
    return parse_scenario({
        "name": f"alongside-{seed}", "origin": _ORIGIN,
        "start": {"x": round(sx, 2), "y": round(sy, 2),
                  "heading_deg": round(rng.uniform(0.0, 360.0), 1),
                  "speed": round(rng.uniform(0.5, 2.0), 2) if moving else 0.0},
        "obstacles": obstacles, "vessel": vessel.model_dump(), "environment": _environment(rng),
        "mother_ship": {"length": length, "beam": beam, "ramp_width": 3.0},
    })


def outline_astern_traffic(seed: int) -> Scenario:
    """A recovery to a ship given by its outline (square stern with the ramp, tapered bow),
    with 1-3 boats crossing astern of it at 1-3 m/s across the approach, timed to pass the
    ramp axis while the boat comes in; start 40-120 m out within 45 degrees (issue 27)."""
    rng = np.random.default_rng(80_000 + seed)
    vessel = Vessel()
    length, beam = rng.uniform(40.0, 90.0), rng.uniform(10.0, 18.0)
    h = beam / 2.0
    outline = [[0.0, -h], [0.0, h], [-0.7 * length, h], [-length, 0.0], [-0.7 * length, -h]]
    dist, sx, sy = _out_at_sea(rng, 40.0, 120.0, 45.0)
    obstacles = []
    for _ in range(int(rng.integers(1, 4))):
        cross_x = rng.uniform(8.0, 0.7 * sx)  # where it crosses the ramp axis
        speed = rng.uniform(1.0, 3.0) * rng.choice([-1.0, 1.0])
        t_cross = (dist - cross_x) / 1.5 + rng.uniform(-10.0, 10.0)
        obstacles.append({"x": round(cross_x, 2), "y": round(-speed * max(t_cross, 1.0), 2),
                          "radius": round(rng.uniform(1.5, 4.0), 2), "vx": 0.0,
                          "vy": round(speed, 3)})
    obstacles = _clear_of(obstacles, [(sx, sy), (0.0, 0.0)], vessel)
    return parse_scenario({
        "name": f"outline-astern-traffic-{seed}", "origin": _ORIGIN,
        "start": {"x": round(sx, 2), "y": round(sy, 2),
                  "heading_deg": round(math.degrees(math.atan2(-sy, -sx)) % 360, 2),
                  "speed": 1.0},
        "obstacles": obstacles, "vessel": vessel.model_dump(), "environment": _environment(rng),
        "mother_ship": {"length": round(length, 1), "ramp_width": 3.0,
                        "outline": [[round(a, 2), round(b, 2)] for a, b in outline]},
    })


# --- the review's kinds (issue 27): passages, ships at the ramp, strong cross current, far ---

def _wall(x0: float, y0: float, x1: float, y1: float, r: float = 2.0) -> list[dict]:
    """Touching circles of radius r from (x0, y0) to (x1, y1), 1.5 r apart."""
    n = max(int(math.hypot(x1 - x0, y1 - y0) / (1.5 * r)), 1)
    return [{"x": round(x0 + (x1 - x0) * k / n, 2), "y": round(y0 + (y1 - y0) * k / n, 2),
             "radius": r} for k in range(n + 1)]


def _recovery(name: str, sx: float, sy: float, obstacles: list[dict], rng: np.random.Generator,
              environment: dict | None = None, speed: float = 1.0) -> Scenario:
    vessel = Vessel()
    obstacles = _clear_of(obstacles, [(sx, sy), (0.0, 0.0)], vessel)
    return parse_scenario({
        "name": name, "origin": _ORIGIN,
        "start": {"x": round(sx, 2), "y": round(sy, 2),
                  "heading_deg": round(math.degrees(math.atan2(-sy, -sx)) % 360, 2),
                  "speed": speed},
        "obstacles": obstacles, "vessel": vessel.model_dump(),
        "environment": environment or _environment(rng),
    })


def narrow_passage(seed: int) -> Scenario:
    """A wall across the approach, 150-300 m long, with one gap of 8-14 m (the only way
    through) 15-60 m off the direct line."""
    rng = np.random.default_rng(90_000 + seed)
    sx, sy = rng.uniform(90.0, 150.0), rng.uniform(-20.0, 20.0)
    wx = rng.uniform(0.35, 0.65) * sx
    gap_y = rng.uniform(15.0, 60.0) * rng.choice([-1.0, 1.0])
    gap = rng.uniform(8.0, 14.0)
    half = rng.uniform(75.0, 150.0)
    walls = (_wall(wx, -half, wx, gap_y - gap / 2 - 2.0)
             + _wall(wx, gap_y + gap / 2 + 2.0, wx, half))
    return _recovery(f"narrow-passage-{seed}", sx, sy, walls, rng)


def harbour_entrance(seed: int) -> Scenario:
    """Two staggered breakwaters across the approach, each leaving a 10-16 m entrance at
    opposite ends: an S-shaped way in."""
    rng = np.random.default_rng(91_000 + seed)
    sx, sy = rng.uniform(110.0, 160.0), rng.uniform(-15.0, 15.0)
    x_out, x_in = rng.uniform(0.55, 0.7) * sx, rng.uniform(0.25, 0.4) * sx
    side = rng.choice([-1.0, 1.0])
    width = rng.uniform(10.0, 16.0)
    open_out, open_in = side * rng.uniform(20.0, 40.0), -side * rng.uniform(10.0, 30.0)
    walls = []
    for wx, opening in ((x_out, open_out), (x_in, open_in)):
        if opening > 0:
            walls += _wall(wx, -90.0, wx, opening - width / 2 - 2.0)
        else:
            walls += _wall(wx, opening + width / 2 + 2.0, wx, 90.0)
    return _recovery(f"harbour-entrance-{seed}", sx, sy, walls, rng)


def ship_at_ramp(seed: int) -> Scenario:
    """A ship 3-6 m in radius crossing the ramp axis 8-25 m out at 2-4 m/s, timed to pass
    about when the boat arrives."""
    rng = np.random.default_rng(92_000 + seed)
    dist, sx, sy = _out_at_sea(rng, 60.0, 130.0, 30.0)
    cross_x, speed = rng.uniform(8.0, 25.0), rng.uniform(2.0, 4.0) * rng.choice([-1.0, 1.0])
    t_cross = (dist - cross_x) / 1.8 + rng.uniform(-10.0, 10.0)
    ship = {"x": round(cross_x, 2), "y": round(-speed * max(t_cross, 1.0), 2),
            "radius": round(rng.uniform(3.0, 6.0), 2), "vx": 0.0, "vy": round(speed, 3)}
    return _recovery(f"ship-at-ramp-{seed}", sx, sy, [ship], rng)


def head_on(seed: int) -> Scenario:
    """A ship coming down the approach at 1.5-3x the boat's top speed, head-on, meeting the
    boat 30-70 % of the way in."""
    rng = np.random.default_rng(93_000 + seed)
    dist, sx, sy = _out_at_sea(rng, 70.0, 140.0, 20.0)
    frac = rng.uniform(0.3, 0.7)
    route = math.atan2(-sy, -sx)
    speed = rng.uniform(1.5, 3.0) * Vessel().speed_max
    vx, vy = -speed * math.cos(route), -speed * math.sin(route)  # towards the start
    t_meet = frac * dist / 1.8
    px, py = sx + frac * (0.0 - sx), sy + frac * (0.0 - sy)
    ship = {"x": round(px - vx * t_meet, 2), "y": round(py - vy * t_meet, 2),
            "radius": round(rng.uniform(3.0, 6.0), 2), "vx": round(vx, 3), "vy": round(vy, 3)}
    return _recovery(f"head-on-{seed}", sx, sy, [ship], rng)


def cross_current(seed: int) -> Scenario:
    """A random recovery in a 1.2 m/s current across the ramp axis (60-120 deg off it)."""
    rng = np.random.default_rng(94_000 + seed)
    data = random_recovery(300 + seed).model_dump()
    data["environment"]["current_speed"] = 1.2
    data["environment"]["current_dir_deg"] = round(
        (rng.uniform(60.0, 120.0) * rng.choice([-1.0, 1.0])) % 360.0, 1)
    data["name"] = f"cross-current-{seed}"
    return parse_scenario(data)


def far_start(seed: int) -> Scenario:
    """A recovery from 1.2-1.6 km out with 4-10 obstacles along the way."""
    rng = np.random.default_rng(95_000 + seed)
    _, sx, sy = _out_at_sea(rng, 1200.0, 1600.0, 20.0)
    obstacles = [{"x": round(sx * f + rng.normal(0.0, 10.0), 2),
                  "y": round(sy * f + rng.normal(0.0, 25.0), 2),
                  "radius": round(rng.uniform(2.0, 8.0), 2)}
                 for f in rng.uniform(0.05, 0.95, size=int(rng.integers(4, 11)))]
    return _recovery(f"far-start-{seed}", sx, sy, obstacles, rng)


def goal_blocked(seed: int) -> Scenario:
    """A slow vessel lying on the run-in for the first 25-35 s, then drifting clear."""
    rng = np.random.default_rng(96_000 + seed)
    _, sx, sy = _out_at_sea(rng, 40.0, 90.0, 30.0)
    block_x, clear_s = rng.uniform(6.0, 15.0), rng.uniform(25.0, 35.0)
    r = rng.uniform(2.0, 3.5)
    speed = (r + 6.0) / clear_s * rng.choice([-1.0, 1.0])  # off the axis after clear_s
    blocker = {"x": round(block_x, 2), "y": 0.0, "radius": round(r, 2), "vx": 0.0,
               "vy": round(speed, 3)}
    return _recovery(f"goal-blocked-{seed}", sx, sy, [blocker], rng)


REVIEW_FAMILIES = {
    "narrow_passage": narrow_passage,
    "harbour_entrance": harbour_entrance,
    "ship_at_ramp": ship_at_ramp,
    "head_on": head_on,
    "cross_current": cross_current,
    "far_start": far_start,
    "goal_blocked": goal_blocked,
}


HIDDEN_FAMILIES = {
    "pointing_away": pointing_away,
    "strong_current": strong_current,
    "crossing_ships": crossing_ships,
    "behind_ramp": behind_ramp,
    "long_wall": long_wall,
    "dense_field": dense_field,
    "alongside": alongside,
    "outline_astern_traffic": outline_astern_traffic,
}
