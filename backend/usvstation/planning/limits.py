"""Memory bound of one IGA plan (issue 12: "peak memory at most 500 MB on any accepted input").

The planner's large arrays all have sizes fixed by validated inputs: the
population P, the candidates per draw C, the waypoints N (at most
`max_waypoints` + 2, plus at most 24 run-out legs), and the obstacle circles
M after the timing-margin sweep (a fast obstacle becomes a chain of circles,
`problem.sweep_copies`). `estimate_bytes` adds up the bytes of every array
whose size grows with them, with the counts of live arrays read off the code:

    circles            M x 600 B      obstacle fields, their sweeps, hull field
    evaluator pairs    S x M x 200 B  (segment, obstacle) pairs kept by Evaluator
                                      and the temporaries of one pruning pass
    preheat draws      2P x 4C x 320 B  about 40 live float64 arrays of one draw of
                                      the harder preheating round (2P walks, 4C
                                      candidates each)
    preheat pairing    2P x M x 17 B  the (obstacle, walk) box mask and its pairs
    preheat blocks     N x M x 56 B   obstacles near each waypoint block
    population         2P x N x 320 B  one evaluated batch: paths, gates, terms
    kernels            64 MB          the chunked eq. 9 passes (2^18 elements, 8 B,
                                      at most 16 temporaries, twice over)

with S = N - 1 segments. A plan whose estimate exceeds `PLAN_BYTES_MAX`
(500 MB less `BASE_BYTES` for the interpreter, NumPy, SciPy and the
station's modules) is refused before any of it is allocated, with one line
naming what to lower. Measured peaks stay below the estimate
(docs/planner.md, "Bounds").
"""

from __future__ import annotations

import math

import numpy as np

from usvstation.planning.problem import sweep_copies
from usvstation.planning.start import MAX_PREFIX_LEGS
from usvstation.scenario import Scenario, ScenarioError
from usvstation.scenario.options import IGAOptions

MEMORY_LIMIT_BYTES = 500 * 2**20  # the bound on a planning process's peak
BASE_BYTES = 150 * 2**20  # interpreter, NumPy, SciPy and the station's modules (about 100 MB)
PLAN_BYTES_MAX = MEMORY_LIMIT_BYTES - BASE_BYTES
KERNEL_BYTES = 64 * 2**20


class PlanTooLarge(ScenarioError):
    """The plan would need more memory than the bound; the message says what to lower."""


def circle_count(scenario: Scenario) -> int:
    """Obstacle circles after the timing-margin sweep (problem.sweep_moving)."""
    obs = scenario.obstacles
    if not obs:
        return 0
    v = scenario.vessel
    speed = np.array([math.hypot(o.vx, o.vy) for o in obs])
    inflated = np.array([o.radius for o in obs]) + v.length + v.compensation_radius
    return int(sweep_copies(speed, inflated, v.time_margin_s).sum())


def estimate_bytes(scenario: Scenario, opts: IGAOptions) -> int:
    """Upper estimate of the bytes one IGA plan of `scenario` allocates at its peak."""
    m = circle_count(scenario)
    n = opts.max_waypoints + 2 + MAX_PREFIX_LEGS
    walks, cands = 2 * opts.population, 4 * opts.candidates
    total = (600 * m + 200 * (n - 1) * m + 320 * walks * cands + 17 * walks * m
             + 56 * n * m + 320 * walks * n + KERNEL_BYTES)
    return int(total)


def check_memory(scenario: Scenario, opts: IGAOptions) -> None:
    """Raise PlanTooLarge (one line) when the plan's estimate exceeds PLAN_BYTES_MAX."""
    need = estimate_bytes(scenario, opts)
    if need <= PLAN_BYTES_MAX:
        return
    m = circle_count(scenario)
    raise PlanTooLarge(
        f"planner: this plan would need about {need / 2**20:.0f} MB, above the "
        f"{PLAN_BYTES_MAX / 2**20:.0f} MB a plan may use ({len(scenario.obstacles)} obstacles "
        f"swept into {m} circles by vessel.time_margin_s, population {opts.population}, "
        f"candidates {opts.candidates}, max_waypoints {opts.max_waypoints}); lower one of them"
    )
