"""A plan worker's limits: its address space is capped, and planning works under the cap."""

import subprocess
import sys

SCRIPT = """
from usvstation.services.plans import init_worker
init_worker(1024)
import numpy
from usvstation.planning.plan import plan_scenario
from usvstation.scenario import load_scenario
try:
    numpy.ones(1124 * 131072)
    print("allocated")
except MemoryError:
    print("MemoryError")
print(plan_scenario(load_scenario("case1"), seed=1).metrics.collision_free)
"""


def test_memory_limit_is_set_in_the_worker_and_planning_fits_under_it():
    out = subprocess.run([sys.executable, "-c", SCRIPT], capture_output=True, text=True,
                         timeout=240)
    assert out.returncode == 0, out.stderr[-2000:]
    assert out.stdout.split() == ["MemoryError", "True"]
