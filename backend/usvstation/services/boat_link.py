"""Link handling for the boat service: the BoatLink, its events turned into stored
telemetry, status texts and live events, and the link's part of /api/boat."""

from __future__ import annotations

from collections.abc import Callable

from usvstation.geo import RampFrame
from usvstation.geometry import MS
from usvstation.link.protocol import (
    BoatRebooted,
    BoatReport,
    LinkDown,
    LinkEvent,
    LinkUp,
    StatusTextReceived,
    Telemetry,
    TelemetryReceived,
)
from usvstation.link.station import BoatLink
from usvstation.records import BoatSnapshot, StatusText, TelemetryRow
from usvstation.services.hub import LiveHub
from usvstation.store.db import Store, utc_now

STATUS_KEPT = 50
SEVERITIES = ("EMERGENCY", "ALERT", "CRITICAL", "ERROR", "WARNING", "NOTICE", "INFO", "DEBUG")


class LinkHandler:
    """Owns the BoatLink; telemetry goes to the store and the hub, reports to `on_report`."""

    def __init__(self, link: BoatLink, device: str, store: Store, hub: LiveHub,
                 on_report: Callable[[BoatReport], None],
                 on_reboot: Callable[[BoatRebooted], None]) -> None:
        self.link, self.device, self.store, self.hub = link, device, store, hub
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
        link.add_listener(self._on_event)

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

    def _on_event(self, ev: LinkEvent) -> None:
        if isinstance(ev, TelemetryReceived):
            self._ingest(ev.telemetry)
        elif isinstance(ev, BoatReport):
            self.report_at = self.clock.now()
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
            item: StatusText = {"time": utc_now(self.clock), "severity": sev, "text": ev.text}
            self.status = [*self.status[-(STATUS_KEPT - 1):], item]
            self.hub.publish("status", item)

    def _ingest(self, t: Telemetry) -> None:
        self.frames += 1
        moving = self.moving_frame() if self.moving_frame is not None else None
        row = telemetry_row(t, moving or self.frame, self.run, utc_now(self.clock))
        self.store.writer.put(row)
        self.telemetry, self.telemetry_at = row, self.clock.now()
        if self.run is not None and self.run_t0 is None:
            self.run_t0 = row["boat_time"]
        self.hub.publish("telemetry", row)


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
