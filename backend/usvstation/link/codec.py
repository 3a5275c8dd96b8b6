"""usv-link framing and message codec (protocol/README.md "Framing"), sans-IO.

A frame body is `version u8 | msg_id u8 | seq u8 | payload | crc16 (big-endian)`,
with CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF) over version..payload, so the CRC
of a whole valid body is 0. On the wire a body is COBS-encoded and sent between two
0x00 delimiters: `00 COBS(body) 00`. The leading delimiter lets a receiver recover a
frame that follows garbage; empty frames (two delimiters in a row) are ignored.

The message types come from protocol/messages.toml through the generated module
`usvstation.link.messages`. Hot paths use precompiled `struct.Struct`s, the C CRC in
`binascii.crc_hqx`, `bytes.split` for delimiting and block-wise (not byte-wise) COBS.
"""

from __future__ import annotations

import struct
import zlib
from binascii import crc_hqx
from collections.abc import Iterable, Sequence
from typing import Any, NamedTuple

from usvstation.link import messages as m

HEADER_LEN = 3
CRC_LEN = 2
MIN_BODY = HEADER_LEN + CRC_LEN
MAX_BODY = HEADER_LEN + m.MAX_PAYLOAD + CRC_LEN
MAX_ENCODED = MAX_BODY + 1  # COBS adds one byte to bodies shorter than 254
FROZEN_HEARTBEAT = struct.Struct("<IB")  # definition_crc, protocol_version: all versions

Message = Any  # one of the NamedTuple types in usvstation.link.messages


class _Spec:
    __slots__ = ("cls", "fixed_len", "make", "max_len", "msg_id", "struct", "text_max")

    def __init__(self, cls: type) -> None:
        self.cls = cls
        self.msg_id = cls.ID
        self.struct = struct.Struct(cls.FORMAT)
        self.text_max = cls.TEXT_MAX
        self.fixed_len = self.struct.size
        self.max_len = self.fixed_len + self.text_max
        self.make = cls._make


SPECS: dict[int, _Spec] = {cls.ID: _Spec(cls) for cls in m.MESSAGE_TYPES}
_SPEC_BY_CLASS: dict[type, _Spec] = {s.cls: s for s in SPECS.values()}
MESSAGE_BY_NAME: dict[str, type] = {cls.NAME: cls for cls in m.MESSAGE_TYPES}


class RawFrame(NamedTuple):
    """A frame that passed COBS, CRC and length checks, payload not yet unpacked."""

    version: int
    msg_id: int
    seq: int
    payload: bytes


# ----------------------------------------------------------------------------- COBS


def cobs_encode(data: bytes) -> bytes:
    """Consistent Overhead Byte Stuffing: the result has no 0x00 byte."""
    out = bytearray()
    for piece in data.split(b"\x00"):
        while len(piece) >= 254:
            out.append(0xFF)
            out += piece[:254]
            piece = piece[254:]
        out.append(len(piece) + 1)
        out += piece
    return bytes(out)


def cobs_decode(enc: bytes) -> bytes | None:
    """Inverse of cobs_encode; None if `enc` is not a valid COBS encoding."""
    out = bytearray()
    i, n = 0, len(enc)
    while i < n:
        code = enc[i]
        j = i + code
        if code == 0 or j > n:
            return None
        out += enc[i + 1 : j]
        i = j
        if code != 0xFF and i < n:
            out.append(0)
    return bytes(out)


# ----------------------------------------------------------------------------- CRCs


def crc16(data: bytes, crc: int = 0xFFFF) -> int:
    """CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF, no reflection, no final xor)."""
    return crc_hqx(data, crc)


def mission_crc32(origin: tuple[int, int, int], items: Sequence[Any]) -> int:
    """Whole-mission CRC-32 (zlib/IEEE 802.3) as in protocol/README.md "Mission CRC-32":
    over origin_lat_e7 i32, origin_lon_e7 i32, ramp_bearing_cdeg u16, count u16, then each
    item's lat_e7 i32, lon_e7 i32, t_ms u32, speed_cms u16, heading_cdeg u16 (little-endian)."""
    crc = zlib.crc32(_ORIGIN.pack(*origin, len(items)))
    for it in items:
        crc = zlib.crc32(_ITEM.pack(it.lat_e7, it.lon_e7, it.t_ms, it.speed_cms,
                                    it.heading_cdeg), crc)
    return crc


_ORIGIN = struct.Struct("<iiHH")
_ITEM = struct.Struct("<iiIHH")


# ----------------------------------------------------------------------------- encoding


def encode_payload(msg: Message) -> bytes:
    """The payload bytes of a message (little-endian fields, text last)."""
    spec = _SPEC_BY_CLASS.get(type(msg))
    if spec is None:
        raise TypeError(f"not a usv-link message: {type(msg).__name__}")
    if spec.text_max:
        *fixed, text = msg
        raw = text.encode("utf-8", "surrogateescape")
        if len(raw) > spec.text_max:  # cut at a character boundary
            raw = raw[: spec.text_max].decode("utf-8", "ignore").encode("utf-8")
        try:
            return spec.struct.pack(*fixed) + raw
        except struct.error as exc:
            raise ValueError(f"{spec.cls.NAME}: {exc}") from None
    try:
        return spec.struct.pack(*msg)
    except struct.error as exc:
        raise ValueError(f"{spec.cls.NAME} {msg}: {exc}") from None


def encode_frame(msg_id: int, seq: int, payload: bytes, version: int = m.PROTOCOL_VERSION) -> bytes:
    """The wire bytes `00 COBS(body) 00` of one frame."""
    body = bytes((version, msg_id, seq & 0xFF)) + payload
    body += crc_hqx(body, 0xFFFF).to_bytes(2, "big")
    return b"\x00" + cobs_encode(body) + b"\x00"


class Encoder:
    """Encodes messages into frames with a rolling sequence number (one per sender)."""

    def __init__(self, first_seq: int = 0) -> None:
        self.seq = first_seq & 0xFF

    def encode(self, msg: Message) -> bytes:
        frame = encode_frame(msg.ID, self.seq, encode_payload(msg))
        self.seq = (self.seq + 1) & 0xFF
        return frame

    def encode_many(self, msgs: Iterable[Message]) -> bytes:
        return b"".join(self.encode(x) for x in msgs)


# ----------------------------------------------------------------------------- decoding


def decode_body(frame: bytes) -> tuple[int, int, int, bytes]:
    """(version, msg_id, seq, payload) of one complete wire frame; ValueError if invalid."""
    enc = frame.strip(b"\x00")
    body = cobs_decode(enc)
    if body is None or len(body) < MIN_BODY or crc_hqx(body, 0xFFFF) != 0:
        raise ValueError("not a valid usv-link frame")
    return body[0], body[1], body[2], body[3:-2]


def unpack_payload(msg_id: int, payload: bytes, version: int = m.PROTOCOL_VERSION) -> Message:
    """A message from a checked payload (as RawFrame gives)."""
    if version != m.PROTOCOL_VERSION:  # only HEARTBEAT's frozen prefix is readable
        crc, ver = FROZEN_HEARTBEAT.unpack_from(payload)
        return m.Heartbeat(crc, ver, 0, 0, 0, 0, 0, 0)
    spec = SPECS[msg_id]
    if spec.text_max:
        fixed = spec.struct.unpack_from(payload)
        text = payload[spec.fixed_len :].decode("utf-8", "surrogateescape")
        return spec.make((*fixed, text))
    return spec.make(spec.struct.unpack(payload))


class DecoderStats:
    """Counters of a FrameDecoder; `lost` estimates frames missing from sequence gaps."""

    __slots__ = ("bad_cobs", "bad_crc", "bad_length", "bad_version", "frames", "lost",
                 "oversize", "unknown_id")

    def __init__(self) -> None:
        self.frames = self.bad_cobs = self.bad_crc = self.bad_length = 0
        self.bad_version = self.unknown_id = self.oversize = self.lost = 0

    @property
    def errors(self) -> int:
        return (self.bad_cobs + self.bad_crc + self.bad_length + self.bad_version
                + self.unknown_id + self.oversize)

    def as_dict(self) -> dict[str, int]:
        return {k: getattr(self, k) for k in self.__slots__} | {"errors": self.errors}


class FrameDecoder:
    """Streaming decoder: feed any chunks of bytes, get the messages of the valid frames.

    Never raises on input: garbage, truncated and corrupted frames are dropped and
    counted in `stats`; decoding restarts at the next 0x00. A frame longer than
    MAX_ENCODED bytes is dropped whole (as the C parser does with its fixed buffer).
    """

    def __init__(self) -> None:
        self._buf = b""
        self._overflow = False
        self._last_seq = -1
        self.stats = DecoderStats()

    def feed(self, data: bytes) -> list[Message]:
        """Messages of the frames completed by `data`, in order."""
        out = []
        for raw in self._frames(data):
            if raw.version != m.PROTOCOL_VERSION:
                out.append(unpack_payload(raw.msg_id, raw.payload, raw.version))
                continue
            spec = SPECS[raw.msg_id]
            if spec.text_max:
                out.append(unpack_payload(raw.msg_id, raw.payload))
            else:
                out.append(spec.make(spec.struct.unpack(raw.payload)))
        return out

    def feed_raw(self, data: bytes) -> list[RawFrame]:
        """The checked frames completed by `data`, payloads not unpacked."""
        return list(self._frames(data))

    def _frames(self, data: bytes) -> Iterable[RawFrame]:
        if 0 not in data:
            self._append(data)
            return
        parts = data.split(b"\x00")
        first = parts[0]
        if self._buf or self._overflow:
            first = self._buf + first
            if self._overflow or len(first) > MAX_ENCODED:
                first = b"\xff" * (MAX_ENCODED + 1)  # flags the oversize frame below
        self._buf, self._overflow = b"", False
        parts[0] = first
        tail = parts.pop()
        for part in parts:
            if part:
                raw = self._check(part)
                if raw is not None:
                    yield raw
        self._append(tail)

    def _append(self, data: bytes) -> None:
        if self._overflow:
            return
        self._buf += data
        if len(self._buf) > MAX_ENCODED:
            self._buf, self._overflow = b"", True

    def _check(self, part: bytes) -> RawFrame | None:
        st = self.stats
        if len(part) > MAX_ENCODED:
            st.oversize += 1
            return None
        body = cobs_decode(part)
        if body is None:
            st.bad_cobs += 1
            return None
        n = len(body)
        if n < MIN_BODY or crc_hqx(body, 0xFFFF):
            st.bad_crc += 1
            return None
        version, msg_id, seq = body[0], body[1], body[2]
        payload = body[3:-2]
        if version != m.PROTOCOL_VERSION:
            if msg_id != m.Heartbeat.ID or len(payload) < FROZEN_HEARTBEAT.size:
                st.bad_version += 1
                return None
        else:
            spec = SPECS.get(msg_id)
            if spec is None:
                st.unknown_id += 1
                return None
            if not spec.fixed_len <= len(payload) <= spec.max_len:
                st.bad_length += 1
                return None
        st.frames += 1
        if self._last_seq >= 0:
            st.lost += (seq - self._last_seq - 1) & 0xFF
        self._last_seq = seq
        return RawFrame(version, msg_id, seq, payload)
