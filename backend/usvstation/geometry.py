"""Plane geometry and link units, defined once for the whole station (core layer).

Conventions: radians inside the code, degrees only at the edges; the ramp frame
has +x along the ramp and +y to its left, angles anticlockwise from +x. Every
function takes a Python/NumPy scalar and gives a float, or takes an array and
gives an array (element-wise, vectorised). This module imports only math and
NumPy, so every layer may use it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

import numpy as np
from numpy.typing import ArrayLike

TWO_PI = 2.0 * math.pi


def _scalar(a: object) -> bool:
    return isinstance(a, (int, float))  # np.float64 is a float


# --- angles ---------------------------------------------------------------------------------
def _wrap(a: ArrayLike, low: float, period: float) -> float | np.ndarray:
    """`a` wrapped to [low, low + period); a tiny negative remainder (it rounds to `period`)
    goes to `low`."""
    if _scalar(a):
        w = (a - low) % period + low
        return low if w >= low + period else w
    w = np.mod(np.asarray(a, dtype=float) - low, period) + low
    w = np.where(w >= low + period, low, w)
    return w[()] if w.ndim == 0 else w  # a 0-d array gives a NumPy scalar, as np.mod does


def wrap_angle(angle: ArrayLike) -> float | np.ndarray:
    """Radians wrapped to [-pi, pi)."""
    return _wrap(angle, -math.pi, TWO_PI)


def angle_diff(a: ArrayLike, b: ArrayLike) -> float | np.ndarray:
    """Smallest signed angle a - b in [-pi, pi), radians; positive when a is anticlockwise
    of b. Antisymmetric except at exactly +-pi."""
    both = _scalar(a) and _scalar(b)
    return wrap_angle(a - b if both else np.subtract(a, b, dtype=float))


def wrap_deg(angle_deg: ArrayLike) -> float | np.ndarray:
    """Degrees wrapped to [0, 360) (a compass bearing)."""
    return _wrap(angle_deg, 0.0, 360.0)


def wrap_180(angle_deg: ArrayLike) -> float | np.ndarray:
    """Degrees wrapped to (-180, 180] (a relative bearing, positive clockwise on a compass)."""
    r = _wrap(angle_deg, -180.0, 360.0)
    if isinstance(r, np.ndarray):
        return np.where(r == -180.0, 180.0, r)
    return 180.0 if r == -180.0 else r  # a float or a NumPy scalar


# --- paths ------------------------------------------------------------------------------------
def cross_track_error(px: float, py: float, ax: float, ay: float, bx: float, by: float) -> float:
    """Signed distance (m) of P from the line A->B: POSITIVE LEFT of the direction of travel.

    The one sign convention of the station: the ramp frame's +y is to the left, and the
    wire's USV_THRUST.cross_track is positive left (protocol/usv_recovery.xml). Only the
    telemetry record (API, store, console) shows it positive right (docs/api.md), negated at
    that edge. A degenerate segment (A = B) gives the unsigned distance |P - A|.
    """
    dx, dy = bx - ax, by - ay
    length = math.hypot(dx, dy)
    if length == 0.0:
        return math.hypot(px - ax, py - ay)
    return (dx * (py - ay) - dy * (px - ax)) / length


def position_at(times: ArrayLike, xs: ArrayLike, ys: ArrayLike, t: ArrayLike
                ) -> tuple[float, float] | tuple[np.ndarray, np.ndarray]:
    """Position on a timed path (waypoints (x_i, y_i) reached at increasing times t_i): linear
    in time between waypoints (paper 000 eq. 9), held at the ends. Floats for a scalar t."""
    x, y = np.interp(t, times, xs), np.interp(t, times, ys)
    return (float(x), float(y)) if _scalar(t) else (x, y)


# --- obstacles --------------------------------------------------------------------------------
def inflated_radius(r_obs: ArrayLike, hull_length: float, r_c: float) -> float | np.ndarray:
    """R_l = R_obs + D_USV + R_c (paper 000 eq. 7): the obstacle radius grown by the hull
    length D_USV and the compensation radius R_c (drift; the paper takes 1 m)."""
    r = r_obs if _scalar(r_obs) else np.asarray(r_obs, dtype=float)
    return r + hull_length + r_c


# --- records ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class Pose:
    """A pose in the ramp frame: position x, y (m) and heading psi (rad, anticlockwise
    from +x)."""

    x: float
    y: float
    psi: float


def require_finite(record: object, what: str) -> None:
    """Refuse a dataclass record with a field that is not a finite number: a ValueError
    `"<what>: <field> must be finite (got <value>)"` naming the first such field."""
    for f in fields(record):  # type: ignore[arg-type]
        value = getattr(record, f.name)
        if not math.isfinite(value):
            raise ValueError(f"{what}: {f.name} must be finite (got {value})")


# --- link units (MAVLink integer fields) -------------------------------------------------------
@dataclass(frozen=True)
class WireUnit:
    """A value in SI units (degrees for angles) <-> the wire's integer round(value * scale),
    rounded half to even; `turn` wraps a compass angle into 0..turn-1."""

    scale: float
    turn: int | None = None

    def to_wire(self, value: ArrayLike) -> int | np.ndarray:
        """The wire integer(s) of `value` (an int for a scalar, an int64 array otherwise)."""
        if self.turn is not None:
            value = wrap_deg(value)
        if _scalar(value):
            n = round(value * self.scale)
        else:
            n = np.rint(np.asarray(value, dtype=float) * self.scale).astype(np.int64)
        return n if self.turn is None else n % self.turn

    def from_wire(self, n: ArrayLike) -> float | np.ndarray:
        """The value of wire integer(s) `n`."""
        return n / self.scale if _scalar(n) else np.asarray(n) / self.scale


E7 = WireUnit(1e7)  # degrees <-> 1e-7 degrees (latitude, longitude)
CDEG = WireUnit(100.0, turn=36000)  # compass degrees <-> centidegrees 0..35999
CM = WireUnit(100.0)  # m or m/s <-> cm or cm/s
MS = WireUnit(1000.0)  # s <-> ms
