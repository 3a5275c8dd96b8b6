"""A minimal stock-autopilot stand-in as a sans-IO state machine: the vehicle side of the
standard mission and command protocols, for the standard link's unit tests and `bench
link`'s `standard_upload`. The independent counterpart is MAVSDK
(tests/integration/test_mavsdk_vehicle.py); this one answers what the mission and command
protocols ask with a vehicle's timeouts (it re-requests a missing item after 0.25 s, five
times), commits an uploaded mission only whole at its final ACK, takes custom modes as
its profile numbers them (refusing `refused_modes`), arms and disarms, takes
SETUP_SIGNING, heartbeats at 1 Hz and reports its position at 5 Hz (moving to each
position target while armed).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from usvstation.link import wire
from usvstation.link.mavlink import usv_recovery as mav
from usvstation.link.standard import VehicleProfile
from usvstation.link.standard_mission import StandardItem


@dataclass
class StandardVehicle:
    """The vehicle (system 1, component 1) of `profile`; feed bytes and time in."""

    profile: VehicleProfile
    lat: int = 305135000
    lon: int = 114419000
    mode: int = 0
    armed: bool = False
    refused_modes: set[int] = field(default_factory=set)
    mission: list[StandardItem] = field(default_factory=list)
    receiving: dict[int, StandardItem] | None = None
    expected: int = 0
    request_at: float = 0.0
    requests: int = 0
    commands: list[tuple[int, tuple[float, ...]]] = field(default_factory=list)
    targets: list[Any] = field(default_factory=list)
    uploads: int = 0  # missions committed
    key: bytes | None = None
    next_heartbeat: float = 0.0
    next_position: float = 0.0
    boot_ms0: float = 0.0

    unix0: float = 1.7e9  # wall clock at time 0 (signing)

    def __post_init__(self) -> None:
        self.codec = wire.Codec(1, mav.MAV_COMP_ID_AUTOPILOT1, None)
        self.out = bytearray()

    def send(self, msg: Any, now: float) -> None:
        stamp = wire.signing_time(self.unix0 + now) if self.key else None
        self.out += self.codec.encode(msg, stamp)

    def receive(self, data: bytes, now: float) -> None:
        msgs, _ = self.codec.feed(data)
        for m in msgs:
            handler = getattr(self, "_on_" + m.get_type().lower(), None)
            if handler is not None and getattr(m, "target_system", 1) in (0, 1):
                handler(m, now)

    # --- mission server
    def _on_mission_count(self, m: Any, now: float) -> None:
        self.receiving, self.expected = {}, m.count
        self._request(0, now)

    def _request(self, seq: int, now: float) -> None:
        """Ask for item `seq` (the first time; `poll` asks again after 0.25 s)."""
        self.request_at, self.requests = now + 0.25, 1
        self.send(self.codec.mav.mission_request_int_encode(255, 190, seq, 0), now)

    def _on_mission_item_int(self, m: Any, now: float) -> None:
        rx = self.receiving
        if rx is None or m.seq != len(rx):
            return
        rx[m.seq] = StandardItem.from_msg(m)
        if len(rx) == self.expected:
            self.mission = [rx[i] for i in range(self.expected)]
            self.receiving = None
            self.uploads += 1
            self.send(self.codec.mav.mission_ack_encode(255, 190, 0, 0), now)
        else:
            self._request(len(rx), now)

    def _on_mission_request_list(self, m: Any, now: float) -> None:
        self.send(self.codec.mav.mission_count_encode(255, 190, len(self.mission), 0), now)

    def _on_mission_request_int(self, m: Any, now: float) -> None:
        if m.seq >= len(self.mission):
            self.send(self.codec.mav.mission_ack_encode(255, 190, 13, 0), now)
            return
        i = self.mission[m.seq]
        self.send(self.codec.mav.mission_item_int_encode(
            255, 190, i.seq, i.frame, i.command, 0, i.autocontinue, i.param1, i.param2,
            i.param3, i.param4, i.x, i.y, i.z, 0), now)

    def _on_mission_clear_all(self, m: Any, now: float) -> None:
        self.mission, self.receiving = [], None
        self.send(self.codec.mav.mission_ack_encode(255, 190, 0, 0), now)

    # --- commands
    def _on_command_long(self, c: Any, now: float) -> None:
        params = (c.param1, c.param2, c.param3, c.param4, c.param5, c.param6, c.param7)
        self.commands.append((c.command, params))
        result = mav.MAV_RESULT_ACCEPTED
        if c.command == mav.MAV_CMD_DO_SET_MODE:
            mode = int(c.param2) if self.profile.mode_params == "number" else \
                (int(c.param2) << 16) | (int(c.param3) << 24)
            if mode in self.refused_modes:
                result = mav.MAV_RESULT_TEMPORARILY_REJECTED
            else:
                self.mode = mode
        elif c.command == mav.MAV_CMD_COMPONENT_ARM_DISARM:
            self.armed = c.param1 == 1
        else:
            result = mav.MAV_RESULT_UNSUPPORTED
        self.send(self.codec.mav.command_ack_encode(c.command, result, 0, 0, 255, 190), now)

    def _on_set_position_target_global_int(self, m: Any, now: float) -> None:
        self.targets.append(m)

    def _on_setup_signing(self, m: Any, now: float) -> None:
        self.key = bytes(m.secret_key)
        self.codec = wire.Codec(1, mav.MAV_COMP_ID_AUTOPILOT1, self.key,
                                timestamp=wire.signing_time(self.unix0 + now))

    # --- timers
    def poll(self, now: float) -> None:
        if now >= self.next_heartbeat:
            self.next_heartbeat += 1.0
            base = mav.MAV_MODE_FLAG_CUSTOM_MODE_ENABLED | (
                mav.MAV_MODE_FLAG_SAFETY_ARMED if self.armed else 0)
            autopilot = mav.MAV_AUTOPILOT_PX4 if self.profile.mode_params == "px4" else \
                mav.MAV_AUTOPILOT_ARDUPILOTMEGA
            self.send(self.codec.mav.heartbeat_encode(
                mav.MAV_TYPE_SURFACE_BOAT, autopilot, base, self.mode, mav.MAV_STATE_ACTIVE),
                now)
        if now >= self.next_position:
            self.next_position += 0.2
            if self.targets and self.armed:
                self.lat, self.lon = self.targets[-1].lat_int, self.targets[-1].lon_int
            self.send(self.codec.mav.global_position_int_encode(
                int((now - self.boot_ms0) * 1000), self.lat, self.lon, 0, 0, 0, 0, 0, 9000),
                now)
        if self.receiving is not None and now >= self.request_at:
            if self.requests >= 6:  # asked six times: the transfer failed
                self.receiving = None
                self.send(self.codec.mav.mission_ack_encode(255, 190, 15, 0), now)
            else:
                self.requests += 1
                self.request_at = now + 0.25
                self.send(self.codec.mav.mission_request_int_encode(
                    255, 190, len(self.receiving), 0), now)

    def data_to_send(self) -> bytes:
        data = bytes(self.out)
        self.out.clear()
        return data
