"""The mother ship's hull in the ramp frame, and the approach corridor (issue 27).

Pure Python (no NumPy), so that input validation stays quick: the planners
(planning/hull.py) and the API's plan submission share these definitions.

- The hull polygon: `mother_ship.outline`, else the box x in [-length, 0],
  |y| <= beam / 2 (stern at the ramp end); none without `beam` or `outline`.
- The approach corridor W: the wedge x >= 0, |y| <= ramp_width / 2 + x tan(a)
  on the ramp axis, a = the arrival cone's half-angle (`align_max_deg`, 10
  deg): the ramp's own half-width at the ramp end, opening outwards as the
  arrival cone does. The planners keep eq. 7's margin from the hull
  everywhere outside W; inside W the boat is entering the ramp.
- A start inside the hull, or whose hull (a circle of half the boat's length)
  touches the ship's hull outside W, is refused in one sentence.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from usvstation.scenario import Scenario
    from usvstation.scenario.ships import MotherShip

Polygon = list[tuple[float, float]]
ALIGN_DEG = 10.0  # default half-angle of the corridor: the IGA's arrival cone (align_max_deg)


def hull_polygon(ship: MotherShip | None) -> Polygon | None:
    """The hull polygon in the ramp frame (counter-clockwise), or None when it has no shape."""
    if ship is None:
        return None
    if ship.outline is not None:
        ring = [(float(p[0]), float(p[1])) for p in ship.outline]
    elif ship.beam is not None:
        h = ship.beam / 2.0
        ring = [(0.0, -h), (0.0, h), (-ship.length, h), (-ship.length, -h)]
    else:
        return None
    area = sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(ring, ring[1:] + ring[:1], strict=True))
    return ring if area > 0.0 else ring[::-1]


def in_corridor(x: float, y: float, ramp_width: float, align_deg: float = ALIGN_DEG) -> bool:
    """True inside the approach corridor W (closed)."""
    return x >= 0.0 and abs(y) <= ramp_width / 2.0 + x * math.tan(math.radians(align_deg))


def inside(x: float, y: float, ring: Polygon) -> bool:
    """Point strictly inside the polygon (even-odd rule; a point on an edge is not inside)."""
    if distance_to_outline(x, y, ring) == 0.0:
        return False
    hit = False
    for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1], strict=True):
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            hit = not hit
    return hit


def distance_to_outline(x: float, y: float, ring: Polygon) -> float:
    """Distance from a point to the polygon's edges, m."""
    best = math.inf
    for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1], strict=True):
        dx, dy = x1 - x0, y1 - y0
        dd = dx * dx + dy * dy
        s = 0.0 if dd == 0.0 else min(max(((x - x0) * dx + (y - y0) * dy) / dd, 0.0), 1.0)
        best = min(best, math.hypot(x - x0 - s * dx, y - y0 - s * dy))
    return best


def start_refusal(scenario: Scenario) -> str | None:
    """Why a start cannot be planned from beside the mother ship (one sentence), or None.

    Refused: a start inside the hull (behind the ramp, or anywhere in the
    outline), or one whose hull circle (half the boat's length) touches the
    ship's hull outside the approach corridor. The planners and the API's plan
    submission both call this (through the scenario's validation).
    """
    ship = scenario.mother_ship
    ring = hull_polygon(ship)
    if ship is None or ring is None:
        return None
    s = scenario.start
    what = "mother_ship.outline" if ship.outline is not None else (
        f"the mother ship's hull (x in [{-ship.length:g}, 0], |y| <= {ship.beam / 2:g} m "
        "of the ramp frame)" if ship.beam is not None else "the mother ship's hull")
    if inside(s.x, s.y, ring):
        return (f"start: ({s.x:g}, {s.y:g}) lies inside {what}, behind the ramp; a recovery "
                "starts in the water")
    if in_corridor(s.x, s.y, ship.ramp_width):
        return None
    half = scenario.vessel.length / 2.0
    d = distance_to_outline(s.x, s.y, ring)
    if d <= half:
        return (f"start: ({s.x:g}, {s.y:g}) is {d:.2f} m from {what}: the boat's hull (half "
                f"its length, {half:g} m) touches the ship; start further off")
    return None
