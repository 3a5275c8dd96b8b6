"""The boat side of usv-link as a sans-IO state machine (protocol/README.md "Boat").

`BoatProtocol` is what the STM32 firmware does, in Python: it stages missions and
activates them atomically after a verified MISSION_END, executes commands once per
command_id, sends HEARTBEAT and TELEMETRY, and holds station (failsafe) when the
station link is lost. It drives any `Vehicle` (sim/vehicle.py). Time comes in as
`now` (link clock, seconds); the boat clock runs `sim_speed` times faster.
"""

from __future__ import annotations

import math
from collections import OrderedDict
from dataclasses import dataclass
from typing import Any

import numpy as np

from usvstation.geo import RampFrame
from usvstation.link import messages as m
from usvstation.link.codec import Encoder, FrameDecoder, mission_crc32
from usvstation.link.mission import item_problem
from usvstation.link.protocol import heartbeat_matches, mismatch_message
from usvstation.sim.sensors import Battery, GpsNoise
from usvstation.sim.vehicle import Vehicle, Waypoint

NAK = m.NakReason
STAGE = m.MissionStage


@dataclass(frozen=True)
class BoatConfig:
    telemetry_hz: float = 5.0  # 0 < hz <= 50, frames per second of boat time
    failsafe_timeout_s: float = m.LINK_TIMEOUT_MS / 1000
    heartbeat_period_s: float = m.HEARTBEAT_PERIOD_MS / 1000
    sim_speed: float = 1.0  # boat seconds per link-clock second
    max_step_s: float = 0.05  # vehicle integration step, boat time

    def __post_init__(self) -> None:
        if not 0 < self.telemetry_hz <= 50:
            raise ValueError(f"telemetry_hz must be in (0, 50], got {self.telemetry_hz}")
        if self.failsafe_timeout_s <= 0:
            raise ValueError("failsafe_timeout_s must be positive")
        if self.sim_speed <= 0:
            raise ValueError(f"sim_speed must be positive, got {self.sim_speed}")


@dataclass
class _Staging:
    begin: m.MissionBegin
    items: dict[int, m.MissionItem]

    def same(self, b: m.MissionBegin) -> bool:
        return self.begin == b


class MissionStager:
    """Stages one mission's items; verifies count, ranges, times and the CRC-32 at END.
    Returns the answer (MISSION_ACK or MISSION_NAK) for each message; never touches
    the active mission itself."""

    def __init__(self) -> None:
        self.staging: _Staging | None = None

    def on_begin(self, b: m.MissionBegin) -> m.MissionAck | m.MissionNak:
        if b.mission_id == 0:
            return m.MissionNak(0, STAGE.BEGIN, 0, NAK.UNKNOWN_MISSION, 0)
        if b.count == 0:
            return m.MissionNak(b.mission_id, STAGE.BEGIN, 0, NAK.BAD_COUNT, 0)
        if b.count > m.MAX_MISSION_ITEMS:
            return m.MissionNak(b.mission_id, STAGE.BEGIN, 0, NAK.TOO_MANY_ITEMS, 0)
        if self.staging is None or not self.staging.same(b):
            self.staging = _Staging(b, {})  # a new mission: drop any other staging
        return m.MissionAck(b.mission_id, STAGE.BEGIN, 0, len(self.staging.items))

    def on_item(self, it: m.MissionItem) -> m.MissionAck | m.MissionNak:
        st = self.staging
        if st is None or st.begin.mission_id != it.mission_id:
            return m.MissionNak(it.mission_id, STAGE.ITEM, it.index, NAK.UNKNOWN_MISSION, 0)
        n = len(st.items)
        if it.index >= st.begin.count:
            return m.MissionNak(it.mission_id, STAGE.ITEM, it.index, NAK.BAD_INDEX, n)
        if item_problem(it):
            return m.MissionNak(it.mission_id, STAGE.ITEM, it.index, NAK.BAD_ITEM, n)
        old = st.items.get(it.index)
        if old is not None and old != it:
            return m.MissionNak(it.mission_id, STAGE.ITEM, it.index, NAK.CONFLICT, n)
        st.items[it.index] = it  # a duplicate of a staged item changes nothing
        return m.MissionAck(it.mission_id, STAGE.ITEM, it.index, len(st.items))

    def on_end(self, e: m.MissionEnd) -> tuple[m.MissionAck | m.MissionNak, list | None]:
        """The answer, and the verified items (in order) when the mission may be activated."""
        st = self.staging
        if st is None or st.begin.mission_id != e.mission_id:
            return m.MissionNak(e.mission_id, STAGE.END, 0, NAK.UNKNOWN_MISSION, 0), None
        b, n = st.begin, len(st.items)
        if e.count != b.count:
            return m.MissionNak(e.mission_id, STAGE.END, 0, NAK.BAD_COUNT, n), None
        if e.mission_crc != b.mission_crc:
            self.staging = None
            return m.MissionNak(e.mission_id, STAGE.END, 0, NAK.CRC_MISMATCH, n), None
        missing = next((i for i in range(b.count) if i not in st.items), None)
        if missing is not None:
            return m.MissionNak(e.mission_id, STAGE.END, missing, NAK.MISSING_ITEMS, n), None
        items = [st.items[i] for i in range(b.count)]
        for i in range(1, len(items)):
            if items[i].t_ms <= items[i - 1].t_ms:
                self.staging = None
                return m.MissionNak(e.mission_id, STAGE.END, i, NAK.BAD_ITEM, n), None
        origin = (b.origin_lat_e7, b.origin_lon_e7, b.ramp_bearing_cdeg)
        if mission_crc32(origin, items) != b.mission_crc:
            self.staging = None
            return m.MissionNak(e.mission_id, STAGE.END, 0, NAK.CRC_MISMATCH, n), None
        self.staging = None
        return m.MissionAck(e.mission_id, STAGE.END, 0, n), items


@dataclass(frozen=True)
class ActiveMission:
    begin: m.MissionBegin
    items: tuple[m.MissionItem, ...]

    @property
    def mission_id(self) -> int:
        return self.begin.mission_id


MAX_CATCH_UP_S = 1.0  # link-clock seconds of missed TELEMETRY frames sent late, not skipped


class BoatProtocol:
    """The simulated boat's protocol engine: feed bytes and time in, take bytes out."""

    def __init__(self, vehicle: Vehicle, frame: RampFrame, config: BoatConfig | None = None,
                 *, gps: GpsNoise | None = None, battery: Battery | None = None,
                 now: float = 0.0) -> None:
        self.vehicle = vehicle
        self.frame = frame
        self.cfg = config or BoatConfig()
        self.gps = gps or GpsNoise()
        self.battery = battery or Battery()
        self.encoder = Encoder()
        self.decoder = FrameDecoder()
        self.stager = MissionStager()
        self.active: ActiveMission | None = None
        self.state = m.State.IDLE
        self.mode = m.Mode.STANDBY
        self.failsafe = False
        self.linked = False
        self.mismatch: str | None = None
        self.started = now
        self.last_now = now
        self.last_rx = -math.inf
        self.boat_time = 0.0
        self.next_telemetry = now
        self.next_heartbeat = now
        self.guidance_until = -math.inf
        self.next_mismatch_text = now
        self.recent_commands: OrderedDict[int, m.CommandAck] = OrderedDict()
        self.log: list[str] = []  # status texts and events, for the runner to print
        self._out = bytearray()

    # ---- I/O boundary
    def receive_data(self, data: bytes, now: float) -> None:
        self.update(now)
        for msg in self.decoder.feed(data):
            self._handle(msg, now)

    def data_to_send(self) -> bytes:
        data = bytes(self._out)
        self._out.clear()
        return data

    def _send(self, msg: Any) -> None:
        self._out += self.encoder.encode(msg)

    def _text(self, severity: m.Severity, text: str) -> None:
        self.log.append(f"{severity.name}: {text}")
        self._send(m.StatusText(severity, text))

    @property
    def flags(self) -> int:
        f = m.Flag(0)
        if self.failsafe:
            f |= m.Flag.FAILSAFE
        if self.stager.staging is not None:
            f |= m.Flag.STAGING
        if not self.linked:
            f |= m.Flag.LINK_LOST
        return int(f)

    def heartbeat(self, now: float) -> m.Heartbeat:
        return m.Heartbeat(m.DEFINITION_CRC, m.PROTOCOL_VERSION, m.Sender.BOAT, self.mode,
                           self.state, self.flags, self.active.mission_id if self.active else 0,
                           int((now - self.started) * 1000) & 0xFFFFFFFF)

    def _report_state(self, now: float) -> None:
        self._send(self.heartbeat(now))
        self.next_heartbeat = now + self.cfg.heartbeat_period_s

    # ---- messages
    def _handle(self, msg: Any, now: float) -> None:
        if isinstance(msg, m.Heartbeat):
            self._on_heartbeat(msg, now)
            return
        if not self.linked:
            return  # no handshake (or a mismatched one): nothing is acted on
        self.last_rx = now
        if isinstance(msg, m.Command):
            self._on_command(msg, now)
        elif isinstance(msg, m.MissionBegin):
            if self.state == m.State.RUNNING:
                self._send(m.MissionNak(msg.mission_id, STAGE.BEGIN, 0, NAK.BUSY, 0))
            else:
                self._send(self.stager.on_begin(msg))
        elif isinstance(msg, m.MissionItem):
            self._send(self._late_duplicate(msg) or self.stager.on_item(msg))
        elif isinstance(msg, m.MissionEnd):
            self._on_end(msg, now)
        elif isinstance(msg, m.GuidanceSetpoint):
            self._on_guidance(msg, now)

    def _on_heartbeat(self, hb: m.Heartbeat, now: float) -> None:
        if hb.sender == m.Sender.BOAT and heartbeat_matches(hb):
            return  # our own heartbeat echoed back: not a station
        if not heartbeat_matches(hb):
            self.mismatch = mismatch_message("station", hb, me="boat")
            short = (f"mismatch station v{hb.protocol_version} 0x{hb.definition_crc:08X} "
                     f"boat v{m.PROTOCOL_VERSION} 0x{m.DEFINITION_CRC:08X}")
            if self.linked:
                self._link_lost(now, "definition mismatch")
            if now >= self.next_mismatch_text:
                self.log.append(self.mismatch)
                self._text(m.Severity.ERROR, short)
                self.next_mismatch_text = now + 5.0
            return
        self.mismatch = None
        self.last_rx = now
        if not self.linked:
            self.linked = True
            self._report_state(now)  # answer at once: completes the station's handshake
            if self.failsafe:
                self._text(m.Severity.WARNING, "link restored; holding: RESUME to continue")
            else:
                self._text(m.Severity.INFO, "link up")

    def _late_duplicate(self, it: m.MissionItem) -> m.MissionAck | None:
        """An item of the already active mission (its ACK was lost): acknowledge again."""
        a = self.active
        if (self.stager.staging is None and a is not None and it.mission_id == a.mission_id
                and it.index < len(a.items) and a.items[it.index] == it):
            return m.MissionAck(it.mission_id, STAGE.ITEM, it.index, len(a.items))
        return None

    def _on_end(self, e: m.MissionEnd, now: float) -> None:
        a = self.active
        if (self.stager.staging is None and a is not None and e.mission_id == a.mission_id
                and e.mission_crc == a.begin.mission_crc):
            self._send(m.MissionAck(e.mission_id, STAGE.END, 0, len(a.items)))  # duplicate END
            return
        if self.state == m.State.RUNNING:
            self._send(m.MissionNak(e.mission_id, STAGE.END, 0, NAK.BUSY, 0))
            return
        begin = self.stager.staging.begin if self.stager.staging else None
        answer, items = self.stager.on_end(e)
        if items is None or begin is None:
            self._send(answer)
            return
        waypoints = self._waypoints(begin, items)  # build fully, then swap: atomic
        self.vehicle.set_mission(waypoints)
        self.active = ActiveMission(begin, tuple(items))
        self.state, self.mode, self.failsafe = m.State.READY, m.Mode.STANDBY, False
        self._send(answer)
        self._text(m.Severity.INFO, f"mission {e.mission_id} active: {len(items)} waypoints")
        self._report_state(now)

    def _waypoints(self, begin: m.MissionBegin, items: list[m.MissionItem]) -> list[Waypoint]:
        """Wire items (geodetic) to the vehicle's world frame (the sim's ramp frame)."""
        lat = np.array([it.lat_e7 for it in items]) / 1e7
        lon = np.array([it.lon_e7 for it in items]) / 1e7
        x, y = self.frame.to_ramp(lat, lon)
        heading = np.radians(self.frame.compass_to_heading_deg(
            np.array([it.heading_cdeg for it in items]) / 100))
        return [Waypoint(float(x[i]), float(y[i]), it.t_ms / 1000, it.speed_cms / 100,
                         float(heading[i])) for i, it in enumerate(items)]

    def _on_command(self, c: m.Command, now: float) -> None:
        ack = self.recent_commands.get(c.command_id)
        if ack is not None and ack.command == c.command:
            self._send(ack)  # a retry: answer again, do not execute twice
            return
        result = self._execute(c, now)
        ack = m.CommandAck(c.command_id, c.command, result, self.state)
        self.recent_commands[c.command_id] = ack
        while len(self.recent_commands) > 32:
            self.recent_commands.popitem(last=False)
        self._send(ack)
        self._report_state(now)

    def _execute(self, c: m.Command, now: float) -> m.CommandResult:
        R, S = m.CommandResult, m.State
        state = self.state
        if c.command == m.CommandCode.START:
            if self.active is None:
                return R.NO_MISSION
            if c.mission_id != self.active.mission_id:
                return R.MISSION_MISMATCH
            if state != S.READY:
                return R.REJECTED_STATE
            self.vehicle.start()
            self.state, self.mode = S.RUNNING, m.Mode.AUTO
            self._text(m.Severity.INFO, f"mission {self.active.mission_id} started")
        elif c.command == m.CommandCode.HOLD:
            if state not in (S.RUNNING, S.HOLD):
                return R.REJECTED_STATE
            self.vehicle.hold()
            self.state, self.mode = S.HOLD, m.Mode.STANDBY
        elif c.command == m.CommandCode.RESUME:
            if state not in (S.HOLD, S.RUNNING):
                return R.REJECTED_STATE
            if state == S.HOLD:
                self.vehicle.resume()
            self.state, self.mode, self.failsafe = S.RUNNING, m.Mode.AUTO, False
        elif c.command == m.CommandCode.ABORT:
            if self.active is not None or state not in (S.IDLE, S.ABORTED):
                self.vehicle.abort()
                self._text(m.Severity.WARNING, "aborted: thrusters stopped, mission dropped")
            self.active, self.failsafe = None, False
            self.state, self.mode = S.ABORTED, m.Mode.STANDBY
        else:
            return R.UNKNOWN_COMMAND
        return R.ACCEPTED

    def _on_guidance(self, g: m.GuidanceSetpoint, now: float) -> None:
        if self.state != m.State.RUNNING or g.valid_ms == 0:
            return
        heading = math.radians(float(self.frame.compass_to_heading_deg(g.heading_cdeg / 100)))
        self.vehicle.set_guidance(heading, g.speed_cms / 100)
        self.mode = m.Mode.GUIDED
        self.guidance_until = now + g.valid_ms / 1000

    # ---- time
    def update(self, now: float) -> None:
        """Advance to link time `now`: vehicle, guidance expiry, failsafe, periodic frames.

        TELEMETRY frames keep a fixed schedule, `started + k * telemetry_period` of the
        link clock (k/telemetry_hz of boat time): the vehicle is advanced to each due
        instant and sampled there, so a late call never shifts the grid. After a stall
        longer than MAX_CATCH_UP_S the missed frames are skipped, the grid kept.
        """
        period = self.telemetry_period
        behind = now - self.next_telemetry
        if behind > MAX_CATCH_UP_S:
            self.next_telemetry += math.floor(behind / period) * period
        while self.next_telemetry <= now:
            self._advance_to(self.next_telemetry)
            self._send(self.telemetry())
            self.next_telemetry += period
        self._advance_to(now)
        if self.mode == m.Mode.GUIDED and now >= self.guidance_until:
            self.vehicle.clear_guidance()
            self.mode = m.Mode.AUTO if self.state == m.State.RUNNING else m.Mode.STANDBY
        if self.state == m.State.RUNNING and self.vehicle.state.mission_complete:
            self.state, self.mode = m.State.DONE, m.Mode.STANDBY
            self._text(m.Severity.INFO, f"mission {self.active.mission_id} complete")
            self._report_state(now)
        if self.linked and now - self.last_rx > self.cfg.failsafe_timeout_s:
            self._link_lost(now, f"no frame from the station for "
                                 f"{self.cfg.failsafe_timeout_s:.1f} s")
        if now >= self.next_heartbeat:
            self._report_state(now)

    @property
    def telemetry_period(self) -> float:
        """Link-clock seconds between TELEMETRY frames: `telemetry_hz` per second of boat
        time (so a faster sim sends faster), at most 50 frames per second on the link."""
        return max(1.0 / (self.cfg.telemetry_hz * self.cfg.sim_speed), 1.0 / 50.0)

    def _link_lost(self, now: float, reason: str) -> None:
        """Failsafe: hold station when running, and report it."""
        self.linked = False
        if self.state == m.State.RUNNING:
            self.vehicle.hold()
            self.state, self.mode, self.failsafe = m.State.HOLD, m.Mode.STANDBY, True
            self._text(m.Severity.CRITICAL, f"failsafe hold: {reason}"[:m.STATUS_TEXT_MAX])
        else:
            self._text(m.Severity.WARNING, f"link lost: {reason}"[:m.STATUS_TEXT_MAX])
        self._report_state(now)

    def _advance_to(self, now: float) -> None:
        dt_link = max(0.0, now - self.last_now)
        self.last_now = max(self.last_now, now)
        self._advance_vehicle(dt_link * self.cfg.sim_speed)

    def _advance_vehicle(self, dt: float) -> None:
        while dt > 1e-12:
            h = min(dt, self.cfg.max_step_s)
            self.vehicle.step(h)
            s = self.vehicle.state
            self.battery.step(h, s.thrust_left, s.thrust_right)
            self.boat_time += h
            dt -= h

    def next_deadline(self) -> float:
        d = min(self.next_telemetry, self.next_heartbeat)
        if self.linked:
            d = min(d, self.last_rx + self.cfg.failsafe_timeout_s + 1e-3)
        if self.mode == m.Mode.GUIDED:
            d = min(d, self.guidance_until)
        return d

    # ---- telemetry
    def telemetry(self) -> m.Telemetry:
        s = self.vehicle.state
        dx, dy = self.gps.sample(1.0 / self.cfg.telemetry_hz)
        lat, lon = self.frame.to_geodetic(s.x + dx, s.y + dy)
        compass = self.frame.heading_to_compass_deg
        return m.Telemetry(
            time_ms=round(self.boat_time * 1000) & 0xFFFFFFFF,
            lat_e7=round(float(lat) * 1e7), lon_e7=round(float(lon) * 1e7),
            fix_type=self.gps.fix_type, satellites=self.gps.satellites,
            hdop_c=_clamp(round(self.gps.hdop * 100), 0, 0xFFFF),
            sog_cms=_clamp(round(s.speed * 100), 0, 0xFFFF),
            cog_cdeg=round(float(compass(math.degrees(s.course))) * 100) % 36000,
            heading_cdeg=round(float(compass(math.degrees(s.heading))) * 100) % 36000,
            yaw_rate_cdegs=_clamp(round(-math.degrees(s.yaw_rate) * 100), -0x8000, 0x7FFF),
            thrust_left_pm=_clamp(round(s.thrust_left * 1000), -1000, 1000),
            thrust_right_pm=_clamp(round(s.thrust_right * 1000), -1000, 1000),
            battery_mv=_clamp(round(self.battery.voltage * 1000), 0, 0xFFFF),
            wp_index=_clamp(s.waypoint_index, 0, 0xFFFF),
            xte_cm=_clamp(round(s.cross_track_error * 100), -0x8000, 0x7FFF),
            state=self.state, mode=self.mode, flags=self.flags,
        )


def _clamp(v: int, lo: int, hi: int) -> int:
    return lo if v < lo else hi if v > hi else v
