"""Fuzzing the decoders: >= 10,000 random and mutated byte streams (hypothesis).

The Python decoder never raises and recovers every valid frame embedded in garbage;
the C parser, built under -fsanitize=address,undefined, survives the very same
streams and reports exactly the frames the Python decoder reports.
"""

from __future__ import annotations

import random

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from protocol_helpers import RANGES, build_c_tool, python_decode_lines, run_tool

from usvstation.link import codec
from usvstation.link import messages as m

RANDOM_EXAMPLES = 5000
MUTATED_EXAMPLES = 5000


def _frame_pool(n: int = 400) -> list[bytes]:
    """Valid frames of every message type with random values (seeded, built once)."""
    rng = random.Random(4)
    enc = codec.Encoder()
    pool = []
    for i in range(n):
        cls = m.MESSAGE_TYPES[i % len(m.MESSAGE_TYPES)]
        values = [rng.randint(*RANGES[c]) for c in cls.FORMAT[1:]]
        if cls.TEXT_MAX:
            values.append("".join(rng.choice("aé✓ 0") for _ in range(rng.randint(0, 16))))
        pool.append(enc.encode(cls._make(values)))
    return pool


POOL = _frame_pool()
embedded_stream = st.lists(
    st.tuples(st.binary(max_size=80), st.sampled_from(POOL)), max_size=6
).flatmap(lambda pairs: st.binary(max_size=80).map(
    lambda tail: (b"".join(g + f for g, f in pairs) + tail, [f for _, f in pairs])))


@st.composite
def mutated_stream(draw):
    """A valid stream with bit flips, deleted, inserted and duplicated bytes, truncated."""
    data = bytearray(draw(embedded_stream)[0])
    for _ in range(draw(st.integers(1, 8))):
        if not data:
            break
        op = draw(st.sampled_from(["flip", "delete", "insert", "dup", "zero"]))
        i = draw(st.integers(0, len(data) - 1))
        if op == "flip":
            data[i] ^= 1 << draw(st.integers(0, 7))
        elif op == "delete":
            del data[i]
        elif op == "insert":
            data.insert(i, draw(st.integers(0, 255)))
        elif op == "dup":
            data[i:i] = data[i : i + draw(st.integers(1, 40))]
        else:
            data[i] = 0
    return bytes(data[: draw(st.integers(0, len(data)))])


def _fuzz() -> list[bytes]:
    streams: list[bytes] = []
    common = {"deadline": None, "database": None,
              "suppress_health_check": [HealthCheck.too_slow, HealthCheck.data_too_large]}

    @settings(max_examples=RANDOM_EXAMPLES, **common)
    @given(embedded_stream, st.integers(1, 64))
    def random_streams(case, chunk):
        stream, frames = case
        streams.append(stream)
        dec = codec.FrameDecoder()
        got = []
        for i in range(0, len(stream), chunk):  # fed in arbitrary chunks
            got += dec.feed_raw(stream[i : i + chunk])
        wire = iter(codec.encode_frame(r.msg_id, r.seq, r.payload, r.version) for r in got)
        assert all(f in wire for f in frames)  # every embedded frame, in order

    @settings(max_examples=MUTATED_EXAMPLES, **common)
    @given(st.one_of(mutated_stream(), st.binary(max_size=400)))
    def mutated_streams(stream):
        streams.append(stream)
        dec = codec.FrameDecoder()
        for msg in dec.feed(stream):  # must not raise; every result is re-encodable
            codec.encode_payload(msg)
        assert dec.stats.frames + dec.stats.errors <= stream.count(0) + 1

    random_streams()
    mutated_streams()
    return streams


@pytest.fixture(scope="module")
def fuzzed_streams() -> list[bytes]:
    return _fuzz()


def test_python_decoder_survives_and_recovers(fuzzed_streams):
    assert len(fuzzed_streams) >= RANDOM_EXAMPLES + MUTATED_EXAMPLES


def test_c_parser_survives_the_same_streams_under_sanitizers(fuzzed_streams, tmp_path):
    exe = build_c_tool(tmp_path, sanitize=True)
    c_lines = run_tool(exe, "decode", "\n".join(s.hex() for s in fuzzed_streams) + "\n")
    assert c_lines == python_decode_lines(fuzzed_streams)
