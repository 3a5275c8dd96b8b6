"""The simulated sea: scripted motion, manoeuvres, and its sentences decoded back to truth."""

from __future__ import annotations

import asyncio
import math
import socket

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from usvstation.scenario import ScenarioError, load_scenario, parse_scenario
from usvstation.shipinputs.decode import SentenceDecoder, apply_reports
from usvstation.sim.sea import SeaModel, SimulatedSea, UdpSender
from usvstation.world.model import World

BASE = load_scenario("case1").model_dump(mode="json")


def sea_scenario(**extra: object) -> dict:
    return {**BASE, "mother_ship": {"speed": 1.5, "course_deg": 270.0,
                                    "lever_arm": {"forward": -30.0, "starboard": 0.0}},
            "traffic": [
                {"mmsi": 211000101, "name": "TURNER", "start": {"x": 120.0, "y": -40.0},
                 "course_deg": 0.0, "speed": 2.0, "length": 8.0,
                 "manoeuvres": [{"t": 10.0, "course_deg": 90.0}, {"t": 20.0, "speed": 0.0}]},
                {"mmsi": 211000102, "name": "BEE", "start": {"x": 80.0, "y": 50.0},
                 "course_deg": 180.0, "speed": 1.0, "ais_class": "B"},
                {"mmsi": 211000103, "name": "RADAR1", "start": {"x": 150.0, "y": 0.0},
                 "course_deg": 45.0, "speed": 3.0, "report": "arpa"},
            ], **extra}


def test_scenario_accepts_mother_ship_and_traffic_and_names_bad_fields() -> None:
    sc = parse_scenario(sea_scenario())
    assert sc.mother_ship.speed == 1.5 and len(sc.traffic) == 3
    bad = sea_scenario()
    bad["traffic"][0]["manoeuvres"] = [{"t": 5.0}]
    with pytest.raises(ScenarioError, match=r"traffic\[0\]\.manoeuvres\[0\]"):
        parse_scenario(bad)
    bad = sea_scenario()
    bad["mother_ship"]["sped"] = 1
    with pytest.raises(ScenarioError, match=r"mother_ship\.sped: unknown field"):
        parse_scenario(bad)


def test_ramp_starts_at_origin_and_ship_lies_along_the_lever_arm() -> None:
    model = SeaModel(parse_scenario(sea_scenario()))
    # origin ramp bearing 90 (east), stern ramp: the ship heads west, 30 m west of its ramp
    own = model.mother_at(0.0)
    assert model.heading_deg == 270.0
    assert (own.east, own.north) == pytest.approx((-30.0, 0.0), abs=1e-9)
    assert model.ramp_at(10.0) == pytest.approx((-15.0, 0.0), abs=1e-9)


def test_manoeuvres_change_course_then_speed() -> None:
    model = SeaModel(parse_scenario(sea_scenario()))
    start = model.traffic_at(0.0)[0]
    a = model.traffic_at(15.0)[0]  # 10 s north at 2 m/s, then 5 s east
    assert (a.east - start.east, a.north - start.north) == pytest.approx((10.0, 20.0))
    b = model.traffic_at(40.0)[0]  # stopped at t = 20
    assert (b.east - start.east, b.north - start.north) == pytest.approx((20.0, 20.0))
    assert (b.speed, b.course_deg) == (0.0, 90.0)


def test_sentences_decode_back_to_the_truth() -> None:
    model = SeaModel(parse_scenario(sea_scenario()))
    t = 12.0
    dec, world = SentenceDecoder(), World(lever_arm=model.mother.lever_arm)
    for line in model.sentences(t, static=True):
        apply_reports(world, 0.0, dec.feed(line))
    assert dec.stats.bad == 0
    pose = world.ramp(0.0)
    frame = model.frame0
    x, y = frame.to_ramp(pose.lat, pose.lon)
    e, n = frame.ramp_to_enu(x, y)
    assert (float(e), float(n)) == pytest.approx(model.ramp_at(t), abs=0.05)
    assert pose.ramp_bearing_deg == pytest.approx(90.0)
    truth = {s.key: s for s in model.traffic_at(t)}
    assert set(world.tracks) == set(truth)
    for key, tr in world.tracks.items():
        s = truth[key]
        tx, ty = frame.to_ramp(tr.lat, tr.lon)
        te, tn = frame.ramp_to_enu(tx, ty)
        assert math.hypot(float(te) - s.east, float(tn) - s.north) < 0.5, key
        assert tr.speed == pytest.approx(s.speed, abs=0.06), key
    assert world.tracks["ais:211000101"].name == "TURNER"
    assert world.tracks["ais:211000102"].length == 10.0  # class B: type 24 part B


def test_traffic_relative_to_the_moving_ramp() -> None:
    model = SeaModel(parse_scenario(sea_scenario()))
    rows = model.traffic_in_ramp_frame(0.0)
    assert rows[0, :2] == pytest.approx((120.0, -40.0))
    # ship goes west at 1.5 = -x in the ramp frame (bearing 90): relative velocity + 1.5 in x
    assert rows[1, 2:] == pytest.approx((1.5, -1.0), abs=1e-9)


def test_simulated_sea_sends_udp_and_records_truth() -> None:
    async def main() -> tuple[int, int]:
        rx = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        rx.bind(("127.0.0.1", 0))
        rx.setblocking(False)
        sender = UdpSender(rx.getsockname())
        sea = SimulatedSea(parse_scenario(sea_scenario()), sender, rate_hz=5.0, sim_speed=10.0)
        stop = asyncio.Event()
        task = asyncio.create_task(sea.run(stop))
        loop = asyncio.get_running_loop()
        got = []
        while len(got) < 20:
            got.append(await loop.sock_recv(rx, 4096))
        stop.set()
        await task
        rx.close()
        sender.close()
        dec = SentenceDecoder()
        for data in got:
            dec.feed(data)
        return dec.stats.bad, len(sea.truth)

    bad, records = asyncio.run(main())
    assert bad == 0 and records >= 1


@settings(max_examples=40)
@given(st.floats(-170.0, 170.0), st.floats(0.0, 5.0), st.floats(0.5, 10.0),
       st.floats(0.0, 40.0), st.floats(0.0, 60.0))
def test_a_turning_mother_ship_sails_the_arc_its_velocity_integrates_to(
        turn_deg, speed, rate, turn_at, t):
    """The mother ship turns at its rate the shorter way round; its position is the integral
    of its velocity (a fine Euler sum), its hull and the stern ramp turn with its course."""
    doc = sea_scenario()
    doc["mother_ship"] = {"speed": speed, "course_deg": 270.0, "turn_rate_deg_s": rate,
                          "lever_arm": {"forward": -20.0},
                          "manoeuvres": [{"t": turn_at, "course_deg": (270.0 + turn_deg) % 360.0}]}
    model = SeaModel(parse_scenario(doc))
    own = model.mother_at(t)
    steps = max(1, int(t / 0.002))
    e = n = 0.0
    for i in range(steps):
        mid = model.mother_at((i + 0.5) * t / steps)
        e, n = e + mid.ve * t / steps, n + mid.vn * t / steps
    start = model.mother_at(0.0)
    assert (own.east - start.east, own.north - start.north) == pytest.approx((e, n), abs=2e-3)
    done = min(max(t - turn_at, 0.0) * rate, abs(turn_deg))
    expected = 270.0 + math.copysign(done, turn_deg)
    assert (own.course_deg - expected + 180.0) % 360.0 - 180.0 == pytest.approx(0.0, abs=1e-6)
    assert (own.heading_deg - own.course_deg + 180.0) % 360.0 - 180.0 == pytest.approx(
        0.0, abs=1e-6)
    bearing = model.ramp_bearing_at(t) - own.heading_deg - 180.0
    assert (bearing + 180.0) % 360.0 - 180.0 == pytest.approx(0.0, abs=1e-6)
    # the ramp end stays 20 m astern of the reference point, along the ship's heading
    re, rn = model.ramp_at(t)
    h = math.radians(own.heading_deg)
    assert (re - own.east, rn - own.north) == pytest.approx((-20.0 * math.sin(h),
                                                             -20.0 * math.cos(h)), abs=1e-9)
