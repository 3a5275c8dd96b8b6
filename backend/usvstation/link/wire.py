"""usv-link 2 on the wire: pymavlink's generated MAVLink 2 codec with signing, sans-IO.

`Codec` wraps the mavgen-generated `MAVLink` class (link/mavlink/usv_recovery.py) for one
side of the link: it encodes messages with this side's system/component id, signs them
with the 32-byte key (MAVLink 2 signing: link id, 48-bit timestamp in 10 us since
2015-01-01, SHA-256 truncated to 6 bytes), decodes received bytes and sorts out what was
refused and why. No I/O and no clock: callers pass the signing time in.

Signature checks use pymavlink's own code with one correction (`_CheckedMAVLink`):
pymavlink stores a stream's new timestamp before it has verified the signature, so a
forged frame with a far-future timestamp would lock the real station out; here the
signature is verified first. Streams the boat has not seen since boot must also be newer
than `stream_floor` (the highest timestamp the boat persisted, protocol/README.md
"Replay after reboot").
"""

from __future__ import annotations

import hashlib
import os
import struct
import zlib
from collections import Counter
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from usvstation.link.mavlink import usv_recovery as mav

STATION_ID = 255
STATION_COMPONENT = mav.MAV_COMP_ID_MISSIONPLANNER
BOAT_ID = 1
BOAT_COMPONENT = mav.MAV_COMP_ID_AUTOPILOT1
EPOCH_2015 = 1420070400  # MAVLink signing epoch, unix seconds
TICKS_PER_S = 100_000  # signing timestamp unit: 10 us
MAX_MISSION_ITEMS = 256
KEY_BYTES = 32
_ITEM_CRC = struct.Struct("<IiiIHHHH")

# recovery commands and their names
COMMANDS = {"start": mav.MAV_CMD_USV_START, "hold": mav.MAV_CMD_USV_HOLD,
            "resume": mav.MAV_CMD_USV_RESUME, "abort": mav.MAV_CMD_USV_ABORT}
COMMAND_NAMES = {v: k for k, v in COMMANDS.items()}
BOAT_STATES = {v: e.name.removeprefix("USV_BOAT_STATE_")
               for v, e in mav.enums["USV_BOAT_STATE"].items()
               if not e.name.endswith("_ENUM_END")}
MISSION_RESULTS = {v: e.name.removeprefix("USV_MISSION_")
                   for v, e in mav.enums["USV_MISSION_RESULT"].items() if v < 10}
COMMAND_REASONS = {v: e.name.removeprefix("USV_COMMAND_REASON_")
                   for v, e in mav.enums["USV_COMMAND_REASON"].items() if v < 6}


def signing_time(unix_s: float) -> int:
    """A MAVLink signing timestamp (10 us ticks since 2015-01-01) for a unix time."""
    return max(0, int((unix_s - EPOCH_2015) * TICKS_PER_S))


def new_key() -> bytes:
    return os.urandom(KEY_BYTES)


def read_key(path: str | os.PathLike[str]) -> bytes:
    """A link key file: 64 hex digits (what `usv-station link-key new` writes)."""
    text = open(path, encoding="ascii").read().strip()  # noqa: SIM115
    try:
        key = bytes.fromhex(text)
    except ValueError:
        raise ValueError(f"link key {path}: not hexadecimal") from None
    if len(key) != KEY_BYTES:
        raise ValueError(f"link key {path}: {len(key)} bytes, expected {KEY_BYTES}")
    return key


def write_key(path: str | os.PathLike[str], key: bytes | None = None) -> bytes:
    """Write a new (or the given) key as hex, readable by the owner only."""
    key = key or new_key()
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    with os.fdopen(fd, "w", encoding="ascii") as fh:
        fh.write(key.hex() + "\n")
    return key


def item_crc32(items: Iterable[Any]) -> int:
    """CRC-32 of a mission (USV_MISSION_BEGIN.crc32): items in seq order, 24 bytes each."""
    crc = 0
    for it in items:
        crc = zlib.crc32(_ITEM_CRC.pack(it.mission_id, it.lat, it.lon, it.t_ms, it.seq,
                                        it.speed_cms, it.course_cdeg, it.heading_cdeg), crc)
    return crc


def to_i32(u: int) -> int:
    """A uint32 carried bit for bit in an int32 field (COMMAND_INT x/y)."""
    u &= 0xFFFFFFFF
    return u - (1 << 32) if u & 0x80000000 else u


def to_u32(i: int) -> int:
    return i & 0xFFFFFFFF


def frame_lengths(data: bytes | bytearray) -> list[int]:
    """Split a buffer of whole MAVLink 2 frames (as one side writes them) into frame
    lengths; bytes that do not start a frame form one chunk up to the next 0xFD."""
    out, i, n = [], 0, len(data)
    while i < n:
        if data[i] == mav.PROTOCOL_MARKER_V2 and i + 3 <= n:
            size = 12 + data[i + 1] + (mav.MAVLINK_SIGNATURE_BLOCK_LEN if data[i + 2] & 1 else 0)
            size = min(size, n - i)
        else:
            j = data.find(bytes([mav.PROTOCOL_MARKER_V2]), i + 1)
            size = (j if j > 0 else n) - i
        out.append(size)
        i += size
    return out


def split_frames(data: bytes | bytearray) -> list[bytes]:
    chunks, i = [], 0
    for size in frame_lengths(data):
        chunks.append(bytes(data[i:i + size]))
        i += size
    return chunks


class _CheckedMAVLink(mav.MAVLink):
    """pymavlink's MAVLink with the signature verified before the stream timestamp moves,
    a floor for streams new since boot, and the reason of the last refusal."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.stream_floor = 0
        self.last_refusal = ""
        self.bad_signature = False  # the frame being decoded carried a failing signature

    def check_signature(self, msgbuf: bytearray, srcSystem: int, srcComponent: int) -> bool:
        key = self.signing.secret_key
        assert key is not None
        tlow, thigh = self.mav_sign_unpacker.unpack(msgbuf[-12:-6])
        timestamp = tlow + (thigh << 32)
        if hashlib.sha256(key + bytes(msgbuf[:-6])).digest()[:6] != bytes(msgbuf[-6:]):
            self.last_refusal = "bad signature"
            self.bad_signature = True
            return False
        stream = (msgbuf[-13], srcSystem, srcComponent)
        last = self.signing.stream_timestamps.get(stream)
        if last is not None and timestamp <= last:
            self.last_refusal = "replayed"
            self.bad_signature = True
            return False
        if last is None and (timestamp <= self.stream_floor
                             or timestamp + 6000 * 1000 < self.signing.timestamp):
            self.last_refusal = "replayed"  # older than what this boat already accepted
            self.bad_signature = True
            return False
        self.signing.stream_timestamps[stream] = timestamp
        self.signing.timestamp = max(self.signing.timestamp, timestamp)
        return True

    def decode(self, msgbuf: bytearray) -> Any:
        self.last_refusal = "unsigned"
        self.bad_signature = False
        return super().decode(msgbuf)

    def take_unsigned(self, allowed: frozenset[int]) -> Any:
        """pymavlink's allow_unsigned_callback: ids in `allowed` without a signature; never
        a frame whose signature failed (pymavlink would take it as unsigned)."""
        return lambda _mav, msg_id: msg_id in allowed and not self.bad_signature


@dataclass(frozen=True)
class Refused:
    """A received frame that was not accepted: why, from whom (0 if unknown), which id."""

    reason: str  # unsigned | bad signature | replayed | corrupt
    system_id: int
    msg_id: int


class Codec:
    """One side's MAVLink 2 encoder/decoder. key None: unsigned (--insecure-link)."""

    def __init__(self, system_id: int, component_id: int, key: bytes | None = None, *,
                 link_id: int = 0, timestamp: int = 0, allow_unsigned: Sequence[int] = (),
                 stream_floor: int = 0) -> None:
        self.mav = _CheckedMAVLink(None, srcSystem=system_id, srcComponent=component_id)
        self.mav.robust_parsing = True
        self.key = key
        self.refused: Counter[str] = Counter()
        self.frames_in = 0
        self.bytes_out = 0
        self._allowed = frozenset(allow_unsigned)
        if key is not None:
            if len(key) != KEY_BYTES:
                raise ValueError(f"link key: {len(key)} bytes, expected {KEY_BYTES}")
            allowed = frozenset(allow_unsigned)
            self.mav.signing.secret_key = key
            self.mav.signing.link_id = link_id
            self.mav.signing.timestamp = timestamp
            self.mav.signing.sign_outgoing = True
            self.mav.signing.allow_unsigned_callback = \
                self.mav.take_unsigned(allowed) if allowed else None
            self.mav.stream_floor = stream_floor

    @property
    def signed(self) -> bool:
        return self.key is not None

    def require_signed(self, allow_unsigned: Sequence[int] = (mav.MAVLINK_MSG_ID_RADIO_STATUS,)
                       ) -> None:
        """From now on refuse unsigned frames but `allow_unsigned` (a standard vehicle
        signs once SETUP_SIGNING reached it; its unsigned frames were taken until then)."""
        allowed = frozenset(allow_unsigned)
        self._allowed = allowed
        self.mav.signing.allow_unsigned_callback = \
            self.mav.take_unsigned(allowed) if allowed else None

    @property
    def timestamp(self) -> int:
        return self.mav.signing.timestamp

    @property
    def streams(self) -> dict[tuple[int, int, int], int]:
        return self.mav.signing.stream_timestamps

    def encode(self, msg: Any, timestamp: int | None = None) -> bytes:
        """Pack (and sign) one message; `timestamp` advances the signing clock."""
        if timestamp is not None and timestamp > self.mav.signing.timestamp:
            self.mav.signing.timestamp = timestamp
        data = msg.pack(self.mav)
        self.mav.seq = (self.mav.seq + 1) % 256
        self.bytes_out += len(data)
        return data

    def feed(self, data: bytes) -> tuple[list[Any], list[Refused]]:
        """Decode received bytes: accepted messages and refused frames (noise and unknown
        message ids are counted as corrupt/unknown without a record). With a key, only
        validly signed messages pass, apart from the `allow_unsigned` ids."""
        msgs: list[Any] = []
        refused: list[Refused] = []
        for msg in self.mav.parse_buffer(data) or ():
            if isinstance(msg, mav.MAVLink_bad_data):
                buf = msg.data
                reason = str(msg.reason)
                if reason == "Invalid signature":
                    why = self.mav.last_refusal
                    sysid = buf[5] if len(buf) > 9 else 0
                    msg_id = buf[7] | buf[8] << 8 | buf[9] << 16 if len(buf) > 9 else 0
                    self.refused[why] += 1
                    refused.append(Refused(why, sysid, msg_id))
                else:
                    self.refused["corrupt"] += 1
                continue
            if isinstance(msg, mav.MAVLink_unknown):
                self.refused["unknown"] += 1  # pymavlink checks neither CRC nor signature
                continue
            if self.key is not None and not msg._signed \
                    and msg.get_msgId() not in self._allowed:
                self.refused["unsigned"] += 1
                refused.append(Refused("unsigned", msg.get_srcSystem(), msg.get_msgId()))
                continue
            self.frames_in += 1
            msgs.append(msg)
        return msgs, refused
