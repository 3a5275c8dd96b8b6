"""usv-link codec: CRCs, COBS, frames, messages, shared vectors and the generated files."""

from __future__ import annotations

import importlib.util
import json
import struct
import sys
import zlib
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from protocol_helpers import any_message

from usvstation.link import codec
from usvstation.link import messages as m

ROOT = Path(__file__).resolve().parents[2]


def _generator():
    spec = importlib.util.spec_from_file_location("usv_generate", ROOT / "protocol" / "generate.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules["usv_generate"] = mod
    spec.loader.exec_module(mod)
    return mod


def test_crc16_is_ccitt_false_and_crc32_is_ieee():
    assert codec.crc16(b"123456789") == 0x29B1  # the catalogue check value
    assert zlib.crc32(b"123456789") == 0xCBF43926


def test_cobs_known_examples():
    assert codec.cobs_encode(b"") == b"\x01"
    assert codec.cobs_encode(b"\x00") == b"\x01\x01"
    assert codec.cobs_encode(b"\x11\x22\x00\x33") == b"\x03\x11\x22\x02\x33"
    assert codec.cobs_encode(bytes(range(1, 255))) == b"\xff" + bytes(range(1, 255)) + b"\x01"
    assert codec.cobs_decode(b"\x05\x11") is None  # the code points past the end
    assert codec.cobs_decode(b"\x03\x11\x22\x02\x33") == b"\x11\x22\x00\x33"


@given(st.binary(max_size=600))
def test_cobs_round_trip_has_no_zero(data):
    enc = codec.cobs_encode(data)
    assert 0 not in enc
    assert codec.cobs_decode(enc) == data


@settings(max_examples=500)
@given(any_message, st.integers(0, 255))
def test_every_message_round_trips_through_a_frame(msg, seq):
    frame = codec.Encoder(seq).encode(msg)
    assert frame[0] == 0 and frame[-1] == 0 and 0 not in frame[1:-1]
    assert len(frame) <= codec.MAX_ENCODED + 2
    assert codec.decode_body(frame)[:3] == (m.PROTOCOL_VERSION, msg.ID, seq)
    assert codec.FrameDecoder().feed(frame) == [msg]


def test_layout_is_little_endian_with_big_endian_crc():
    frame = codec.Encoder(7).encode(m.Command(command_id=0x1234, command=m.CommandCode.START,
                                              mission_id=0x0506))
    version, msg_id, seq, payload = codec.decode_body(frame)
    assert (version, msg_id, seq) == (1, 2, 7)
    assert payload == bytes([0x34, 0x12, 0x01, 0x06, 0x05])
    body = codec.cobs_decode(frame[1:-1])
    assert body[-2:] == codec.crc16(body[:-2]).to_bytes(2, "big")


def test_text_is_cut_at_a_character_boundary():
    msg = m.StatusText(1, "é" * 40)  # 80 bytes of UTF-8
    out = codec.FrameDecoder().feed(codec.Encoder().encode(msg))[0]
    assert out.text == "é" * 25


def test_out_of_range_field_is_refused_with_the_message_name():
    with pytest.raises(ValueError, match="MISSION_ITEM"):
        codec.Encoder().encode(m.MissionItem(1, 0, 91 * 10**7, 0, -5, 0, 0))


def test_decoder_recovers_after_garbage_split_anywhere():
    msgs = [m.Heartbeat(m.DEFINITION_CRC, 1, 2, 1, 2, 0, 7, 1000 * i) for i in range(5)]
    wire = b"\x13\x00\xff\xfe" + codec.Encoder().encode_many(msgs) + b"\x42" * 300
    for cut in range(0, len(wire), 7):
        dec = codec.FrameDecoder()
        assert dec.feed(wire[:cut]) + dec.feed(wire[cut:]) == msgs


def test_decoder_counts_errors_and_lost_frames():
    enc = codec.Encoder()
    frames = [enc.encode(m.GuidanceSetpoint(i, 100, 500)) for i in range(6)]
    bad = bytearray(frames[1])
    bad[5] ^= 0x10
    dec = codec.FrameDecoder()
    out = dec.feed(frames[0] + bytes(bad) + frames[3] + b"\x01" * 200 + b"\x00" + frames[4])
    assert [g.heading_cdeg for g in out] == [0, 3, 4]
    assert dec.stats.bad_crc == 1 and dec.stats.oversize == 1
    assert dec.stats.lost == 2  # seq 1 and 2 never arrived intact


def test_foreign_version_heartbeat_is_read_from_its_frozen_prefix():
    payload = struct.pack("<IB", 0xDEADBEEF, 9) + b"\x02" * 12
    frame = codec.encode_frame(0, 3, payload, version=9)
    other = codec.encode_frame(9, 4, b"\x01" * 37, version=9)
    dec = codec.FrameDecoder()
    out = dec.feed(frame + other)
    assert out == [m.Heartbeat(0xDEADBEEF, 9, 0, 0, 0, 0, 0, 0)]
    assert dec.stats.bad_version == 1


def test_mission_crc32_layout():
    items = [m.MissionItem(3, 0, 305135000, 1144182000, 0, 100, 27000),
             m.MissionItem(3, 1, -1, 2, 1500, 65535, 35999)]
    expected = zlib.crc32(struct.pack("<iiHH", 10, -20, 9000, 2) + struct.pack(
        "<iiIHH", 305135000, 1144182000, 0, 100, 27000) + struct.pack("<iiIHH", -1, 2, 1500,
                                                                      65535, 35999))
    assert codec.mission_crc32((10, -20, 9000), items) == expected


def test_shared_vectors_encode_and_decode_exactly():
    doc = json.loads((ROOT / "protocol" / "vectors" / "frames.json").read_text())
    assert doc["definition_crc"] == f"0x{m.DEFINITION_CRC:08X}"
    for vec in doc["frames"]:
        cls = codec.MESSAGE_BY_NAME[vec["name"]]
        msg = cls(**vec["fields"])
        assert codec.Encoder(vec["seq"]).encode(msg).hex() == vec["frame_hex"], vec["name"]
        assert codec.FrameDecoder().feed(bytes.fromhex(vec["frame_hex"])) == [msg]
    names = {v["name"] for v in doc["frames"]}
    assert names == {cls.NAME for cls in m.MESSAGE_TYPES}


def test_stream_vectors_recover_every_embedded_frame():
    doc = json.loads((ROOT / "protocol" / "vectors" / "streams.json").read_text())
    for vec in doc["streams"]:
        got = [codec.encode_frame(r.msg_id, r.seq, r.payload, r.version).hex()
               for r in codec.FrameDecoder().feed_raw(bytes.fromhex(vec["stream_hex"]))]
        it = iter(got)
        assert all(f in it for f in vec["embedded_frames_hex"])


def test_generated_files_are_fresh():
    """Fails when protocol/messages.toml changed without `python protocol/generate.py`."""
    gen = _generator()
    d = gen.load_definition()
    for path, text in gen.outputs(d).items():
        assert path.read_text(encoding="utf-8") == text, f"stale {path}: run protocol/generate.py"
    frames, streams = gen.gen_vectors(d)
    assert gen.FRAMES.read_text(encoding="utf-8") == frames
    assert gen.STREAMS.read_text(encoding="utf-8") == streams


def test_definition_crc_tracks_layout_not_docs():
    gen = _generator()
    d = gen.load_definition()
    assert gen.definition_crc(d) == m.DEFINITION_CRC
    d["messages"][9]["doc"] = "reworded"
    assert gen.definition_crc(d) == m.DEFINITION_CRC
    d["messages"][9]["fields"][1]["type"] = "u32"
    assert gen.definition_crc(d) != m.DEFINITION_CRC
    assert gen.gen_c_header(d) != (ROOT / "protocol/c/usv_messages.h").read_text()
