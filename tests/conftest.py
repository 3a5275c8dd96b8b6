import sys
from pathlib import Path

# let integration tests import their helpers (serverutil) by name
sys.path.insert(0, str(Path(__file__).parent / "integration"))

# Hypothesis: no per-example deadline. A deadline is a wall-clock assertion, and the suite
# must pass on a loaded 2-core machine (timings belong to `usv-station bench`).
from hypothesis import settings

settings.register_profile("station", deadline=None)
settings.load_profile("station")
