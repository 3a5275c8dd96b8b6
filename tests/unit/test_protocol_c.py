"""The C99 codec (protocol/c) against the Python codec: both directions byte-identical.

Built with gcc -std=c99 -Wall -Wextra -Werror -pedantic, once plain and once under
-fsanitize=address,undefined. Skipped only when gcc is missing, and never under CI=true.
"""

from __future__ import annotations

import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from protocol_helpers import (
    ROOT,
    any_message,
    build_c_tool,
    encode_line,
    field_tokens,
    python_decode_lines,
    run_tool,
)

from usvstation.link import codec

VECTORS = json.loads((ROOT / "protocol" / "vectors" / "frames.json").read_text())["frames"]


@pytest.fixture(scope="module", params=[False, True], ids=["strict", "asan-ubsan"])
def tool(request, tmp_path_factory):
    return build_c_tool(tmp_path_factory.mktemp("c"), sanitize=request.param)


def _vector_messages():
    return [(codec.MESSAGE_BY_NAME[v["name"]](**v["fields"]), v["seq"], v["frame_hex"])
            for v in VECTORS]


def test_python_encodes_c_decodes_and_re_encodes_identically(tool):
    vecs = _vector_messages()
    lines = run_tool(tool, "decode", "\n".join(hexf for _, _, hexf in vecs) + "\n")
    assert len(lines) == len(vecs)
    for line, (msg, _, hexf) in zip(lines, vecs, strict=True):
        _, frame_hex, *fields = line.split()
        assert frame_hex == hexf
        assert fields == field_tokens(msg), msg.NAME


def test_c_encodes_python_decodes_and_re_encodes_identically(tool):
    vecs = _vector_messages()
    lines = run_tool(tool, "encode", "\n".join(encode_line(msg, seq) for msg, seq, _ in vecs))
    assert lines == [hexf for _, _, hexf in vecs]
    for line, (msg, seq, _) in zip(lines, vecs, strict=True):
        frame = bytes.fromhex(line)
        assert codec.FrameDecoder().feed(frame) == [msg]
        assert codec.Encoder(seq).encode(msg) == frame


def test_whole_vector_stream_in_one_parser(tool):
    """All vector frames back to back in one stream, through one C parser."""
    stream = "".join(hexf for _, _, hexf in _vector_messages())
    lines = run_tool(tool, "decode", stream + "\n")
    assert [ln.split()[1] for ln in lines] == [hexf for _, _, hexf in _vector_messages()]


def test_random_messages_both_directions(tool):
    msgs: list = []

    @settings(max_examples=1500, deadline=None, database=None)
    @given(any_message, st.integers(0, 255))
    def collect(msg, seq):
        msgs.append((msg, seq))

    collect()
    py_frames = [codec.Encoder(seq).encode(msg).hex() for msg, seq in msgs]
    c_frames = run_tool(tool, "encode", "\n".join(encode_line(x, s) for x, s in msgs) + "\n")
    assert c_frames == py_frames
    decoded = run_tool(tool, "decode", "\n".join(py_frames) + "\n")
    assert decoded == python_decode_lines([bytes.fromhex(f) for f in py_frames])
