"""Plane geometry for line-of-sight guidance (scalar, allocation-free)."""

from __future__ import annotations

import math


def circle_segment_intersections(
    cx: float, cy: float, radius: float, ax: float, ay: float, bx: float, by: float
) -> list[float]:
    """Fractions s in [0, 1] (ascending) where segment A->B crosses the circle (c, radius).

    A tangent touch gives one fraction; a degenerate segment gives none.
    """
    dx, dy = bx - ax, by - ay
    a = dx * dx + dy * dy
    if a == 0.0:
        return []
    fx, fy = ax - cx, ay - cy
    b = 2.0 * (fx * dx + fy * dy)
    c = fx * fx + fy * fy - radius * radius
    disc = b * b - 4.0 * a * c
    if disc < 0.0:
        return []
    root = math.sqrt(disc)
    # Numerically stable pair of roots.
    q = -0.5 * (b + math.copysign(root, b)) if b != 0.0 else 0.5 * root
    roots = sorted({q / a, c / q} if q != 0.0 else {0.0})
    return [min(max(s, 0.0), 1.0) for s in roots if -1e-12 <= s <= 1.0 + 1e-12]


def project_on_segment(px: float, py: float, ax: float, ay: float, bx: float, by: float) -> float:
    """Fraction s in [0, 1] of the point of segment A->B nearest to P."""
    dx, dy = bx - ax, by - ay
    a = dx * dx + dy * dy
    if a == 0.0:
        return 0.0
    s = ((px - ax) * dx + (py - ay) * dy) / a
    return min(max(s, 0.0), 1.0)

