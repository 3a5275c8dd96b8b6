"""Re-planning policy and the re-planning problem built from the monitor's prediction."""

from __future__ import annotations

import numpy as np
import pytest

from usvstation.scenario import load_scenario
from usvstation.world.monitor import BoatState, TargetState, assess
from usvstation.world.replan import ReplanImpossible, ReplanState, decide, replan_scenario

PLAN = np.array([[100.0, 0.0, 0.0], [50.0, 0.0, 50.0], [0.0, 0.0, 100.0]])


@pytest.mark.parametrize(("policy", "level", "kind", "state", "t", "action"), [
    ("auto", "warning", "clearance", ReplanState(), 0.0, "apply"),
    ("confirm", "warning", "collision_course", ReplanState(), 0.0, "propose"),
    ("confirm", "warning", "slip", ReplanState(), 0.0, "propose"),
    ("off", "warning", "clearance", ReplanState(), 0.0, "none"),
    ("auto", "caution", "clearance", ReplanState(), 0.0, "none"),
    ("auto", "warning", "cross_track", ReplanState(), 0.0, "none"),
    ("auto", "warning", "clearance", ReplanState(in_flight=True), 0.0, "none"),
    ("confirm", "warning", "clearance", ReplanState(awaiting_operator=True), 0.0, "none"),
    ("auto", "warning", "clearance", ReplanState(last_t=0.0), 9.9, "none"),
    ("auto", "warning", "clearance", ReplanState(last_t=0.0), 10.0, "apply"),
])
def test_decide(policy, level, kind, state, t, action) -> None:
    assert decide(policy, level, kind, state, t) == action


def test_replan_scenario_starts_ahead_on_the_predicted_path_with_the_targets() -> None:
    base = load_scenario("case1")
    crossing = TargetState("ais:1", 30.0, -20.0, 0.0, 1.0, 3.0)
    onboard = TargetState("ais:2", 49.5, 0.5, 0.0, 0.0, 1.0)  # already at the boat
    a = assess(PLAN, BoatState(50.0, 0.0, -1.0, 0.0, 50.0), [crossing, onboard], 1.2)
    sc, dropped = replan_scenario(base, a, [crossing, onboard], speed=1.0,
                                  frame_velocity=(-1.5, 0.0), lead_s=2.0, seed=7)
    assert dropped == ["ais:2"]
    assert (sc.start.x, sc.start.y, sc.start.heading_deg) == pytest.approx((48.0, 0.0, 180.0))
    (ob,) = sc.obstacles
    assert (ob.x, ob.y, ob.vx, ob.vy, ob.radius) == pytest.approx((30.0, -18.0, 0.0, 1.0, 3.0))
    # the ship runs at -1.5 m/s along x: the water flows past the ramp at +1.5 m/s
    assert (sc.environment.current_speed, sc.environment.current_dir_deg) == pytest.approx(
        (1.5, 0.0))
    assert sc.name == "case1 (re-plan)" and sc.origin == base.origin


def test_replan_at_the_ramp_is_refused() -> None:
    a = assess(PLAN, BoatState(0.0, 0.0, -1.0, 0.0, 100.0), [], 1.2)
    with pytest.raises(ReplanImpossible, match=r"start\.x: the boat is at the ramp"):
        replan_scenario(load_scenario("case1"), a, [], speed=1.0)


def test_world_scenario_takes_the_targets_and_the_apparent_current() -> None:
    from usvstation.world.replan import world_scenario

    base = load_scenario("case1")
    far = TargetState("ais:1", 40.0, 30.0, 0.5, -1.0, 4.0)
    at_ramp = TargetState("ais:2", 2.0, 0.0, 0.0, 0.0, 2.0)
    beyond = TargetState("ais:3", 622_810.0, 380_949.0, 0.0, 0.0, 10.0)  # 730 km away
    sc, dropped = world_scenario(base, [far, at_ramp, beyond], frame_velocity=(0.0, 1.0))
    assert dropped == ["ais:2", "ais:3"]
    assert [(o.x, o.y, o.radius, o.vx, o.vy) for o in sc.obstacles] == [
        (40.0, 30.0, 4.0, 0.5, -1.0)]
    assert (sc.environment.current_speed, sc.environment.current_dir_deg) == pytest.approx(
        (1.0, 270.0))
    assert sc.start == base.start and sc.origin == base.origin
    # a re-plan of that plan for the same ship adds nothing: the water's current is kept
    again, _ = world_scenario(sc, [far], frame_velocity=(0.0, 1.0))
    assert (again.environment.current_speed, again.environment.current_dir_deg) == \
        pytest.approx((1.0, 270.0))
    # the ship slowed to 0.5 m/s: half the apparent current
    slower, _ = world_scenario(sc, [far], frame_velocity=(0.0, 0.5))
    assert slower.environment.current_speed == pytest.approx(0.5)
    from usvstation.dynamics import Environment
    water = Environment.from_scenario(sc.environment)  # the simulated sea: still water
    assert water.current == pytest.approx((0.0, 0.0), abs=1e-12)
