"""The moving ramp: the pose stream over usv-link 2 (USV_RAMP_POSE), the boat's frame
extrapolation, tracking in the ship-fixed frame with the physics in still water, and the
stale-pose rule."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st
from link_harness import FRAME, Harness, make_mission

from usvstation.dynamics import Environment
from usvstation.guidance.observer import Measurement
from usvstation.link.protocol import LinkConfig, RampPoseSample, StatusTextReceived
from usvstation.sim.boat import S_HOLD, S_RUNNING, BoatConfig
from usvstation.sim.dynamic import DynamicVehicle
from usvstation.sim.frame import RampMotion
from usvstation.sim.vehicle import Waypoint
from usvstation.world.model import offset_geodetic

finite = st.floats(-200.0, 200.0)
angle = st.floats(-math.pi, math.pi)


@given(finite, finite, angle, finite, finite)
def test_ramp_and_world_points_round_trip(ox, oy, theta, x, y):
    m = RampMotion(ox, oy, theta, 1.0, -0.5, 0.01, 3.0)
    wx, wy = m.to_world(x, y)
    rx, ry = m.to_ramp(wx, wy)
    assert rx == pytest.approx(x, abs=1e-9) and ry == pytest.approx(y, abs=1e-9)


@given(st.floats(-3, 3), st.floats(-3, 3), st.floats(-0.05, 0.05), st.floats(0, 30),
       st.floats(0, 30))
def test_extrapolation_composes_and_keeps_speed(vx, vy, omega, t1, t2):
    m = RampMotion(10.0, -5.0, 0.3, vx, vy, omega, 0.0)
    a, b = m.at(t1).at(t1 + t2), m.at(t1 + t2)
    for name in ("x", "y", "theta", "vx", "vy"):
        assert getattr(a, name) == pytest.approx(getattr(b, name), abs=1e-6)
    assert math.hypot(b.vx, b.vy) == pytest.approx(math.hypot(vx, vy), abs=1e-9)
    assert b.theta == pytest.approx(0.3 + omega * (t1 + t2), abs=1e-9)


def test_a_point_fixed_on_a_turning_ramp_measures_still():
    m = RampMotion(0.0, 0.0, 0.2, 1.2, 0.4, 0.02, 0.0).at(7.0)
    x, y = m.to_world(30.0, -4.0)
    vx, vy = m.point_velocity(x, y)
    sog, cog = math.hypot(vx, vy), math.atan2(vy, vx)
    r = m.measure(Measurement(x, y, m.theta + 1.0, sog, cog, m.omega, 7.0))
    assert (r.x, r.y) == pytest.approx((30.0, -4.0), abs=1e-9)
    assert r.sog == pytest.approx(0.0, abs=1e-9) and r.r == pytest.approx(0.0, abs=1e-12)
    assert r.psi == pytest.approx(1.0)


def _mission(speed: float) -> list[Waypoint]:
    """A straight run to the ramp end from (85, 10) at `speed` relative to the ramp."""
    d = math.hypot(85.0, 10.0)
    heading = math.atan2(-10.0, -85.0)
    n = 8
    return [Waypoint(85.0 * (1 - i / (n - 1)), 10.0 * (1 - i / (n - 1)), d * i / (n - 1) / speed,
                     speed, heading) for i in range(n)]


def _sail(v: DynamicVehicle, ramp_xy, limit: float = 200.0) -> list[tuple[float, float]]:
    v.set_mission(_mission(1.2))
    v.start()
    out = []
    while not v.state.mission_complete and v.state.t < limit:
        v.step(0.1)
        out.append(ramp_xy(v))
    return out


def test_tracking_in_a_moving_frame_over_still_water_equals_the_apparent_current():
    """Galilean invariance: the ship making 1 m/s along -x over still water is, in the
    ship-fixed frame, the water flowing at +1 m/s past a fixed ramp (bench live's model)."""
    heading = math.atan2(-10.0, -85.0)
    fixed = DynamicVehicle(85.0, 10.0, heading, speed=0.5, env=Environment.with_current(1.0, 0.0))
    motion = RampMotion(vx=-1.0)
    # the same start relative to the ramp: 0.5 m/s along the heading (plus the ship's way)
    moving = DynamicVehicle(85.0, 10.0, heading, speed=0.5,
                            env=Environment.with_current(0.0, 0.0), frame=motion)
    a = _sail(fixed, lambda v: (v.state.x, v.state.y))
    b = _sail(moving, lambda v: (v.in_ramp().x, v.in_ramp().y))
    assert fixed.state.mission_complete and moving.state.mission_complete
    assert len(a) == len(b)
    assert max(math.hypot(p[0] - q[0], p[1] - q[1]) for p, q in zip(a, b, strict=True)) < 1e-6
    # over ground the boat made good the ship's way as well, and it ends on the moving ramp
    s = moving.state
    assert (s.x, s.y) == pytest.approx(motion.at(s.t).to_world(*b[-1]), abs=1e-9)
    assert math.hypot(*b[-1]) < 2.0
    for _ in range(50):  # recovered: carried by the ramp at the ship's speed
        moving.step(0.1)
    s = moving.state
    assert s.speed == pytest.approx(1.0) and motion.at(s.t).to_ramp(s.x, s.y) == \
        pytest.approx(b[-1], abs=1e-9)


def _pose(h: Harness, dt: float = 0.0, east: float = 0.0, ve: float = 0.0,
          bearing: float = FRAME.ramp_bearing_deg) -> RampPoseSample:
    lat, lon = offset_geodetic(FRAME.lat, FRAME.lon, east, 0.0)
    return RampPoseSample(h.t + dt, lat, lon, bearing, 0.0, ve, 0.0)


def test_the_station_streams_the_pose_at_4_hz_labelled_in_boat_time():
    h = Harness(boat_cfg=BoatConfig(sim_speed=3.0))
    h.connect()
    h.run(4.0)  # TIMESYNC samples spanning 2 s: the clock rate is known
    assert h.station.clock_rate == pytest.approx(3.0, rel=0.02)
    assert h.boat.ramp_poses == 0  # nothing set: nothing streamed
    h.station.set_ramp_pose(_pose(h, dt=-0.5, east=20.0, ve=1.5))
    sent0 = h.station.ramp_poses_sent
    h.run(3.0)
    assert 11 <= h.station.ramp_poses_sent - sent0 <= 13
    assert h.boat.ramp_poses >= 1
    assert not h.boat.ramp_stale  # the same pose again and again: the stream is alive
    m = h.boat.ramp
    # labelled with the pose's own instant: 3.5 link seconds ago, 10.5 s of boat time
    assert h.boat.boat_time - m.t0 == pytest.approx(10.5, abs=0.1)
    # the frame: the origin 20 m east; +x on the origin's bearing (east); 1.5 m/s east
    assert (m.x, m.y, m.theta) == pytest.approx((20.0, 0.0, 0.0), abs=0.01)
    assert (m.vx, m.vy, m.omega) == pytest.approx((1.5, 0.0, 0.0), abs=1e-6)


def test_a_stale_pose_holds_a_running_boat_and_the_next_one_is_reported():
    h = Harness(link_cfg=LinkConfig())
    h.connect()
    mission = make_mission(7)
    h.station.start_upload(mission, h.t)
    assert h.run(20.0, until=lambda: h.boat.active is not None)
    h.station.set_ramp_pose(_pose(h))
    h.run(1.0)
    h.station.send_command("start", h.t, mission.mission_id, mission.crc)
    assert h.run(3.0, until=lambda: h.boat.state == S_RUNNING)
    h.run(1.5)
    assert h.boat.state == S_RUNNING and not h.boat.ramp_stale
    h.station.set_ramp_pose(None)  # the stream stops; heartbeats go on
    assert h.run(2.6, until=lambda: h.boat.state == S_HOLD)
    assert h.boat.ramp_stale and h.boat.linked
    h.run(0.5)
    texts = [e.text for e in h.of(StatusTextReceived)]
    assert "ramp pose stale 2 s: holding" in texts
    assert not h.boat.ramp.moving  # frozen: the hold is over ground
    h.station.set_ramp_pose(_pose(h))
    h.run(1.0)
    assert not h.boat.ramp_stale and h.boat.state == S_HOLD  # the operator resumes
    assert "ramp pose back: RESUME to go on" in [e.text for e in h.of(StatusTextReceived)]


def test_poses_older_than_the_one_in_use_are_ignored():
    h = Harness()
    h.connect()
    h.run(3.0)
    h.station.set_ramp_pose(_pose(h, east=10.0))
    h.run(0.5)
    t0 = h.boat.ramp.t0
    h.station.set_ramp_pose(_pose(h, dt=-2.0, east=50.0))  # an older fix, sent later
    h.run(0.5)
    assert h.boat.ramp.t0 == t0 and h.boat.ramp.x == pytest.approx(10.0, abs=0.01)


def test_ramp_pose_values_are_checked_naming_the_field():
    with pytest.raises(ValueError, match="ramp pose: vn must be finite"):
        RampPoseSample(0.0, 30.0, 114.0, 90.0, vn=float("nan"))
    with pytest.raises(ValueError, match="ramp_pose_period_s must be in"):
        LinkConfig(ramp_pose_period_s=0.8)


def test_a_kinematic_boat_rides_the_moving_ramp_and_starts_by_ramp_distance():
    h = Harness()
    h.connect()
    h.run(2.0)
    h.station.set_ramp_pose(_pose(h, ve=1.5))  # the ramp end at the origin, 1.5 m/s east (+x)
    h.run(10.0)
    ramp = h.boat.ramp.at(h.boat.boat_time)
    assert ramp.x == pytest.approx(15.0, abs=0.5)
    s = h.boat.vehicle.state  # over ground: carried east with the ramp, its place kept on it
    # (the first pose keeps the boat where it is over ground: it arrives a step after its
    # instant, when the ramp has already moved 3 cm)
    assert (s.x - ramp.x, s.y) == pytest.approx((85.0, 10.0), abs=0.05)
    assert s.speed == pytest.approx(1.5) and s.course == pytest.approx(0.0)
    x, _ = FRAME.to_ramp(h.station.telemetry.lat, h.station.telemetry.lon)
    assert float(x) > 95.0  # what the station hears is the boat over ground
    mission = make_mission(9)  # waypoint 0 at (85, 10) of the ramp frame: 15 m away over
    h.station.start_upload(mission, h.t)  # ground, 0 m on the ramp
    assert h.run(20.0, until=lambda: h.boat.active is not None)
    h.station.send_command("start", h.t, mission.mission_id, mission.crc)
    assert h.run(3.0, until=lambda: h.boat.state == S_RUNNING)
