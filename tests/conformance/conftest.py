"""Boat processes for the usv-link 2 conformance tests (tests/conformance/test_boat.py).

Every test runs against every boat in BOATS: a process that serves the boat side of the
link on a new pseudo-terminal. The contract a boat command follows:
  - argv gets: --link-key PATH (hex key file), --nv-file PATH (its non-volatile memory,
    kept across restarts of the process: a reboot), --boat-id 1;
  - it prints, as its first stdout line, a line containing "on /dev/<pty>" naming the
    device the station opens;
  - it places the boat at case1's start (ramp frame (85, 10), origin 30.5135 N 114.4182 E,
    ramp bearing 90) and follows timed waypoints (kinematic vehicle), at sim speed 1.
The C boat (protocol/c/boat/, issue 11 item 8) adds itself to BOATS, and so does the same
C boat as the firmware binary in QEMU's Cortex-M3 (`usv-station hil --pty`, issue 29): its
vehicle is the 3-DOF Otter driven by the firmware's own thrust through the HIL bridge.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))

EXE = os.path.join(os.path.dirname(sys.executable), "usv-station")
PYTHON_BOAT = [EXE, "sim", "--link", "pty", "--vehicle", "kinematic", "--scenario", "case1",
               "--telemetry-hz", "5", "--seed", "1"]
from c_boat_support import c_compiler, conformance_argv  # noqa: E402
from hil_support import conformance_argv as qemu_argv  # noqa: E402
from hil_support import qemu_expected  # noqa: E402

# each boat's command line, made when a test first starts that boat: the C boat
# (protocol/c/boat) when a C compiler exists, the firmware image in QEMU when the ARM tools
# exist (or under CI), each built once per test process (a worker that never runs these
# tests builds nothing)
BOATS: dict[str, Callable[[], list[str]]] = {"python": lambda: PYTHON_BOAT}
if c_compiler() is not None:
    BOATS["c"] = lambda: conformance_argv()["c"]
if qemu_expected():
    BOATS["qemu"] = lambda: qemu_argv()["qemu"]


class BoatProcess:
    """One boat process; restart() is a reboot (same non-volatile memory, new pty)."""

    def __init__(self, argv: list[str], key_path: Path, nv_path: Path) -> None:
        self.argv = [*argv, "--link-key", str(key_path), "--nv-file", str(nv_path),
                     "--boat-id", "1"]
        self.proc: subprocess.Popen | None = None
        self.device = ""
        self.start()

    def start(self) -> str:
        self.proc = subprocess.Popen(self.argv, stdout=subprocess.PIPE,
                                     stderr=subprocess.DEVNULL, text=True)
        line = self.proc.stdout.readline()
        match = re.search(r"on (/dev/\S+)", line)
        if match is None:
            self.stop()
            raise RuntimeError(f"boat did not announce its device: {line!r}")
        self.device = match.group(1)
        return self.device

    def stop(self) -> None:
        if self.proc is not None and self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(5)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(5)
        if self.proc is not None and self.proc.stdout is not None:
            self.proc.stdout.close()
        self.proc = None

    def restart(self) -> str:
        self.stop()
        return self.start()


@pytest.fixture(params=sorted(BOATS))
def boat(request, tmp_path):
    from usvstation.link.wire import write_key

    key_path = tmp_path / "link.key"
    write_key(key_path)
    proc = BoatProcess(BOATS[request.param](), key_path, tmp_path / "nv.json")
    proc.key_path = key_path
    yield proc
    proc.stop()
