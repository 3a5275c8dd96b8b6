import os
import sys
from pathlib import Path

# let integration tests import their helpers (serverutil) by name
sys.path.insert(0, str(Path(__file__).parent / "integration"))

# Stations started by the tests (in-process or `serve` subprocesses, which inherit this)
# allow a plan 120 s instead of 10 s: plan workers run at idle CPU priority, so on a loaded
# machine a plan can wait long for the CPU. test_faults passes --plan-timeout-s to test the
# limit itself.
os.environ.setdefault("USV_STATION_PLAN_TIMEOUT_S", "120")
