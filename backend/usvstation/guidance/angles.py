"""Angle helpers (radians inside the code; degrees only at the edges)."""

from __future__ import annotations

import math

import numpy as np

TWO_PI = 2.0 * math.pi


def wrap_angle(angle: float) -> float:
    """`angle` wrapped to [-pi, pi)."""
    return (angle + math.pi) % TWO_PI - math.pi


def wrap_angles(angles: np.ndarray) -> np.ndarray:
    """Element-wise wrap_angle for arrays."""
    return np.mod(np.asarray(angles, dtype=float) + math.pi, TWO_PI) - math.pi


def angle_diff(a: float, b: float) -> float:
    """Smallest signed angle a - b, in [-pi, pi); positive when a is anticlockwise of b."""
    return wrap_angle(a - b)


def heading_of(dx: float, dy: float) -> float:
    """Ramp-frame heading (anticlockwise from +x) of the vector (dx, dy)."""
    return math.atan2(dy, dx)
