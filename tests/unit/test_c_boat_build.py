"""The C boat (protocol/c/boat) builds warning-free, survives fuzzing under ASan/UBSan and
fits an STM32F103's RAM.

The suite fuzzes USV_C_BOAT_FUZZ_N inputs (default 20,000); the full run is
`make -C protocol/c/boat fuzz-run` (1,000,000 inputs) or this test with
USV_C_BOAT_FUZZ_N=1000000.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess

import pytest
from c_boat_support import BOAT_DIR, build_c_boat, c_compiler

pytestmark = pytest.mark.skipif(c_compiler() is None,
                                reason="no C compiler (cc/gcc) to build protocol/c/boat")

STRICT = ["-std=c99", "-Wall", "-Wextra", "-pedantic"]
M3_RAM_LIMIT = 12 * 1024


@pytest.mark.parametrize("source", ["usv_boat.c", "host_main.c", "fuzz_main.c",
                                    "stm32_main.c"])
def test_sources_compile_without_a_single_warning(source, tmp_path):
    cc = c_compiler()
    out = subprocess.run([cc, *STRICT, "-O2", "-I", str(BOAT_DIR), "-isystem",
                          str(BOAT_DIR.parent / "mavlink"), "-c", str(BOAT_DIR / source),
                          "-o", str(tmp_path / "x.o")], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stderr == ""


def test_make_builds_the_host_program(tmp_path):
    exe = build_c_boat(tmp_path)
    out = subprocess.run([str(exe)], capture_output=True, text=True)
    assert out.returncode == 2
    assert out.stderr.splitlines()[0] == "usv_boat_host: DEVICE|PORT missing"
    out = subprocess.run([str(exe), "0"], capture_output=True, text=True)
    assert "--link-key PATH required (or --insecure-link)" in out.stderr
    bad = tmp_path / "bad.key"
    bad.write_text("abc\n")
    out = subprocess.run([str(exe), "0", "--link-key", str(bad)], capture_output=True,
                         text=True)
    assert out.returncode == 2
    assert out.stderr.strip() == (f"usv_boat_host: --link-key {bad}: not a 32-byte key "
                                  "(32 raw bytes or 64 hex digits)")


def test_fuzzed_inputs_under_address_and_undefined_sanitizers(tmp_path):
    n = int(os.environ.get("USV_C_BOAT_FUZZ_N", "20000"))
    exe = build_c_boat(tmp_path, "fuzz")
    out = subprocess.run([str(exe), str(n), "7"], capture_output=True, text=True,
                         timeout=3600)
    assert out.returncode == 0, out.stderr[-4000:]
    assert out.stderr == ""
    m = re.match(r"usv_boat_fuzz: (\d+) inputs \(seed 7\) ok; boat sent (\d+) frames "
                 r"\((\d+) unparsable\)", out.stdout)
    assert m is not None, out.stdout
    assert int(m.group(1)) == n and int(m.group(2)) > n // 2 and m.group(3) == "0"
    activations = int(re.search(r"activations (\d+)", out.stdout).group(1))
    assert activations > 0  # the fuzzer reaches past verification, not only the parser


@pytest.mark.skipif(shutil.which("arm-none-eabi-gcc") is None,
                    reason="arm-none-eabi-gcc not installed (apt-get install gcc-arm-none-eabi)")
def test_cortex_m3_image_static_ram_fits_12_kib(tmp_path):
    out = subprocess.run(["make", "-s", "-C", str(BOAT_DIR), f"BUILD={tmp_path}", "m3"],
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stderr == ""
    rows = {line.split()[-1]: [int(x) for x in line.split()[:3]]
            for line in out.stdout.splitlines()[1:]}
    _text, data, bss = rows[f"{tmp_path}/usv_boat_m3.elf"]
    assert data + bss <= M3_RAM_LIMIT
    assert rows[f"{tmp_path}/usv_boat_m3.o"][1:] == [0, 0]  # the core owns no static RAM
