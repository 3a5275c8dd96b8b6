"""x-y-t modelling of obstacles (paper 000 section 3.2.1, eq. 7-9).

Obstacles are circles; a moving one sweeps an oblique cylinder in (x, y, t)
(eq. 8). A path segment is a straight line in (x, y, t) travelled at its
average velocity (the paper's assumption behind eq. 9). Whether it enters a
circle is decided exactly by the quadratic of eq. 9 in the time tau since the
segment began, restricted to the segment's time window [0, dT].

Sign convention (the paper's eq. 8/9 print "+V t" for an obstacle that moves
by +V t): with the boat at p0 + u tau and the obstacle centre at
c0 + w (t0 + tau), the relative position is d(tau) = d0 + (u - w) tau with
d0 = p0 - c0 - w t0, and eq. 9 reads

    q(tau) = |u - w|^2 tau^2 + 2 d0.(u - w) tau + |d0|^2 - R^2 = 0.

The segment enters the open circle iff q < 0 somewhere in (0, dT): its
roots tau1 < tau2 exist (discriminant > 0) and (tau1, tau2) overlaps
(0, dT). `eq9_roots` gives the roots.

The hot loop uses the same quadratic in normalised time s = tau / dT,
q(s) = A s^2 + B s + C, whose coefficients need no division: with e0, e1
the relative positions p - c(t) at the segment's two ends, C = |e0|^2 - R^2,
A = |e1 - e0|^2 (= a dT^2) and B = |e1|^2 - R^2 - C - A (= b dT). It has a
root in (0, 1) where q dips below zero iff q < 0 at an end, or its vertex
-B / 2A lies in (0, 1) and B^2 > 4 A C.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

Num = np.ndarray | float  # anything that broadcasts

# Elements (obstacle or pair x path or candidate) from which pruning by x-y-t boxes pays:
# below it, testing everything costs fewer NumPy calls than the pruning (evaluator, preheating).
PRUNE_ELEMENTS = 4096


@dataclass(frozen=True)
class ObstacleField:
    """Obstacle circles at t = 0 with their velocities; `inflated` is R_l of eq. 7."""

    centre: np.ndarray  # (M, 2) m
    velocity: np.ndarray  # (M, 2) m/s
    radius: np.ndarray  # (M,) m, R_obs
    inflated: np.ndarray  # (M,) m, R_l = R_obs + D_USV + R_c
    source: np.ndarray | None = None  # (M,) index of the scenario obstacle each circle stands for

    @property
    def count(self) -> int:
        return int(self.radius.shape[0])

    @property
    def static(self) -> np.ndarray:
        return ~np.any(self.velocity != 0.0, axis=1)

    def hits(
        self, x0: np.ndarray, y0: np.ndarray, t0: np.ndarray,
        x1: np.ndarray, y1: np.ndarray, t1: np.ndarray, inflated: bool = True,
    ) -> np.ndarray:
        """Segments against every obstacle: shape (M,) + broadcast shape of the inputs."""
        shape = np.broadcast_shapes(np.shape(x0), np.shape(x1), np.shape(t0), np.shape(t1))
        ex0, ey0 = relative_positions(*np.broadcast_arrays(x0, y0, t0), self)
        ex1, ey1 = relative_positions(*np.broadcast_arrays(x1, y1, t1), self)
        r = (self.inflated if inflated else self.radius).reshape((-1,) + (1,) * len(shape))
        return hits_from_relative(ex0, ey0, ex1, ey1, r)

    def clearance(self, x: np.ndarray, y: np.ndarray, t: np.ndarray) -> float | None:
        """Smallest distance from a timed polyline to any obstacle circle's edge, m."""
        if self.count == 0:
            return None
        e = (slice(None), None)
        c, v = self.centre, self.velocity
        d = closest_approach(x[:-1][e], y[:-1][e], t[:-1][e], x[1:][e], y[1:][e], t[1:][e],
                             c[:, 0], c[:, 1], v[:, 0], v[:, 1])
        return float(np.min(d - self.radius))


def eq9_coefficients(
    x0: Num, y0: Num, t0: Num, x1: Num, y1: Num, t1: Num,
    cx: Num, cy: Num, vx: Num, vy: Num, r: Num,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Coefficients (a, b, c) of eq. 9, q(tau) = a tau^2 + b tau + c, for tau = t - t0."""
    dt = np.asarray(t1 - t0, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        wx = np.where(dt > 0.0, (x1 - x0) / dt, 0.0) - vx
        wy = np.where(dt > 0.0, (y1 - y0) / dt, 0.0) - vy
    dx = x0 - cx - vx * t0
    dy = y0 - cy - vy * t0
    return wx * wx + wy * wy, 2.0 * (dx * wx + dy * wy), dx * dx + dy * dy - r * r


def eq9_roots(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Real roots tau1 <= tau2 of eq. 9 (nan where there are none)."""
    disc = b * b - 4.0 * a * c
    root = np.sqrt(np.where(disc >= 0.0, disc, np.nan))
    with np.errstate(divide="ignore", invalid="ignore"):
        return (-b - root) / (2.0 * a), (-b + root) / (2.0 * a)


def relative_positions(
    x: np.ndarray, y: np.ndarray, t: np.ndarray, field: ObstacleField
) -> tuple[np.ndarray, np.ndarray]:
    """Boat minus obstacle centre at each point: arrays of shape (M,) + x.shape.

    The obstacle axis comes first so that NumPy's inner loops run over the
    (long) point axes rather than over a handful of obstacles.
    """
    e = (slice(None),) + (None,) * np.ndim(x)
    c, v = field.centre, field.velocity
    return x - (c[:, 0][e] + v[:, 0][e] * t), y - (c[:, 1][e] + v[:, 1][e] * t)


def hits_from_relative(
    ex0: np.ndarray, ey0: np.ndarray, ex1: np.ndarray, ey1: np.ndarray, r: np.ndarray
) -> np.ndarray:
    """Eq. 9 in normalised time: does the relative motion e0 -> e1 enter the open circle r?"""
    r2 = r * r
    return _hits_q(ex0 * ex0 + ey0 * ey0 - r2, ex1 * ex1 + ey1 * ey1 - r2, ex1 - ex0, ey1 - ey0)


def polyline_hits(ex: np.ndarray, ey: np.ndarray, r: np.ndarray, axis: int = 1) -> np.ndarray:
    """Eq. 9 for every segment of timed polylines given relative positions along `axis`.

    The end-point terms C are computed once per waypoint and shared by the
    two segments that meet there.
    """
    c = ex * ex + ey * ey - r * r
    n = c.shape[axis]
    head, tail = (slice(None),) * axis + (slice(0, n - 1),), (slice(None),) * axis + (slice(1, n),)
    return _hits_q(c[head], c[tail], np.diff(ex, axis=axis), np.diff(ey, axis=axis))


def _hits_q(c0: np.ndarray, c1: np.ndarray, dx: np.ndarray, dy: np.ndarray) -> np.ndarray:
    a = dx * dx + dy * dy
    b = c1 - c0 - a
    vertex_inside = (b < 0.0) & (b > -2.0 * a) & (b * b > 4.0 * a * c0)
    return (c0 < 0.0) | (c1 < 0.0) | vertex_inside


def segments_hit_circles(
    x0: Num, y0: Num, t0: Num, x1: Num, y1: Num, t1: Num,
    cx: Num, cy: Num, vx: Num, vy: Num, r: Num,
) -> np.ndarray:
    """True where the segment (x0, y0, t0) -> (x1, y1, t1) enters the open moving circle.

    All arguments broadcast. Touching the circle (tangent) is not a hit;
    starting or ending inside it is.
    """
    return hits_from_relative(
        x0 - cx - vx * t0, y0 - cy - vy * t0, x1 - cx - vx * t1, y1 - cy - vy * t1, r
    )


def closest_approach(
    x0: Num, y0: Num, t0: Num, x1: Num, y1: Num, t1: Num, cx: Num, cy: Num, vx: Num, vy: Num
) -> np.ndarray:
    """Smallest centre-to-centre distance over the segment's time window (broadcast).

    Evaluates the relative position at the closest instant (normalised time
    s* in [0, 1]) rather than the quadratic's value, which would lose
    precision to cancellation.
    """
    dt = t1 - t0
    ex, ey = x0 - cx - vx * t0, y0 - cy - vy * t0
    dx, dy = (x1 - x0) - vx * dt, (y1 - y0) - vy * dt
    dd = np.asarray(dx * dx + dy * dy, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(dd > 0.0, -(ex * dx + ey * dy) / dd, 0.0)
    s = np.clip(s, 0.0, 1.0)
    return np.hypot(ex + s * dx, ey + s * dy)

