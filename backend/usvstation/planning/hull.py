"""The mother ship's hull as the planners see it (issue 27; an extension of paper 000).

Paper 000 inflates circles (eq. 7); a ship's hull is a polygon whose stern
holds the goal itself. The planners keep eq. 7's margin m from the hull
polygon P (scenario/hull.py) everywhere except in the approach corridor W,
the wedge on the ramp axis that is the ramp's own half-width at the ramp end
and opens at the arrival cone's angle:

    keep-out = {p : dist(p, P) < m(p)},  m(p) = min(m, dist(p, W)),

the margin tapering to 0 at the corridor's edges, so that no keep-out
reaches into W and a run-in along the axis is always open. Every planner
already tests segments against circles (eq. 9), so the keep-out is built of
static circles centred on P's edges `spacing` apart: a circle of radius
sqrt(m^2 + (spacing / 2)^2) at every sample covers the band of half-width m
along an edge (the worst point lies midway between two samples), capped at
the sample's distance to W. Their raw radius is 0: clearance is measured
from the hull's outline.

The exact rule, for the validator and the independent checker: the boat's
hull circle (half its length) never touches P while its centre is outside W,
and its centre never enters P (`outline_clearance`).
"""

from __future__ import annotations

import math

import numpy as np

from usvstation.scenario import Scenario
from usvstation.scenario.hull import ALIGN_DEG, hull_polygon

SPACING_M = 1.0  # most distance between two keep-out circles along the hull, m
NEAR_CORRIDOR_M = 4.0  # within this of the corridor, circles sit 4 times closer


def hull_ring(scenario: Scenario) -> np.ndarray | None:
    """(K, 2) polygon of the hull in the ramp frame, counter-clockwise; None without one."""
    ring = hull_polygon(scenario.mother_ship)
    return None if ring is None else np.array(ring, dtype=float)


def corridor(scenario: Scenario) -> tuple[float, float]:
    """(half-width at the ramp end, tan of the opening angle) of the approach corridor W."""
    ship = scenario.mother_ship
    assert ship is not None
    return ship.ramp_width / 2.0, math.tan(math.radians(ALIGN_DEG))


def distance_to_corridor(p: np.ndarray, half: float, tan_a: float) -> np.ndarray:
    """(N,) distance from points (N, 2) to the wedge W = {x >= 0, |y| <= half + x tan_a}."""
    x, y = p[:, 0], np.abs(p[:, 1])
    inside = (x >= 0.0) & (y <= half + x * tan_a)
    # the ray from (0, half) along (1, tan_a), and the mouth segment x = 0, |y| <= half
    u = np.array([1.0, tan_a]) / math.hypot(1.0, tan_a)
    rx, ry = x, y - half
    s = np.maximum(rx * u[0] + ry * u[1], 0.0)
    to_ray = np.hypot(rx - s * u[0], ry - s * u[1])
    to_mouth = np.hypot(np.minimum(x, 0.0), np.maximum(y - half, 0.0))
    return np.where(inside, 0.0, np.minimum(to_ray, to_mouth))


def edge_samples(ring: np.ndarray, spacing: float, half: float, tan_a: float) -> np.ndarray:
    """Points along the polygon's edges at most `spacing` apart (closer near the corridor),
    every vertex included."""
    pts = []
    for a, b in zip(ring, np.roll(ring, -1, axis=0), strict=True):
        length = float(np.hypot(*(b - a)))
        s = np.linspace(0.0, 1.0, max(2, math.ceil(length / spacing) + 1))[:, None]
        near = distance_to_corridor(a + s * (b - a), half, tan_a).min() < NEAR_CORRIDOR_M
        step = spacing / 4.0 if near else spacing
        n = max(1, math.ceil(length / step))
        s = np.arange(n)[:, None] / n
        pts.append(a + s * (b - a))
    return np.concatenate(pts)


def keepout_circles(scenario: Scenario, margin: float,
                    spacing: float = SPACING_M) -> tuple[np.ndarray, np.ndarray]:
    """(centres (K, 2), radii (K,)) of the static circles that keep `margin` from the hull
    outside the corridor; empty without a hull or with no margin."""
    ring = hull_ring(scenario)
    if ring is None or margin <= 0.0:
        return np.zeros((0, 2)), np.zeros(0)
    half, tan_a = corridor(scenario)
    centres = edge_samples(ring, spacing, half, tan_a)
    gap = np.max(np.hypot(*np.diff(np.vstack([centres, centres[:1]]), axis=0).T))
    full = math.sqrt(margin * margin + (gap / 2.0) ** 2)
    radii = np.minimum(full, distance_to_corridor(centres, half, tan_a))
    keep = radii > 1e-3
    return centres[keep], radii[keep]


def outline_clearance(scenario: Scenario, x: np.ndarray, y: np.ndarray) -> float | None:
    """Least water between the boat's hull circle and the ship's hull over a polyline, m,
    not counting the stretches where the boat's centre is inside the corridor (exact for
    straight segments); negative when the centre enters the hull. None without a hull."""
    ring = hull_ring(scenario)
    if ring is None:
        return None
    half, tan_a = corridor(scenario)
    half_hull = scenario.vessel.length / 2.0
    best = math.inf
    for k in range(len(x) - 1):
        for p0, p1 in _outside_corridor(np.array([x[k], y[k]]), np.array([x[k + 1], y[k + 1]]),
                                        half, tan_a):
            best = min(best, _segment_polygon_distance(p0, p1, ring) - half_hull)
    return None if best == math.inf else float(best)


def _outside_corridor(p0: np.ndarray, p1: np.ndarray, half: float, tan_a: float
                      ) -> list[tuple[np.ndarray, np.ndarray]]:
    """The parts of segment p0 -> p1 outside the (convex) corridor W."""
    d = p1 - p0
    lo, hi = 0.0, 1.0
    # W = {x >= 0} & {y - tan_a x <= half} & {-y - tan_a x <= half}: clip s in [0, 1]
    for a, b, c in ((-1.0, 0.0, 0.0), (-tan_a, 1.0, half), (-tan_a, -1.0, half)):
        num = c - (a * p0[0] + b * p0[1])
        den = a * d[0] + b * d[1]
        if abs(den) < 1e-15:
            if num < 0.0:
                lo, hi = 1.0, 0.0
            continue
        t = num / den
        if den > 0.0:
            hi = min(hi, t)
        else:
            lo = max(lo, t)
    if lo >= hi:  # no part inside W
        return [(p0, p1)]
    out = []
    if lo > 0.0:
        out.append((p0, p0 + lo * d))
    if hi < 1.0:
        out.append((p0 + hi * d, p1))
    return out


def _segment_polygon_distance(p0: np.ndarray, p1: np.ndarray, ring: np.ndarray) -> float:
    """Distance from a segment to a polygon (0 when they meet; minus the depth of the deeper
    end when the segment lies inside)."""
    a, b = ring, np.roll(ring, -1, axis=0)
    if _segments_cross(p0, p1, a, b).any():
        return 0.0
    d = min(float(_point_segment(p0, a, b).min()), float(_point_segment(p1, a, b).min()),
            float(_point_segment_many(a, p0, p1).min()))
    if _inside(p0, ring) or _inside(p1, ring):
        return -d
    return d


def _point_segment(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distance from point p to each segment a_i b_i."""
    d = b - a
    dd = np.einsum("ij,ij->i", d, d)
    s = np.clip(np.einsum("ij,ij->i", p - a, d) / np.where(dd > 0, dd, 1.0), 0.0, 1.0)
    return np.hypot(*(p - a - s[:, None] * d).T)


def _point_segment_many(q: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distance from each point q_i to the segment a b."""
    d = b - a
    dd = float(d @ d)
    s = np.clip((q - a) @ d / (dd if dd > 0 else 1.0), 0.0, 1.0)
    return np.hypot(*(q - a - s[:, None] * d).T)


def _segments_cross(p0: np.ndarray, p1: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Whether segment p0 p1 meets each segment a_i b_i (touching included)."""
    def orient(p: np.ndarray, q: np.ndarray, r: np.ndarray) -> np.ndarray:
        return (q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1]) - \
            (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0])

    o1, o2 = orient(p0, p1, a), orient(p0, p1, b)
    o3, o4 = orient(a, b, p0), orient(a, b, p1)
    return (o1 * o2 <= 0.0) & (o3 * o4 <= 0.0) & ~((o1 == 0) & (o2 == 0) & (o3 == 0) & (o4 == 0))


def _inside(p: np.ndarray, ring: np.ndarray) -> bool:
    a, b = ring, np.roll(ring, -1, axis=0)
    cross = (a[:, 1] > p[1]) != (b[:, 1] > p[1])
    with np.errstate(divide="ignore", invalid="ignore"):
        xint = a[:, 0] + (p[1] - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
    return bool(np.count_nonzero(cross & (p[0] < xint)) % 2)
