"""Sentences sent over UDP to a real `usv-station serve --nmea` appear in GET /api/world."""

from __future__ import annotations

import math
import socket
import time

import pynmea2
import pytest
from pyais import encode_dict
from stationproc import StationProcess

from usvstation.geo import RampFrame
from usvstation.world.model import KNOT, compass_to_enu, offset_geodetic

OWN_LAT, OWN_LON, OWN_HDG = 30.51234, 122.04321, 123.4
AIS = [  # mmsi, type, lat, lon, sog kn, cog
    (211000011, 1, 30.5150, 122.0400, 10.0, 45.0),
    (211000012, 18, 30.5100, 122.0480, 4.0, 300.0),
]
TTM = (5, 0.30, 90.0, 5.0, 180.0)  # number, range NM, bearing T, speed kn, course
MALFORMED = [b"$HEHDT,271.5,T*2F", b"!AIVDM,1,1,,A,139>JhOP1T8fQ7PAMCl4lSh1P000,0*03",
             b"$GPGGA,1200", b"complete garbage \xff\xfe"]


def nmea(body: str) -> bytes:
    return f"${body}*{pynmea2.NMEASentence.checksum(body):02X}\r\n".encode()


def dm(value: float, width: int) -> str:
    a = abs(value)
    return f"{int(a):0{width}d}{(a - int(a)) * 60:09.6f}"


def sentences() -> list[bytes]:
    out = [
        nmea(f"GPGGA,120000.00,{dm(OWN_LAT, 2)},N,{dm(OWN_LON, 3)},E,1,12,0.7,4.0,M,9.0,M,,"),
        nmea(f"HEHDT,{OWN_HDG:.1f},T"),
        nmea(f"RATTM,{TTM[0]:02d},{TTM[1]:.2f},{TTM[2]:.1f},T,{TTM[3]:.1f},{TTM[4]:.1f},T,"
             ",,N,TGT5,T,,120000.00,A"),
    ]
    for mmsi, kind, lat, lon, sog, cog in AIS:
        out += [(line + "\r\n").encode() for line in encode_dict(
            {"type": kind, "mmsi": mmsi, "lat": lat, "lon": lon, "speed": sog, "course": cog},
            talker_id="AI", sentence_type="VDM")]
    return out


def distance_m(lat1: float, lon1: float, lat2: float, lon2: float) -> float:
    e, n = RampFrame(lat1, lon1, 90.0).to_ramp(lat2, lon2)
    return math.hypot(float(e), float(n))


@pytest.fixture
def station(tmp_path):
    st = StationProcess(tmp_path / "data", "--nmea", "udp://127.0.0.1:0")
    try:
        yield st
    finally:
        st.stop()


def test_udp_sentences_appear_in_api_world(station: StationProcess) -> None:
    world = station.client.get("/api/world").json()
    (src,) = world["stats"]["sources"]
    assert src["url"].startswith("udp://127.0.0.1:") and src["state"] == "listening"
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    t0 = time.monotonic()
    try:
        # one datagram per sentence, the malformed ones in between, as a ship's network sends
        for data in [*sentences()[:2], *MALFORMED[:2], *sentences()[2:], *MALFORMED[2:]]:
            sock.sendto(data, ("127.0.0.1", src["port"]))
    finally:
        sock.close()
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        world = station.client.get("/api/world").json()
        ids = {t["id"] for t in world["targets"]}
        if world["stats"]["sentences"] >= 9 and {"ais:211000011", "ais:211000012",
                                                 "arpa:5"} <= ids:
            break
        time.sleep(0.02)
    print(f"world complete {time.monotonic() - t0:.3f} s after sending (not asserted)")

    assert world["stats"]["sentences"] == 9 and world["stats"]["bad"] == 4
    own = world["own_ship"]
    assert distance_m(own["lat"], own["lon"], OWN_LAT, OWN_LON) < 1.0
    assert own["heading_deg"] == pytest.approx(OWN_HDG)
    ramp = world["ramp"]
    assert ramp["source"] == "own_ship"
    frame = RampFrame(ramp["lat"], ramp["lon"], ramp["ramp_bearing_deg"])
    targets = {t["id"]: t for t in world["targets"]}

    def check(tid: str, lat: float, lon: float, sog_ms: float, cog: float) -> None:
        t = targets[tid]
        ve, vn = compass_to_enu(sog_ms, cog)
        sent_now = offset_geodetic(lat, lon, ve * t["age_s"], vn * t["age_s"])
        assert distance_m(t["lat"], t["lon"], *sent_now) < 2.0, tid
        x, y = frame.to_ramp(t["lat"], t["lon"])
        assert (t["x"], t["y"]) == pytest.approx((float(x), float(y)), abs=0.01)
        e, n = frame.ramp_to_enu(t["vx"], t["vy"])
        assert math.hypot(float(e) - ve, float(n) - vn) < 0.1, tid
        assert t["radius"] > 0 and t["age_s"] >= 0

    for mmsi, _, lat, lon, sog, cog in AIS:
        check(f"ais:{mmsi}", lat, lon, sog * KNOT, cog)
        assert targets[f"ais:{mmsi}"]["mmsi"] == mmsi
        assert targets[f"ais:{mmsi}"]["source"] == "ais"
    b = math.radians(TTM[2])
    tlat, tlon = offset_geodetic(OWN_LAT, OWN_LON, TTM[1] * 1852 * math.sin(b),
                                 TTM[1] * 1852 * math.cos(b))
    check("arpa:5", tlat, tlon, TTM[3] * KNOT, TTM[4])
    assert targets["arpa:5"]["source"] == "arpa" and targets["arpa:5"]["name"] == "TGT5"
    ws = station.client.get("/api/world/scenario").json()
    assert len(ws["scenario"]["obstacles"]) + len(ws["dropped"]) == len(world["targets"])
    assert ws["scenario"]["name"] == "case1"
