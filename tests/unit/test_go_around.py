"""A go-around end to end in simulated time (issue 24): the station uploads and starts a
recovery, the simulated boat (its sensors, observer, approach gates) misses a gate, reports
GO_AROUND, backs away and stands by; RESUME brings it round for a new approach, which
arrives on the ramp. The station protocol and the boat protocol are joined in memory on
one simulated clock (tests/unit/link_harness.py); nothing waits on the wall clock."""

from __future__ import annotations

import math
from dataclasses import replace

import pytest
from link_harness import FRAME, KEY, UNIX0, Harness

from usvstation.dynamics import Environment
from usvstation.guidance.approach import ArrivalLimits
from usvstation.link.mission import mission_from_plan
from usvstation.link.protocol import CommandOutcome, StatusTextReceived, UploadResult
from usvstation.sim.boat import BoatConfig, BoatProtocol
from usvstation.sim.dynamic import DynamicVehicle
from usvstation.sim.sensors import GpsNoise

SPEED = 1.5  # m/s along the plan


def straight_in(x0: float = 90.0, n: int = 10) -> list[dict]:
    return [{"x": x0 * (1 - i / (n - 1)), "y": 0.0, "t": x0 * i / (n - 1) / SPEED,
             "speed": SPEED, "heading_deg": 180.0} for i in range(n)]


class DynamicHarness(Harness):
    """The link harness with the simulated boat's dynamic vehicle behind the boat."""

    def _new_boat(self, x: float, y: float, boot_id: int = 1) -> BoatProtocol:
        self.vehicle = DynamicVehicle(
            x, y, math.pi, speed=SPEED, env=Environment.with_current(0.3, math.pi / 2),
            sensors="rtk-moving-base", seed=5, arrival=ArrivalLimits())
        return BoatProtocol(self.vehicle, FRAME, self.boat_cfg, key=self.key, nv=self.nv,
                            gps=GpsNoise(bias_std_m=0, white_std_m=0), now=self.t,
                            unix_time=UNIX0 + self.t, boot_id=boot_id)


def test_gate_missed_go_around_standby_new_approach_arrival():
    h = DynamicHarness(key=KEY, x=90.0, y=0.0, boat_cfg=BoatConfig(sim_speed=4.0))
    h.connect()
    mission = mission_from_plan(straight_in(), FRAME, 11)
    h.station.start_upload(mission, h.t)
    assert h.run(30.0, until=lambda: bool(h.of(UploadResult)))
    assert h.of(UploadResult)[-1].ok
    h.station.send_command("start", h.t, mission.mission_id, mission.crc)
    assert h.run(10.0, until=lambda: h.station.report.state == "RUNNING")
    v = h.vehicle

    # 35 m out the RTK corrections drop out: the fix degrades to RTK float
    assert h.run(60.0, dt=0.05, until=lambda: v.truth.x < 35.0)
    good = v.sensors.profile
    v.sensors.profile = replace(good, gnss=replace(good.gnss, fix_type=5))
    crossed = []
    assert h.run(60.0, dt=0.05, until=lambda: (crossed.append(v.truth.x <= 0.0) or
                                               h.station.report.state == "GO_AROUND"))
    texts = [e.text for e in h.of(StatusTextReceived)]
    assert "go-around: gate 30 m: no RTK-class fix" in texts

    # it stands by 50 m out on the axis, never having touched the ramp
    assert h.run(120.0, dt=0.05, until=lambda: (crossed.append(v.truth.x <= 0.0) or
                                                v.phase == "standby"))
    assert not any(crossed)
    assert v.standby == pytest.approx((50.0, 0.0), abs=1e-3)
    h.run(10.0, dt=0.05)
    assert "go-around: at standby, RESUME to approach" in [
        e.text for e in h.of(StatusTextReceived)]
    assert math.hypot(v.state.x - 50.0, v.state.y) < 3.0
    assert h.station.report.state == "GO_AROUND"

    # the corrections are back: RESUME flies a new approach, which arrives
    v.sensors.profile = good
    n = len(h.of(CommandOutcome))
    h.station.send_command("resume", h.t)
    assert h.run(10.0, dt=0.05, until=lambda: len(h.of(CommandOutcome)) > n)
    assert h.of(CommandOutcome)[-1].accepted
    assert h.run(120.0, dt=0.05, until=lambda: h.station.report.state == "DONE")
    t = v.truth
    assert abs(t.y) <= 0.3 and abs(t.x) <= 0.3
    assert abs(math.degrees(math.remainder(t.heading - math.pi, 2 * math.pi))) <= 5.0
    assert v.go_arounds == 1 and v.gates.passed == [30.0, 15.0, 5.0]


def test_resume_before_the_standby_point_is_refused_and_hold_acts():
    h = DynamicHarness(key=KEY, x=90.0, y=0.0, boat_cfg=BoatConfig(sim_speed=4.0))
    h.connect()
    mission = mission_from_plan(straight_in(), FRAME, 12)
    h.station.start_upload(mission, h.t)
    assert h.run(30.0, until=lambda: bool(h.of(UploadResult)))
    h.station.send_command("start", h.t, mission.mission_id, mission.crc)
    v = h.vehicle
    v.sensors.profile = replace(v.sensors.profile, gnss=replace(v.sensors.profile.gnss,
                                                                fix_type=3))
    assert h.run(120.0, dt=0.05, until=lambda: h.station.report.state == "GO_AROUND")
    n = len(h.of(CommandOutcome))
    h.station.send_command("resume", h.t)
    assert h.run(10.0, dt=0.05, until=lambda: len(h.of(CommandOutcome)) > n)
    assert not h.of(CommandOutcome)[-1].accepted
    assert "RESUME refused: go-around not at standby yet" in [
        e.text for e in h.of(StatusTextReceived)]
    h.station.send_command("hold", h.t)
    assert h.run(10.0, dt=0.05, until=lambda: h.station.report.state == "HOLD")
    h.station.send_command("resume", h.t)  # back to the go-around it was flying
    assert h.run(10.0, dt=0.05, until=lambda: h.station.report.state == "GO_AROUND")
