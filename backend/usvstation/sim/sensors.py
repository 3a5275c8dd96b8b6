"""Sensor models of the simulated boat (seeded, no I/O).

A simulated boat steers on what its sensors say, never on the truth (issue 23 item 3):
`BoatSensors` turns the simulator's true state into the boat's navigation solution
(a `guidance.Measurement`) through a named `SensorProfile`:

- GNSS: fixes at `rate_hz`, each `latency_s` old when it arrives, with white noise and a
  first-order Gauss-Markov bias (a slow random walk of stationary std `bias_std_m`,
  correlation time `bias_tau_s`) per axis, velocity noise (so COG and SOG are noisy too),
  and outages (Poisson, `dropout_per_min`, mean length `dropout_s`). Between fixes, and
  through an outage, the navigation solution dead-reckons from the latest fix with its
  velocity, as a receiver's navigation filter does.
- `relative` GNSS (moving-baseline RTK between the mother ship and the boat): the fix is
  the boat's position and velocity relative to the ramp, in the ramp frame, with its own
  (centimetre) noise; it does not depend on how well the ship knows where it is.
- compass: a constant bias, white noise and a first-order lag; gyro: bias and noise.

Profiles (`SENSOR_PROFILES`): `exact` (the truth, for protocol tests and comparisons),
`rtk` (0.02 m), `gnss` (1.5 m CEP, mostly a slow random walk), `rtk-moving-base`
(ramp-relative, 0.02 m). The GNSS CEP of a circular Gaussian error of std s per axis
is 1.1774 s.

Also: `GpsNoise` (the error the link benches add to a KinematicVehicle's fixes), a
`Battery` and `NavSensors` (white errors only, kept for the tracking bench).
"""

from __future__ import annotations

import math
from collections import deque
from dataclasses import dataclass, field, replace

import numpy as np

from usvstation.geometry import angle_diff, wrap_angle
from usvstation.guidance.observer import Measurement


@dataclass
class GpsNoise:
    """GPS position error: a first-order Gauss-Markov bias (slow wander, std `bias_std_m`,
    correlation time `tau_s`) plus white noise (`white_std_m`) per fix, in metres."""

    bias_std_m: float = 0.8
    tau_s: float = 60.0
    white_std_m: float = 0.4
    fix_type: int = 3
    satellites: int = 12
    hdop: float = 0.9
    seed: int = 0
    _rng: np.random.Generator = field(init=False, repr=False)
    _bias: np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self._rng = np.random.default_rng(self.seed)
        self._bias = self._rng.normal(0.0, self.bias_std_m, 2)

    def sample(self, dt: float) -> tuple[float, float]:
        """The position error (dx, dy) of a fix taken dt seconds after the previous one."""
        if self.tau_s > 0 and dt > 0:
            a = math.exp(-dt / self.tau_s)
            self._bias = a * self._bias + self._rng.normal(
                0.0, self.bias_std_m * math.sqrt(1 - a * a), 2)
        w = self._rng.normal(0.0, self.white_std_m, 2)
        return float(self._bias[0] + w[0]), float(self._bias[1] + w[1])


@dataclass
class Battery:
    """A 4S lithium pack: voltage falls linearly with the charge drawn by the thrusters."""

    full_v: float = 16.8
    empty_v: float = 13.2
    capacity_ah: float = 20.0
    idle_a: float = 0.5
    full_thrust_a: float = 30.0  # both thrusters at full
    used_ah: float = 0.0

    def step(self, dt: float, thrust_left: float, thrust_right: float) -> None:
        amps = self.idle_a + self.full_thrust_a * (abs(thrust_left) + abs(thrust_right)) / 2
        self.used_ah = min(self.capacity_ah, self.used_ah + amps * dt / 3600)

    @property
    def voltage(self) -> float:
        return self.full_v - (self.full_v - self.empty_v) * self.used_ah / self.capacity_ah


@dataclass
class NavSensors:
    """The boat's own navigation sensors as guidance sees them: white errors on the GNSS
    fix (`position_std_m` per axis), the GNSS velocity (`velocity_std_mps` per axis, so
    COG/SOG are noisy too) and the compass (`heading_std_rad`); the gyro is exact.
    Call it with a dynamics.VesselState to get a guidance.Measurement. Seeded, no I/O."""

    position_std_m: float = 0.05  # RTK-class fix
    velocity_std_mps: float = 0.05
    heading_std_rad: float = math.radians(0.5)
    seed: int = 0
    _rng: np.random.Generator = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self._rng = np.random.default_rng(self.seed)

    def __call__(self, state) -> Measurement:
        ex, ey = self._rng.normal(0.0, self.position_std_m, 2)
        nvx, nvy = self._rng.normal(0.0, self.velocity_std_mps, 2)
        vx, vy = state.velocity
        vx, vy = vx + nvx, vy + nvy
        sog = math.hypot(vx, vy)
        cog = math.atan2(vy, vx) if sog > 1e-9 else state.psi
        psi = state.psi + float(self._rng.normal(0.0, self.heading_std_rad))
        return Measurement(state.x + ex, state.y + ey, psi, sog, cog, state.r, state.t)


# ---------------------------------------------------------------- sensor profiles (issue 23)

CEP_PER_SIGMA = math.sqrt(2.0 * math.log(2.0))  # CEP of a circular Gaussian / its axis std


@dataclass(frozen=True)
class GnssSpec:
    """A GNSS receiver (or, `relative`, a moving-baseline RTK pair); metres, seconds."""

    white_std_m: float = 0.0  # per axis, independent per fix
    bias_std_m: float = 0.0  # per axis, stationary std of the Gauss-Markov wander
    bias_tau_s: float = 120.0  # its correlation time
    velocity_std_mps: float = 0.0  # per axis
    rate_hz: float = 0.0  # fixes per second; 0: a fix at every call (exact)
    latency_s: float = 0.0  # age of a fix when it arrives
    dropout_per_min: float = 0.0  # mean outages per minute
    dropout_s: float = 0.0  # mean outage length
    relative: bool = False  # position and velocity relative to the ramp (ramp frame)
    fix_type: int = 3  # GPS_FIX_TYPE reported: 3 3D, 6 RTK fixed
    satellites: int = 12
    hdop: float = 0.9

    def __post_init__(self) -> None:
        for name in ("white_std_m", "bias_std_m", "velocity_std_mps", "rate_hz",
                     "latency_s", "dropout_per_min", "dropout_s"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value >= 0.0):
                raise ValueError(f"gnss: {name} must be finite and >= 0 (got {value})")
        if not self.bias_tau_s > 0.0:
            raise ValueError(f"gnss: bias_tau_s must be > 0 (got {self.bias_tau_s})")

    @property
    def cep_m(self) -> float:
        """Circular error probable of the position (m), white and bias together."""
        return CEP_PER_SIGMA * math.hypot(self.white_std_m, self.bias_std_m)


@dataclass(frozen=True)
class CompassSpec:
    """The heading sensor: a constant bias, white noise, a first-order lag."""

    bias_deg: float = 0.0
    noise_deg: float = 0.0
    lag_s: float = 0.0

    def __post_init__(self) -> None:
        if not (math.isfinite(self.bias_deg) and abs(self.bias_deg) <= 45.0):
            raise ValueError(f"compass: bias_deg must be within [-45, 45] (got {self.bias_deg})")
        for name in ("noise_deg", "lag_s"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value >= 0.0):
                raise ValueError(f"compass: {name} must be finite and >= 0 (got {value})")


@dataclass(frozen=True)
class GyroSpec:
    """The yaw-rate sensor: a constant bias and white noise (deg/s)."""

    bias_deg_s: float = 0.0
    noise_deg_s: float = 0.0

    def __post_init__(self) -> None:
        if not (math.isfinite(self.bias_deg_s) and math.isfinite(self.noise_deg_s)
                and self.noise_deg_s >= 0.0):
            raise ValueError("gyro: bias_deg_s and noise_deg_s must be finite, noise >= 0")


@dataclass(frozen=True)
class SensorProfile:
    """What a simulated boat knows about itself: GNSS, compass and gyro (speed and course
    over ground come from the GNSS velocity)."""

    name: str
    gnss: GnssSpec = GnssSpec()
    compass: CompassSpec = CompassSpec()
    gyro: GyroSpec = GyroSpec()

    def with_compass_bias(self, bias_deg: float) -> SensorProfile:
        """The same profile with a compass that reads `bias_deg` too high (anticlockwise)."""
        return replace(self, compass=replace(self.compass, bias_deg=bias_deg))


_COMPASS = CompassSpec(noise_deg=0.5, lag_s=0.2)
_GYRO = GyroSpec(bias_deg_s=0.05, noise_deg_s=0.1)

SENSOR_PROFILES: dict[str, SensorProfile] = {
    "exact": SensorProfile("exact", GnssSpec(fix_type=6)),  # the truth: as good as RTK
    # RTK fixed on the boat: 0.02 m per axis, 10 Hz, 50 ms old.
    "rtk": SensorProfile("rtk", GnssSpec(
        white_std_m=0.02, bias_std_m=0.005, bias_tau_s=300.0, velocity_std_mps=0.03,
        rate_hz=10.0, latency_s=0.05, dropout_per_min=0.1, dropout_s=1.0, fix_type=6,
        satellites=16, hdop=0.7), _COMPASS, _GYRO),
    # Plain GNSS: 1.5 m CEP, most of it a slow random walk (std 1.2 m, 120 s), 5 Hz.
    "gnss": SensorProfile("gnss", GnssSpec(
        white_std_m=0.4, bias_std_m=1.2, bias_tau_s=120.0, velocity_std_mps=0.1,
        rate_hz=5.0, latency_s=0.1, dropout_per_min=0.2, dropout_s=2.0, fix_type=3,
        satellites=10, hdop=1.2), _COMPASS, _GYRO),
    # Moving-baseline RTK between the mother ship and the boat: the boat's position and
    # velocity relative to the ramp, centimetre noise, whatever the ship's own error.
    "rtk-moving-base": SensorProfile("rtk-moving-base", GnssSpec(
        white_std_m=0.02, bias_std_m=0.005, bias_tau_s=300.0, velocity_std_mps=0.03,
        rate_hz=10.0, latency_s=0.05, dropout_per_min=0.1, dropout_s=1.0, relative=True,
        fix_type=6, satellites=16, hdop=0.7), _COMPASS, _GYRO),
}


def sensor_profile(profile: str | SensorProfile) -> SensorProfile:
    """A profile by name (or the profile itself); ValueError naming the known ones."""
    if isinstance(profile, SensorProfile):
        return profile
    try:
        return SENSOR_PROFILES[profile]
    except KeyError:
        raise ValueError(f"sensors: unknown profile {profile!r}; available: "
                         f"{', '.join(SENSOR_PROFILES)}") from None


@dataclass(frozen=True)
class _Fix:
    t: float  # when it was taken
    arrives: float
    x: float
    y: float
    vx: float
    vy: float


class BoatSensors:
    """The boat's navigation solution from the true state through a `SensorProfile`.

    `measure(truth, t, ramp)` takes the true state (anything with x, y, psi, r and a
    `velocity` over ground, e.g. a dynamics.VesselState, in the world frame) at time t and,
    for a `relative` GNSS, the true ramp frame at t (sim.frame.RampMotion; None: the
    world frame). It returns a `Measurement`: in the world frame for an absolute GNSS, in
    the ramp frame for a relative one (`relative` says which). Call it once per control
    step with increasing t; everything it draws comes from `seed`, so the same calls give
    the same measurements.
    """

    def __init__(self, profile: str | SensorProfile = "exact", seed: int = 0) -> None:
        self.profile = sensor_profile(profile)
        self.seed = seed
        self._rng = np.random.default_rng([seed, 23])
        g = self.profile.gnss
        self._bias = self._rng.normal(0.0, g.bias_std_m, 2) if g.bias_std_m > 0 else np.zeros(2)
        self._fixes: deque[_Fix] = deque()
        self._latest: _Fix | None = None
        self._next_fix = -math.inf
        self._outage_until = -math.inf
        self._heading: float | None = None  # the compass's lagged reading (without bias)
        self._last_t: float | None = None

    @property
    def relative(self) -> bool:
        return self.profile.gnss.relative

    @property
    def fix_ok(self) -> bool:
        """False during a GNSS outage (the solution is dead-reckoned)."""
        return self._last_t is None or self._last_t >= self._outage_until

    @property
    def fix_age(self) -> float:
        """Seconds since the latest fix used was taken (latency plus any outage)."""
        if self._latest is None or self._last_t is None:
            return 0.0
        return self._last_t - self._latest.t

    def measure(self, truth, t: float, ramp=None) -> Measurement:
        dt = 0.0 if self._last_t is None else max(t - self._last_t, 0.0)
        self._last_t = t
        g = self.profile.gnss
        tx, ty = truth.x, truth.y
        tvx, tvy = truth.velocity
        if g.relative and ramp is not None:  # the truth as seen from the ramp
            m = ramp.measure(Measurement(tx, ty, truth.psi, math.hypot(tvx, tvy),
                                         math.atan2(tvy, tvx), truth.r, t))
            tx, ty = m.x, m.y
            tvx, tvy = m.velocity
            psi_true, r_true = m.psi, m.r
        else:
            psi_true, r_true = truth.psi, truth.r
        self._gnss(t, dt, tx, ty, tvx, tvy)
        f = self._latest
        assert f is not None
        age = t - f.t
        x, y = f.x + f.vx * age, f.y + f.vy * age
        sog = math.hypot(f.vx, f.vy)
        psi = self._compass(psi_true, dt)
        cog = math.atan2(f.vy, f.vx) if sog > 1e-9 else psi
        gy = self.profile.gyro
        r = r_true + math.radians(gy.bias_deg_s)
        if gy.noise_deg_s > 0:
            r += float(self._rng.normal(0.0, math.radians(gy.noise_deg_s)))
        return Measurement(x, y, psi, sog, cog, r, t)

    def _gnss(self, t: float, dt: float, x: float, y: float, vx: float, vy: float) -> None:
        g = self.profile.gnss
        rng = self._rng
        if g.bias_std_m > 0 and dt > 0:
            a = math.exp(-dt / g.bias_tau_s)
            self._bias = a * self._bias + rng.normal(0.0, g.bias_std_m * math.sqrt(1 - a * a), 2)
        if g.dropout_per_min > 0 and dt > 0 and t >= self._outage_until and \
                rng.random() < 1.0 - math.exp(-g.dropout_per_min / 60.0 * dt):
            self._outage_until = t + float(rng.exponential(g.dropout_s)) if g.dropout_s else t
        if t >= self._next_fix and (t >= self._outage_until or self._latest is None):
            ex, ey = (rng.normal(0.0, g.white_std_m, 2) if g.white_std_m > 0 else (0.0, 0.0))
            ev = rng.normal(0.0, g.velocity_std_mps, 2) if g.velocity_std_mps > 0 \
                else (0.0, 0.0)
            fix = _Fix(t, t + g.latency_s, float(x + self._bias[0] + ex),
                       float(y + self._bias[1] + ey), float(vx + ev[0]), float(vy + ev[1]))
            self._fixes.append(fix)
            if self._latest is None:  # the first fix is there at once
                self._latest = fix
            self._next_fix = t + 1.0 / g.rate_hz if g.rate_hz > 0 else t
        while self._fixes and self._fixes[0].arrives <= t + 1e-12:
            self._latest = self._fixes.popleft()

    def _compass(self, psi: float, dt: float) -> float:
        c = self.profile.compass
        if self._heading is None or c.lag_s <= 0.0:
            self._heading = psi
        else:
            self._heading = wrap_angle(self._heading + (1.0 - math.exp(-dt / c.lag_s))
                                       * angle_diff(psi, self._heading))
        reading = self._heading + math.radians(c.bias_deg)
        if c.noise_deg > 0:
            reading += float(self._rng.normal(0.0, math.radians(c.noise_deg)))
        return float(wrap_angle(reading))
