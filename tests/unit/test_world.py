"""World model: own ship, ramp pose through the lever arm, track prediction and ageing."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from usvstation.geo import RampFrame
from usvstation.scenario.ships import LeverArm
from usvstation.world.model import (
    LOST_AFTER_S,
    OWN_SHIP_STALE_S,
    World,
    WorldConfig,
    compass_to_enu,
    offset_geodetic,
)

LAT, LON = 30.5, 122.0


def test_ramp_pose_of_a_stern_ramp_lies_astern_and_points_astern() -> None:
    world = World(lever_arm=LeverArm(forward=-40.0, starboard=0.0, ramp_bearing_offset_deg=180))
    world.update_own(0.0, lat=LAT, lon=LON, heading_deg=90.0)
    pose = world.ramp(0.0)
    assert pose is not None
    assert pose.ramp_bearing_deg == pytest.approx(270.0)
    x, y = RampFrame(LAT, LON, 0.0).to_ramp(pose.lat, pose.lon)  # x north, y west
    assert float(x) == pytest.approx(0.0, abs=1e-6)
    assert float(y) == pytest.approx(40.0, abs=1e-3)  # 40 m west of a ship heading east


def test_starboard_lever_arm_of_a_ship_heading_north_is_east() -> None:
    world = World(lever_arm=LeverArm(forward=0.0, starboard=5.0))
    world.update_own(0.0, lat=LAT, lon=LON, heading_deg=0.0)
    pose = world.ramp(0.0)
    e, n = RampFrame(LAT, LON, 90.0).to_ramp(pose.lat, pose.lon)  # x east
    assert (float(e), float(n)) == pytest.approx((5.0, 0.0), abs=1e-3)


def test_own_ship_and_ramp_are_dead_reckoned() -> None:
    world = World(lever_arm=LeverArm(forward=0.0))
    world.update_own(10.0, lat=LAT, lon=LON, heading_deg=0.0, course_deg=0.0, speed=2.0)
    pose = world.ramp(20.0)
    x, _y = RampFrame(LAT, LON, 0.0).to_ramp(pose.lat, pose.lon)
    assert float(x) == pytest.approx(20.0, abs=1e-3)
    assert (pose.ve, pose.vn) == pytest.approx((0.0, 2.0), abs=1e-12)


def test_without_a_fix_the_ramp_is_the_anchor() -> None:
    anchor = RampFrame(LAT, LON, 45.0)
    world = World(anchor=anchor)
    world.update_own(0.0, heading_deg=10.0)
    pose = world.ramp(5.0)
    assert (pose.lat, pose.lon, pose.ramp_bearing_deg, pose.moving) == (LAT, LON, 45.0, False)


def test_target_prediction_in_ramp_frame_with_ground_and_relative_velocity() -> None:
    world = World(anchor=RampFrame(LAT, LON, 0.0))
    tlat, tlon = offset_geodetic(LAT, LON, 0.0, 100.0)  # 100 m north = +x
    world.update_track(0.0, "ais:1", "ais", mmsi=1, lat=tlat, lon=tlon, speed=3.0,
                       course_deg=180.0, length=12.0)
    (t,) = world.targets(10.0)
    assert (t["x"], t["y"]) == pytest.approx((70.0, 0.0), abs=1e-3)
    assert (t["vx"], t["vy"]) == pytest.approx((-3.0, 0.0), abs=1e-9)
    assert (t["rvx"], t["rvy"]) == (t["vx"], t["vy"])
    assert t["radius"] == 6.0 and t["age_s"] == 10.0


def test_relative_velocity_subtracts_the_ship() -> None:
    world = World(lever_arm=LeverArm(forward=0.0, ramp_bearing_offset_deg=180.0))
    world.update_own(0.0, lat=LAT, lon=LON, heading_deg=0.0, course_deg=0.0, speed=1.5)
    tlat, tlon = offset_geodetic(LAT, LON, 50.0, 0.0)
    world.update_track(0.0, "ais:2", "ais", lat=tlat, lon=tlon, speed=1.5, course_deg=0.0)
    (t,) = world.targets(0.0)
    # ramp +x points south: a target sailing north at the ship's speed is still in the frame
    assert (t["vx"], t["vy"]) == pytest.approx((-1.5, 0.0), abs=1e-9)
    assert (t["rvx"], t["rvy"]) == pytest.approx((0.0, 0.0), abs=1e-9)


def test_static_report_keeps_position_and_names_the_track() -> None:
    world = World(anchor=RampFrame(LAT, LON, 0.0))
    world.update_track(0.0, "ais:3", "ais", lat=LAT, lon=LON, speed=1.0, course_deg=90.0)
    world.update_track(5.0, "ais:3", "ais", name="ALPHA", length=30.0)
    tr = world.tracks["ais:3"]
    assert (tr.lat, tr.name, tr.length, tr.t) == (LAT, "ALPHA", 30.0, 0.0)


def test_silent_tracks_age_out_but_manual_ones_stay() -> None:
    frame = RampFrame(LAT, LON, 0.0)
    world = World(anchor=frame, config=WorldConfig(max_age_s=30.0))
    world.update_track(0.0, "ais:4", "ais", lat=LAT, lon=LON)
    world.set_manual(0.0, [(50.0, 5.0, 3.0, 0.0, -0.5)], frame)
    assert world.expire(30.0) == []
    assert world.expire(30.5) == ["ais:4"]
    (m,) = world.targets(100.0)
    assert m["id"] == "manual:0" and m["source"] == "manual" and m["radius"] == 3.0
    assert (m["x"], m["y"]) == pytest.approx((50.0, -45.0), abs=1e-3)


def test_radar_target_from_range_and_bearing() -> None:
    world = World()
    world.update_own(0.0, lat=LAT, lon=LON, heading_deg=90.0)
    assert world.update_radar_target(0.0, 7, 500.0, 0.0, 2.0, 45.0, relative=True) is not None
    tr = world.tracks["arpa:7"]
    e, n = RampFrame(LAT, LON, 90.0).to_ramp(tr.lat, tr.lon)
    assert (float(e), float(n)) == pytest.approx((500.0, 0.0), abs=0.01)


def test_radar_target_needs_an_own_fix() -> None:
    assert World().update_radar_target(0.0, 1, 100.0, 0.0, 1.0, 0.0) is None


@given(st.floats(0.0, 20.0), st.floats(0.0, 360.0, exclude_max=True),
       st.floats(1.0, 600.0))
def test_prediction_moves_by_speed_times_time(speed: float, course: float, dt: float) -> None:
    world = World(anchor=RampFrame(LAT, LON, 0.0))
    world.update_track(0.0, "sim:1", "sim", lat=LAT, lon=LON, speed=speed, course_deg=course)
    (t,) = world.targets(dt)
    assert math.hypot(t["x"], t["y"]) == pytest.approx(speed * dt, abs=1e-6)
    ve, vn = compass_to_enu(speed, course)
    assert (t["vy"], t["vx"]) == pytest.approx((-ve, vn), abs=1e-9)


def test_a_silent_own_ship_stays_dead_reckoned_and_stale_never_the_origin() -> None:
    anchor = RampFrame(0.0, 0.0, 90.0)  # the scenario's origin, far away
    world = World(anchor=anchor, lever_arm=LeverArm(forward=0.0))
    world.update_own(0.0, lat=LAT, lon=LON, heading_deg=270.0, course_deg=270.0, speed=1.0)
    assert not world.own.stale(OWN_SHIP_STALE_S)
    for t in (OWN_SHIP_STALE_S + 0.1, 120.0, 3600.0):
        pose = world.ramp(t)
        assert world.own.stale(t) and pose.moving
        x, _ = RampFrame(LAT, LON, 90.0).to_ramp(pose.lat, pose.lon)  # x east
        assert float(x) == pytest.approx(-t, abs=1e-2 * t)  # still sailing west at 1 m/s


@pytest.mark.parametrize(("east", "dt", "jumps"), [
    (1.0, 1.0, False),  # on its way at 1 m/s
    (60.0, 1.0, True),  # 60 m in a second at 1 m/s: a wrong fix
    (60.0, 60.0, False),  # a minute without a fix, then where it should be
    (11.0, 0.5, True), (10.5, 0.0, True)])
def test_a_fix_further_than_the_speed_allows_is_a_jump(east: float, dt: float,
                                                       jumps: bool) -> None:
    world = World()
    world.update_own(0.0, lat=LAT, lon=LON, course_deg=90.0, speed=1.0)
    world.update_own(dt, lat=LAT, lon=LON)  # a fix on the spot is no jump
    assert world.own.t_jump is None
    lat, lon = offset_geodetic(LAT, LON, east, 0.0)
    world.update_own(2 * dt, lat=lat, lon=lon)
    assert (world.own.t_jump is not None) is jumps
    if jumps:
        assert world.own.jump_m == pytest.approx(east, abs=1e-3)
        assert world.own.jump_allowed_m == pytest.approx(10.0 + 1.5 * dt)


def test_targets_carry_class_heading_and_are_lost_after_silence() -> None:
    world = World(anchor=RampFrame(LAT, LON, 90.0))
    lat, lon = offset_geodetic(LAT, LON, 50.0, 0.0)
    world.update_track(0.0, "ais:1", "ais", mmsi=1, lat=lat, lon=lon, speed=2.0,
                       course_deg=0.0, heading_deg=5.0, ais_class="B", length=12.0)
    (t,) = world.targets(LOST_AFTER_S)
    assert (t["ais_class"], t["heading_deg"], t["length"], t["lost"]) == ("B", 5.0, 12.0, False)
    (t,) = world.targets(LOST_AFTER_S + 0.1)
    assert t["lost"]


@pytest.mark.parametrize(("arm", "reference"), [
    (LeverArm(forward=-20.0), (-20.0, 0.0)),  # a stern ramp 20 m aft: the antenna forward
    (LeverArm(forward=-20.0, starboard=5.0), (-20.0, -5.0)),  # +y of a stern ramp: starboard
    (LeverArm(forward=10.0, starboard=0.0, ramp_bearing_offset_deg=0.0), (-10.0, 0.0))])
def test_the_ships_reference_in_the_ramp_frame_agrees_with_the_ramp_pose(arm, reference) -> None:
    from usvstation.world.model import reference_in_ramp

    assert reference_in_ramp(arm) == pytest.approx(reference, abs=1e-9)
    world = World(lever_arm=arm)
    world.update_own(0.0, lat=LAT, lon=LON, heading_deg=33.0)
    pose = world.ramp(0.0)
    x, y = pose.frame.to_ramp(LAT, LON)  # the antenna seen from the ramp
    assert (float(x), float(y)) == pytest.approx(reference, abs=1e-3)
