"""Shared helpers for the usv-link protocol tests: message strategies and the C vector tool."""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest
from hypothesis import strategies as st

from usvstation.link import codec
from usvstation.link import messages as m

ROOT = Path(__file__).resolve().parents[2]
C_DIR = ROOT / "protocol" / "c"
STRICT = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O1"]
SANITIZE = ["-g", "-fsanitize=address,undefined", "-fno-sanitize-recover=all",
            "-fno-omit-frame-pointer"]
RANGES = {"B": (0, 0xFF), "H": (0, 0xFFFF), "I": (0, 0xFFFFFFFF), "b": (-0x80, 0x7F),
          "h": (-0x8000, 0x7FFF), "i": (-0x80000000, 0x7FFFFFFF)}


def message_strategy(cls: type) -> st.SearchStrategy:
    ints = [st.integers(*RANGES[c]) for c in cls.FORMAT[1:]]
    if cls.TEXT_MAX:
        text = st.text(max_size=cls.TEXT_MAX).filter(
            lambda s: len(s.encode("utf-8")) <= cls.TEXT_MAX)
        return st.tuples(*ints, text).map(cls._make)
    return st.tuples(*ints).map(cls._make)


any_message = st.sampled_from(m.MESSAGE_TYPES).flatmap(message_strategy)


def build_c_tool(out_dir: Path, sanitize: bool) -> Path:
    """Compile protocol/c with the strict flags (and ASan/UBSan); skip if there is no gcc,
    except under CI=true where a missing compiler is a failure."""
    gcc = shutil.which("gcc")
    if gcc is None:
        if os.environ.get("CI", "").lower() == "true":
            pytest.fail("gcc is required under CI to test the C codec")
        pytest.skip("gcc not installed: the C codec is not tested here")
    exe = out_dir / ("vector_tool_san" if sanitize else "vector_tool")
    cmd = [gcc, *STRICT, *(SANITIZE if sanitize else []), f"-I{C_DIR}",
           str(C_DIR / "usv_link.c"), str(C_DIR / "tests" / "vector_tool.c"), "-o", str(exe)]
    res = subprocess.run(cmd, capture_output=True, text=True, check=False)
    assert res.returncode == 0, f"C build failed:\n{' '.join(cmd)}\n{res.stderr}"
    return exe


def run_tool(exe: Path, mode: str, text: str) -> list[str]:
    env = dict(os.environ, ASAN_OPTIONS="detect_leaks=1:abort_on_error=1",
               UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1")
    res = subprocess.run([str(exe), mode], input=text, capture_output=True, text=True,
                         env=env, check=False, timeout=120)
    assert res.returncode == 0, (
        f"{exe.name} {mode} failed ({res.returncode}):\n{res.stderr[-3000:]}")
    return res.stdout.splitlines()


def field_tokens(msg) -> list[str]:
    """A message's values as the C tool prints them (text as hex, '-' when empty)."""
    out = []
    for v in msg:
        if isinstance(v, str):
            raw = v.encode("utf-8", "surrogateescape")
            out.append(raw.hex() if raw else "-")
        else:
            out.append(str(int(v)))
    return out


def encode_line(msg, seq: int) -> str:
    """One input line for `vector_tool encode`."""
    nums = [str(int(v)) for v in msg if not isinstance(v, str)]
    text = [v for v in msg if isinstance(v, str)]
    raw = text[0].encode("utf-8", "surrogateescape").hex() if text and text[0] else "-"
    return f"{msg.ID} {seq} {len(nums)} {' '.join(nums)} {raw}"


def python_decode_lines(streams: list[bytes]) -> list[str]:
    """What `vector_tool decode` must print for these streams, computed in Python."""
    lines = []
    for k, stream in enumerate(streams):
        for raw in codec.FrameDecoder().feed_raw(stream):
            if raw.version != m.PROTOCOL_VERSION:
                frame = codec.encode_frame(raw.msg_id, raw.seq, raw.payload, raw.version)
                lines.append(f"{k} {frame.hex()} foreign")
                continue
            msg = codec.unpack_payload(raw.msg_id, raw.payload)
            frame = codec.encode_frame(msg.ID, raw.seq, codec.encode_payload(msg))
            lines.append(" ".join([str(k), frame.hex(), *field_tokens(msg)]))
    return lines
