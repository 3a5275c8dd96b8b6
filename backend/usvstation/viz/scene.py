"""What the 3D view draws beyond the plan and the track (issue 25): the day, dusk and night
palettes, the mother ship's hull and the world's targets, in the ship-fixed ramp frame.

Pure geometry and colours (NumPy, no viser), so it is tested without a server; viz/view.py
puts the results in the viser scene.

- Palettes after ECDIS (IEC 62288): day on a light sea, dusk on a dark grey one, night dark
  and red only (nothing brighter than the console's #e03c1e; viser's labels, drawn on white,
  are hidden), for the scene and viser's GUI.
- The hull: the mother ship's outline in the ramp frame (scenario/hull.py: `outline`, else
  the box x in [-length, 0], |y| <= beam / 2) as a prism over the time axis, since in the
  ship-fixed frame the hull stands still; a ship without a shape shows its length on the
  axis only.
- Targets: each world target at the present time, its predicted track in (x, y, t) along its
  velocity relative to the ramp (where the plan sees it), red when dangerous (predicted hull
  clearance under the plan's margin), grey and dashed when lost.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from usvstation.scenario.hull import hull_polygon
from usvstation.scenario.ships import MotherShip

Rgb = tuple[int, int, int]


@dataclass(frozen=True)
class Palette:
    """The colours of the 3D view for one light level."""

    name: str
    dark: bool  # viser's GUI in dark mode
    brand: Rgb  # viser's GUI accent
    background: Rgb
    grid: Rgb
    plan: Rgb
    track: Rgb
    obstacle: Rgb
    obstacle_moving: Rgb
    hull: Rgb
    ramp: Rgb
    target: Rgb
    danger: Rgb
    lost: Rgb
    start: Rgb
    plane: Rgb
    labels: bool = True  # viser draws labels on white: hidden at night


PALETTES: dict[str, Palette] = {
    "day": Palette("day", False, (43, 108, 176), (247, 250, 252), (160, 174, 192),
                   (40, 90, 220), (220, 40, 40), (150, 90, 60), (230, 120, 60),
                   (74, 85, 104), (120, 120, 120), (26, 32, 44), (197, 48, 48),
                   (160, 174, 192), (40, 160, 60), (120, 170, 220)),
    "dusk": Palette("dusk", True, (99, 179, 237), (26, 32, 44), (74, 85, 104),
                    (99, 179, 237), (245, 101, 101), (192, 132, 96), (237, 137, 54),
                    (160, 174, 192), (113, 128, 150), (226, 232, 240), (252, 129, 129),
                    (113, 128, 150), (104, 211, 145), (74, 110, 150)),
    "night": Palette("night", True, (90, 18, 8), (10, 0, 0), (60, 12, 6),
                     (200, 50, 30), (224, 60, 30), (110, 24, 10), (140, 36, 20),
                     (140, 36, 20), (90, 18, 8), (200, 50, 30), (224, 60, 30),
                     (80, 18, 8), (160, 40, 20), (60, 12, 6), labels=False),
}


def palette(name: str) -> Palette:
    """The palette called `name` (day, dusk, night); ValueError naming them otherwise."""
    try:
        return PALETTES[name]
    except KeyError:
        raise ValueError(f"unknown palette {name!r}; palettes: {', '.join(PALETTES)}") from None


def background_image(p: Palette) -> np.ndarray:
    """A one-colour image for viser's scene background."""
    return np.full((8, 8, 3), p.background, dtype=np.uint8)


def hull_prism(ship: MotherShip | None, height: float) -> tuple[np.ndarray, np.ndarray] | None:
    """Vertices and faces of the hull's outline swept from z = 0 to `height` (a prism: the
    hull stands still in the ship-fixed frame), or None when the ship has no shape."""
    ring = hull_polygon(ship)
    if ring is None:
        return None
    n = len(ring)
    base = np.array(ring, dtype=float)
    vertices = np.vstack([np.column_stack([base, np.zeros(n)]),
                          np.column_stack([base, np.full(n, height)])])
    i = np.arange(n)
    j = (i + 1) % n
    faces = np.concatenate([np.column_stack([i, j, n + j]), np.column_stack([i, n + j, n + i])])
    return vertices.astype(np.float32), faces.astype(np.uint32)


def hull_outline(ship: MotherShip | None) -> np.ndarray | None:
    """The hull's outline at z = 0 as (N, 2, 3) line segments; a ship without a shape: its
    length along the axis behind the ramp; None without a mother ship."""
    if ship is None:
        return None
    ring = hull_polygon(ship)
    if ring is None:
        return np.array([[[0.0, 0.0, 0.0], [-ship.length, 0.0, 0.0]]], dtype=np.float32)
    pts = np.array([[x, y, 0.0] for x, y in ring + ring[:1]], dtype=np.float32)
    return np.stack([pts[:-1], pts[1:]], axis=1)


@dataclass(frozen=True)
class TargetSweep:
    """One target as the 3D view draws it: where it is now and its predicted track."""

    id: str
    label: str
    position: tuple[float, float, float]  # x, y, z of now
    segments: np.ndarray  # (1, 2, 3) from now to the horizon along its relative velocity
    color: Rgb


def target_sweeps(targets: list[dict], t_now: float, horizon_s: float, time_scale: float,
                  p: Palette, dangerous: frozenset[str] = frozenset()) -> list[TargetSweep]:
    """The world's targets (`records.Target`: ramp-frame x, y and velocity relative to the
    ramp rvx, rvy) at mission time t_now, swept to the horizon."""
    out = []
    span = max(horizon_s - t_now, 0.0)
    for g in targets:
        x, y, z = float(g["x"]), float(g["y"]), t_now * time_scale
        end = (x + float(g["rvx"]) * span, y + float(g["rvy"]) * span, (t_now + span) * time_scale)
        name = g.get("name") or (str(g["mmsi"]) if g.get("mmsi") else g["id"])
        color = p.lost if g.get("lost") else p.danger if g["id"] in dangerous else p.target
        out.append(TargetSweep(g["id"], f"{name}{' (lost)' if g.get('lost') else ''}",
                               (x, y, z), np.array([[[x, y, z], end]], dtype=np.float32),
                               color))
    return out
