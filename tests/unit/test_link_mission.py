"""Plan waypoints <-> wire mission items: round trip, rounding bounds, refusals."""

from __future__ import annotations

import math
import struct
import zlib

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from usvstation.geo import RampFrame
from usvstation.link.mission import (
    MissionError,
    MissionItem,
    Origin,
    mission_from_plan,
    plan_from_mission,
)
from usvstation.link.wire import item_crc32


@settings(max_examples=60, deadline=None)
@given(
    st.floats(-60, 60), st.floats(-179, 179), st.floats(0, 359.99),
    st.lists(st.tuples(st.floats(-500, 500), st.floats(-500, 500), st.floats(0, 5),
                       st.floats(0, 359.99)), min_size=2, max_size=40),
)
def test_plan_round_trips_within_wire_resolution(lat, lon, bearing, rows):
    frame = RampFrame(lat, lon, bearing)
    wps = [{"x": x, "y": y, "t": 2.5 * i, "speed": v, "heading_deg": h}
           for i, (x, y, v, h) in enumerate(rows)]
    mission = mission_from_plan(wps, frame, 42)
    assert [it.seq for it in mission.items] == list(range(len(wps)))
    back = plan_from_mission(mission, frame)
    for a, b in zip(wps, back, strict=True):
        # 1e-7 deg is 1.1 cm of latitude; less for longitude
        assert math.hypot(a["x"] - b["x"], a["y"] - b["y"]) < 0.02
        # half a wire unit (1 ms, 1 cm/s), plus float rounding
        assert abs(a["t"] - b["t"]) <= 0.0005 + 1e-9
        assert abs(a["speed"] - b["speed"]) <= 0.005 + 1e-9
        dh = (a["heading_deg"] - b["heading_deg"] + 180) % 360 - 180
        assert abs(dh) <= 0.006
    assert mission.crc == item_crc32(mission.items)


def test_origin_and_heading_convention_on_the_wire():
    frame = RampFrame(30.5135, 114.4182, 90.0)  # +x points east
    wps = [{"x": 10.0, "y": 0.0, "t": 0.0, "speed": 1.0, "heading_deg": 180.0},
           {"x": 10.0, "y": 5.0, "t": 5.0, "speed": 1.0, "heading_deg": 180.0}]
    mission = mission_from_plan(wps, frame, 1)
    it = mission.items[0]
    assert mission.origin == Origin(305135000, 1144182000, 9000)
    assert it.lat == 305135000 and it.lon > 1144182000  # 10 m east
    assert it.heading_cdeg == 27000  # ramp heading 180 = towards the ramp = compass west
    assert it.course_cdeg == 0  # the leg goes +y = left of +x (east) = north


def test_missions_refused_with_the_field_named():
    frame = RampFrame(30.5135, 114.4182, 90.0)
    one = [{"x": 0.0, "y": 0.0, "t": 0.0, "speed": 1.0, "heading_deg": 0.0}]
    with pytest.raises(MissionError, match=r"a mission has 2\.\.256 waypoints, got 1"):
        mission_from_plan(one, frame, 1)
    fast = [*one, {"x": 1.0, "y": 0.0, "t": 1.0, "speed": 31.0, "heading_deg": 0.0}]
    with pytest.raises(MissionError, match=r"waypoint 1: speed 31\.0 outside 0\.\.30\.0 m/s"):
        mission_from_plan(fast, frame, 1)
    late = [{**one[0], "t": 1.0}, {"x": 1.0, "y": 0.0, "t": 2.0, "speed": 1.0,
                                   "heading_deg": 0.0}]
    with pytest.raises(MissionError, match="waypoint 0: t_ms 1000 of item 0 is not 0"):
        mission_from_plan(late, frame, 1)
    same = [*one, {"x": 1.0, "y": 0.0, "t": 0.0, "speed": 1.0, "heading_deg": 0.0}]
    with pytest.raises(MissionError, match="waypoint 1: t_ms 0 not after"):
        mission_from_plan(same, frame, 1)


def test_crc32_layout_is_the_documented_24_bytes_per_item():
    it = MissionItem(0x01020304, 1, -2, 3, 4, 5, 6, 7)
    raw = struct.pack("<IiiIHHHH", 0x01020304, -2, 3, 4, 1, 5, 6, 7)
    assert item_crc32([it]) == zlib.crc32(raw)
