"""COLREGs risk and encounter classification of paper 001 (pure, NumPy), with the digest's fixes.

Frame: ENU metres with compass angles (course clockwise from north,
velocity U (sin chi, cos chi)). The station's ramp frame is right-handed
too, so its x/y can be used as E/N directly; a ramp-frame heading h (CCW
from +x) is the compass course 90 - h.

- `cpa`: DCPA/TCPA in vector form. FIX of [001 eq. 10-11]: the printed
  angle convention makes TCPA negative for an approaching target and
  arctan loses the quadrant.
- `fuzzy_risk`: [001 eq. 12-14]. FIXes: the middle branch of eq. 12 uses
  DCPA - (l1 + l2)/2; the last branch of eq. 13 mirrors the first
  (0.2, not 0.4); t1 and t2 use sqrt(max(., 0)). `paper=True` keeps the
  literal eq. 13 and the |TCPA| branch for opening targets; the default
  (station) mode also sets the risk to 0 once a target is past CPA.
- `classify`: the (alpha, beta) sectors of DNV trafficgen (Rules 13-15),
  mapped to 001's areas A-G; `EncounterLatch` keeps the class found when the
  risk first appears (a head-on at 8 m offset reads "no risk" at 40 m).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from enum import StrEnum

import numpy as np

from usvstation.geometry import angle_diff
from usvstation.geometry import wrap_180 as wrap180
from usvstation.geometry import wrap_deg as wrap360

EPS = 1e-9


class Encounter(StrEnum):
    HEAD_ON = "head-on"
    CROSSING_GIVE_WAY = "crossing-give-way"
    CROSSING_STAND_ON = "crossing-stand-on"
    OVERTAKING_GIVE_WAY = "overtaking-give-way"
    OVERTAKING_STAND_ON = "overtaking-stand-on"
    NO_RISK = "no-risk"


GIVE_WAY_STARBOARD = (Encounter.HEAD_ON, Encounter.CROSSING_GIVE_WAY)


def velocity(course_deg: float, speed: float) -> np.ndarray:
    """ENU velocity of a compass course (deg) and speed (m/s)."""
    c = math.radians(course_deg)
    return np.array([speed * math.sin(c), speed * math.cos(c)])


def bearing_deg(frm: np.ndarray, to: np.ndarray) -> float:
    """Compass bearing from `frm` to `to` (ENU)."""
    return wrap360(math.degrees(math.atan2(to[0] - frm[0], to[1] - frm[1])))


def cpa(p_own: np.ndarray, v_own: np.ndarray, p_t: np.ndarray, v_t: np.ndarray
        ) -> tuple[float, float]:
    """(DCPA m, TCPA s): TCPA = -(p.w)/|w|^2, DCPA = |p x w|/|w| (digest 2.3, fixing eq. 10-11)."""
    p = np.asarray(p_t, float) - np.asarray(p_own, float)
    w = np.asarray(v_t, float) - np.asarray(v_own, float)
    ww = float(w @ w)
    if ww < EPS:
        return float(math.hypot(*p)), 0.0
    return abs(float(p[0] * w[1] - p[1] * w[0])) / math.sqrt(ww), -float(p @ w) / ww


def cpa_batch(p: np.ndarray, w: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Vectorised `cpa` over relative positions p and velocities w of shape (..., 2)."""
    ww = (w * w).sum(-1)
    small = ww < EPS
    safe = np.where(small, 1.0, ww)
    tcpa = np.where(small, 0.0, -(p * w).sum(-1) / safe)
    dcpa = np.where(small, np.hypot(p[..., 0], p[..., 1]),
                    np.abs(p[..., 0] * w[..., 1] - p[..., 1] * w[..., 0]) / np.sqrt(safe))
    return dcpa, tcpa


def ship_domain(gamma_deg: float, paper: bool = False) -> float:
    """rho(gamma) of [001 eq. 13], gamma the relative bearing of the target (deg)."""
    g = wrap360(gamma_deg)
    if g == 0.0:
        g = 360.0
    if g <= 112.5:
        return 1.1 - 0.2 * g / 180.0
    if g <= 180.0:
        return 1.0 - 0.4 * g / 180.0
    if g <= 247.5:
        return 1.0 - 0.4 * (360.0 - g) / 180.0
    return 1.1 - (0.4 if paper else 0.2) * (360.0 - g) / 180.0


@dataclass(frozen=True)
class Risk:
    l1: float
    l2: float
    t1: float
    t2: float
    u_d: float
    u_t: float
    u: float
    dcpa: float
    tcpa: float


def fuzzy_risk(dcpa: float, tcpa: float, v_rel: float, beta_deg: float, scale_m: float = 20.0,
               l2_factor: float = 2.0, paper: bool = False, opening: bool = False) -> Risk:
    """Collision risk u of [001 eq. 12-14] with l1 = 1.5 rho L_d and l2 = l2_factor l1.

    `opening`: range increasing; in station mode a target past CPA and
    opening has u = 0 (the paper keeps the |TCPA| branch).
    """
    l1 = 1.5 * ship_domain(beta_deg, paper) * scale_m
    l2 = l2_factor * l1
    d = abs(dcpa)
    if d < l1:
        u_d = 1.0
    elif d <= l2:
        u_d = 0.5 - 0.5 * math.sin(math.pi / (l2 - l1) * (d - (l1 + l2) / 2.0))
    else:
        u_d = 0.0
    vr = max(v_rel, EPS)
    t1 = math.sqrt(max(l1 * l1 - d * d, 0.0)) / vr
    t2 = math.sqrt(max(l2 * l2 - d * d, 0.0)) / vr
    tt = abs(tcpa)
    if t2 <= t1:
        u_t = 0.0
    elif tt <= t1:
        u_t = 1.0
    elif tt <= t2:
        u_t = ((t2 - tt) / (t2 - t1)) ** 2
    else:
        u_t = 0.0
    u = 0.0 if u_d == 0.0 or u_t == 0.0 else max(u_d, u_t)
    if not paper and tcpa < 0.0 and opening:
        u = 0.0
    return Risk(l1, l2, t1, t2, u_d, u_t, u, dcpa, tcpa)


def relative_angles(p_own: np.ndarray, course_own: float, p_t: np.ndarray, course_t: float
                    ) -> tuple[float, float]:
    """(beta in [0, 360), alpha in (-180, 180]): target seen from own, own seen from target."""
    beta = wrap360(bearing_deg(p_own, p_t) - course_own)
    alpha = wrap180(bearing_deg(p_t, p_own) - course_t)
    return beta, alpha


def classify(beta_deg: float, alpha_deg: float, headon_deg: float = 5.0,
             overtake_deg: float = 67.5) -> Encounter:
    """Encounter class from (alpha, beta), trafficgen's sectors (digest 2.6)."""
    b360, b180 = wrap360(beta_deg), wrap180(beta_deg)
    a360, a180 = wrap360(alpha_deg), wrap180(alpha_deg)
    if 112.5 < b360 < 247.5 and abs(a180) <= overtake_deg:
        return Encounter.OVERTAKING_STAND_ON
    if 112.5 < a360 < 247.5 and abs(b180) <= overtake_deg:
        return Encounter.OVERTAKING_GIVE_WAY
    if abs(b180) <= headon_deg and abs(a180) <= headon_deg:
        return Encounter.HEAD_ON
    if 0.0 < b180 < 112.5 and -112.5 < a180 <= headon_deg:
        return Encounter.CROSSING_GIVE_WAY
    if 0.0 < a180 < 112.5 and -112.5 < b180 <= headon_deg:
        return Encounter.CROSSING_STAND_ON
    return Encounter.NO_RISK


def area(encounter: Encounter, beta_deg: float) -> str:
    """001's area letter A-G (digest 2.6; split of A/B at 67.5 deg and E/F at 292.5 deg)."""
    b = wrap360(beta_deg)
    return {
        Encounter.HEAD_ON: "G",
        Encounter.CROSSING_GIVE_WAY: "A" if b < 67.5 else "B",
        Encounter.CROSSING_STAND_ON: "E" if b > 292.5 else "F",
        Encounter.OVERTAKING_STAND_ON: "C" if b <= 180.0 else "D",
        Encounter.OVERTAKING_GIVE_WAY: "-",
        Encounter.NO_RISK: "-",
    }[encounter]


@dataclass
class EncounterLatch:
    """Encounter class per target, fixed when the risk first exceeds zero (digest 2.3)."""

    headon_deg: float = 12.0
    classes: dict[int, Encounter] = field(default_factory=dict)

    def update(self, target: int, risk: float, beta_deg: float, alpha_deg: float
               ) -> Encounter | None:
        if target not in self.classes and risk > 0.0:
            c = classify(beta_deg, alpha_deg, self.headon_deg)
            if c is Encounter.NO_RISK:  # risk without a sector: the nearest rule by bearing
                c = (Encounter.CROSSING_GIVE_WAY if 0.0 < wrap180(beta_deg) < 112.5
                     else Encounter.CROSSING_STAND_ON if -112.5 < wrap180(beta_deg) <= 0.0
                     else Encounter.OVERTAKING_STAND_ON)
            self.classes[target] = c
        return self.classes.get(target)


def course_from_ramp_heading(heading_rad: float) -> float:
    """Compass course (deg) of a ramp-frame heading (rad, CCW from +x)."""
    return wrap360(90.0 - math.degrees(heading_rad))


@dataclass(frozen=True)
class TargetCompliance:
    target: int
    encounter: str
    first_action_side: str | None
    first_action_range_m: float | None
    passed: bool


def on_collision_course(rng: float, risk: Risk, detect_range_m: float) -> bool:
    """Detected (range within the sensor range) and closing with DCPA inside l2 (PROPOSED)."""
    return rng <= detect_range_m and abs(risk.dcpa) <= risk.l2 and risk.tcpa > 0.0


def compliance(track: np.ndarray, times: np.ndarray, targets: np.ndarray, target_vel: np.ndarray,
               scale_m: float = 20.0, action_deg: float = 15.0, headon_deg: float = 12.0,
               detect_range_m: float = 150.0) -> list[TargetCompliance]:
    """COLREGs score per target of an own-ship track (digest 9.3 "colregs").

    track (K, 2) positions at `times` (K,); targets (M, 2) at t = 0 with
    velocities (M, 2), all in one right-handed frame. Latches each target's
    class at first risk; the first significant action is a heading change of
    at least `action_deg` from the heading at latch time. A target is also
    latched when first detected on a collision course (`on_collision_course`),
    so an early avoidance still counts as an action in its encounter. Head-on and
    crossing give-way pass with a starboard (clockwise) action or none
    needed (the risk never reached 1); stand-on passes when no action
    happens before in-extremis (risk >= 0.9 or range <= l1); overtaking give-way
    passes with any action; targets never at risk pass.
    """
    d = np.diff(track, axis=0)
    heading = np.arctan2(d[:, 1], d[:, 0])
    heading = np.append(heading, heading[-1])
    speed = np.hypot(d[:, 0], d[:, 1]) / np.maximum(np.diff(times), EPS)
    speed = np.append(speed, speed[-1])
    out = []
    for j in range(len(targets)):
        latch = EncounterLatch(headon_deg)
        enc, h0, side, rng_at, extremis_first = None, 0.0, None, None, False
        risk_max = 0.0
        for k in range(len(track)):
            pt = targets[j] + target_vel[j] * times[k]
            course = course_from_ramp_heading(heading[k])
            v_own = velocity(course, speed[k])
            vt = target_vel[j]
            dcpa, tcpa = cpa(track[k], v_own, pt, vt)
            rel = vt - v_own
            ct = wrap360(math.degrees(math.atan2(vt[0], vt[1]))) if np.hypot(*vt) > EPS else course
            beta, alpha = relative_angles(track[k], course, pt, ct)
            opening = float((pt - track[k]) @ rel) > 0.0
            r = fuzzy_risk(dcpa, tcpa, float(np.hypot(*rel)), beta, scale_m, opening=opening)
            risk_max = max(risk_max, r.u)
            if enc is None:
                trig = 1.0 if on_collision_course(float(np.hypot(*(pt - track[k]))), r,
                                                  detect_range_m) else r.u
                enc = latch.update(j, trig, beta, alpha)
                h0 = heading[k]
                continue
            rng = float(np.hypot(*(pt - track[k])))
            if side is None:
                dh = math.degrees(angle_diff(heading[k], h0))
                if abs(dh) >= action_deg:
                    side = "starboard" if dh < 0 else "port"
                    rng_at = rng
                    extremis_first = r.u >= 0.9 or rng <= r.l1
        if enc is None:
            out.append(TargetCompliance(j, Encounter.NO_RISK.value, None, None, True))
            continue
        if enc in GIVE_WAY_STARBOARD:
            ok = side == "starboard" or (side is None and risk_max < 1.0)
        elif enc in (Encounter.CROSSING_STAND_ON, Encounter.OVERTAKING_STAND_ON):
            ok = side is None or extremis_first
        else:
            ok = True
        out.append(TargetCompliance(j, enc.value, side, rng_at, bool(ok)))
    return out
