"""The MAVLink 2 codec with signing (link/wire.py): round trips, framing, refusals, keys."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from usvstation.link import wire
from usvstation.link.mission import MissionItem

KEY = bytes(range(32))
T0 = wire.signing_time(1.7e9)

u16, u32 = st.integers(0, 0xFFFF), st.integers(0, 0xFFFFFFFF)
i32 = st.integers(-(2**31), 2**31 - 1)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(u32, u16, i32, i32, u32, u16, u16, u16), min_size=1, max_size=20),
       st.integers(1, 64))
def test_items_round_trip_signed_in_any_chunking(rows, chunk):
    tx = wire.Codec(255, 190, KEY, timestamp=T0)
    rx = wire.Codec(1, 1, KEY, timestamp=T0)
    items = [MissionItem(*r) for r in rows]
    data = b"".join(tx.encode(tx.mav.usv_mission_item_encode(
        1, 1, it.mission_id, it.seq, it.lat, it.lon, it.t_ms, it.speed_cms, it.course_cdeg,
        it.heading_cdeg)) for it in items)
    assert [len(f) for f in wire.split_frames(data)] == wire.frame_lengths(data)
    got = []
    for i in range(0, len(data), chunk):
        msgs, refused = rx.feed(data[i:i + chunk])
        assert refused == []
        got += [MissionItem.from_msg(m) for m in msgs]
    assert got == items


def test_refusals_are_named_and_a_forged_future_timestamp_locks_nobody_out():
    tx = wire.Codec(255, 190, KEY, timestamp=T0)
    rx = wire.Codec(1, 1, KEY, timestamp=T0)
    hb = tx.mav.heartbeat_encode(6, 8, 0, 0, 4)
    good = tx.encode(hb)
    assert len(rx.feed(good)[0]) == 1
    assert rx.feed(good)[1][0].reason == "replayed"
    assert rx.feed(wire.Codec(255, 190).encode(hb))[1][0].reason == "unsigned"
    forger = wire.Codec(255, 190, bytes(32), timestamp=T0 + 10**9)  # far future, wrong key
    assert rx.feed(forger.encode(hb))[1][0].reason == "bad signature"
    assert len(rx.feed(tx.encode(hb))[0]) == 1  # the real station still gets through
    corrupt = bytearray(tx.encode(hb))
    corrupt[12] ^= 0xFF
    assert rx.feed(bytes(corrupt)) == ([], []) and rx.refused["corrupt"] == 1


def test_new_streams_must_be_newer_than_the_persisted_floor():
    tx = wire.Codec(255, 190, KEY, timestamp=T0)
    frame = tx.encode(tx.mav.heartbeat_encode(6, 8, 0, 0, 4))
    rebooted = wire.Codec(1, 1, KEY, timestamp=T0, stream_floor=T0 + 100)
    assert rebooted.feed(frame)[1][0].reason == "replayed"


def test_uint32_travels_bit_for_bit_in_int32():
    for u in (0, 1, 0x7FFFFFFF, 0x80000000, 0xFFFFFFFF):
        assert wire.to_u32(wire.to_i32(u)) == u


def test_key_files(tmp_path):
    path = tmp_path / "k"
    key = wire.write_key(path)
    assert wire.read_key(path) == key and len(key) == 32
    assert oct(path.stat().st_mode & 0o777) == "0o600"
    with pytest.raises(FileExistsError):
        wire.write_key(path)
    (tmp_path / "short").write_text("abcd\n")
    with pytest.raises(ValueError, match="2 bytes, expected 32"):
        wire.read_key(tmp_path / "short")
    (tmp_path / "text").write_text("not hex\n")
    with pytest.raises(ValueError, match="not hexadecimal"):
        wire.read_key(tmp_path / "text")


def test_link_key_settings(tmp_path):
    from usvstation.config import LinkKeyError, Settings, resolve_link_key

    sim = Settings(data_dir=tmp_path / "d")
    key = resolve_link_key(sim)  # the embedded sim: a key generated into the data dir
    assert len(key) == 32 and resolve_link_key(sim) == key
    assert (tmp_path / "d" / "link.key").exists()
    with pytest.raises(LinkKeyError, match="needs --link-key PATH"):
        resolve_link_key(Settings(link="/dev/ttyUSB0", data_dir=tmp_path))
    assert resolve_link_key(Settings(link="/dev/ttyUSB0", insecure_link=True)) is None
    with pytest.raises(LinkKeyError, match="contradict"):
        resolve_link_key(Settings(insecure_link=True, link_key=tmp_path / "k"))
    with pytest.raises(LinkKeyError, match="No such file"):
        resolve_link_key(Settings(link="/dev/ttyUSB0", link_key=tmp_path / "missing"))
