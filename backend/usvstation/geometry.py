"""Plane geometry and link units, defined once for the whole station (core layer).

Conventions: radians inside the code, degrees only at the edges; the ramp frame
has +x along the ramp and +y to its left, angles anticlockwise from +x. Every
function takes a Python/NumPy scalar and gives a float, or takes an array and
gives an array (element-wise, vectorised). This module imports only math and
NumPy, so every layer may use it.
"""

from __future__ import annotations

import math
from typing import overload

import numpy as np
from numpy.typing import ArrayLike

TWO_PI = 2.0 * math.pi

Scalar = float | int


def _scalar(a: object) -> bool:
    return isinstance(a, (int, float))  # np.float64 is a float


# --- angles ---------------------------------------------------------------------------------
@overload
def wrap_angle(angle: Scalar) -> float: ...
@overload
def wrap_angle(angle: ArrayLike) -> np.ndarray: ...
def wrap_angle(angle: ArrayLike) -> float | np.ndarray:
    """Radians wrapped to [-pi, pi) (a tiny negative remainder rounds up to 2 pi: kept in)."""
    if _scalar(angle):
        w = (angle + math.pi) % TWO_PI - math.pi
        return -math.pi if w >= math.pi else w
    w = np.mod(np.asarray(angle, dtype=float) + math.pi, TWO_PI) - math.pi
    return np.where(w >= math.pi, -math.pi, w)


@overload
def angle_diff(a: Scalar, b: Scalar) -> float: ...
@overload
def angle_diff(a: ArrayLike, b: ArrayLike) -> np.ndarray: ...
def angle_diff(a: ArrayLike, b: ArrayLike) -> float | np.ndarray:
    """Smallest signed angle a - b in [-pi, pi), radians; positive when a is anticlockwise
    of b. Antisymmetric except at exactly +-pi."""
    if _scalar(a) and _scalar(b):
        return wrap_angle(a - b)
    return wrap_angle(np.asarray(a, dtype=float) - np.asarray(b, dtype=float))


@overload
def wrap_deg(angle_deg: Scalar) -> float: ...
@overload
def wrap_deg(angle_deg: ArrayLike) -> np.ndarray: ...
def wrap_deg(angle_deg: ArrayLike) -> float | np.ndarray:
    """Degrees wrapped to [0, 360) (a compass bearing; -1e-20 gives 0, not 360)."""
    if _scalar(angle_deg):
        w = angle_deg % 360.0
        return 0.0 if w == 360.0 else w
    w = np.mod(np.asarray(angle_deg, dtype=float), 360.0)
    return np.where(w == 360.0, 0.0, w)


@overload
def wrap_180(angle_deg: Scalar) -> float: ...
@overload
def wrap_180(angle_deg: ArrayLike) -> np.ndarray: ...
def wrap_180(angle_deg: ArrayLike) -> float | np.ndarray:
    """Degrees wrapped to (-180, 180] (a relative bearing: positive clockwise on a compass)."""
    if _scalar(angle_deg):
        r = (angle_deg + 180.0) % 360.0 - 180.0
        return 180.0 if r == -180.0 else r
    r = np.mod(np.asarray(angle_deg, dtype=float) + 180.0, 360.0) - 180.0
    return np.where(r == -180.0, 180.0, r)


# --- paths ------------------------------------------------------------------------------------
def cross_track_error(px: float, py: float, ax: float, ay: float, bx: float, by: float) -> float:
    """Signed distance (m) of P from the line A->B: POSITIVE LEFT of the direction of travel.

    The one sign convention of the station: the ramp frame's +y is to the left, and the
    wire's USV_THRUST.cross_track is positive left (protocol/usv_recovery.xml). A degenerate
    segment (A = B) gives the unsigned distance |P - A|.
    """
    dx, dy = bx - ax, by - ay
    length = math.hypot(dx, dy)
    if length == 0.0:
        return math.hypot(px - ax, py - ay)
    return (dx * (py - ay) - dy * (px - ax)) / length


@overload
def position_at(times: ArrayLike, xs: ArrayLike, ys: ArrayLike,
                t: Scalar) -> tuple[float, float]: ...
@overload
def position_at(times: ArrayLike, xs: ArrayLike, ys: ArrayLike,
                t: ArrayLike) -> tuple[np.ndarray, np.ndarray]: ...
def position_at(times: ArrayLike, xs: ArrayLike, ys: ArrayLike, t: ArrayLike
                ) -> tuple[float, float] | tuple[np.ndarray, np.ndarray]:
    """Position on a timed path (waypoints (x_i, y_i) reached at times t_i, increasing):
    linear in time between waypoints (paper 000 eq. 9), held at the ends outside them."""
    x = np.interp(t, times, xs)
    y = np.interp(t, times, ys)
    if _scalar(t):
        return float(x), float(y)
    return x, y


# --- obstacles --------------------------------------------------------------------------------
@overload
def inflated_radius(r_obs: Scalar, hull_length: float, r_c: float) -> float: ...
@overload
def inflated_radius(r_obs: ArrayLike, hull_length: float, r_c: float) -> np.ndarray: ...
def inflated_radius(r_obs: ArrayLike, hull_length: float, r_c: float) -> float | np.ndarray:
    """R_l = R_obs + D_USV + R_c (paper 000 eq. 7): the obstacle radius grown by the hull
    length D_USV and the compensation radius R_c (drift; the paper takes 1 m)."""
    if _scalar(r_obs):
        return r_obs + hull_length + r_c
    return np.asarray(r_obs, dtype=float) + hull_length + r_c


# --- link units (MAVLink integer fields) -------------------------------------------------------
@overload
def _rounded(value: Scalar, scale: float) -> int: ...
@overload
def _rounded(value: ArrayLike, scale: float) -> np.ndarray: ...
def _rounded(value: ArrayLike, scale: float) -> int | np.ndarray:
    if _scalar(value):
        return round(value * scale)
    return np.rint(np.asarray(value, dtype=float) * scale).astype(np.int64)


@overload
def _scaled(value: Scalar, scale: float) -> float: ...
@overload
def _scaled(value: ArrayLike, scale: float) -> np.ndarray: ...
def _scaled(value: ArrayLike, scale: float) -> float | np.ndarray:
    if _scalar(value):
        return value / scale
    return np.asarray(value, dtype=float) / scale


def deg_to_e7(deg: ArrayLike) -> int | np.ndarray:
    """Degrees to the wire's 1e-7 degree integers (lat/lon), rounded half to even."""
    return _rounded(deg, 1e7)


def e7_to_deg(e7: ArrayLike) -> float | np.ndarray:
    """1e-7 degree integers to degrees."""
    return _scaled(e7, 1e7)


def deg_to_cdeg(deg: ArrayLike) -> int | np.ndarray:
    """A compass angle in degrees to the wire's centidegrees 0..35999."""
    return _rounded(wrap_deg(deg), 100.0) % 36000


def cdeg_to_deg(cdeg: ArrayLike) -> float | np.ndarray:
    """Centidegrees to degrees."""
    return _scaled(cdeg, 100.0)


def mps_to_cms(speed: ArrayLike) -> int | np.ndarray:
    """m/s to the wire's cm/s integers."""
    return _rounded(speed, 100.0)


def cms_to_mps(cms: ArrayLike) -> float | np.ndarray:
    """cm/s to m/s."""
    return _scaled(cms, 100.0)


def s_to_ms(seconds: ArrayLike) -> int | np.ndarray:
    """Seconds to the wire's millisecond integers."""
    return _rounded(seconds, 1000.0)


def ms_to_s(ms: ArrayLike) -> float | np.ndarray:
    """Milliseconds to seconds."""
    return _scaled(ms, 1000.0)
