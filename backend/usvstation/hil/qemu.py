"""The QEMU side of `usv-station hil`: the firmware image (built with `make qemu` when
needed) and the qemu-system-arm command line (no processes started here)."""

from __future__ import annotations

import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path

from usvstation.hil.provision import CONFIG_PAGE_ADDR, NV_PAGE_ADDR

BOAT_DIR = Path(__file__).resolve().parents[3] / "protocol" / "c" / "boat"
IMAGE = "usv_boat_qemu.elf"
MACHINE = "stm32vldiscovery"  # STM32F100RB: Cortex-M3, 128 KB flash, 8 KB RAM, 3 USARTs
QEMU = "qemu-system-arm"


class ImageError(RuntimeError):
    """The firmware image cannot be built or QEMU is missing (one line for the operator)."""


def build_image(build_dir: Path | None = None) -> Path:
    """`make -C protocol/c/boat qemu` (make rebuilds only what changed); the ELF's path."""
    if not (BOAT_DIR / "Makefile").is_file():
        raise ImageError(f"no firmware sources at {BOAT_DIR}; give the image with --image")
    for tool in ("make", "arm-none-eabi-gcc"):
        if shutil.which(tool) is None:
            raise ImageError(f"{tool} not found: apt-get install make gcc-arm-none-eabi "
                             "libnewlib-arm-none-eabi (or give the image with --image)")
    build = build_dir or BOAT_DIR / "build"
    out = subprocess.run(["make", "-s", "-C", str(BOAT_DIR), f"BUILD={build}", "qemu"],
                         capture_output=True, text=True)
    if out.returncode != 0:
        tail = (out.stderr or out.stdout).strip().splitlines()[-1:] or ["(no output)"]
        raise ImageError(f"make qemu failed: {tail[0]}")
    return build / IMAGE


def qemu_binary() -> str:
    path = shutil.which(QEMU)
    if path is None:
        raise ImageError(f"{QEMU} not found: apt-get install qemu-system-arm")
    return path


@dataclass(frozen=True)
class QemuCommand:
    """qemu-system-arm for the boat: USART1 (the radio) and USART2 (HIL) are QEMU's first
    and second `-serial`, each a client of a Unix socket the bridge listens on; the
    provisioning page and the signing-floor page image are loaded into flash by QEMU's
    generic loader; semihosting (host files) lets the firmware rewrite its page image."""

    image: Path
    config_page: Path
    radio_socket: Path
    hil_socket: Path
    nv_image: Path | None = None  # loaded when it exists
    monitor_socket: Path | None = None  # the QEMU monitor (HMP), for inspection

    def argv(self) -> list[str]:
        args = [qemu_binary(), "-M", MACHINE, "-nodefaults", "-display", "none",
                "-kernel", str(self.image),
                "-chardev", f"socket,id=radio,path={_opt(self.radio_socket)}",
                "-chardev", f"socket,id=hil,path={_opt(self.hil_socket)}",
                "-serial", "chardev:radio", "-serial", "chardev:hil",
                "-device", f"loader,file={_opt(self.config_page)},addr={CONFIG_PAGE_ADDR:#x},"
                           "force-raw=on",
                "-semihosting-config", "enable=on,target=native"]
        if self.nv_image is not None and self.nv_image.is_file() \
                and 0 < self.nv_image.stat().st_size <= 1024:
            args += ["-device", f"loader,file={_opt(self.nv_image)},addr={NV_PAGE_ADDR:#x},"
                                "force-raw=on"]
        if self.monitor_socket is not None:
            args += ["-monitor", f"unix:{_opt(self.monitor_socket)},server=on,wait=off"]
        return args


def _opt(path: Path) -> str:
    """A path as a QEMU option value (a comma is written twice)."""
    return str(path).replace(",", ",,")
