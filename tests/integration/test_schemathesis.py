"""schemathesis against /openapi.json of a running station: every operation, no 5xx."""

import re
import subprocess
import sys
from pathlib import Path

from stationproc import StationProcess

SCHEMATHESIS = Path(sys.executable).parent / "schemathesis"


def test_no_server_errors_on_500_plus_generated_requests(tmp_path):
    # one worker: schemathesis' concurrent workers can trip CPython 3.11's ast.parse,
    # which is not thread-safe (a tool error, not the station's)
    st = StationProcess(tmp_path / "data", "--sim-speed", "5")
    try:
        out = subprocess.run(
            [str(SCHEMATHESIS), "run", f"{st.url}/openapi.json",
             "-H", f"Authorization: Bearer {st.token}", "--checks", "not_a_server_error",
             "--phases", "coverage,fuzzing", "-n", "10", "--seed", "7", "-w", "1"],
            capture_output=True, text=True, timeout=300,
            cwd=tmp_path,  # its .schemathesis cache goes there, not into the checkout
        )
    finally:
        st.stop()
    report = out.stdout + out.stderr
    assert out.returncode == 0, report[-4000:]
    tested = re.search(r"Tested: (\d+)", report)
    selected = re.search(r"Selected: (\d+)/(\d+)", report)
    assert tested and selected and int(tested.group(1)) == int(selected.group(2)) >= 14
    cases = re.search(r"(\d+) generated, (\d+) passed", report)
    assert cases, report[-2000:]
    assert int(cases.group(1)) == int(cases.group(2)) >= 500
