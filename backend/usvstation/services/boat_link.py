"""Link handling for the boat service: the BoatLink, its events turned into stored
telemetry, status texts and live events, and the link's part of /api/boat.

The link runs where its `LinkHost` says (link/station.py): on a thread and loop of its own in
`serve`, on the station's loop in simulated time. `LinkHandler` has a part on each side:
on the link's loop every position report becomes a telemetry row handed to the telemetry
writer (its own thread), so storing never waits for the web API; everything else, the row
included, crosses to the station's loop in order (`LinkHost.to_owner`: the typed queue),
where it is published and turned into mission states.
"""

from __future__ import annotations

import logging
import random
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass

from usvstation.clock import REAL_CLOCK, Clock, utc_iso
from usvstation.config import Settings
from usvstation.geo import RampFrame
from usvstation.geometry import MS
from usvstation.link.protocol import (
    BoatRebooted,
    BoatReport,
    LinkConfig,
    LinkDown,
    LinkEvent,
    LinkUp,
    StatusTextReceived,
    Telemetry,
    TelemetryReceived,
)
from usvstation.link.standard import PROFILES, StandardConfig
from usvstation.link.standard_link import StandardLink
from usvstation.link.station import BoatLink, LinkHost, LinkThread, SameLoop, StreamFactory
from usvstation.link.transport import open_stream
from usvstation.records import BoatSnapshot, DuplicateBoat, StatusText, TelemetryRow
from usvstation.services.hub import LiveHub
from usvstation.store.db import Store, utc_now

STATUS_KEPT = 50
SEVERITIES = ("EMERGENCY", "ALERT", "CRITICAL", "ERROR", "WARNING", "NOTICE", "INFO", "DEBUG")
DUPLICATE_WINDOW_S = 60.0  # a boot id heard again within this long: two boats, not a reboot
log = logging.getLogger("usvstation.link")


def make_link(settings: Settings, key: bytes | None, device: str, *, session: int,
              stream_factory: StreamFactory | None = None,
              clock: Clock = REAL_CLOCK) -> BoatLink:
    """The station's BoatLink to the paired boat on `device` (or the streams
    `stream_factory` makes), as the settings say (`boat_protocol` standard: a StandardLink to
    a stock autopilot, link/standard_link.py); not started."""
    baud = settings.baud
    factory = stream_factory or (lambda: open_stream(device, baud))
    if settings.boat_protocol == "standard":
        std = StandardConfig(boat_id=settings.boat_id, station_id=settings.station_id,
                             baud=baud, link_timeout_s=settings.heartbeat_timeout_s,
                             profile=PROFILES[settings.vehicle_profile],
                             guided=settings.standard_guided)
        return StandardLink(device, baud=baud, stream_factory=factory, config=std, key=key,
                            clock=clock, session=session)
    config = LinkConfig(boat_id=settings.boat_id, station_id=settings.station_id,
                        baud=baud, link_timeout_s=settings.heartbeat_timeout_s)
    return BoatLink(device, baud=baud, stream_factory=factory, config=config, key=key,
                    clock=clock, session=session)


@dataclass
class OpenedLink:
    """A BoatLink already running on its own thread (`serve` opens it before anything
    slow), for the station to adopt."""

    host: LinkThread
    link: BoatLink
    device: str


def open_link_thread(settings: Settings, key: bytes | None, device: str) -> OpenedLink:
    """Start a LinkThread and the station's BoatLink on it at once, on the wall clock."""
    host = LinkThread()
    host.start_now()
    link = make_link(settings, key, device, session=random.SystemRandom().randrange(1, 1 << 24))
    host.call_blocking(link.start, timeout=10.0)
    return OpenedLink(host, link, device)


@dataclass(frozen=True)
class StoredTelemetry:
    """A position report the link's side stored as `row` (for the station's side to
    publish)."""

    row: TelemetryRow
    event: TelemetryReceived


class DuplicateWatch:
    """Two boats answering as one id: a boot id heard again after another one was (a reboot
    never goes back to an earlier boot id). Pure: fed the reports' boot ids and times."""

    def __init__(self, window_s: float = DUPLICATE_WINDOW_S) -> None:
        self.window_s = window_s
        self.current: int | None = None
        self.heard: dict[int, float] = {}  # boot id -> last heard (first heard first)
        self.switches: deque[float] = deque()  # times the boot id changed
        self.detected_at: float | None = None  # since when two boats are heard

    def observe(self, boot_id: int, now: float) -> bool:
        """One report's boot id at `now`; True when this report reveals a second boat."""
        self._forget(now)
        came_back = boot_id != self.current and boot_id in self.heard
        if boot_id != self.current and self.current is not None:
            self.switches.append(now)
        self.current = boot_id
        self.heard[boot_id] = now
        if came_back and self.detected_at is None:
            self.detected_at = now
            return True
        return False

    def active(self, now: float) -> bool:
        self._forget(now)
        return self.detected_at is not None

    def _forget(self, now: float) -> None:
        cutoff = now - self.window_s
        while self.switches and self.switches[0] < cutoff:
            self.switches.popleft()
        for boot_id in [b for b, t in self.heard.items() if t < cutoff]:
            del self.heard[boot_id]
        if not self.switches:
            self.detected_at = None  # a minute with one boot id: one boat again


class LinkHandler:
    """Owns the BoatLink; telemetry goes to the store (on the link's loop) and the hub,
    reports to `on_report`, every event to `listeners` (on the station's loop)."""

    def __init__(self, link: BoatLink, device: str, store: Store, hub: LiveHub,
                 on_report: Callable[[BoatReport], None],
                 on_reboot: Callable[[BoatRebooted], None],
                 host: LinkHost | None = None) -> None:
        self.link, self.device, self.store, self.hub = link, device, store, hub
        self.host = host or SameLoop()
        self.clock = link.clock
        self.on_report, self.on_reboot = on_report, on_reboot
        self.frame: RampFrame | None = None  # ramp frame for x, y of telemetry
        # the moving ramp's frame of now (WorldService.current_frame), when there is one
        self.moving_frame: Callable[[], RampFrame | None] | None = None
        self.run: int | None = None
        self.run_t0: float | None = None
        self.telemetry: TelemetryRow | None = None
        self.telemetry_at: float | None = None
        self.report_at: float | None = None
        self.status: list[StatusText] = []
        self.frames = 0
        self.ingest_errors = 0
        # every link event, on the station's loop (alerts, the live heartbeat)
        self.listeners: list[Callable[[LinkEvent], None]] = []
        self.duplicates = DuplicateWatch()
        self.on_duplicate: Callable[[DuplicateBoat], None] | None = None
        self._to_station = self.host.to_owner(self._on_event)
        self.host.post(link.add_listener, self._on_link_event)

    @property
    def link_up(self) -> bool:
        return self.link.link_up

    def snapshot(self) -> BoatSnapshot:
        now = self.clock.now()
        p = self.link.protocol
        rep = p.report
        return {
            "link": {
                "up": self.link_up, "device": self.device,
                "signed": p.codec.signed,
                "warning": None if p.codec.signed else
                "insecure link: unsigned, anyone with a radio can command the boat",
                "boat_id": p.config.boat_id, "station_id": p.config.station_id,
                "session": p.session,
                "heartbeat_age_s": None if self.report_at is None
                else round(now - self.report_at, 3),
                "telemetry_age_s": None if self.telemetry_at is None
                else round(now - self.telemetry_at, 3),
                "frames": self.frames,
                "other_systems": {str(k): v for k, v in sorted(p.other_systems.items())},
                "refused": dict(p.refused),
                "frames_bad": p.refused.get("corrupt", 0),
                "frames_lost": p.frames_lost,
                "rtt_s": None if p.rtt.srtt is None else round(p.rtt.srtt, 4),
                "error": self.link.last_error or None,
                "duplicate": self.duplicate(),
            },
            "boat": None if rep is None else {
                "state": rep.state, "mission_id": rep.active_id, "mission_crc32": rep.active_crc32,
                "uptime_s": MS.from_wire(rep.uptime_ms), "boot_id": rep.boot_id,
                "staging": rep.staging, "staged_id": rep.staged_id,
                "swap_at_ms": rep.swap_at_ms, "rejected": rep.rejected,
            },
            "telemetry": self.telemetry,
            "status": self.status[-10:],
        }

    def duplicate(self) -> DuplicateBoat | None:
        """Two boats heard as the paired boat id (boot ids alternating), else None."""
        watch = self.duplicates
        if not watch.active(self.clock.now()) or watch.detected_at is None:
            return None
        detected = self.clock.unix() - (self.clock.now() - watch.detected_at)
        return {"boot_ids": list(watch.heard), "detected_at": utc_iso(detected),
                "switches": len(watch.switches)}

    # --- the link's side (its own loop) -----------------------------------------------------
    def _on_link_event(self, ev: LinkEvent) -> None:
        """On the link's loop: a position report is stored at once; every event goes on to
        the station's side, in order."""
        if isinstance(ev, TelemetryReceived):
            try:
                row = self._ingest(ev.telemetry)
            except Exception:  # never let a bad row stop the link's loop
                self.ingest_errors += 1
                if self.ingest_errors == 1:
                    log.exception("telemetry ingest failed (counted in link.ingest_errors)")
                return
            self._to_station(StoredTelemetry(row, ev))
        else:
            self._to_station(ev)

    def _ingest(self, t: Telemetry) -> TelemetryRow:
        self.frames += 1
        moving = None
        if self.moving_frame is not None:
            try:  # the world's state, read from the link's thread
                moving = self.moving_frame()
            except Exception:
                self.ingest_errors += 1
        row = telemetry_row(t, moving or self.frame, self.run, utc_now(self.clock))
        self.store.writer.put(row)
        return row

    # --- the station's side -----------------------------------------------------------------
    def _on_event(self, item: LinkEvent | StoredTelemetry) -> None:
        if isinstance(item, StoredTelemetry):
            row = item.row
            self.telemetry, self.telemetry_at = row, self.clock.now()
            if self.run is not None and self.run_t0 is None:
                self.run_t0 = row["boat_time"]
            self.hub.publish("telemetry", row)
            ev: LinkEvent = item.event
        else:
            ev = item
        if isinstance(ev, BoatReport):
            self.report_at = self.clock.now()
            if self.duplicates.observe(ev.report.boot_id, self.report_at) \
                    and self.on_duplicate is not None:
                found = self.duplicate()
                if found is not None:
                    self.on_duplicate(found)
            self.on_report(ev)
        elif isinstance(ev, BoatRebooted):
            self.on_reboot(ev)
        elif isinstance(ev, LinkUp):
            self.hub.publish("link", {"up": True, "device": self.device})
        elif isinstance(ev, LinkDown):
            self.hub.publish("link", {"up": False, "reason": ev.reason})
        elif isinstance(ev, StatusTextReceived):
            sev = SEVERITIES[ev.severity] if 0 <= ev.severity < len(SEVERITIES) \
                else str(ev.severity)
            text: StatusText = {"time": utc_now(self.clock), "severity": sev, "text": ev.text}
            self.status = [*self.status[-(STATUS_KEPT - 1):], text]
            self.hub.publish("status", text)
        for listener in self.listeners:
            listener(ev)


def telemetry_row(t: Telemetry, frame: RampFrame | None, run: int | None,
                  received: str) -> TelemetryRow:
    """A position report as a stored row (received at UTC `received`): SI units, compass
    degrees, ramp-frame x, y."""
    x = y = ramp_heading = None
    if frame is not None:
        xs, ys = frame.to_ramp(t.lat, t.lon)
        x, y = round(float(xs), 3), round(float(ys), 3)
        ramp_heading = round(float(frame.compass_to_heading_deg(t.heading_deg)), 2)
    return {
        "run": run, "time": received, "boat_time": t.time_s, "lat": t.lat, "lon": t.lon,
        "x": x, "y": y, "heading_deg": t.heading_deg, "course_deg": t.course_deg,
        "speed": t.speed, "ramp_heading_deg": ramp_heading,
        "yaw_rate_dps": t.yaw_rate_dps, "fix_type": t.fix_type,
        "satellites": t.satellites, "hdop": t.hdop,
        "thrust_left": t.thrust_left, "thrust_right": t.thrust_right,
        "battery_v": t.battery_v, "waypoint_index": t.waypoint_index,
        "cross_track_m": -t.cross_track_m, "state": t.state,
    }
