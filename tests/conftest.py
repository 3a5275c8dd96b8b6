import os
import sys
from pathlib import Path

# let integration tests import their helpers (serverutil) by name
sys.path.insert(0, str(Path(__file__).parent / "integration"))

# Hypothesis: no per-example deadline. A deadline is a wall-clock assertion, and the suite
# must pass on a loaded 2-core machine (timings belong to `usv-station bench`).
from hypothesis import settings

settings.register_profile("station", deadline=None)
settings.load_profile("station")
# Stations started by the tests (in-process or `serve` subprocesses, which inherit this)
# allow a plan 120 s instead of 10 s: plan workers run at nice 10, so on a loaded
# machine a plan can wait long for the CPU. test_faults passes --plan-timeout-s to test the
# limit itself.
os.environ.setdefault("USV_STATION_PLAN_TIMEOUT_S", "120")
