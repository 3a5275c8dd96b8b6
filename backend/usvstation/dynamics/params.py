"""Vessel parameters of the 3-DOF (surge, sway, yaw) manoeuvring model, and two presets.

Body frame: x forward, y to port (left), z up, yaw rate anticlockwise, matching
the ramp frame (x out to sea, y left, heading anticlockwise from +x). The
equations are Fossen's (Handbook of Marine Craft Hydrodynamics and Motion
Control, 2nd ed., 2021, ch. 6 and 10):

    M nu_r' + C_RB(nu_r) nu_r + D(nu_r) nu_r = tau + tau_env

with nu_r the velocity relative to the water. The added-mass Coriolis matrix is
left out (Fossen's Otter model drops its Munk moment; dropping the whole
matrix keeps the model passive, nu^T C nu = 0).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

RHO_WATER = 1025.0  # kg/m^3, sea water
RHO_AIR = 1.225  # kg/m^3
GRAVITY = 9.81  # m/s^2

# Hoerner's 2-D cross-flow drag coefficient against B / (2T) (Hoerner 1965, as
# digitised in Fossen's Python Vehicle Simulator, gnc.Hoerner).
_HOERNER_B2T = np.array([
    0.0109, 0.1766, 0.3530, 0.4519, 0.4728, 0.4929, 0.4933, 0.5585, 0.6464, 0.8336,
    0.9880, 1.3081, 1.6392, 1.8600, 2.3129, 2.6000, 3.0088, 3.4508, 3.7379, 4.0031,
])
_HOERNER_CD = np.array([
    1.9661, 1.9657, 1.8976, 1.7872, 1.5837, 1.2786, 1.2108, 1.0836, 0.9986, 0.8796,
    0.8284, 0.7599, 0.6914, 0.6571, 0.6307, 0.5962, 0.5868, 0.5859, 0.5599, 0.5593,
])


def hoerner_cd(beam: float, draft: float) -> float:
    """2-D cross-flow drag coefficient of a hull section (Hoerner's curve)."""
    return float(np.interp(beam / (2.0 * draft), _HOERNER_B2T, _HOERNER_CD))


@dataclass(frozen=True)
class Thrusters:
    """Two fixed propellers at y = +/-lever_arm, thrust k n|n| with shaft-speed lag."""

    lever_arm: float  # m, |y| of each propeller
    k_forward: float  # N s^2 (thrust = k n^2 for n > 0)
    k_reverse: float  # N s^2 (thrust = -k n^2 for n < 0)
    n_max: float  # rad/s
    n_min: float  # rad/s (negative)
    time_constant: float  # s, first-order shaft-speed lag

    @property
    def thrust_max(self) -> float:
        """Largest forward thrust of one propeller (N)."""
        return self.k_forward * self.n_max**2

    @property
    def thrust_min(self) -> float:
        """Largest reverse thrust of one propeller, as a negative number (N)."""
        return -self.k_reverse * self.n_min**2

    def thrust(self, n: float) -> float:
        """Thrust (N) of one propeller at shaft speed n (rad/s), saturated."""
        n = min(max(n, self.n_min), self.n_max)
        return self.k_forward * n * n if n >= 0.0 else -self.k_reverse * n * n

    def shaft_speed_for(self, thrust: float) -> float:
        """Shaft speed (rad/s) giving `thrust` (N), saturated to the shaft-speed range."""
        if thrust >= 0.0:
            return min(math.sqrt(thrust / self.k_forward), self.n_max)
        return max(-math.sqrt(-thrust / self.k_reverse), self.n_min)


@dataclass(frozen=True)
class VesselParams:
    """Everything the 3-DOF model, the disturbance models and the controllers need."""

    name: str
    length: float  # m, L (also L_OA of paper 002 eq. 24)
    beam: float  # m
    mass: float  # kg, rigid body incl. payload
    x_g: float  # m, centre of gravity ahead of the body origin
    inertia_z: float  # kg m^2, rigid-body yaw inertia about the origin
    added_mass: tuple[float, float, float]  # -X_udot, -Y_vdot, -N_rdot (>= 0)
    linear_damping: tuple[float, float, float]  # -X_u, -Y_v, -N_r (>= 0)
    quadratic_damping: tuple[float, float, float]  # |u|u, |v|v, |r|r coefficients (>= 0)
    draft: float  # m
    crossflow_beam: float  # m, beam used for the strip cross-flow drag (0: none)
    thrusters: Thrusters
    top_speed: float  # m/s, published or computed calm-water top speed
    frontal_area_air: float  # m^2, A_Fw (wind, eq. 24)
    lateral_area_air: float  # m^2, A_Lw
    frontal_area_water: float  # m^2, A_Fc (current, eq. 2 / paper 002 eq. 25)
    lateral_area_water: float  # m^2, A_Lc
    wind_coefficients: tuple[float, float, float] = (0.7, 0.8, 0.05)  # c_x, c_y, c_n
    current_coefficients: tuple[float, float, float] = (0.1, 1.0, 0.05)  # c_x, c_y, c_n
    crossflow_scale: float = 1.0  # multiplies the strip cross-flow drag (HullMismatch)
    sources: dict[str, str] = field(default_factory=dict, compare=False)
    _cache: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        for name in ("length", "beam", "mass", "inertia_z", "draft", "top_speed"):
            if not getattr(self, name) > 0.0:
                raise ValueError(f"vessel {self.name}: {name} must be > 0")
        if min(self.added_mass + self.linear_damping + self.quadratic_damping) < 0.0:
            raise ValueError(f"vessel {self.name}: added mass and damping must be >= 0")
        m, xg = self.mass, self.x_g
        a11, a22, a66 = self.added_mass
        mass_matrix = np.array([
            [m + a11, 0.0, 0.0],
            [0.0, m + a22, m * xg],
            [0.0, m * xg, self.inertia_z + a66],
        ])
        self._cache["M"] = mass_matrix
        self._cache["Minv"] = np.linalg.inv(mass_matrix)
        n = 20
        dx = self.length / n
        x = -self.length / 2.0 + (np.arange(n) + 0.5) * dx
        cd = hoerner_cd(self.crossflow_beam, self.draft) if self.crossflow_beam > 0 else 0.0
        self._cache["strip_x"] = x
        self._cache["strip_k"] = 0.5 * RHO_WATER * self.draft * cd * dx * self.crossflow_scale

    @property
    def mass_matrix(self) -> np.ndarray:
        """M = M_RB + M_A (3x3, symmetric positive definite)."""
        return self._cache["M"].copy()

    @property
    def mass_matrix_inv(self) -> np.ndarray:
        return self._cache["Minv"]

    def coriolis(self, u: float, v: float, r: float) -> np.ndarray:
        """C_RB(nu) nu in the linear-velocity-independent form (Fossen 2021, eq. 6.43).

        C_RB = [[0, -m r, -m x_g r], [m r, 0, 0], [m x_g r, 0, 0]] is
        skew-symmetric, so it does no work.
        """
        m, xg = self.mass, self.x_g
        return np.array([-m * r * v - m * xg * r * r, m * r * u, m * xg * r * u])

    def damping(self, u: float, v: float, r: float) -> np.ndarray:
        """D(nu_r) nu_r: linear + quadratic damping and strip-theory cross-flow drag.

        Every term opposes its velocity, so nu_r . D(nu_r) nu_r >= 0.
        """
        dl, dq = self.linear_damping, self.quadratic_damping
        x = self._cache["strip_x"]
        local = v + x * r
        drag = self._cache["strip_k"] * np.abs(local) * local
        return np.array([
            dl[0] * u + dq[0] * abs(u) * u,
            dl[1] * v + dq[1] * abs(v) * v + float(drag.sum()),
            dl[2] * r + dq[2] * abs(r) * r + float((x * drag).sum()),
        ])

    def surge_drag(self, u: float) -> float:
        """Surge resistance (N) at steady surge speed u through the water, no sway or yaw."""
        d, q = self.linear_damping[0], self.quadratic_damping[0]
        return d * u + q * abs(u) * u

    def sway_drift_speed(self, force: float) -> float:
        """Steady sway speed through the water (m/s) under a side force (N), no yaw rate."""
        table = self._cache.get("sway_table")
        if table is None:
            vs = np.linspace(-4.0, 4.0, 801)
            fs = np.array([self.damping(0.0, v, 0.0)[1] for v in vs])
            table = self._cache["sway_table"] = (fs, vs)
        fs, vs = table
        return float(np.interp(force, fs, vs))

    def calm_water_top_speed(self) -> float:
        """Speed where full thrust on both propellers balances surge drag (N/m/s units)."""
        full = 2.0 * self.thrusters.thrust_max
        d, q = self.linear_damping[0], self.quadratic_damping[0]
        if q == 0.0:
            return full / d
        return (-d + math.sqrt(d * d + 4.0 * q * full)) / (2.0 * q)


@dataclass(frozen=True)
class HullMismatch:
    """How the real hull differs from the model its observer and controllers were tuned on.

    `drag_scale` multiplies every damping term (surge, sway and yaw, linear, quadratic and
    the cross-flow drag: a fouled hull, 1.25 = +25 %); `thrust_scale` multiplies both
    propellers' thrust at every shaft speed (0.85 = 15 % less: a worn or fouled
    propeller, a weak battery). `apply` gives the true hull; the boat keeps the nominal
    one in its controllers (sim/dynamic.py).
    """

    drag_scale: float = 1.0
    thrust_scale: float = 1.0

    def __post_init__(self) -> None:
        for name in ("drag_scale", "thrust_scale"):
            value = getattr(self, name)
            if not (math.isfinite(value) and 0.2 <= value <= 5.0):
                raise ValueError(f"hull mismatch: {name} must be within [0.2, 5] (got {value})")

    @property
    def nominal(self) -> bool:
        return self.drag_scale == 1.0 and self.thrust_scale == 1.0

    def apply(self, params: VesselParams) -> VesselParams:
        """The true hull: `params` with its damping and thrust scaled."""
        if self.nominal:
            return params
        from dataclasses import replace

        d, t = self.drag_scale, self.thrust_scale
        th = replace(params.thrusters, k_forward=params.thrusters.k_forward * t,
                     k_reverse=params.thrusters.k_reverse * t)
        true = replace(params, name=f"{params.name} (drag x{d:g}, thrust x{t:g})",
                       linear_damping=tuple(x * d for x in params.linear_damping),
                       quadratic_damping=tuple(x * d for x in params.quadratic_damping),
                       crossflow_scale=params.crossflow_scale * d, thrusters=th)
        return replace(true, top_speed=true.calm_water_top_speed())


def otter() -> VesselParams:
    """Maritime Robotics Otter USV (L = 2.0 m), reduced to 3-DOF.

    Data from Fossen (2021) and his Python Vehicle Simulator `otter.py`
    (hull 55 kg + 25 kg payload, radii of gyration, 'best practice' added
    mass, X_u from 6 knots at full bollard thrust, yaw time constant 1 s,
    extra |r|r yaw damping 10 x N_r, Hoerner cross-flow drag on one pontoon,
    propeller bollard constants and shaft-speed limits). Wind and submerged
    areas are estimates (see docs/tracking.md).
    """
    m_hull, m_payload = 55.0, 25.0
    m = m_hull + m_payload
    length, beam = 2.0, 1.08
    # CG of hull (0.2, 0, -0.2) corrected for a payload at (0, 0, -0.35).
    x_g = m_hull * 0.2 / m
    r66 = 0.25 * length
    # Fossen's Ig about the origin, then moved again by H(r_g) as in otter.py.
    ig_zz = m_hull * r66**2 + m_hull * x_g**2
    inertia_z = ig_zz + m * x_g**2
    b_pont, cb_pont = 0.25, 0.4
    nabla = m / RHO_WATER
    draft = nabla / (2.0 * cb_pont * b_pont * length)
    a66 = 1.7 * ig_zz
    m66 = inertia_z + a66
    u_max = 6 * 0.5144
    k_pos, k_neg = 0.02216 / 2, 0.01289 / 2
    thrusters = Thrusters(
        lever_arm=0.395,
        k_forward=k_pos,
        k_reverse=k_neg,
        n_max=math.sqrt(0.5 * 24.4 * GRAVITY / k_pos),
        n_min=-math.sqrt(0.5 * 13.6 * GRAVITY / k_neg),
        time_constant=1.0,
    )
    return VesselParams(
        name="otter",
        length=length,
        beam=beam,
        mass=m,
        x_g=x_g,
        inertia_z=inertia_z,
        added_mass=(0.1 * m_hull, 1.5 * m_hull, a66),
        linear_damping=(24.4 * GRAVITY / u_max, 0.0, m66 / 1.0),
        quadratic_damping=(0.0, 0.0, 10.0 * m66),
        draft=draft,
        crossflow_beam=b_pont,
        thrusters=thrusters,
        top_speed=u_max,
        frontal_area_air=0.35,
        lateral_area_air=0.65,
        frontal_area_water=2 * b_pont * draft,
        lateral_area_water=length * draft,
        sources={
            "hydrodynamics, mass, thrusters":
                "Fossen 2021 Handbook; PythonVehicleSimulator otter.py",
            "wind areas": "estimate (hull sides ~0.3 m above water)",
            "wind coefficients": "Fossen 2021 sec. 10.1 simple model, mid-range values",
            "current coefficients (eq. 2)": "estimate",
        },
    )


def trimaran() -> VesselParams:
    """The 6 m trimaran USV of paper 002 (Table I), with estimated twin propellers.

    Mass, inertia, added mass, linear and quadratic damping and the projected
    areas are Table I's. Paper 002 steers with a rudder; the propeller layout
    and thrust limits here are estimates.
    """
    n_max = 100.0
    thrust_max = 1500.0
    k_pos = thrust_max / n_max**2
    thrusters = Thrusters(
        lever_arm=1.0,
        k_forward=k_pos,
        k_reverse=0.55 * k_pos,
        n_max=n_max,
        n_min=-n_max,
        time_constant=1.0,
    )
    params = VesselParams(
        name="trimaran",
        length=6.0,
        beam=2.4,
        mass=446.281,
        x_g=0.0,
        inertia_z=27000.0,
        added_mass=(133.8843, 89.2562, 17399.0),
        linear_damping=(74.3802, 431.4050, 23802.0),
        quadratic_damping=(177.037, 814.459, 177.037),
        draft=1.9698 / (6.0 * 0.6),
        crossflow_beam=0.0,
        thrusters=thrusters,
        top_speed=1.0,
        frontal_area_air=2.0318,
        lateral_area_air=7.6067,
        frontal_area_water=0.3145,
        lateral_area_water=2.1900,
        sources={
            "mass, inertia, added mass, damping, areas": "paper 002 Table I",
            "propellers (layout, thrust, lag), beam, draft": "estimate",
        },
    )
    return _with_top_speed(params)


def _with_top_speed(params: VesselParams) -> VesselParams:
    from dataclasses import replace

    return replace(params, top_speed=params.calm_water_top_speed())


PRESETS = {"otter": otter, "trimaran": trimaran}


def vessel_preset(name: str) -> VesselParams:
    """A preset by name: 'otter' (default vessel) or 'trimaran'."""
    try:
        return PRESETS[name]()
    except KeyError:
        raise ValueError(
            f"vessel: unknown preset {name!r}; available: {', '.join(PRESETS)}"
        ) from None
