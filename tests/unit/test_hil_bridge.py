"""The HIL bridge (usvstation.hil): the vessel model stepped to the firmware's clock by its
own HIL_ACTUATOR_CONTROLS, answered with signed HIL_GPS fixes; the provisioning page and the
QEMU command line. Pure: no QEMU, no sockets."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from usvstation.dynamics import otter
from usvstation.hil.bridge import HilBridge
from usvstation.hil.provision import CONFIG_PAGE_ADDR, NV_PAGE_ADDR, Provision
from usvstation.hil.qemu import QemuCommand
from usvstation.link import wire
from usvstation.link.mavlink import usv_recovery as mav
from usvstation.scenario import load_scenario
from usvstation.sim.sensors import GpsNoise

KEY = bytes(range(32))
UNIX = 1_790_000_000.0  # some UTC of the GNSS
EXACT = dict(bias_std_m=0.0, white_std_m=0.0)


def bridge(**kw) -> HilBridge:
    gps = kw.pop("gps", GpsNoise(**EXACT))
    return HilBridge.for_scenario(load_scenario("case1"), gps, key=KEY, **kw)


class Firmware:
    """The firmware's end of the HIL link: signed HIL_ACTUATOR_CONTROLS out, HIL_GPS in."""

    def __init__(self, key: bytes | None = KEY, system_id: int = 1) -> None:
        self.tx = wire.Codec(system_id, mav.MAV_COMP_ID_AUTOPILOT1, key,
                             timestamp=wire.signing_time(UNIX - 10))
        self.rx = wire.Codec(system_id, mav.MAV_COMP_ID_AUTOPILOT1, key)

    def controls(self, t_s: float, left: float, right: float) -> bytes:
        c = [left, right] + [0.0] * 14
        msg = self.tx.mav.hil_actuator_controls_encode(round(t_s * 1e6), c,
                                                       mav.MAV_MODE_FLAG_HIL_ENABLED, 0)
        return self.tx.encode(msg)

    def fixes(self, data: bytes) -> list:
        msgs, refused = self.rx.feed(data)
        assert refused == []
        return [m for m in msgs if m.get_type() == "HIL_GPS"]


def drive(b: HilBridge, fw: Firmware, seconds: float, left: float, right: float,
          t0: float = 0.0, period: float = 0.05) -> list:
    out = []
    for k in range(round(seconds / period) + 1):
        t = t0 + k * period
        out += fw.fixes(b.receive(fw.controls(t, left, right), UNIX + t))
    return out


def test_a_fix_answers_each_control_at_the_start_pose_with_utc_and_heading():
    b, fw = bridge(), Firmware()
    fix, = fw.fixes(b.receive(fw.controls(0.0, 0.0, 0.0), UNIX))
    frame = b.frame
    lat, lon = frame.to_geodetic(85.0, 10.0)  # case1's start
    assert (fix.lat, fix.lon) == (round(float(lat) * 1e7), round(float(lon) * 1e7))
    assert fix.time_usec == round(UNIX * 1e6) and fix.fix_type == 3
    assert fix.yaw == 27000  # ramp heading 180 on a ramp bearing 90: due west
    assert fix.vel == 0 and fix.get_srcComponent() == mav.MAV_COMP_ID_GPS


def test_full_ahead_drives_the_otter_along_its_heading_at_its_top_speed():
    b, fw = bridge(), Firmware()
    fixes = drive(b, fw, 60.0, 1.0, 1.0)
    s = b.truth
    assert s.t == pytest.approx(60.0)  # the model's time is the firmware's
    assert abs(s.y - 10.0) < 0.01 and s.x < 85.0 - 100.0  # straight west, along -x
    assert fixes[-1].vel / 100 == pytest.approx(otter().top_speed, rel=0.05)
    assert fixes[-1].cog == 27000 and b.stats.fixes == len(fixes) == 1201


def test_differential_throttle_turns_the_boat_to_starboard():
    b, fw = bridge(), Firmware()
    fixes = drive(b, fw, 10.0, 0.6, 0.2)  # left ahead of right: clockwise, compass up
    assert 27000 < fixes[-1].yaw <= 36000 or fixes[-1].yaw < 9000


def test_the_run_is_the_same_however_late_the_bytes_arrive():
    b1, b2 = bridge(), bridge()
    fw1, fw2 = Firmware(), Firmware()
    for k in range(200):
        t = 0.05 * k
        thr = (0.8, 0.3) if k < 100 else (0.2, 0.9)
        b1.receive(fw1.controls(t, *thr), UNIX + t)
        b2.receive(fw2.controls(t, *thr), UNIX + 3.7 * t + 100)  # a slow, busy host
    assert b1.truth == b2.truth


def test_a_firmware_clock_going_back_is_a_reset_the_boat_stays_where_it_is():
    b, fw = bridge(), Firmware()
    drive(b, fw, 20.0, 1.0, 1.0)
    here = b.truth
    fix, = fw.fixes(b.receive(fw.controls(0.0, 0.0, 0.0), UNIX + 21))
    assert b.stats.resets == 1 and b.truth == here
    frame_x, frame_y = b.frame.to_ramp(fix.lat / 1e7, fix.lon / 1e7)
    assert math.hypot(frame_x - here.x, frame_y - here.y) < 0.05


@pytest.mark.parametrize("key, system_id, why", [
    (None, 1, "unsigned"), (bytes(32), 1, "bad signature"),
    (KEY, 2, "not HIL_ACTUATOR_CONTROLS of the boat")])
def test_unsigned_forged_or_foreign_controls_move_nothing(key, system_id, why):
    b = bridge()
    out = b.receive(Firmware(key, system_id).controls(0.0, 1.0, 1.0), UNIX)
    out += b.receive(Firmware(key, system_id).controls(5.0, 1.0, 1.0), UNIX + 5)
    assert out == b"" and b.stats.controls == 0 and b.stats.refused[why] >= 1
    assert (b.truth.x, b.truth.y, b.truth.t) == (85.0, 10.0, 0.0)


@given(st.floats(width=32), st.floats(-1.0, 1.0, width=32))
def test_throttle_is_clamped_and_maps_to_shaft_speed(wild, throttle):
    b = bridge()
    th = b.vessel.params.thrusters
    n = throttle * (th.n_max if throttle >= 0 else -th.n_min)
    assert b._newtons(throttle) == pytest.approx(th.thrust(n), abs=1e-9)
    b.receive(Firmware().controls(0.0, wild, throttle), UNIX)
    left, right = b.stats.thrust
    assert left == (max(-1.0, min(1.0, wild)) if math.isfinite(wild) else 0.0)
    assert right == throttle


def test_without_gnss_time_the_fix_carries_the_firmware_time():
    b, fw = bridge(gnss_time=False), Firmware()
    fix, = fw.fixes(b.receive(fw.controls(12.5, 0.0, 0.0), UNIX))
    assert fix.time_usec == 12_500_000


def test_gps_noise_moves_the_fix_not_the_boat():
    b, fw = bridge(gps=GpsNoise(seed=3)), Firmware()
    fixes = drive(b, fw, 5.0, 0.0, 0.0)
    xs = [b.frame.to_ramp(f.lat / 1e7, f.lon / 1e7)[0] for f in fixes]
    assert b.truth.x == 85.0 and 0.0 < max(abs(float(x) - 85.0) for x in xs) < 5.0


def test_provisioning_refuses_what_a_boat_cannot_take():
    assert len(Provision(key=KEY).to_bytes()) == 204
    for bad, field in [(dict(boat_id=255), "station_id"), (dict(key=b"short"), "key"),
                       (dict(clock_speedup=50.0), "clock_speedup"),
                       (dict(nv_path="x" * 200), "nv_path")]:
        with pytest.raises(ValueError, match=field):
            Provision(**bad).to_bytes()


def test_qemu_serial_order_is_usart1_radio_then_usart2_hil(tmp_path):
    nv = tmp_path / "n,v.bin"
    cmd = QemuCommand(Path("fw.elf"), tmp_path / "p.bin", tmp_path / "r.sock",
                      tmp_path / "h.sock", nv)
    argv = cmd.argv()
    assert [argv[i + 1] for i, a in enumerate(argv) if a == "-serial"] == \
        ["chardev:radio", "chardev:hil"]
    assert f"loader,file={tmp_path}/p.bin,addr={CONFIG_PAGE_ADDR:#x},force-raw=on" in argv
    assert not any(str(NV_PAGE_ADDR) in a or f"{NV_PAGE_ADDR:#x}" in a for a in argv)
    nv.write_bytes(bytes(8))
    assert f"loader,file={tmp_path}/n,,v.bin,addr={NV_PAGE_ADDR:#x},force-raw=on" in \
        cmd.argv()
