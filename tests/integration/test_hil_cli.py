"""`usv-station hil` refuses bad input with one clear line and exit 2, before or after QEMU
started (a port in use: QEMU is ended again)."""

from __future__ import annotations

import socket
import subprocess

import pytest
from hil_support import EXE, require_qemu, session_image


def hil(*args: str, timeout: float = 120) -> subprocess.CompletedProcess:
    return subprocess.run([EXE, "hil", *args], capture_output=True, text=True,
                          timeout=timeout)


@pytest.mark.parametrize("args, line", [
    (["--port", "0"], "usv-station hil: the boat needs --link-key PATH (the station's key) "
                      "or, knowingly, --insecure-link (not both)"),
    (["--port", "0", "--insecure-link", "--sim-speed", "50"],
     "usv-station hil: --sim-speed: 50 outside 0.1..20"),
    (["--port", "70000", "--insecure-link"], "usv-station hil: --port: 70000 is not a TCP port"),
    (["--pty", "--insecure-link", "--scenario", "no-such-scenario"],
     "usv-station hil: invalid scenario: "),
    (["--pty", "--link-key", "/nonexistent/key"],
     "usv-station hil: link key /nonexistent/key: No such file or directory"),
])
def test_bad_input_is_one_line_and_exit_2(args, line):
    out = hil(*args, "--image", "/nonexistent.elf")
    assert out.returncode == 2
    assert out.stderr.startswith(line) and out.stderr.count("\n") == 1, out.stderr
    assert out.stdout == ""


def test_port_and_pty_exclude_each_other_and_one_is_needed():
    assert "one of the arguments --port --pty is required" in hil("--insecure-link").stderr
    assert "not allowed with argument" in hil("--pty", "--port", "1", "--insecure-link").stderr


def test_a_port_in_use_is_refused_after_qemu_started_and_ended():
    require_qemu()
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen(1)
        port = taken.getsockname()[1]
        out = hil("--port", str(port), "--insecure-link", "--image", str(session_image()))
    assert out.returncode == 2
    assert out.stderr.strip().splitlines()[-1] == \
        f"usv-station hil: cannot listen on 127.0.0.1:{port}: Address already in use"
