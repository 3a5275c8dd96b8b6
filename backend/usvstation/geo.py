"""Ramp frame <-> WGS-84 through a local tangent plane on the WGS-84 ellipsoid.

The ramp frame has its origin at the ramp end, +x along the ramp centre line
(compass bearing `ramp_bearing_deg`, clockwise from north) and +y to its left.
It is a rotation of the local East-North-Up plane at the origin; the
ENU <-> geodetic step is pymap3d's exact ellipsoidal transformation (not the
paper's divide-by-100000 shortcut, paper 000 eq. 6).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pymap3d
from numpy.typing import ArrayLike

from usvstation.geometry import wrap_deg

_WGS84 = pymap3d.Ellipsoid.from_name("wgs84")


@dataclass(frozen=True)
class RampFrame:
    """A ramp frame anchored at (lat, lon) with +x on compass bearing `ramp_bearing_deg`."""

    lat: float
    lon: float
    ramp_bearing_deg: float = 0.0
    height: float = 0.0

    @property
    def _axes(self) -> tuple[float, float]:
        b = np.radians(self.ramp_bearing_deg)
        return float(np.sin(b)), float(np.cos(b))

    def ramp_to_enu(self, x: ArrayLike, y: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
        """Ramp (x, y) to local (east, north), metres."""
        s, c = self._axes
        x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
        # +x = (sin b, cos b) in (E, N); +y is +x turned 90 degrees anticlockwise.
        return x * s - y * c, x * c + y * s

    def enu_to_ramp(self, east: ArrayLike, north: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
        """Local (east, north) to ramp (x, y), metres."""
        s, c = self._axes
        e, n = np.asarray(east, dtype=float), np.asarray(north, dtype=float)
        return e * s + n * c, -e * c + n * s

    def to_geodetic(self, x: ArrayLike, y: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
        """Ramp (x, y) in metres to WGS-84 (lat, lon) in degrees."""
        e, n = self.ramp_to_enu(x, y)
        # The sea surface lies below the tangent plane (about 2 m at 5 km): find the
        # up-offset whose point has the origin's ellipsoidal height, so that
        # to_ramp (which drops "up") inverts this exactly.
        up = np.zeros_like(e)
        for _ in range(4):
            lat, lon, h = pymap3d.enu2geodetic(
                e, n, up, self.lat, self.lon, self.height, ell=_WGS84, deg=True
            )
            up = up - (np.asarray(h) - self.height)
        return np.asarray(lat, dtype=float), np.asarray(lon, dtype=float)

    def to_ramp(self, lat: ArrayLike, lon: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
        """WGS-84 (lat, lon) in degrees to ramp (x, y) in metres (on the tangent plane)."""
        lat_a, lon_a = np.asarray(lat, dtype=float), np.asarray(lon, dtype=float)
        e, n, _ = pymap3d.geodetic2enu(
            lat_a, lon_a, np.full_like(lat_a, self.height), self.lat, self.lon, self.height,
            ell=_WGS84, deg=True,
        )
        return self.enu_to_ramp(e, n)

    def heading_to_compass_deg(self, heading_deg: ArrayLike) -> np.ndarray:
        """Ramp heading (anticlockwise from +x) to compass heading (clockwise from north)."""
        return wrap_deg(self.ramp_bearing_deg - np.asarray(heading_deg, dtype=float))

    def compass_to_heading_deg(self, compass_deg: ArrayLike) -> np.ndarray:
        """Compass heading (clockwise from north) to ramp heading (anticlockwise from +x)."""
        return wrap_deg(self.ramp_bearing_deg - np.asarray(compass_deg, dtype=float))

    def vector_to_ramp(self, east: ArrayLike, north: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
        """Rotate a horizontal vector (velocity, force) from ENU into the ramp frame."""
        return self.enu_to_ramp(east, north)
