"""The final approach interrupted (issue 24): a HOLD or a failsafe at any point of the
approach, a hot swap on it, a START close to the ramp, a plan that comes in from the side.
Whatever happens the boat arrives within the safe contact (0.5 m, 8 deg) or goes around,
never touching the ramp outside it: judged on the truth, in simulated time."""

from __future__ import annotations

import math
from dataclasses import replace

import pytest
from link_harness import FRAME, KEY
from test_go_around import SPEED, DynamicHarness, straight_in

from usvstation.dynamics import Environment
from usvstation.guidance.approach import ArrivalLimits, EscapeRoute, escape_routes, obstacle_check
from usvstation.link.mission import mission_from_plan
from usvstation.link.protocol import CommandOutcome, StatusTextReceived, UploadResult
from usvstation.scenario import Obstacle
from usvstation.sim.boat import BoatConfig
from usvstation.sim.dynamic import DynamicVehicle
from usvstation.sim.vehicle import Waypoint

LIMITS = ArrivalLimits()


def rtk_lost(profile):
    """The profile with its RTK corrections gone (RTK float, fix type 5)."""
    return replace(profile, gnss=replace(profile.gnss, fix_type=5))


def waypoints(rows: list[dict]) -> list[Waypoint]:
    return [Waypoint(r["x"], r["y"], r["t"], r["speed"], math.radians(r["heading_deg"]))
            for r in rows]


def vehicle(current: float = 0.0, x0: float = 90.0, seed: int = 3, path_check=None,
            rows: list[dict] | None = None) -> DynamicVehicle:
    rows = rows or straight_in(x0)
    v = DynamicVehicle(rows[0]["x"], rows[0]["y"], math.radians(rows[0]["heading_deg"]),
                       speed=SPEED, env=Environment.with_current(current, math.pi / 2),
                       sensors="rtk-moving-base", seed=seed, arrival=LIMITS,
                       path_check=path_check)
    v.set_mission(waypoints(rows))
    v.start()
    return v


def fly(v: DynamicVehicle, seconds: float, until=None) -> bool:
    end = v.truth.t + seconds
    while v.truth.t < end:
        v.step(0.1)
        if until is not None and until():
            return True
    return until is None


def judged(v: DynamicVehicle) -> str:
    """Fly on until the boat is on the ramp or has gone around: 'arrived' (true hull
    within the safe contact), 'bad', or 'go_around' (then it must stand by, never having
    touched the ramp)."""
    fly(v, 200.0, until=lambda: v.phase in ("done", "go_around"))
    if v.phase == "done":
        t = v.truth
        heading = abs(math.degrees(math.remainder(t.heading - math.pi, 2 * math.pi)))
        return "arrived" if abs(t.y) <= LIMITS.contact_offset and heading <= 8.0 else "bad"
    assert v.phase == "go_around", v.phase
    touched = []
    fly(v, 150.0, until=lambda: touched.append(v.truth.x <= 0.0) or v.phase == "standby")
    assert v.phase == "standby" and not any(touched)
    return "go_around"


@pytest.mark.parametrize("current", [0.0, 0.3])
@pytest.mark.parametrize("at_m", [40.0, 22.0, 9.0, 3.0, 1.0])
def test_hold_and_resume_anywhere_on_the_approach_arrives_well_or_goes_around(at_m, current):
    v = vehicle(current)
    assert fly(v, 120.0, until=lambda: v.truth.x <= at_m)
    v.hold()
    fly(v, 12.0)
    assert v.phase in ("hold", "done")  # done: too close to stop, the ramp caught it
    v.resume()
    outcome = judged(v)
    assert outcome in ("arrived", "go_around")
    if current == 0.0 and at_m >= 3.0:  # slack water: the hull held along the axis
        assert outcome == "arrived", v.go_around


def test_a_hold_on_the_final_approach_keeps_the_hull_along_the_axis_in_slack_water():
    v = vehicle(0.0)
    assert fly(v, 120.0, until=lambda: v.truth.x <= 4.0)
    v.hold()
    worst = []
    fly(v, 20.0, until=lambda: worst.append(abs(math.remainder(v.truth.heading - math.pi,
                                                                2 * math.pi))) and False)
    assert math.degrees(max(worst)) < LIMITS.heading * 180 / math.pi
    assert v.truth.x > 0.0  # it stopped short of the ramp (backing astern)


def test_resumed_inside_the_last_gate_off_the_axis_goes_around():
    v = vehicle(0.0)
    assert fly(v, 120.0, until=lambda: v.truth.x <= 3.0)
    v.hold()
    fly(v, 5.0)
    v.keeper.hold_at(v.measurement.x, v.measurement.y + 0.6)  # pushed off the axis
    fly(v, 15.0)
    v.resume()
    assert v.phase == "go_around" and v.go_around.startswith("resumed")
    assert judged(v) == "go_around"


def test_a_start_close_to_the_ramp_goes_around_instead_of_touching_it():
    rows = [{"x": 4.0, "y": 1.0, "t": 0.0, "speed": 1.0, "heading_deg": 180.0},
            {"x": 0.0, "y": 0.0, "t": 4.0, "speed": 1.0, "heading_deg": 180.0}]
    v = vehicle(rows=rows)
    fly(v, 1.0)
    assert v.go_around == "at the ramp without an approach"
    assert judged(v) == "go_around"


def test_a_plan_coming_in_from_the_side_never_touches_the_ramp_without_its_gates():
    # onto the axis from the side 3 m out: too late and too steep to join the approach
    rows = [{"x": 20.0, "y": 25.0, "t": 0.0, "speed": SPEED, "heading_deg": 235.8},
            {"x": 3.0, "y": 0.0, "t": 20.1, "speed": SPEED, "heading_deg": 180.0},
            {"x": 0.0, "y": 0.0, "t": 22.1, "speed": SPEED, "heading_deg": 180.0}]
    v = vehicle(rows=rows)
    assert judged(v) == "go_around"


def test_the_escape_route_goes_back_along_the_plan_around_what_it_avoided():
    """A plan that swerves around an obstacle on the axis: the escape route retraces it to
    where it lies 50 m out (the standby point, on the plan), not straight through it."""
    plan = [(90.0, 0.0), (60.0, 0.0), (45.0, 8.0), (30.0, 8.0), (20.0, 0.0), (0.0, 0.0)]
    routes = escape_routes((10.0, 0.1), (50.0, 0.0), plan, (0.0, 0.0), LIMITS)
    back, straight = routes
    assert back.points[:3] == [(10.0, 0.1), (20.0, 0.0), (30.0, 8.0)]
    assert math.hypot(*back.standby) == pytest.approx(50.0)
    i, f = back.on_plan
    a, b = plan[i], plan[i + 1]
    assert back.standby == pytest.approx((a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])))
    assert straight == EscapeRoute([(10.0, 0.1), (50.0, 0.0)])
    blocked = obstacle_check([Obstacle(x=35.0, y=0.0, radius=3.0)], 1.0)
    from usvstation.guidance.trajectory import Trajectory

    def timed(points):
        return Trajectory.from_xyt([(x, y, 3.0 * k) for k, (x, y) in enumerate(points)])

    assert blocked(timed(back.points)) and not blocked(timed(straight.points))


def test_a_go_around_stands_by_on_the_plan_facing_the_ramp_and_resume_flies_the_plan():
    rows = [{"x": 90.0, "y": 0.0, "t": 0.0, "speed": SPEED, "heading_deg": 180.0},
            {"x": 60.0, "y": 0.0, "t": 20.0, "speed": SPEED, "heading_deg": 151.9},
            {"x": 45.0, "y": 8.0, "t": 31.3, "speed": SPEED, "heading_deg": 180.0},
            {"x": 30.0, "y": 8.0, "t": 41.3, "speed": SPEED, "heading_deg": 218.7},
            {"x": 20.0, "y": 0.0, "t": 49.9, "speed": SPEED, "heading_deg": 180.0},
            {"x": 0.0, "y": 0.0, "t": 63.2, "speed": SPEED, "heading_deg": 180.0}]
    check = obstacle_check([Obstacle(x=35.0, y=0.0, radius=3.0)], 1.0)
    v = vehicle(rows=rows, path_check=check)
    assert fly(v, 120.0, until=lambda: v.truth.x <= 8.0)
    good = v.sensors.profile
    v.sensors.profile = rtk_lost(good)
    assert fly(v, 30.0, until=lambda: v.phase == "go_around")
    assert v.go_around == "gate 5 m: no RTK-class fix"
    clear = []
    assert fly(v, 200.0, until=lambda: clear.append(
        math.hypot(v.truth.x - 35.0, v.truth.y) - 4.0) or v.phase == "standby")
    assert min(clear) > 0.0 and math.hypot(*v.standby) == pytest.approx(50.0)
    fly(v, 40.0)
    assert abs(math.degrees(math.remainder(v.truth.heading - math.pi, 2 * math.pi))) < 10.0
    assert math.hypot(v.truth.x - v.standby[0], v.truth.y - v.standby[1]) < 2.0
    v.sensors.profile = good
    assert v.reapproach() is None
    assert judged(v) == "arrived"
    assert min(clear) > 0.0


def test_resume_at_standby_is_refused_when_a_known_obstacle_blocks_the_new_approach():
    # an obstacle the boat knows moves onto the axis after the plan was made
    crossing = Obstacle(x=25.0, y=-30.0, radius=3.0, vx=0.0, vy=0.4)
    v = vehicle(path_check=obstacle_check([crossing], 1.0))
    assert fly(v, 120.0, until=lambda: v.truth.x <= 36.0)
    v._start_go_around("test")
    assert fly(v, 120.0, until=lambda: v.phase == "standby")
    problem = v.reapproach()
    assert problem == "new approach blocked by an obstacle", (problem, v.truth.t)


# --- through the link: failsafe, hot swaps on the approach and at standby -------------


def started(h: DynamicHarness, mission_id: int = 21) -> None:
    h.connect()
    mission = mission_from_plan(straight_in(), FRAME, mission_id)
    h.station.start_upload(mission, h.t)
    assert h.run(30.0, until=lambda: bool(h.of(UploadResult)))
    h.station.send_command("start", h.t, mission.mission_id, mission.crc)
    assert h.run(10.0, until=lambda: h.station.report.state == "RUNNING")


def command(h: DynamicHarness, name: str) -> CommandOutcome:
    n = len(h.of(CommandOutcome))
    h.station.send_command(name, h.t)
    assert h.run(10.0, dt=0.05, until=lambda: len(h.of(CommandOutcome)) > n)
    return h.of(CommandOutcome)[-1]


@pytest.mark.parametrize("at_m", [40.0, 20.0, 9.0])
def test_a_failsafe_on_the_approach_then_resume_arrives_well_or_goes_around(at_m):
    h = DynamicHarness(key=KEY, x=90.0, y=0.0, boat_cfg=BoatConfig(sim_speed=1.0))
    started(h)
    v = h.vehicle
    assert h.run(80.0, dt=0.05, until=lambda: v.truth.x <= at_m)
    h.station_silent = True  # 4 s of radio silence: the boat fails safe after 3 s
    assert h.run(6.0, dt=0.05, until=lambda: h.boat.state == 6)  # FAILSAFE
    h.station_silent = False
    assert h.run(10.0, dt=0.05, until=lambda: h.station.report.state == "FAILSAFE")
    assert command(h, "resume").accepted
    crossing = []
    assert h.run(120.0, dt=0.05, until=lambda: crossing.append(v.truth.x) or
                 h.station.report.state in ("DONE", "GO_AROUND"))
    t = v.truth
    if h.station.report.state == "DONE":
        assert abs(t.y) <= 0.5
        assert abs(math.degrees(math.remainder(t.heading - math.pi, 2 * math.pi))) <= 8.0
    else:
        assert min(crossing) > 0.0


def test_a_hot_swap_on_the_final_approach_is_dropped_and_the_approach_flown_on():
    h = DynamicHarness(key=KEY, x=90.0, y=0.0, boat_cfg=BoatConfig(sim_speed=4.0))
    started(h)
    v = h.vehicle
    assert h.run(60.0, dt=0.05, until=lambda: v.truth.x <= 26.0)
    assert v.committed
    swap = mission_from_plan(straight_in(20.0, 4), FRAME, 22)
    h.station.start_upload(swap, h.t, swap_at_ms=h.boat.uptime_ms + 3000)
    assert h.run(60.0, dt=0.05, until=lambda: h.station.report.state == "DONE")
    texts = [e.text for e in h.of(StatusTextReceived)]
    assert any(t in ("swap of 22 refused: on the final approach",
                     "swap to 22 dropped: on the final approach") for t in texts), texts
    assert h.station.report.active_id == 21
    assert v.gates.passed[-1] == 5.0 and abs(v.truth.y) <= 0.3


def test_the_new_approach_is_a_hot_swap_taken_at_the_standby_point_only():
    h = DynamicHarness(key=KEY, x=90.0, y=0.0, boat_cfg=BoatConfig(sim_speed=4.0))
    started(h)
    v = h.vehicle
    good = v.sensors.profile
    v.sensors.profile = rtk_lost(good)
    assert h.run(120.0, dt=0.05, until=lambda: h.station.report.state == "GO_AROUND")
    # before the standby point: refused at END
    early = mission_from_plan(straight_in(50.0, 6), FRAME, 23)
    h.station.start_upload(early, h.t, swap_at_ms=h.boat.uptime_ms + 3000)
    assert h.run(30.0, dt=0.05, until=lambda: len(h.of(UploadResult)) >= 2)
    assert not h.of(UploadResult)[-1].ok
    assert "swap of 23 refused: go-around not at standby yet" in [
        e.text for e in h.of(StatusTextReceived)]
    assert h.run(120.0, dt=0.05, until=lambda: v.at_standby)
    h.run(5.0, dt=0.05)
    v.sensors.profile = good
    # at standby: the station's new approach (from where the boat is) is taken
    sx, sy = v.state.x, v.state.y
    rows = [{"x": sx * (1 - i / 5), "y": sy * (1 - i / 5), "t": sx * i / 5 / SPEED,
             "speed": SPEED, "heading_deg": 180.0} for i in range(6)]
    new = mission_from_plan(rows, FRAME, 24)
    h.station.start_upload(new, h.t, swap_at_ms=h.boat.uptime_ms + 3000)
    assert h.run(30.0, dt=0.05, until=lambda: h.station.report.active_id == 24)
    assert h.station.report.state == "RUNNING"
    assert any(e.text.startswith("new approach: mission 24 at") for e in h.of(StatusTextReceived))
    assert h.run(120.0, dt=0.05, until=lambda: h.station.report.state == "DONE")
    assert abs(v.truth.y) <= 0.3 and v.go_arounds == 1
