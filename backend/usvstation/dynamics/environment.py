"""Environment: current, second-order wave drift and wind (paper 000 eq. 2-5, paper 002 eq. 24).

Directions are ramp-frame angles (radians, anticlockwise from +x) of where the
flow goes to, like the scenario file's `*_dir_deg`. Forces are returned in the
body frame (x forward, y to port, N anticlockwise) as numpy arrays [X, Y, N].

The vessel model applies the current through the relative velocity (Fossen
2021 ch. 10); `current_force` (eq. 2) is the same effect written as a force on
a hull at rest and is not added on top, which would count the current twice.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from usvstation.dynamics.params import GRAVITY, RHO_AIR, RHO_WATER, VesselParams

# WMO sea state code 3700: (lowest, highest) significant wave height in metres.
SEA_STATE_HEIGHTS = {
    0: (0.0, 0.0),
    1: (0.0, 0.1),
    2: (0.1, 0.5),
    3: (0.5, 1.25),
    4: (1.25, 2.5),
    5: (2.5, 4.0),
    6: (4.0, 6.0),
    7: (6.0, 9.0),
    8: (9.0, 14.0),
}
# Eq. 4's cubic fits are used within wavelength / length ratios [0, 1], where all
# three fall to within 0.1 of zero at 1 (W_x 0.09, W_y 0.08, W_n -0.01); past it
# the cubics diverge (W_y(2) = 19) while real drift forces vanish for waves much
# longer than the hull, so beyond the range the value at 1 decays as (1 / ratio)^2
# (an assumption, documented in docs/tracking.md).
MAX_FIT_RATIO = 1.0
WAVELENGTH_MODELS = ("dispersion", "paper")


@dataclass(frozen=True)
class WaveField:
    """Regular waves: height h_w (m), period (s), wavelength (m), direction of travel (rad)."""

    height: float
    period: float
    wavelength: float
    direction: float

    def __post_init__(self) -> None:
        if self.height < 0.0 or self.period <= 0.0 or self.wavelength <= 0.0:
            raise ValueError(
                "waves: height must be >= 0, period and wavelength > 0 "
                f"(got {self.height}, {self.period}, {self.wavelength})"
            )

    @classmethod
    def from_wind(cls, wind_speed: float, direction: float,
                  wavelength: str = "dispersion") -> WaveField:
        """Waves raised by a wind of `wind_speed` m/s (paper 000 eq. 5).

        Height and period are eq. 5's. The wavelength comes from the deep-water
        dispersion relation lambda = g T^2 / (2 pi) (= 1.56 T^2) by default;
        `wavelength="paper"` keeps eq. 5's 0.54 T^2 (which gives 26.9 m where
        dispersion gives 77.7 m for T = 7.06 s).
        """
        if wind_speed < 0.0:
            raise ValueError(f"waves: wind speed must be >= 0 (got {wind_speed})")
        v = wind_speed
        height = 0.015 * v**2 + 1.5
        period = -0.001 * v**3 + 0.042 * v**2 + 5.6
        return cls(height, period, wavelength_of(period, wavelength), direction)

    @classmethod
    def from_sea_state(cls, code: int, direction: float,
                       wavelength: str = "dispersion") -> WaveField:
        """Waves of WMO sea state `code`: the middle of its height band.

        Eq. 5 gives h_w >= 1.5 m at any wind (sea state 4 or more), so the
        height comes from the WMO table; the period and wavelength come from
        eq. 5 at the wind that raises such a sea (Pierson-Moskowitz,
        H_s = 0.21 U^2 / g).
        """
        if code not in SEA_STATE_HEIGHTS:
            raise ValueError(f"waves: sea state must be 0..8 (got {code})")
        lo, hi = SEA_STATE_HEIGHTS[code]
        height = 0.5 * (lo + hi)
        wind = math.sqrt(GRAVITY * height / 0.21)
        from_eq5 = cls.from_wind(wind, direction, wavelength)
        return cls(height, from_eq5.period, from_eq5.wavelength, direction)


def wavelength_of(period: float, model: str = "dispersion") -> float:
    """Wavelength (m) of waves of `period` s: deep-water dispersion, or eq. 5's 0.54 T^2."""
    if model == "dispersion":
        return GRAVITY * period**2 / (2.0 * math.pi)
    if model == "paper":
        return 0.54 * period**2
    raise ValueError(
        f"waves: unknown wavelength model {model!r}; available: {', '.join(WAVELENGTH_MODELS)}")


@dataclass(frozen=True)
class Wind:
    """Wind of `speed` m/s blowing towards `direction` (rad)."""

    speed: float
    direction: float

    def __post_init__(self) -> None:
        if self.speed < 0.0:
            raise ValueError(f"wind: speed must be >= 0 (got {self.speed})")


@dataclass(frozen=True)
class Push:
    """A constant earth-frame force (N) on the hull inside a rectangle of the plane.

    For disturbances papers give as forces (paper 004 Table 7: 1 N of wind,
    15 N of waves in an area). Bounds default to the whole plane.
    """

    fx: float
    fy: float
    x_min: float = -math.inf
    x_max: float = math.inf
    y_min: float = -math.inf
    y_max: float = math.inf

    def __post_init__(self) -> None:
        if not (math.isfinite(self.fx) and math.isfinite(self.fy)):
            raise ValueError(f"push: force must be finite (got {self.fx}, {self.fy})")
        if not (self.x_min < self.x_max and self.y_min < self.y_max):
            raise ValueError("push: need x_min < x_max and y_min < y_max")

    def at(self, x: float, y: float) -> tuple[float, float]:
        inside = self.x_min <= x <= self.x_max and self.y_min <= y <= self.y_max
        return (self.fx, self.fy) if inside else (0.0, 0.0)


@dataclass(frozen=True)
class Environment:
    """What acts on the boat: a uniform current (earth-frame velocity), waves, wind and pushes."""

    current: tuple[float, float] = (0.0, 0.0)
    waves: WaveField | None = None
    wind: Wind | None = None
    pushes: tuple[Push, ...] = ()

    @classmethod
    def with_current(
        cls, speed: float, direction: float, waves: WaveField | None = None,
        wind: Wind | None = None,
    ) -> Environment:
        """A current of `speed` m/s flowing towards `direction` (rad)."""
        if speed < 0.0:
            raise ValueError(f"current: speed must be >= 0 (got {speed})")
        return cls((speed * math.cos(direction), speed * math.sin(direction)), waves, wind)

    @classmethod
    def from_scenario(cls, environment: Any, waves: WaveField | None = None) -> Environment:
        """From a scenario's `environment` block (current and wind; directions in degrees).

        Waves are not in the scenario file; pass them explicitly (eq. 5 would
        make 1.5 m waves from any wind, which is rarely what a scenario means).
        """
        wind = None
        if environment.wind_speed > 0.0:
            wind = Wind(environment.wind_speed, math.radians(environment.wind_dir_deg))
        # the water's own current: an apparent current planned for a moving ramp frame has
        # that frame's velocity folded in (scenario Environment.frame_vx, frame_vy)
        c = math.radians(environment.current_dir_deg)
        cx = environment.current_speed * math.cos(c) + getattr(environment, "frame_vx", 0.0)
        cy = environment.current_speed * math.sin(c) + getattr(environment, "frame_vy", 0.0)
        speed = math.hypot(cx, cy)
        return cls.with_current(speed, math.atan2(cy, cx) if speed > 0.0 else c, waves, wind)

    @property
    def calm(self) -> bool:
        return (self.current == (0.0, 0.0) and self.waves is None and self.wind is None
                and not self.pushes)

    def push_body(self, x: float, y: float, psi: float) -> tuple[float, float]:
        """Sum of the pushes at (x, y) in the body frame (N, surge and sway)."""
        fx = fy = 0.0
        for p in self.pushes:
            px, py = p.at(x, y)
            fx, fy = fx + px, fy + py
        c, s = math.cos(psi), math.sin(psi)
        return c * fx + s * fy, -s * fx + c * fy

    def current_body(self, psi: float) -> tuple[float, float]:
        """Current velocity (u_c, v_c) in the body frame at heading psi."""
        cx, cy = self.current
        c, s = math.cos(psi), math.sin(psi)
        return c * cx + s * cy, -s * cx + c * cy

    def forces(self, params: VesselParams, psi: float, u: float, v: float) -> np.ndarray:
        """Wave drift plus wind force [X, Y, N] at heading psi, body-axis ground velocity u, v."""
        tau = np.zeros(3)
        if self.waves is not None:
            tau += wave_drift_force(params, self.waves, psi)
        if self.wind is not None:
            tau += wind_force(params, self.wind, psi, u, v)
        return tau


def drift_coefficients(ratio: float) -> tuple[float, float, float]:
    """Daidola's wave drift coefficients W_x, W_y, W_n at wavelength / length `ratio` (eq. 4).

    The cubics within [0, MAX_FIT_RATIO]; beyond, their value there times
    (MAX_FIT_RATIO / ratio)^2 (long waves carry the hull, drift vanishes).
    """
    q = min(max(ratio, 0.0), MAX_FIT_RATIO)
    wx = 0.05 - 0.2 * q + 0.75 * q**2 - 0.51 * q**3
    wy = 0.46 + 6.83 * q - 15.65 * q**2 + 8.44 * q**3
    wn = -0.11 + 0.68 * q - 0.79 * q**2 + 0.21 * q**3
    if ratio > MAX_FIT_RATIO:
        k = (MAX_FIT_RATIO / ratio) ** 2
        wx, wy, wn = k * wx, k * wy, k * wn
    return wx, wy, wn


def wave_drift_force(params: VesselParams, waves: WaveField, psi: float) -> np.ndarray:
    """Mean second-order wave drift force [X, Y, N] (paper 000 eq. 3-4).

    F = 1/2 rho g L xi^2 W(lambda / L): eq. 3 as printed has no g, which is
    not a force (kg/s^2); Daidola's form carries rho g (Fossen 2021 sec.
    10.2). chi is the encounter angle, the waves' direction of travel
    relative to the bow (0: following seas). The yaw moment carries L^2
    (eq. 3 prints L, which is not a moment).
    """
    chi = waves.direction - psi
    amplitude = 0.5 * waves.height
    wx, wy, wn = drift_coefficients(waves.wavelength / params.length)
    q = 0.5 * RHO_WATER * GRAVITY * params.length * amplitude**2
    return np.array([
        q * math.cos(chi) * wx,
        q * math.sin(chi) * wy,
        q * params.length * math.sin(chi) * wn,
    ])


def wind_force(params: VesselParams, wind: Wind, psi: float, u: float, v: float) -> np.ndarray:
    """Wind force [X, Y, N] from the relative wind (paper 002 eq. 24).

    Coefficients C_x = -c_x cos(g), C_y = -c_y sin(g), C_N = -c_n sin(2g),
    with g the angle the relative wind comes from (0: from ahead, pi/2: from
    port), after Fossen (2021) sec. 10.1.
    """
    c, s = math.cos(psi), math.sin(psi)
    wx, wy = wind.speed * math.cos(wind.direction), wind.speed * math.sin(wind.direction)
    # Air velocity relative to the hull, body frame.
    ax = c * wx + s * wy - u
    ay = -s * wx + c * wy - v
    speed2 = ax * ax + ay * ay
    if speed2 == 0.0:
        return np.zeros(3)
    gamma = math.atan2(-ay, -ax)
    cx, cy, cn = params.wind_coefficients
    q = 0.5 * RHO_AIR * speed2
    return np.array([
        -q * cx * math.cos(gamma) * params.frontal_area_air,
        -q * cy * math.sin(gamma) * params.lateral_area_air,
        -q * cn * math.sin(2.0 * gamma) * params.lateral_area_air * params.length,
    ])


def current_force(params: VesselParams, speed: float, encounter: float) -> np.ndarray:
    """Force [X, Y, N] of a current on a hull at rest (paper 000 eq. 2, paper 002 eq. 25).

    `encounter` is the direction the current flows to relative to the bow
    (0: from astern). Coefficients C_x = c_x cos, C_y = c_y sin,
    C_n = c_n sin(2 beta) (estimates); areas are the submerged projections.
    """
    cx, cy, cn = params.current_coefficients
    q = 0.5 * RHO_WATER * speed**2
    return np.array([
        q * params.frontal_area_water * cx * math.cos(encounter),
        q * params.lateral_area_water * cy * math.sin(encounter),
        q * params.lateral_area_water * params.length * cn * math.sin(2.0 * encounter),
    ])
