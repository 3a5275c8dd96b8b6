"""A MAVLink vehicle made of MAVSDK's server plugins (pip `mavsdk` 4.x: the MAVSDK C++
library in-process, no mavsdk_server), for tests/integration/test_mavsdk_vehicle.py.

    python mavsdk_vehicle.py udpin://127.0.0.1:PORT LAT LON [SECONDS]

MAVSDK's `mission_raw_server` takes and serves the mission (MISSION_COUNT /
MISSION_REQUEST_INT / MISSION_ITEM_INT / MISSION_ACK, both ways), `action_server` arms,
disarms and changes modes (PX4's custom modes: it accepts MANUAL, MISSION, STABILIZED and
OFFBOARD and refuses the rest, AUTO.LOITER among them), `telemetry_server` sends
GLOBAL_POSITION_INT, GPS_RAW_INT, SYS_STATUS, ATTITUDE and VFR_HUD, `param_server` answers
parameter requests, and `mavlink_direct` lets it see the station's
SET_POSITION_TARGET_GLOBAL_INT. What it received is printed as one JSON line per event
(ready, mission, mode, arm, target); the vehicle moves to each position target while armed
in OFFBOARD. It ends after SECONDS (default 300) whatever happens, or when killed.
"""

from __future__ import annotations

import ctypes
import json
import math
import sys
import threading
import time

from mavsdk import ComponentType, Configuration, Mavsdk
from mavsdk.plugins.action_server.action_server import ActionServer, AllowableFlightModes
from mavsdk.plugins.mavlink_direct.mavlink_direct import MavlinkDirect
from mavsdk.plugins.mission_raw_server.mission_raw_server import MissionRawServer
from mavsdk.plugins.param_server.param_server import ParamServer
from mavsdk.plugins.telemetry_server import telemetry_server as ts

MAV_TYPE_SURFACE_BOAT = 11
OFFBOARD = 7  # ActionServer.FlightMode.OFFBOARD
_print_lock = threading.Lock()


def say(event: str, **fields: object) -> None:
    with _print_lock:
        print(json.dumps({"event": event, **fields}), flush=True)


class Vehicle:
    def __init__(self, url: str, lat: float, lon: float) -> None:
        cfg = Configuration.create_with_component_type(ComponentType.AUTOPILOT)
        # a surface boat in HEARTBEAT (the C API has the setter, the Python binding not yet)
        lib = cfg._lib
        lib.mavsdk_configuration_set_mav_type.argtypes = [ctypes.c_void_p, ctypes.c_uint8]
        lib.mavsdk_configuration_set_mav_type(cfg._handle, MAV_TYPE_SURFACE_BOAT)
        self.sdk = Mavsdk(cfg)
        result = self.sdk.add_any_connection(url)
        if int(result) != 0:
            raise SystemExit(f"mavsdk: cannot listen on {url}: {result}")
        sc = self.sdk.server_component()
        self.mission = MissionRawServer(sc)
        self.action = ActionServer(sc)
        self.telemetry = ts.TelemetryServer(sc)
        self.params = ParamServer(sc)
        self.params.provide_param_int("MAV_TYPE", MAV_TYPE_SURFACE_BOAT)
        self.action.set_allowable_flight_modes(AllowableFlightModes(
            can_auto_mode=True, can_guided_mode=True, can_stabilize_mode=True))
        self.action.set_armable(True, True)
        self.action.set_disarmable(True, True)
        self.lat, self.lon = lat, lon
        self.vn = self.ve = 0.0
        self.armed = False
        self.mode = 0
        self.target: tuple[float, float, float, float] | None = None
        self.direct: MavlinkDirect | None = None
        self.mission.subscribe_incoming_mission(self._on_mission)
        self.action.subscribe_flight_mode_change(self._on_mode)
        self.action.subscribe_arm_disarm(self._on_arm)

    def _on_mission(self, result, plan, _ud) -> None:
        items = [{k: getattr(it, k) for k in ("seq", "frame", "command", "param1", "param2",
                                               "param3", "param4", "x", "y", "z")}
                 for it in plan.mission_items]
        say("mission", result=result.name, items=items)

    def _on_mode(self, result, mode, _ud) -> None:
        if result.name == "SUCCESS":
            self.mode = int(mode)
        say("mode", result=result.name, mode=mode.name)

    def _on_arm(self, result, arm, _ud) -> None:
        if result.name == "SUCCESS":
            self.armed = bool(arm.arm)
        say("arm", result=result.name, arm=bool(arm.arm), force=bool(arm.force))

    def _on_target(self, msg, _ud) -> None:
        f = json.loads(msg.fields_json)
        self.target = (f["lat_int"] * 1e-7, f["lon_int"] * 1e-7, f["vx"], f["vy"])
        say("target", lat=self.target[0], lon=self.target[1], vx=f["vx"], vy=f["vy"],
            frame=f["coordinate_frame"], type_mask=f["type_mask"])

    def _watch_targets(self) -> None:
        """MavlinkDirect on the ground station's system, once MAVSDK has discovered it."""
        if self.direct is None:
            systems = self.sdk.get_systems()
            if systems:
                self.direct = MavlinkDirect(systems[0])
                self.direct.subscribe_message("SET_POSITION_TARGET_GLOBAL_INT", self._on_target)

    def step(self, dt: float) -> None:
        if self.armed and self.mode == OFFBOARD and self.target is not None:
            self.lat, self.lon, self.vn, self.ve = self.target  # follows the targets exactly
        else:
            self.vn = self.ve = 0.0
        heading = math.degrees(math.atan2(self.ve, self.vn)) % 360 if self.vn or self.ve else 0
        speed = math.hypot(self.vn, self.ve)
        self.telemetry.publish_position(ts.Position(self.lat, self.lon, 0.0, 0.0),
                                        ts.VelocityNed(self.vn, self.ve, 0.0),
                                        ts.Heading(heading))
        self.telemetry.publish_raw_gps(
            ts.RawGps(timestamp_us=int(time.monotonic() * 1e6), latitude_deg=self.lat,
                      longitude_deg=self.lon, absolute_altitude_m=0.0, hdop=0.8, vdop=1.2,
                      velocity_m_s=speed, cog_deg=heading),
            ts.GpsInfo(num_satellites=14, fix_type=ts.FixType.FIX_3D))
        battery = ts.Battery(voltage_v=12.6, remaining_percent=80.0)
        self.telemetry.publish_sys_status(battery, True, True, True, True, True)
        self.telemetry.publish_attitude(ts.EulerAngle(0.0, 0.0, heading, 0),
                                        ts.AngularVelocityBody(0.0, 0.0, 0.0))
        self.telemetry.publish_visual_flight_rules_hud(ts.FixedwingMetrics(
            airspeed_m_s=speed, throttle_percentage=50.0 if self.armed else 0.0,
            climb_rate_m_s=0.0, groundspeed_m_s=speed, heading_deg=heading,
            absolute_altitude_m=0.0))


def main() -> None:
    url, lat, lon = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    seconds = float(sys.argv[4]) if len(sys.argv) > 4 else 300.0
    vehicle = Vehicle(url, lat, lon)
    say("ready", url=url)
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        vehicle._watch_targets()
        vehicle.step(0.2)
        time.sleep(0.2)


if __name__ == "__main__":
    main()
