"""Load every compiled kernel of the IGA once per process (or compile it, the first time in
an environment: numba's `cache=True` keeps the machine code on disk).

`warm()` plans a small recovery (one moving obstacle, a boat under way, a current) with a
tiny population and finishes and checks the plan (smoothing, clearances), which calls each
kernel with the argument types of a real plan.
`plan_scenario` calls it before it plans, and a plan worker when it starts. Loading from the
cache counts in a plan's budget like the imports do; compiling (`compiled()`: numba missed
its cache) does not (planning/budget.py `Budget.excluding`).
"""

from __future__ import annotations

import functools

from usvstation.planning import kernel, kernel_ga, kernel_geom, kernel_preheat
from usvstation.planning.budget import Budget
from usvstation.planning.iga import run_iga
from usvstation.planning.problem import Problem
from usvstation.planning.smoothing import smooth_path
from usvstation.planning.validate import hull_clearance, plan_violations
from usvstation.scenario import parse_scenario


@functools.cache
def warm() -> bool:
    """Load (or compile) the kernels now; False without numba. Only the first call works."""
    if not kernel.AVAILABLE:
        return False
    scenario = parse_scenario({
        "name": "warm-up", "start": {"x": 40.0, "y": 6.0, "heading_deg": 180.0, "speed": 1.0},
        "goal": {"x": 0.0, "y": 0.0},
        "obstacles": [{"x": 20.0, "y": -4.0, "radius": 1.0, "vx": 0.0, "vy": 0.3}],
        "environment": {"current_speed": 0.2, "current_dir_deg": 90.0},
    })
    opts = scenario.planner_options(seed=1, population=8, generations_max=2)
    problem = Problem.from_scenario(scenario)
    best = run_iga(problem, opts, budget=Budget(None, 3600.0)).best  # compiling is slow
    x, y, t, v = best.x[0], best.y[0], best.t[0], best.v[0]  # the ramp frame: no rotation
    smooth_path(x, y, t, problem.obstacles)  # as plan.build_plan finishes a plan
    doc = {"waypoints": [{"x": float(a), "y": float(b), "t": float(c), "speed": float(d)}
                         for a, b, c, d in zip(x, y, t, v, strict=True)]}
    hull_clearance(doc, scenario)
    plan_violations(doc, scenario)
    return True


def compiled() -> bool:
    """True when a kernel was compiled in this process (numba missed its cache), not
    loaded: the first run in an environment."""
    dispatchers = [getattr(m, name) for m in (kernel, kernel_ga, kernel_geom, kernel_preheat)
                   for name in dir(m)]
    return any(sum(d.stats.cache_misses.values()) for d in dispatchers
               if hasattr(d, "stats") and hasattr(d.stats, "cache_misses"))

