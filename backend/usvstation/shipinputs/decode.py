"""Sentence decoding (pure): NMEA 0183 with pynmea2, AIS with pyais, into world reports.

Own ship: GGA, RMC (position; RMC also course and speed), VTG (course and speed), HDT,
HDG (magnetic heading corrected by deviation and variation), THS (true heading; pynmea2
has no THS, so its two fields are read here after the checksum check), and `!AIVDO`
position reports. Targets: ARPA TTM (range and bearing from the own ship) and TLL
(position), AIS `!AIVDM` types 1, 2, 3, 18 (position), 5 and 24 (name and size) and 19
(both), multi-fragment messages reassembled. Every line counts in `sentences`; a line
that fails its checksum or cannot be parsed counts in `bad` and is skipped; a valid
sentence of a type not used here counts in `ignored`.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

import pynmea2
from pyais.exceptions import AISBaseException
from pyais.messages import NMEAMessage

from usvstation.world.model import KNOT, MotionReport, OwnShipReport, World

FRAGMENT_TIMEOUT_S = 10.0  # an AIS message whose fragments do not all arrive in time is bad
_DIST_UNIT_M = {"N": 1852.0, "K": 1000.0, "S": 1609.344}
_AIS_POSITION = {1, 2, 3, 18, 19}


@dataclass(frozen=True, kw_only=True)
class TrackReport(MotionReport):
    """An AIS report: position and motion (types 1-3, 18, 19) and/or static data (5, 19, 24)."""

    mmsi: int
    name: str | None = None
    length: float | None = None
    beam: float | None = None
    ais_class: str | None = None  # "A" (types 1-3, 5) or "B" (18, 19, 24)


@dataclass(frozen=True)
class ArpaReport:
    """A target tracked by the own ship's radar (ARPA): its number, and its name if given."""

    number: int
    name: str | None = field(default=None, kw_only=True)


@dataclass(frozen=True)
class RadarReport(ArpaReport):
    """ARPA TTM: the target by range and bearing from the own ship."""

    range_m: float
    bearing_deg: float
    relative: bool
    speed: float
    course_deg: float


@dataclass(frozen=True)
class RadarFix(ArpaReport):
    """ARPA TLL: the target's position."""

    lat: float
    lon: float


Report = OwnShipReport | TrackReport | RadarReport | RadarFix


@dataclass
class DecoderStats:
    sentences: int = 0
    bad: int = 0
    ignored: int = 0
    reasons: Counter[str] = field(default_factory=Counter)  # why lines were bad


class SentenceDecoder:
    """Feeds lines, returns reports; keeps AIS fragments until their message is whole."""

    def __init__(self) -> None:
        self.stats = DecoderStats()
        self._fragments: dict[tuple[str, str, str], tuple[float, list[NMEAMessage]]] = {}

    def feed(self, line: str | bytes, t: float = 0.0) -> list[Report]:
        """Decode one line received at station time t (never raises on bad input)."""
        if isinstance(line, bytes):
            line = line.decode("ascii", errors="replace")
        line = line.strip()
        if not line:
            return []
        self.stats.sentences += 1
        self._expire(t)
        try:
            if line.startswith("!"):
                return self._ais(line, t)
            if line.startswith("$"):
                return self._nmea(line)
            raise _Bad("not a sentence")
        except _Bad as exc:
            self.stats.bad += 1
            self.stats.reasons[str(exc)] += 1
            return []

    # --- NMEA 0183 -------------------------------------------------------------------------
    def _nmea(self, line: str) -> list[Report]:
        if "*" not in line:
            raise _Bad("no checksum")
        try:
            msg = pynmea2.parse(line, check=True)
        except pynmea2.ChecksumError:
            raise _Bad("checksum") from None
        except pynmea2.SentenceTypeError:
            return self._unknown_type(line)
        except (pynmea2.ParseError, ValueError, IndexError):
            raise _Bad("parse") from None
        try:
            return self._nmea_fields(msg)
        except (ValueError, TypeError, AttributeError, IndexError):
            raise _Bad("parse") from None

    def _unknown_type(self, line: str) -> list[Report]:
        body, _, given = line[1:].partition("*")
        try:
            ok = int(given[:2], 16) == pynmea2.NMEASentence.checksum(body)
        except ValueError:
            ok = False
        if not ok:
            raise _Bad("checksum")
        fields = body.split(",")
        if fields[0][2:] == "THS" and len(fields) >= 3:  # $--THS,heading,mode
            if fields[2] in ("V", "") or not fields[1]:
                return []  # heading not valid
            try:
                return [OwnShipReport(heading_deg=float(fields[1]))]
            except ValueError:
                raise _Bad("parse") from None
        self.stats.ignored += 1
        return []

    def _nmea_fields(self, msg: pynmea2.NMEASentence) -> list[Report]:
        kind = msg.sentence_type
        if kind == "GGA":
            if not msg.gps_qual or int(msg.gps_qual) == 0 or not msg.lat:
                return []  # no fix
            return [OwnShipReport(lat=msg.latitude, lon=msg.longitude)]
        if kind == "RMC":
            if msg.status != "A" or not msg.lat:
                return []
            speed = _num(msg.spd_over_grnd)
            speed = None if speed is None else speed * KNOT
            course = _num(msg.true_course)
            return [OwnShipReport(lat=msg.latitude, lon=msg.longitude, speed=speed,
                                  course_deg=course)]
        if kind == "VTG":
            kts, kmph = _num(msg.spd_over_grnd_kts), _num(msg.spd_over_grnd_kmph)
            speed = kts * KNOT if kts is not None else None if kmph is None else kmph / 3.6
            course = _num(msg.true_track)
            return [OwnShipReport(course_deg=course, speed=speed)]
        if kind == "HDT":
            heading = _num(msg.heading)
            return [] if heading is None else [OwnShipReport(heading_deg=heading)]
        if kind == "HDG":
            heading = _num(msg.heading)
            if heading is None or _num(msg.variation) is None:
                return []  # a magnetic heading without variation is not a true heading
            dev = _signed(msg.deviation, msg.dev_dir)
            var = _signed(msg.variation, msg.var_dir)
            return [OwnShipReport(heading_deg=(heading + dev + var) % 360.0)]
        if kind == "TTM":
            return self._ttm(msg)
        if kind == "TLL":
            if not msg.lat or not msg.lon:
                return []
            return [RadarFix(int(msg.target_number), msg.latitude, msg.longitude,
                             name=msg.target_name or None)]
        self.stats.ignored += 1
        return []

    @staticmethod
    def _ttm(msg: pynmea2.NMEASentence) -> list[Report]:
        if msg.status == "L":  # lost target
            return []
        unit = _DIST_UNIT_M.get(msg.dist_unit or "N")
        if unit is None:
            raise ValueError("unit")
        return [RadarReport(
            number=int(msg.target_number), range_m=float(msg.distance) * unit,
            bearing_deg=float(msg.bearing), relative=msg.brg_ref == "R",
            speed=(_num(msg.speed) or 0.0) * unit / 3600.0,
            course_deg=_num(msg.cog) or 0.0, name=msg.name or None,
        )]

    # --- AIS -------------------------------------------------------------------------------
    def _ais(self, line: str, t: float) -> list[Report]:
        try:
            msg = NMEAMessage(line.encode("ascii", errors="replace"))
        except AISBaseException:
            raise _Bad("parse") from None
        if not msg.is_valid:
            raise _Bad("checksum")
        if msg.is_multi:
            key = (msg.talker.value if hasattr(msg.talker, "value") else str(msg.talker),
                   str(msg.seq_id), str(msg.channel))
            _, parts = self._fragments.get(key, (t, []))
            if msg.frag_num != len(parts) + 1:
                self._fragments.pop(key, None)
                raise _Bad("fragment order")
            parts = [*parts, msg]
            if msg.frag_num < msg.frag_cnt:
                self._fragments[key] = (t, parts)
                return []
            self._fragments.pop(key, None)
            try:
                msg = NMEAMessage.assemble_from_iterable(parts)
            except AISBaseException:
                raise _Bad("parse") from None
        try:
            ais = msg.decode()
        except (AISBaseException, ValueError, IndexError, TypeError):
            raise _Bad("parse") from None
        own = line[3:6] == "VDO"
        return _ais_report(ais, own)

    def _expire(self, t: float) -> None:
        stale = [k for k, (t0, _) in self._fragments.items() if t - t0 > FRAGMENT_TIMEOUT_S]
        for key in stale:
            del self._fragments[key]
            self.stats.bad += 1
            self.stats.reasons["fragment missing"] += 1


class _Bad(Exception):
    """A line that is counted as bad and skipped; the message is the reason."""


def _num(value: object) -> float | None:
    """A numeric NMEA field: None when empty."""
    if value is None or value == "":
        return None
    return float(value)  # type: ignore[arg-type]


def _signed(value: object, direction: str | None) -> float:
    number = _num(value)
    return 0.0 if number is None else number * (-1.0 if direction == "W" else 1.0)


def _ais_report(ais: object, own: bool) -> list[Report]:
    kind = getattr(ais, "msg_type", None)
    mmsi = getattr(ais, "mmsi", None)
    if kind is None or mmsi is None:
        raise _Bad("parse")
    pos: dict[str, float | None] = {}
    if kind in _AIS_POSITION:
        lat, lon = getattr(ais, "lat", None), getattr(ais, "lon", None)
        if lat is None or lon is None:
            raise _Bad("parse")
        if abs(lat) <= 90.0 and abs(lon) <= 180.0:  # 91 / 181: not available
            speed = getattr(ais, "speed", None)
            course = getattr(ais, "course", None)
            heading = getattr(ais, "heading", None)
            pos = {
                "lat": float(lat), "lon": float(lon),
                "speed": None if speed is None or speed >= 102.3 else float(speed) * KNOT,
                "course_deg": None if course is None or course >= 360.0 else float(course),
                "heading_deg": None if heading is None or heading >= 360 else float(heading),
            }
            if pos["speed"] is not None and pos["course_deg"] is None and pos["speed"] < 0.05:
                pos["course_deg"] = 0.0
    static: dict[str, float | str | None] = {}
    name = getattr(ais, "shipname", None)
    if isinstance(name, str) and name.strip("@ "):
        static["name"] = name.strip("@ ")
    bow, stern = getattr(ais, "to_bow", None), getattr(ais, "to_stern", None)
    port, stbd = getattr(ais, "to_port", None), getattr(ais, "to_starboard", None)
    if bow is not None and stern is not None and bow + stern > 0:
        static["length"] = float(bow + stern)
    if port is not None and stbd is not None and port + stbd > 0:
        static["beam"] = float(port + stbd)
    if own:
        if not pos:
            return []
        return [OwnShipReport(**pos)]
    if not pos and not static:
        return []
    ais_class = "B" if kind in (18, 19, 24) else "A" if kind in (1, 2, 3, 5) else None
    return [TrackReport(mmsi=int(mmsi), **pos, **static,  # type: ignore[arg-type]
                        ais_class=ais_class)]


def apply_reports(world: World, t: float, reports: list[Report]) -> bool:
    """Merge decoded reports into the world at station time t; True if anything changed."""
    changed = False
    for r in reports:
        if isinstance(r, OwnShipReport):
            world.update_own(t, lat=r.lat, lon=r.lon, heading_deg=r.heading_deg,
                             course_deg=r.course_deg, speed=r.speed)
        elif isinstance(r, TrackReport):
            world.update_track(t, f"ais:{r.mmsi}", "ais", mmsi=r.mmsi, lat=r.lat, lon=r.lon,
                               speed=r.speed, course_deg=r.course_deg,
                               heading_deg=r.heading_deg, name=r.name, length=r.length,
                               beam=r.beam, ais_class=r.ais_class)
        elif isinstance(r, RadarReport):
            if world.update_radar_target(t, r.number, r.range_m, r.bearing_deg, r.speed,
                                         r.course_deg, relative=r.relative,
                                         name=r.name) is None:
                continue
        else:
            world.update_track(t, f"arpa:{r.number}", "arpa", lat=r.lat, lon=r.lon,
                               name=r.name)
        changed = True
    return changed
