import sys
from pathlib import Path

# let integration tests import their helpers (serverutil) by name
sys.path.insert(0, str(Path(__file__).parent / "integration"))
