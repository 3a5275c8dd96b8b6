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

# `make test` runs modules on four workers (pytest-xdist, --dist loadscope) in the order
# collected (--no-loadscope-reorder): the longest modules first, so that the many short ones
# fill the end and the workers finish together (longest-processing-time-first scheduling).
# Wall seconds of each module in a full `make test` on the 2-core VM (2026-11-26); a module
# not listed follows in file order. Only the order depends on this list, never a result.
LONGEST_FIRST = (
    "tests/conformance/test_boat.py",  # 131 s
    "tests/integration/test_faults.py",  # 129 s (a 40 s database lock, mostly idle)
    "tests/e2e/test_console_at_sea.py",  # 95 s
    "tests/integration/test_c_boat_link.py",  # 94 s
    "tests/integration/test_campaign.py",  # 82 s
    "tests/e2e/test_console.py",  # 70 s
    "tests/sim/test_sea_trial.py",  # 66 s
    "tests/e2e/test_console_state.py",  # 65 s
    "tests/bench/test_bench_tracking.py",  # 55 s
    "tests/e2e/test_console_bridge.py",  # 55 s
    "tests/bench/test_bench_server.py",  # 49 s
    "tests/integration/test_mavsdk_vehicle.py",  # 33 s
    "tests/conformance/test_gcs.py",  # 31 s
    "tests/bench/test_bench_compare.py",  # 30 s
    "tests/integration/test_abuse.py",  # 29 s
    "tests/sim/test_live_loop.py",  # 28 s
    "tests/integration/test_link_floor.py",  # 27 s
    "tests/integration/test_schemathesis.py",  # 23 s
    "tests/integration/test_station_loop.py",  # 23 s
    "tests/integration/test_link_pty.py",  # 23 s
    "tests/e2e/test_console_perf.py",  # 19 s
    "tests/integration/test_c_boat_serve.py",  # 17 s
    "tests/integration/test_hil_cli.py",  # 17 s
    "tests/unit/test_c_boat_build.py",  # 15 s
    "tests/integration/test_link_serve.py",  # 14 s
    "tests/bench/test_bench_arrival.py",  # 14 s
    "tests/integration/test_telemetry_api.py",  # 14 s
    "tests/integration/test_hil_serve.py",  # 14 s
    "tests/e2e/test_console_standard.py",  # 13 s
    "tests/unit/test_approach_interrupted.py",  # 11 s
    "tests/sim/test_alerts_at_sea.py",  # 11 s
)


def pytest_collection_modifyitems(session, config, items):
    """The longest modules first (a stable sort: the order inside a module is kept)."""
    rank = {module: i for i, module in enumerate(LONGEST_FIRST)}
    items.sort(key=lambda item: rank.get(item.nodeid.split("::", 1)[0], len(rank)))
