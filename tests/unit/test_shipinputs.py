"""Ship-input decoding against the project's own sentence fixtures, and fuzzed lines."""

from __future__ import annotations

from pathlib import Path

import pynmea2
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pyais import encode_dict

from usvstation.shipinputs.decode import (
    OwnShipReport,
    RadarFix,
    RadarReport,
    SentenceDecoder,
    TrackReport,
    apply_reports,
)
from usvstation.world.model import KNOT, World

FIXTURES = Path(__file__).parent.parent / "fixtures" / "ship_sentences.nmea"


def fixture_cases() -> list[tuple[str, list[str]]]:
    """(comment, lines) pairs from the fixture file."""
    cases: list[tuple[str, list[str]]] = []
    for line in FIXTURES.read_text(encoding="ascii").splitlines():
        if line.startswith("# ") and not line.startswith("# Sentences") \
                and not line.startswith("# Each"):
            cases.append((line[2:], []))
        elif line and not line.startswith("#"):
            cases[-1][1].append(line)
    return cases


CASES = dict(fixture_cases())


def decode(comment: str) -> tuple[list, SentenceDecoder]:
    dec = SentenceDecoder()
    reports = []
    for line in CASES[comment]:
        reports += dec.feed(line)
    return reports, dec


def one(comment: str) -> object:
    reports, dec = decode(comment)
    assert dec.stats.bad == 0, dec.stats.reasons
    assert len(reports) == 1, reports
    return reports[0]


def test_gga_position() -> None:
    r = one("own GGA: 30.5 N 122.0 E, fix")
    assert r == OwnShipReport(lat=pytest.approx(30.5), lon=pytest.approx(122.0))


def test_rmc_position_course_speed() -> None:
    r = one("own RMC: 30.51 N 122.005 E, 5.0 kn, 90.0 deg")
    assert (r.lat, r.lon, r.course_deg) == pytest.approx((30.51, 122.005, 90.0))
    assert r.speed == pytest.approx(5.0 * 1852 / 3600)


def test_vtg_course_speed() -> None:
    r = one("own VTG: 45 deg true, 4.0 kn")
    assert (r.course_deg, r.speed, r.lat) == (45.0, pytest.approx(4.0 * KNOT), None)


def test_hdt_hdg_ths_headings() -> None:
    assert one("own HDT: 271.5") == OwnShipReport(heading_deg=271.5)
    hdg = one("own HDG: 100.0 magnetic, deviation 1.0 E, variation 5.0 W -> 96.0 true")
    assert hdg.heading_deg == pytest.approx(96.0)
    assert one("own THS: 12.3 autonomous") == OwnShipReport(heading_deg=12.3)


@pytest.mark.parametrize("comment", ["own GGA without fix", "own RMC void", "own THS invalid",
                                     "ARPA TTM 4 lost"])
def test_sentences_without_valid_data_give_nothing_and_are_not_bad(comment: str) -> None:
    reports, dec = decode(comment)
    assert reports == [] and dec.stats.bad == 0 and dec.stats.sentences == 1


def test_ttm_true_bearing_in_nautical_miles() -> None:
    r = one("ARPA TTM 1: 0.50 NM at 045 T, 6.0 kn, course 270")
    assert r == RadarReport(number=1, range_m=926.0, bearing_deg=45.0, relative=False,
                            speed=pytest.approx(6.0 * KNOT), course_deg=270.0, name="TGT01")


def test_ttm_relative_bearing_in_kilometres() -> None:
    r = one("ARPA TTM 2: 1.2 km at 030 relative, 3.6 km/h, course 090")
    assert (r.number, r.range_m, r.bearing_deg, r.relative) == (2, 1200.0, 30.0, True)
    assert (r.speed, r.course_deg, r.name) == (pytest.approx(1.0), 90.0, None)


def test_tll_position() -> None:
    r = one("ARPA TLL 3: 30.502 N 122.001 E")
    assert r == RadarFix(3, pytest.approx(30.502), pytest.approx(122.001), name="BUOY")


def test_unused_valid_sentence_is_ignored_not_bad() -> None:
    reports, dec = decode("satellites in view: valid, not used")
    assert (reports, dec.stats.bad, dec.stats.ignored) == ([], 0, 1)


def test_ais_type_1_and_18() -> None:
    a = one("AIS 1: 211000001, 30.51 N 122.01 E, 10.0 kn, 123.4, hdg 120")
    assert a == TrackReport(mmsi=211000001, lat=pytest.approx(30.51), lon=pytest.approx(122.01),
                            speed=pytest.approx(10.0 * KNOT), course_deg=pytest.approx(123.4),
                            heading_deg=120.0, ais_class="A")
    b = one("AIS 18: 211000002, 30.49 N 121.99 E, 3.2 kn, 300.0")
    assert (b.mmsi, b.speed, b.course_deg, b.heading_deg, b.ais_class) == (
        211000002, pytest.approx(3.2 * KNOT), pytest.approx(300.0), None, "B")


def test_ais_type_5_two_fragments() -> None:
    reports, dec = decode("AIS 5 in two fragments: 211000001 ALPHA 40 x 8")
    assert reports == [TrackReport(mmsi=211000001, name="ALPHA", length=40.0, beam=8.0,
                                   ais_class="A")]
    assert dec.stats.sentences == 2 and dec.stats.bad == 0


def test_ais_type_24_parts_and_19() -> None:
    assert one("AIS 24A: 211000002 BRAVO") == TrackReport(mmsi=211000002, name="BRAVO",
                                                          ais_class="B")
    assert one("AIS 24B: 211000002 12 x 4") == TrackReport(mmsi=211000002, length=12.0,
                                                            beam=4.0, ais_class="B")
    c = one("AIS 19: 211000003 CHARLIE, 30.5 N 122.02 E, 1.0 kn, 0.0, 20 x 6")
    assert (c.name, c.length, c.beam, c.lat, c.lon, c.ais_class) == (
        "CHARLIE", 20.0, 6.0, pytest.approx(30.5), pytest.approx(122.02), "B")


def test_ais_position_not_available_gives_nothing() -> None:
    reports, dec = decode("AIS 3: 211000004, position not available")
    assert reports == [] and dec.stats.bad == 0


def test_aivdo_is_own_ship() -> None:
    r = one("AIVDO 1: own ship 30.5005 N 122.0005 E, 2.0 kn, 10.0, hdg 12")
    assert isinstance(r, OwnShipReport)
    assert (r.lat, r.lon, r.course_deg, r.heading_deg) == pytest.approx(
        (30.5005, 122.0005, 10.0, 12.0))


def test_bad_lines_are_counted_with_their_reason() -> None:
    dec = SentenceDecoder()
    for comment in ("bad: checksum", "bad: AIS checksum", "bad: no checksum", "bad: truncated",
                    "bad: not a sentence"):
        for line in CASES[comment]:
            assert dec.feed(line) == []
    assert (dec.stats.sentences, dec.stats.bad) == (5, 5)
    assert dec.stats.reasons == {"checksum": 2, "no checksum": 2, "not a sentence": 1}


def test_fragment_out_of_order_and_missing_fragment_are_bad() -> None:
    first, second = CASES["AIS 5 in two fragments: 211000001 ALPHA 40 x 8"]
    dec = SentenceDecoder()
    assert dec.feed(second, 0.0) == []
    assert dec.stats.reasons == {"fragment order": 1}
    assert dec.feed(first, 0.0) == []
    assert dec.feed("$HEHDT,271.5,T*2E", 60.0) != []  # the lone first fragment expires
    assert dec.stats.reasons["fragment missing"] == 1


def test_whole_fixture_file_builds_the_world() -> None:
    dec, world = SentenceDecoder(), World()
    for _comment, lines in fixture_cases():
        for line in lines:
            apply_reports(world, 0.0, dec.feed(line))
    assert dec.stats.bad == 5
    assert set(world.tracks) == {"ais:211000001", "ais:211000002", "ais:211000003",
                                 "arpa:1", "arpa:2", "arpa:3"}
    alpha = world.tracks["ais:211000001"]
    assert (alpha.name, alpha.length, alpha.radius) == ("ALPHA", 40.0, 20.0)
    assert world.own.lat == pytest.approx(30.5005)


# --- fuzzing --------------------------------------------------------------------------------
@settings(max_examples=300, deadline=None)
@given(st.one_of(st.text(max_size=120), st.binary(max_size=120)))
def test_any_line_never_raises_and_is_counted(line: str | bytes) -> None:
    dec = SentenceDecoder()
    dec.feed(line)
    text = line.decode("ascii", errors="replace") if isinstance(line, bytes) else line
    assert dec.stats.sentences == (1 if text.strip() else 0)
    assert dec.stats.bad + dec.stats.ignored <= dec.stats.sentences


@settings(max_examples=200, deadline=None)
@given(st.sampled_from([line for c, lines in fixture_cases() for line in lines
                        if not c.startswith("bad")]),
       st.integers(1, 70), st.characters(codec="ascii"))
def test_a_changed_character_is_never_silently_decoded_wrong(line: str, pos: int,
                                                            char: str) -> None:
    pos = min(pos, len(line) - 1)
    mutated = line[:pos] + char + line[pos + 1:]
    dec_a, dec_b = SentenceDecoder(), SentenceDecoder()
    got, orig = dec_a.feed(mutated), dec_b.feed(line)
    assert got == orig or dec_a.stats.bad == 1 or got == []


@settings(max_examples=200, deadline=None)
@given(st.floats(-89.9, 89.9), st.floats(-179.9, 179.9), st.floats(0.0, 102.2),
       st.floats(0.0, 359.9), st.sampled_from([1, 2, 3, 18]),
       st.integers(200000000, 799999999))
def test_ais_position_round_trip(lat: float, lon: float, sog: float, cog: float, kind: int,
                                 mmsi: int) -> None:
    (line,) = encode_dict({"type": kind, "mmsi": mmsi, "lat": lat, "lon": lon, "speed": sog,
                           "course": cog}, talker_id="AI", sentence_type="VDM")
    (r,) = SentenceDecoder().feed(line)
    assert r.mmsi == mmsi
    # AIS resolution (1/10000 minute, 0.1 kn, 0.1 degree); pyais truncates when encoding
    assert r.lat == pytest.approx(lat, abs=1e-4 / 60 + 1e-9)
    assert r.lon == pytest.approx(lon, abs=1e-4 / 60 + 1e-9)
    assert r.speed == pytest.approx(sog * KNOT, abs=0.1 * KNOT + 1e-9)
    assert r.course_deg == pytest.approx(cog, abs=0.1 + 1e-9)


@settings(max_examples=200, deadline=None)
@given(st.floats(-89.99, 89.99), st.floats(-179.99, 179.99), st.floats(0.0, 359.9))
def test_nmea_gga_hdt_round_trip(lat: float, lon: float, heading: float) -> None:
    def deg_min(value: float, width: int) -> str:
        a = abs(value)
        return f"{int(a):0{width}d}{(a - int(a)) * 60:07.4f}"

    gga = pynmea2.GGA("GP", "GGA", ("120000.00", deg_min(lat, 2), "N" if lat >= 0 else "S",
                                    deg_min(lon, 3), "E" if lon >= 0 else "W", "1", "08",
                                    "0.9", "5.0", "M", "0.0", "M", "", ""))
    hdt = pynmea2.HDT("HE", "HDT", (f"{heading:.1f}", "T"))
    dec = SentenceDecoder()
    (p,) = dec.feed(str(gga))
    (h,) = dec.feed(str(hdt))
    assert p.lat == pytest.approx(lat, abs=1e-6) and p.lon == pytest.approx(lon, abs=1e-6)
    assert h.heading_deg == pytest.approx(round(heading, 1), abs=1e-9)
