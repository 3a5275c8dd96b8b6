"""Paper 001's risk model: the digest's DCPA/TCPA, class and fuzzy-risk vectors."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from usvstation.planning import colregs as cr

OWN = np.zeros(2)
V_OWN = cr.velocity(0.0, 2.0)

# (target xy, course, speed, beta, alpha, class, DCPA, TCPA): digest table 2.3
VECTORS = [
    ((8, 40), 180, 2.0, 11.3, 11.3, "no-risk", 8.00, 10.00),
    ((20, 20), 270, 2.0, 45.0, -45.0, "crossing-give-way", 0.00, 10.00),
    ((21.2, 0), 315, 3.0, 90.0, -45.0, "crossing-give-way", 1.21, 9.96),
    ((-20, 20), 90, 2.0, 315.0, 45.0, "crossing-stand-on", 0.00, 10.00),
    ((3, 15), 0, 1.0, 11.3, -168.7, "overtaking-give-way", 3.00, 15.00),
    ((2, -20), 0, 3.5, 174.3, -5.7, "overtaking-stand-on", 2.00, 13.33),
    ((10, -30), 180, 2.0, 161.6, 161.6, "no-risk", 10.00, -7.50),
]


def _closest_approach(xy: tuple, course_deg: float, speed: float) -> tuple[float, float]:
    """Own boat at the origin northwards at 2 m/s; target at xy on a compass course."""
    rx, ry = float(xy[0]), float(xy[1])
    wx = speed * math.sin(math.radians(course_deg)) - 0.0
    wy = speed * math.cos(math.radians(course_deg)) - 2.0
    w2 = wx * wx + wy * wy
    t = -(rx * wx + ry * wy) / w2
    return math.hypot(rx + wx * t, ry + wy * t), t


@pytest.mark.parametrize("xy, course, speed, beta, alpha, cls, dcpa, tcpa", VECTORS)
def test_digest_cpa_vectors(xy, course, speed, beta, alpha, cls, dcpa, tcpa):
    p = np.array(xy, float)
    d, t = cr.cpa(OWN, V_OWN, p, cr.velocity(course, speed))
    # the digest prints 2 decimals: the value rounds to the table's, and it is within 1 mm and
    # 0.01 s of a scalar reference (closest approach of the relative motion, worked by hand)
    assert (round(d, 2), round(t, 2)) == (dcpa, tcpa)
    d_ref, t_ref = _closest_approach(xy, course, speed)
    assert abs(d - d_ref) <= 1e-3 and abs(t - t_ref) <= 1e-2
    b, a = cr.relative_angles(OWN, 0.0, p, course)
    assert b == pytest.approx(beta, abs=0.05)
    assert a == pytest.approx(alpha, abs=0.05)
    assert cr.classify(b, a).value == cls


def test_exact_cpa_values():
    d, t = cr.cpa(OWN, V_OWN, np.array([8.0, 40.0]), cr.velocity(180.0, 2.0))
    assert (d, t) == pytest.approx((8.0, 10.0), abs=1e-9)
    d, t = cr.cpa(OWN, V_OWN, np.array([0.0, 10.0]), V_OWN)  # same velocity: no relative motion
    assert (d, t) == (10.0, 0.0)


# digest table 2.5 (station mode: fixed eq. 12-14, l1 = 1.5 rho 20 m, l2 = 2 l1)
RISK = [
    ((8, 40), 180, 2.0, (32.62, 65.25, 7.91, 16.19, 1.0, 0.558, 1.0)),
    ((20, 20), 270, 2.0, (31.50, 63.00, 11.14, 22.27, 1.0, 1.0, 1.0)),
    ((-20, 20), 90, 2.0, (31.50, 63.00, 11.14, 22.27, 1.0, 1.0, 1.0)),
    ((2, -20), 0, 3.5, (18.38, 36.76, 12.18, 24.47, 1.0, 0.821, 1.0)),
    ((10, -30), 180, 2.0, (19.23, 38.46, 4.11, 9.28, 1.0, 0.119, 1.0)),
]


@pytest.mark.parametrize("xy, course, speed, want", RISK)
def test_digest_fuzzy_risk(xy, course, speed, want):
    p, vt = np.array(xy, float), cr.velocity(course, speed)
    d, t = cr.cpa(OWN, V_OWN, p, vt)
    beta, _ = cr.relative_angles(OWN, 0.0, p, course)
    r = cr.fuzzy_risk(d, t, float(np.hypot(*(vt - V_OWN))), beta)
    got = (r.l1, r.l2, r.t1, r.t2, r.u_d, r.u_t, r.u)
    assert got == pytest.approx(want, abs=0.006)


def test_opening_target_has_no_risk_in_station_mode():
    r = cr.fuzzy_risk(10.0, -7.5, 4.0, 161.6, opening=True)
    assert r.u == 0.0
    assert cr.fuzzy_risk(10.0, -7.5, 4.0, 161.6, opening=True, paper=True).u == 1.0


@given(st.floats(0.001, 359.999).filter(lambda g: abs(g - 112.5) > 1e-6
                                         and abs(g - 247.5) > 1e-6))
def test_ship_domain_fixed_is_symmetric(g):
    assert cr.ship_domain(g) == pytest.approx(cr.ship_domain(360.0 - g), abs=1e-9)


def test_ship_domain_fix_mirrors_the_first_branch():
    assert cr.ship_domain(112.5) == pytest.approx(0.975)
    assert cr.ship_domain(247.5 + 1e-9) == pytest.approx(0.975)
    assert cr.ship_domain(247.5 + 1e-9, paper=True) == pytest.approx(0.85)


@given(st.floats(0.0, 200.0), st.floats(10.0, 40.0))
def test_spatial_risk_is_continuous_and_monotone(d, l1):
    r1 = cr.fuzzy_risk(d, 1.0, 1.0, 0.0, scale_m=l1).u_d
    r2 = cr.fuzzy_risk(d + 0.01, 1.0, 1.0, 0.0, scale_m=l1).u_d
    assert 0.0 <= r2 <= r1 <= 1.0
    assert r1 - r2 < 0.01


def test_encounter_is_latched_at_first_risk():
    latch = cr.EncounterLatch(headon_deg=12.0)
    assert latch.update(0, 0.0, 30.0, -30.0) is None
    assert latch.update(0, 0.4, 11.3, 11.3) is cr.Encounter.HEAD_ON
    # later geometry that alone reads "crossing" does not change the class
    assert latch.update(0, 1.0, 60.0, -40.0) is cr.Encounter.HEAD_ON


def test_compliance_scores_a_starboard_turn_in_head_on():
    t = np.arange(0.0, 120.0)
    # own: north at 2 m/s, at t = 40 s turns 30 deg to starboard
    heading = np.where(t < 40, math.pi / 2, math.pi / 2 - math.radians(30))
    track = np.cumsum(np.stack([np.cos(heading), np.sin(heading)], 1) * 2.0, 0)
    track = np.vstack([[0, 0], track[:-1]])
    tg, tv = np.array([[0.0, 240.0]]), np.array([[0.0, -2.0]])
    res = cr.compliance(track, t, tg, tv)
    assert res[0].encounter == "head-on"
    assert res[0].first_action_side == "starboard" and res[0].passed
    mirrored = track * np.array([-1.0, 1.0])
    res = cr.compliance(mirrored, t, tg, tv)
    assert res[0].first_action_side == "port" and not res[0].passed
