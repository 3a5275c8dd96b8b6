"""The boat firmware in QEMU for tests: build the image (`make qemu` into a temporary
directory) and run `usv-station hil` as a child process that is always ended by its pid.

Without the ARM toolchain or QEMU these tests skip, saying what to install; under CI=true
(.ci/run installs both from Debian) they fail instead, so CI never passes by skipping."""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BOAT_DIR = ROOT / "protocol" / "c" / "boat"
EXE = os.path.join(os.path.dirname(sys.executable), "usv-station")
TOOLS = ("make", "arm-none-eabi-gcc", "qemu-system-arm")
START_TIMEOUT_S = 120.0  # QEMU and the bridge up on a loaded machine


def qemu_missing() -> str | None:
    """Why the QEMU firmware cannot run here (None: it can)."""
    missing = [t for t in TOOLS if shutil.which(t) is None]
    if not missing:
        return None
    return (f"{', '.join(missing)} not installed (apt-get install gcc-arm-none-eabi "
            "libnewlib-arm-none-eabi qemu-system-arm)")


def require_qemu() -> None:
    """Skip the calling test without the tools, or fail under CI."""
    import pytest

    why = qemu_missing()
    if why is not None:
        if os.environ.get("CI") == "true":
            pytest.fail(f"CI: {why}")
        pytest.skip(why)


def build_qemu_image(build_dir: Path) -> Path:
    """`make -C protocol/c/boat BUILD=build_dir qemu`; the ELF."""
    out = subprocess.run(["make", "-s", "-C", str(BOAT_DIR), f"BUILD={build_dir}", "qemu"],
                         capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(f"make qemu failed:\n{out.stdout}\n{out.stderr}")
    return build_dir / "usv_boat_qemu.elf"


_image: Path | None = None


def session_image() -> Path:
    """The image built once per test process into a temporary directory (removed at exit)."""
    global _image
    if _image is None:
        import atexit
        import tempfile

        build = Path(tempfile.mkdtemp(prefix="usv-qemu-"))
        atexit.register(shutil.rmtree, build, True)
        _image = build_qemu_image(build)
    return _image


def qemu_expected() -> bool:
    """The QEMU firmware is tested: its tools are installed, or CI requires them."""
    return qemu_missing() is None or os.environ.get("CI") == "true"


def conformance_argv() -> dict[str, list[str]]:
    """The QEMU firmware's entry for tests/conformance BOATS: `usv-station hil --pty` at
    case1's start (the Otter, GPS noise seed 1); {} without the tools (outside CI)."""
    if not qemu_expected():
        return {}
    return {"qemu": [EXE, "hil", "--pty", "--scenario", "case1", "--telemetry-hz", "5",
                     "--seed", "1", "--image", str(session_image())]}


STACK_PAINT = b"\xa5\xa5\xa5\xa5"  # startup_m3.c paints the free RAM with it


def stack_high_water(monitor: Path, image: Path, dump: Path, timeout: float = 30.0
                     ) -> tuple[int, int]:
    """(bytes of stack ever used, bytes below them never touched) of the firmware in QEMU,
    from a RAM image that QEMU's monitor writes (pmemsave) and the image's symbols."""
    import socket

    syms = {}
    for line in subprocess.run(["arm-none-eabi-nm", str(image)], capture_output=True,
                               text=True, check=True).stdout.splitlines():
        parts = line.split()
        if len(parts) == 3:
            syms[parts[2]] = int(parts[0], 16)
    ram0, ebss, estack = 0x20000000, syms["_ebss"], syms["_estack"]
    with socket.socket(socket.AF_UNIX) as s:
        s.connect(str(monitor))
        s.sendall(f'pmemsave {ram0:#x} {estack - ram0} "{dump}"\n'.encode())
        deadline = time.monotonic() + timeout
        while not (dump.is_file() and dump.stat().st_size == estack - ram0):
            assert time.monotonic() < deadline, "QEMU's monitor wrote no RAM image"
            time.sleep(0.05)
    ram = dump.read_bytes()
    at = ebss - ram0
    while ram[at:at + 4] == STACK_PAINT:
        at += 4
    return estack - ram0 - at, at - (ebss - ram0)


class HilProcess:
    """`usv-station hil` as a child; `where` is what it announced (127.0.0.1:PORT or a pty).
    Its stderr is collected in `log`. Always end it with `close()`."""

    def __init__(self, *args: str) -> None:
        self.log: list[str] = []
        self.proc = subprocess.Popen([EXE, "hil", *args], stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE, text=True)
        threading.Thread(target=self._drain, daemon=True).start()
        try:
            line = self._first_line()
        except BaseException:
            self.close()
            raise
        m = re.search(r" on (\S+) \(", line)
        if m is None:
            self.close()
            raise RuntimeError(f"usv-station hil did not start: {line!r} {self.log[-5:]}")
        self.where = m.group(1)
        self.port = int(self.where.rsplit(":", 1)[1]) if ":" in self.where else None

    def _first_line(self) -> str:
        assert self.proc.stdout is not None
        found: list[str] = []
        reader = threading.Thread(target=lambda: found.append(self.proc.stdout.readline()),
                                  daemon=True)
        reader.start()
        reader.join(START_TIMEOUT_S)
        if not found:
            raise RuntimeError(f"usv-station hil silent after {START_TIMEOUT_S:g} s: "
                               f"{self.log[-5:]}")
        return found[0]

    def _drain(self) -> None:
        assert self.proc.stderr is not None
        for line in self.proc.stderr:
            self.log.append(line.rstrip())

    def wait_log(self, pattern: str, timeout: float = 30.0) -> str:
        """The first stderr line matching `pattern` (after the process ended or in time)."""
        deadline = time.monotonic() + timeout
        while True:
            for line in list(self.log):
                if re.search(pattern, line):
                    return line
            assert time.monotonic() < deadline, f"no {pattern!r} in {self.log[-5:]}"
            time.sleep(0.05)

    def close(self, timeout: float = 20.0) -> int:
        """SIGTERM (the hil process ends its QEMU), then SIGKILL if it lingers."""
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                self.proc.wait(timeout)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(timeout)
        if self.proc.stdout is not None:
            self.proc.stdout.close()
        return self.proc.returncode
