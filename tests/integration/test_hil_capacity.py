"""The QEMU image's mission capacity, chosen at build time to fit 8 KB of RAM (64 items): a
larger mission is refused at its first message, with the reason, and nothing is staged;
one of 64 items is taken whole and read back."""

from __future__ import annotations

from c_boat_support import MavClient, heartbeats, line_north, load_dialect, mission_crc32
from hil_support import HilProcess, require_qemu, session_image

from usvstation.link import wire

CAPACITY = 64
BAD_COUNT = 2  # USV_MISSION_BAD_COUNT


def test_the_8_kib_image_takes_64_items_and_refuses_65(tmp_path):
    require_qemu()
    key = tmp_path / "link.key"
    wire.write_key(key)
    d = load_dialect()
    hil = client = None
    try:
        hil = HilProcess("--port", "0", "--link-key", str(key), "--image", str(session_image()))
        client = MavClient(d, port=hil.port, key=wire.read_key(key))
        client.state(30)  # booted: frames signed before its boot are refused as replays
        with heartbeats(client):
            too_many = line_north(CAPACITY + 1, step_m=2.0, leg_s=1.0)
            mark = client.mark()
            ack = client.upload(7, too_many)
            assert (ack.result, ack.stage) == (BAD_COUNT, 1)
            why = f"mission 7: count {CAPACITY + 1} outside 2..{CAPACITY}"
            client.wait_for(lambda m: m.get_type() == "STATUSTEXT" and m.text == why, 10, mark)
            assert client.state().staged_id == 0

            items = line_north(CAPACITY, step_m=2.0, leg_s=1.0)
            assert client.upload(8, items).result == 0
            state = client.wait_for(lambda m: m.get_type() == "USV_MISSION_STATE"
                                    and m.active_id == 8, 10)
            assert (state.active_count, state.active_crc32) == (CAPACITY,
                                                                mission_crc32(8, items))
            last = client.mark()
            client.send(d.MAVLink_usv_mission_read_message(1, 1, 8, CAPACITY - 1))
            item = client.wait_for(lambda m: m.get_type() == "USV_MISSION_ITEM", 10, last)
            assert (item.seq, item.lat, item.t_ms) == (CAPACITY - 1, items[-1].lat,
                                                       items[-1].t_ms)
    finally:
        if client is not None:
            client.close()
        if hil is not None:
            hil.close()
