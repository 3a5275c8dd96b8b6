"""The C boat (protocol/c/boat) builds warning-free, survives fuzzing under ASan/UBSan, and
its firmware images fit their chips: the STM32F103C8 (64 KB flash, 20 KB RAM with at least
4 KB left for the stack) and QEMU's stm32vldiscovery (8 KB RAM). The firmware tests need
arm-none-eabi-gcc: without it they skip, under CI=true they fail (.ci/run installs it).

The suite fuzzes USV_C_BOAT_FUZZ_N inputs (default 20,000); the full run is
`make -C protocol/c/boat fuzz-run` (1,000,000 inputs) or this test with
USV_C_BOAT_FUZZ_N=1000000.
"""

from __future__ import annotations

import os
import re
import shutil
import struct
import subprocess

import pytest
from c_boat_support import BOAT_DIR, build_c_boat, c_compiler

pytestmark = pytest.mark.skipif(c_compiler() is None,
                                reason="no C compiler (cc/gcc) to build protocol/c/boat")

STRICT = ["-std=c99", "-Wall", "-Wextra", "-pedantic"]
F103_FLASH = 64 * 1024
F103_RAM = 20 * 1024
F103_STACK_MIN = 4 * 1024
QEMU_RAM = 8 * 1024
QEMU_STACK_MIN = 1536  # stm32vldiscovery.ld's STACK_MIN


# the portable sources; the chip's (stm32_*.c, startup_m3.c) build with -Werror in `make m3`
@pytest.mark.parametrize("source", ["usv_boat.c", "host_main.c", "fuzz_main.c", "usv_hil.c",
                                    "usv_provision.c"])
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


def require_arm_gcc() -> None:
    if shutil.which("arm-none-eabi-gcc") is None:
        why = ("arm-none-eabi-gcc not installed (apt-get install gcc-arm-none-eabi "
               "libnewlib-arm-none-eabi)")
        if os.environ.get("CI") == "true":
            pytest.fail(f"CI: {why}")
        pytest.skip(why)


def make_firmware(build: os.PathLike, target: str) -> dict[str, tuple[int, int, int]]:
    """`make TARGET` (strict flags, -Werror): {file: (text, data, bss)} from its
    arm-none-eabi-size table, printed for the CI log."""
    out = subprocess.run(["make", "-s", "-C", str(BOAT_DIR), f"BUILD={build}", target],
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stdout + out.stderr
    assert out.stderr == ""
    print(f"make {target}: arm-none-eabi-size\n{out.stdout}")
    rows = {}
    for line in out.stdout.splitlines():
        parts = line.split()
        if len(parts) == 6 and parts[0].isdigit():
            rows[os.path.basename(parts[5])] = (int(parts[0]), int(parts[1]), int(parts[2]))
    return rows


def test_f103_image_fits_64_kib_flash_and_leaves_4_kib_of_20_kib_ram_for_the_stack(tmp_path):
    require_arm_gcc()
    rows = make_firmware(tmp_path, "m3")
    text, data, bss = rows["usv_boat_m3.elf"]
    flash, ram = text + data, data + bss
    print(f"STM32F103C8: flash {flash} of {F103_FLASH} B, RAM {ram} of {F103_RAM} B, "
          f"stack {F103_RAM - ram} B")
    assert flash <= F103_FLASH, f"flash {flash} B > {F103_FLASH} B"
    assert F103_RAM - ram >= F103_STACK_MIN, \
        f"RAM {ram} B leaves {F103_RAM - ram} B < {F103_STACK_MIN} B for the stack"
    assert rows["usv_boat.o"][1:] == (0, 0)  # the core owns no static RAM


def test_qemu_image_fits_the_stm32vldiscovery_8_kib_ram(tmp_path):
    require_arm_gcc()
    rows = make_firmware(tmp_path, "qemu")
    text, data, bss = rows["usv_boat_qemu.elf"]
    print(f"QEMU stm32vldiscovery: flash {text + data} B, RAM {data + bss} of {QEMU_RAM} B, "
          f"stack {QEMU_RAM - data - bss} B")
    assert QEMU_RAM - (data + bss) >= QEMU_STACK_MIN


def _host_probe(tmp_path) -> str:
    """A host program over usv_provision.c: parse a page file, print its fields; print the
    floor of a page image file; print the record of a floor."""
    src = tmp_path / "probe.c"
    src.write_text(r"""
#include <stdio.h>
#include <stdlib.h>
#include "usv_provision.h"
int main(int argc, char **argv) {
    static uint8_t buf[1024]; usv_provision_t p; uint8_t rec[8]; size_t n; int i;
    FILE *f;
    if (argv[1][0] == 'r') {
        usv_nv_record(strtoull(argv[2], NULL, 10), rec);
        for (i = 0; i < 8; i++) printf("%02x", rec[i]);
        printf("\n");
        return 0;
    }
    f = fopen(argv[2], "rb"); n = fread(buf, 1, sizeof buf, f); fclose(f);
    if (argv[1][0] == 'f') { printf("%llu\n", (unsigned long long)usv_nv_floor(buf, n)); return 0; }
    if (usv_provision_parse(buf, &p) != 0) { printf("invalid\n"); return 0; }
    printf("%u %u %u %u %u %u %u %u %u %u %u %s", p.boat_id, p.station_id, p.signed_link,
           p.telemetry_period_ms, p.link_timeout_ms, p.staging_expiry_ms, p.start_radius_mm,
           p.max_speed_mmps, p.line_baud, p.clock_speedup_milli, p.key[31], p.nv_path);
    printf("\n");
    (void)argc;
    return 0;
}
""")
    exe = tmp_path / "probe"
    subprocess.run([c_compiler(), *STRICT, "-I", str(BOAT_DIR), "-isystem",
                    str(BOAT_DIR.parent / "mavlink"), "-o", str(exe), str(src),
                    str(BOAT_DIR / "usv_provision.c"), str(BOAT_DIR / "usv_boat.c"), "-lm"],
                   check=True, capture_output=True, text=True)
    return str(exe)


def test_provisioning_page_and_floor_records_agree_between_python_and_c(tmp_path):
    from usvstation.hil.provision import Provision, nv_floor, nv_record

    exe = _host_probe(tmp_path)
    page = Provision(boat_id=7, station_id=200, key=bytes(range(1, 33)), telemetry_period_ms=100,
                     link_timeout_ms=2500, staging_expiry_ms=9000, start_radius_m=12.5,
                     max_speed_mps=3.087, line_baud=57600, clock_speedup=4.5,
                     nv_path="/tmp/x nv.bin").to_bytes()
    f = tmp_path / "page.bin"
    f.write_bytes(page)
    out = subprocess.run([exe, "p", str(f)], capture_output=True, text=True).stdout
    assert out == "7 200 1 100 2500 9000 12500 3087 57600 4500 32 /tmp/x nv.bin\n"
    f.write_bytes(page[:100] + bytes([page[100] ^ 1]) + page[101:])  # one bit off: refused
    assert subprocess.run([exe, "p", str(f)], capture_output=True, text=True).stdout == \
        "invalid\n"
    for floor in (1, 0x0123456789AB, 2**48 - 1):
        c_rec = subprocess.run([exe, "r", str(floor)], capture_output=True, text=True).stdout
        assert c_rec.strip() == nv_record(floor).hex()
    # a page with older records, an erased slot, a torn one: the newest valid floor wins
    image = nv_record(5) + b"\xff" * 8 + nv_record(900) + nv_record(77)[:6] + b"\xff\xff" \
        + bytes(8)
    f.write_bytes(image)
    assert subprocess.run([exe, "f", str(f)], capture_output=True, text=True).stdout == "900\n"
    assert nv_floor(image) == 900
    assert nv_floor(bytes(1024)) == nv_floor(b"\xff" * 1024) == 0
    assert struct.unpack("<I", page[-4:])[0] != 0
