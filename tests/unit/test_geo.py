"""Ramp frame <-> WGS-84: exact round trips, orientation of the axes, heading conversions."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from usvstation.geo import RampFrame
from usvstation.geometry import wrap_deg

frames = st.builds(
    RampFrame,
    lat=st.floats(-80.0, 80.0), lon=st.floats(-180.0, 180.0),
    ramp_bearing_deg=st.floats(0.0, 360.0, exclude_max=True),
)


@settings(max_examples=300, deadline=None)
@given(frames, st.floats(0.0, 5000.0), st.floats(0.0, 2 * math.pi))
def test_round_trip_below_a_millimetre_within_5_km(frame, r, a):
    x, y = r * math.cos(a), r * math.sin(a)
    lat, lon = frame.to_geodetic(x, y)
    x2, y2 = frame.to_ramp(lat, lon)
    assert math.hypot(float(x2) - x, float(y2) - y) < 1e-3


@settings(max_examples=100, deadline=None)
@given(frames, st.floats(-0.04, 0.04), st.floats(-0.04, 0.04))
def test_geodetic_round_trip(frame, dlat, dlon):
    lat, lon = frame.lat + dlat, frame.lon + dlon
    x, y = frame.to_ramp(lat, lon)
    lat2, lon2 = frame.to_geodetic(x, y)
    assert float(lat2) == pytest.approx(lat, abs=1e-9)
    assert float(np.mod(lon2 - lon + 180, 360) - 180) == pytest.approx(0.0, abs=1e-9)


def test_axes_follow_the_ramp_bearing():
    east = RampFrame(30.5135, 114.4182, ramp_bearing_deg=90.0)  # +x points east
    lat, lon = east.to_geodetic(100.0, 0.0)
    assert float(lon) > east.lon and float(lat) == pytest.approx(east.lat, abs=1e-5)
    lat, lon = east.to_geodetic(0.0, 100.0)  # +y is left of +x: north
    assert float(lat) > east.lat and float(lon) == pytest.approx(east.lon, abs=1e-9)
    north = RampFrame(30.5135, 114.4182, ramp_bearing_deg=0.0)
    lat, lon = north.to_geodetic(0.0, 100.0)  # +y left of north: west
    assert float(lon) < north.lon


def test_distances_match_the_ellipsoid():
    # 1000 m north of the equator is 1000 / 110574.3 deg of latitude (WGS-84 meridian arc)
    frame = RampFrame(0.0, 0.0, ramp_bearing_deg=0.0)
    lat, _ = frame.to_geodetic(1000.0, 0.0)
    assert float(lat) == pytest.approx(1000.0 / 110574.3, rel=1e-5)


def test_heading_conversions():
    frame = RampFrame(30.0, 114.0, ramp_bearing_deg=90.0)
    # ramp heading 0 (+x) is compass 90 (east); 90 (+y) is north; arriving at 180 is west
    assert frame.heading_to_compass_deg([0.0, 90.0, 180.0]).tolist() == [90.0, 0.0, 270.0]
    assert frame.compass_to_heading_deg([90.0, 0.0, 270.0]).tolist() == [0.0, 90.0, 180.0]


@given(st.floats(0.0, 360.0), st.floats(-720.0, 720.0))
def test_heading_round_trip(bearing, heading):
    frame = RampFrame(0.0, 0.0, ramp_bearing_deg=bearing)
    back = frame.compass_to_heading_deg(frame.heading_to_compass_deg(heading))
    diff = float(np.mod(back - heading + 180.0, 360.0) - 180.0)
    assert abs(diff) < 1e-9


def test_wrap_deg():
    assert wrap_deg([-90.0, 360.0, 725.0]).tolist() == [270.0, 0.0, 5.0]
