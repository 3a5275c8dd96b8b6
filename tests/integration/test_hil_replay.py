"""A recorded signed session replayed to the firmware in QEMU after a reset starts nothing,
even when the GNSS gives no time: the emulated chip keeps its signing floor in its flash page
image file (--nv-file), which QEMU loads into flash at the next boot. Without that file the
same replay starts the mission: the floor is what refuses it.

The conformance suite replays to the QEMU firmware too, with the GNSS time (which alone
refuses the replay); here the GNSS has none (`--no-gnss-time`)."""

from __future__ import annotations

import time
from pathlib import Path

from c_boat_support import (
    CMD_START,
    IDLE,
    RUNNING,
    MavClient,
    heartbeats,
    line_north,
    load_dialect,
    mission_crc32,
)
from hil_support import HilProcess, require_qemu, session_image

from usvstation.hil.provision import nv_floor
from usvstation.link import wire

MISSION_ID = 4242
SESSION = 77


def signed_time(frame: bytes) -> int:
    return int.from_bytes(frame[-12:-6], "little")


def record_a_session(image: Path, key: Path, nv: Path) -> list[bytes]:
    """Upload and START a mission on a boat without GNSS time; return the station's frames
    once the boat's flash page holds a floor at the last of them."""
    d = load_dialect()
    hil = client = None
    try:
        hil = HilProcess("--port", "0", "--link-key", str(key), "--nv-file", str(nv),
                         "--no-gnss-time", "--image", str(image))
        client = MavClient(d, port=hil.port, key=wire.read_key(key))
        with heartbeats(client):
            pos = client.wait_for(lambda m: m.get_type() == "GLOBAL_POSITION_INT", 30)
            items = line_north(3, lat=pos.lat / 1e7, lon=pos.lon / 1e7)
            assert client.upload(MISSION_ID, items).result == 0
            ack = client.command(CMD_START, 1, SESSION, MISSION_ID,
                                 mission_crc32(MISSION_ID, items))
            assert ack.result == 0, ack
            client.wait_state(RUNNING)
            recorded = list(client.sent)
            newest = max(signed_time(f) for f in recorded)
            deadline = time.monotonic() + 30
            while not (nv.is_file() and nv_floor(nv.read_bytes()) >= newest):
                assert time.monotonic() < deadline, "the signing floor never reached flash"
                time.sleep(0.05)
        return recorded
    finally:
        if client is not None:
            client.close()
        if hil is not None:
            hil.close()


def replay(image: Path, key: Path, nv: Path, recorded: list[bytes]) -> object:
    """Boot a boat (no GNSS time) on `nv`, replay the frames, return its report after them."""
    d = load_dialect()
    hil = client = None
    try:
        hil = HilProcess("--port", "0", "--link-key", str(key), "--nv-file", str(nv),
                         "--no-gnss-time", "--image", str(image))
        # a listener that checks no signatures: a boat that has not heard its station yet
        # signs from its boot floor, which is 0 on a chip never linked
        client = MavClient(d, port=hil.port, key=None)
        client.wait_for(lambda m: m.get_type() == "USV_MISSION_STATE", 30)
        start = client.mark()
        client.write(b"".join(recorded))
        # the boat has seen every frame once it refused them all or started the mission
        return client.wait_for(lambda m: m.get_type() == "USV_MISSION_STATE" and (
            m.rejected >= len(recorded) or m.state == RUNNING), 60, start)
    finally:
        if client is not None:
            client.close()
        if hil is not None:
            hil.close()


def test_replayed_session_after_a_reset_starts_nothing_with_the_flash_floor_alone(tmp_path):
    require_qemu()
    image = session_image()
    key = tmp_path / "link.key"
    wire.write_key(key)
    nv = tmp_path / "nv.bin"
    recorded = record_a_session(image, key, nv)

    after_reset = replay(image, key, nv, recorded)  # the same chip: its flash page kept
    assert after_reset.state == IDLE and after_reset.active_id == 0
    assert after_reset.station_session == 0 and after_reset.rejected >= len(recorded)

    fresh = replay(image, key, tmp_path / "factory-new.bin", recorded)  # a chip never linked
    assert fresh.state == RUNNING and fresh.active_id == MISSION_ID
