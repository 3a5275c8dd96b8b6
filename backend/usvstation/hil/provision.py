"""The boat firmware's provisioning page and signing-floor page (protocol/c/boat/
usv_provision.h has the layout): bytes only, no I/O."""

from __future__ import annotations

import struct
import zlib
from dataclasses import dataclass

MAGIC = 0x31505355  # "USP1"
VERSION = 1
PAGE_BYTES = 204
NV_PATH_MAX = 128
NV_RECORD = struct.Struct("<IHH")
CONFIG_PAGE_ADDR = 0x0800F800  # the linker scripts' CONFIG and NV pages
NV_PAGE_ADDR = 0x0800FC00
_HEAD = struct.Struct("<IHBBB3xIIIIIII32s128s")


@dataclass(frozen=True)
class Provision:
    """What a boat is commissioned with: ids, key (None: unsigned link) and link settings.
    Times in the units the firmware takes: telemetry in boat ms, the timeouts in link
    (wall-clock) ms; `clock_speedup` > 1 only in hardware-in-the-loop runs."""

    boat_id: int = 1
    station_id: int = 255
    key: bytes | None = None
    telemetry_period_ms: int = 200
    link_timeout_ms: int = 3000
    staging_expiry_ms: int = 30000
    start_radius_m: float = 10.0
    max_speed_mps: float = 3.0
    line_baud: int = 0
    clock_speedup: float = 1.0
    nv_path: str = ""

    def to_bytes(self) -> bytes:
        """The page (PAGE_BYTES); ValueError naming the field that cannot be provisioned."""
        if not 1 <= self.boat_id <= 255 or not 1 <= self.station_id <= 255 \
                or self.boat_id == self.station_id:
            raise ValueError("boat_id and station_id: two different ids in 1..255")
        if self.key is not None and len(self.key) != 32:
            raise ValueError(f"key: {len(self.key)} bytes, expected 32")
        speedup = round(self.clock_speedup * 1000)
        if not 100 <= speedup <= 20000:
            raise ValueError(f"clock_speedup: {self.clock_speedup} outside 0.1..20")
        path = self.nv_path.encode()
        if len(path) >= NV_PATH_MAX:
            raise ValueError(f"nv_path: longer than {NV_PATH_MAX - 1} bytes")
        if self.telemetry_period_ms < 1 or self.link_timeout_ms < 1:
            raise ValueError("telemetry_period_ms and link_timeout_ms: at least 1")
        body = _HEAD.pack(MAGIC, VERSION, self.boat_id, self.station_id,
                          1 if self.key is not None else 0, self.telemetry_period_ms,
                          self.link_timeout_ms, self.staging_expiry_ms,
                          round(self.start_radius_m * 1000), round(self.max_speed_mps * 1000),
                          self.line_baud, speedup, self.key or bytes(32), path)
        return body + struct.pack("<I", zlib.crc32(body))


def nv_record(floor: int) -> bytes:
    """One signing-floor record (8 bytes) as the firmware writes it."""
    lo, hi = floor & 0xFFFFFFFF, (floor >> 32) & 0xFFFF
    return NV_RECORD.pack(lo, hi, _check(lo, hi))


def nv_floor(page: bytes) -> int:
    """The newest valid signing floor in a page image (0: none)."""
    best = 0
    for at in range(0, len(page) - NV_RECORD.size + 1, NV_RECORD.size):
        lo, hi, check = NV_RECORD.unpack_from(page, at)
        if check == _check(lo, hi):
            best = max(best, hi << 32 | lo)
    return best


def _check(lo: int, hi: int) -> int:
    return (lo ^ (lo >> 16) ^ hi ^ 0xA55A) & 0xFFFF
