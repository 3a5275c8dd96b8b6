"""OMPL baselines for `bench compare` (optional: `pip install ompl`), one process per run.

OMPL's RRT*, Informed RRT* and BIT* plan in R^2 against the obstacles
inflated by eq. 7, each edge checked exactly against the moving circles
timed at the cruise speed (a Python MotionValidator, digest 7.1); the path
then goes through the same finish (gate run-in, turn limit, speed profile)
and the same checker as the seed planners. OMPL's seeding is per process
(`ompl.util.RNG.setSeed` before the first planner), so every run is a fresh
process: `python -m usvstation.bench.ompl_baseline PLANNER SEED` reading the
scenario JSON on stdin and printing one JSON row.
"""

from __future__ import annotations

import json
import subprocess
import sys
from typing import Any

from usvstation.clock import Stopwatch

OMPL_PLANNERS = ("RRTstar", "InformedRRTstar", "BITstar")
CURVE_PLANNERS = ("RRTstar", "BITstar", "PRMstar")  # cost-versus-time curves (issue 27)


def available() -> bool:
    try:
        import ompl  # noqa: F401
    except ImportError:
        return False
    return True


def run_in_process(scenario_json: dict[str, Any], planner: str, seed: int,
                   iterations: int = 3000) -> dict[str, Any]:
    out = subprocess.run(
        [sys.executable, "-m", "usvstation.bench.ompl_baseline", planner, str(seed),
         str(iterations)], input=json.dumps(scenario_json), capture_output=True, text=True,
        timeout=600, check=False)
    lines = [ln for ln in out.stdout.splitlines() if ln.startswith("{")]
    if not lines:
        return {"success": False, "error": (out.stderr.strip().splitlines() or ["no output"])[-1]}
    return json.loads(lines[-1])


def curve_in_process(scenario_json: dict[str, Any], planner: str, seed: int,
                     budgets: list[float]) -> dict[str, Any]:
    """OMPL `planner`'s best path length start -> goal (or run-in gate) after each CPU-time
    budget (s), a fresh planner per budget, in one fresh process."""
    out = subprocess.run(
        [sys.executable, "-m", "usvstation.bench.ompl_baseline", planner, str(seed), "curve",
         ",".join(f"{b:g}" for b in budgets)], input=json.dumps(scenario_json),
        capture_output=True, text=True, timeout=600, check=False)
    lines = [ln for ln in out.stdout.splitlines() if ln.startswith("{")]
    if not lines:
        return {"error": (out.stderr.strip().splitlines() or ["no output"])[-1]}
    return json.loads(lines[-1])


def _plan(scenario_json: dict[str, Any], planner: str, seed: int, iterations: int,
          budgets: list[float] | None = None) -> dict[str, Any]:
    import numpy as np
    from ompl import base as ob
    from ompl import geometric as og
    from ompl import util as ou

    from usvstation.planning.errors import NoFeasiblePlan
    from usvstation.planning.registry import _bounds
    from usvstation.planning.seeds.common import (
        World,
        cruise_speed,
        finish_plan,
        recovery_gates,
    )
    from usvstation.scenario import parse_scenario

    ou.RNG.setSeed(seed)
    watch = Stopwatch()
    sc = parse_scenario(scenario_json)
    world = World.from_scenario(sc)
    cruise = cruise_speed(sc)
    start = np.array([sc.start.x, sc.start.y])
    target = recovery_gates(sc, world)[0] if sc.kind == "recovery" else \
        np.array([sc.goal.x, sc.goal.y])
    xmin, xmax, ymin, ymax = _bounds(sc, target)
    space = ob.RealVectorStateSpace(2)
    bounds = ob.RealVectorBounds(2)
    bounds.setLow(0, xmin)
    bounds.setHigh(0, xmax)
    bounds.setLow(1, ymin)
    bounds.setHigh(1, ymax)
    space.setBounds(bounds)
    ss = og.SimpleSetup(space)
    si = ss.getSpaceInformation()
    cost_to = {}

    def xy(s: Any) -> np.ndarray:
        return np.array([s[0], s[1]])

    def valid(s: Any) -> bool:
        return bool(world.points_free(xy(s)[None], 0.0)[0]) if not world.moving.any() else \
            bool(World(world.cx[~world.moving], world.cy[~world.moving], world.vx[~world.moving],
                       world.vy[~world.moving], world.radius[~world.moving],
                       world.inflated[~world.moving]).points_free(xy(s)[None], 0.0)[0])

    class Timed(ob.MotionValidator):
        def checkMotion(self, s1: Any, s2: Any, *rest: Any) -> bool:
            a, b = xy(s1), xy(s2)
            # time at a: straight-line distance from the start / cruise (a lower bound)
            ta = cost_to.get((round(a[0], 6), round(a[1], 6)),
                             float(np.hypot(*(a - start)))) / cruise
            tb = ta + float(np.hypot(*(b - a))) / cruise
            return not bool(world.segments_hit(a[None], ta, b[None], tb)[0])

    ss.setStateValidityChecker(valid)
    si.setMotionValidator(Timed(si))
    st, gl = space.allocState(), space.allocState()
    st[0], st[1] = float(start[0]), float(start[1])
    gl[0], gl[1] = float(target[0]), float(target[1])
    ss.setStartAndGoalStates(st, gl, 1.0)
    obj = ob.PathLengthOptimizationObjective(si)
    ss.setOptimizationObjective(obj)
    if budgets is not None:
        return {"costs": [_cost_after(ss, si, og, ob, planner, b) for b in budgets],
                "budgets_s": budgets}
    p = getattr(og, planner)(si)
    ss.setPlanner(p)
    ss.setup()
    count = [0]

    def done() -> bool:
        count[0] += 1
        return count[0] > iterations

    solved = ss.solve(ob.PlannerTerminationCondition(done))
    if not solved or not ss.haveExactSolutionPath():
        return {"success": False, "error": "OMPL found no exact solution"}
    path = ss.getSolutionPath()
    pts = np.array([[path.getState(i)[0], path.getState(i)[1]]
                    for i in range(path.getStateCount())])
    if sc.kind == "recovery":
        pts = np.vstack([pts, [[0.0, 0.0]]])
    try:
        plan = finish_plan(sc, pts, f"ompl:{planner}", seed, cruise, watch.elapsed())
    except NoFeasiblePlan as exc:
        return {"success": False, "error": str(exc)}
    return {"success": True, "plan": plan.to_document(),
            "plan_time_ms": watch.elapsed() * 1000}


def _cost_after(ss: Any, si: Any, og: Any, ob: Any, planner: str, budget: float) -> float | None:
    """Length of the best exact solution a fresh `planner` finds within `budget` CPU s."""
    ss.clear()
    ss.setPlanner(getattr(og, planner)(si))
    ss.setup()
    if planner == "PRMstar":  # grows its roadmap on a thread of its own: OMPL's own timer
        solved = ss.solve(budget)
    else:
        spent = Stopwatch()  # CPU time of this process (the curve's one run)
        solved = ss.solve(ob.PlannerTerminationCondition(lambda: spent.cpu() > budget))
    if not solved or not ss.haveExactSolutionPath():
        return None
    return round(float(ss.getSolutionPath().length()), 4)


if __name__ == "__main__":
    name, seed_s, iters = sys.argv[1], sys.argv[2], sys.argv[3]
    if name not in OMPL_PLANNERS + CURVE_PLANNERS:
        raise SystemExit(f"planner: one of {', '.join(OMPL_PLANNERS + CURVE_PLANNERS)}")
    scenario = json.loads(sys.stdin.read())
    if iters == "curve":
        budgets = [float(b) for b in sys.argv[4].split(",")]
        print(json.dumps(_plan(scenario, name, int(seed_s), 0, budgets)))
    else:
        print(json.dumps(_plan(scenario, name, int(seed_s), int(iters))))
