"""Station settings from flags and environment variables (USV_STATION_*), and the access token."""

from __future__ import annotations

import enum
import ipaddress
import os
import secrets
import socket
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

from pydantic import Field, field_validator, model_validator
from pydantic_settings import BaseSettings, SettingsConfigDict

MIN_TOKEN_LENGTH = 16


class Role(enum.IntEnum):
    VIEWER = 1
    OPERATOR = 2


@dataclass(frozen=True)
class Tokens:
    """The operator token ('' turns authentication off) and the optional viewer token."""

    operator: str
    viewer: str | None = None

    def role(self, given: str | None) -> Role | None:
        """The role `given` grants, None for no or a wrong token."""
        if not self.operator:
            return Role.OPERATOR  # authentication off (loopback only, see config.resolve_token)
        if given is None:
            return None
        if secrets.compare_digest(given.encode(), self.operator.encode()):
            return Role.OPERATOR
        if self.viewer and secrets.compare_digest(given.encode(), self.viewer.encode()):
            return Role.VIEWER
        return None


class Settings(BaseSettings):
    """Everything `usv-station serve` needs; flags override USV_STATION_* variables."""

    model_config = SettingsConfigDict(env_prefix="USV_STATION_", extra="forbid")

    # Each field is a `serve` flag (--field-name, cli.py generates them from here) and a
    # USV_STATION_FIELD_NAME variable. `flag`: another flag name; `repeat`: a repeatable
    # flag, else a list is one comma-separated value; `metavar`: the value's name in --help.
    host: str = Field("127.0.0.1", description="address to bind")
    port: int = Field(8000, ge=0, le=65535, description="HTTP port (0: any free port)")
    link: str = Field("sim", description="the boat link: 'sim' (the simulated boat on a "
                      "pseudo-terminal), a serial device, a pyserial URL (socket://host:port: "
                      "TCP) or UDP (udp://host:port to the boat, udpin://host:port to listen)")
    baud: int = Field(57600, gt=0, description="serial baud rate")
    data_dir: Path = Field(Path("data"), description="database, token and key folder")
    token: str | None = Field(None, description="operator access token; default: generated "
                              "into the data dir")
    viser_port: int = Field(8080, ge=0, le=65535, description="3D view port (loopback only; "
                            "browsers reach it at /3d/)")
    sim_speed: float = Field(1.0, gt=0.0, le=100.0, description="simulated boat time runs "
                             "this many times faster")
    sim_gnss_error: bool = Field(True, description="the simulated boat navigates on RTK-class "
                                 "sensors (2 cm GNSS, compass bias and noise; sim/sensors.py "
                                 "'rtk'); off: on exact ones")
    cors_origins: list[str] = Field(default_factory=list, description="origins allowed by "
                                    "CORS for the HTTP API (comma-separated)")
    plan_workers: int = Field(2, ge=1, le=32, description="plan worker processes")
    heartbeat_timeout_s: float = Field(3.0, gt=0.0, description="link time without a frame "
                                       "from the boat before the link is down")
    telemetry_hz: float = Field(5.0, gt=0.0, le=50.0, description="the simulated boat's "
                                "telemetry rate, per second of boat time")
    viewer_token: str | None = Field(None, description="read-only token (telemetry, runs, "
                                     "exports, plans, websocket); default: none")
    allowed_hosts: list[str] = Field(default_factory=list, description="Host header names "
                                     "accepted besides IP addresses, localhost and --host "
                                     "(DNS-rebinding guard; comma-separated)")
    allowed_origins: list[str] = Field(default_factory=list, description="websocket Origins "
                                       "accepted besides the station's own (comma-separated)")
    max_body_bytes: int = Field(1 << 20, ge=1024, le=1 << 30, description="request body "
                                "limit, enforced while the body streams in")
    max_ws_clients: int = Field(64, ge=1, le=10_000, description="live websocket clients "
                                "(then 503)")
    max_connections: int = Field(2048, ge=16, le=100_000, description="open HTTP "
                                 "connections (then 503)")
    max_client_connections: int = Field(256, ge=1, le=100_000, description="open HTTP "
                                        "connections from one client address (more are "
                                        "closed at once)")
    header_timeout_s: float = Field(10.0, gt=0.0, le=300.0, description="time a client "
                                    "has to send a request's headers")
    keep_alive_s: float = Field(5.0, gt=0.0, le=300.0, description="idle keep-alive time")
    plan_timeout_s: float = Field(10.0, gt=0.0, le=3600.0, description="wall-clock limit "
                                  "of one plan")
    plan_memory_mb: int = Field(2048, ge=1024, le=1 << 20, description="memory limit of a "
                                "plan worker, MB (its address space: the compiled fitness "
                                "kernel alone takes about 550 MB of it)")
    plan_queue: int = Field(32, ge=1, le=10_000, description="plans queued or running at "
                            "most (then 429)")
    nmea: list[str] = Field(
        default_factory=list, description="ship sensors, NMEA 0183 and AIS (repeatable): "
        "udp://0.0.0.0:10110, tcp://HOST:PORT, serial:///dev/ttyUSB0?baud=38400 or a device "
        "path", json_schema_extra={"repeat": True, "metavar": "URL"})
    replan: Literal["auto", "confirm", "off"] = Field(
        "confirm", description="on a warning: re-plan and swap (auto), propose a re-plan for "
        "the operator to confirm (confirm) or only alert (off)")
    boat_id: int = Field(1, ge=1, le=254, description="MAVLink system id of the paired boat")
    station_id: int = Field(255, ge=1, le=255, description="this station's MAVLink system id")
    link_key: Path | None = Field(None, description="32-byte signing key file (usv-station "
                                  "link-key new PATH); with the simulated boat default: "
                                  "generated into the data dir",
                                  json_schema_extra={"metavar": "PATH"})
    insecure_link: bool = Field(False, description="unsigned link (anyone with a radio can "
                                "command the boat): explicit opt-in only")
    boat_protocol: Literal["usv-link", "standard"] = Field(
        "usv-link", description="the boat's protocol: usv-link (usv-link 2, timed waypoints, "
        "signed) or standard (a stock MAVLink autopilot: standard missions, modes, GUIDED "
        "position targets; --link socket://HOST:PORT, udp://HOST:PORT or udpin://HOST:PORT)")
    vehicle_profile: Literal["ardupilot-rover", "px4"] = Field(
        "ardupilot-rover", description="with --boat-protocol standard: the autopilot's "
        "modes and mission conventions (docs/link.md)")
    standard_guided: bool = Field(True, description="with --boat-protocol standard: START "
                                  "follows the timed plan with GUIDED position targets (5 "
                                  "Hz); off: the uploaded mission in AUTO at its leg speeds")
    frontend_dir: Path | None = Field(
        None, description="operator console files (index.html, app/, node_modules/); "
        "default: frontend/ of the source checkout")
    charts_dir: Path | None = Field(
        None, description="folder of offline chart packages (*.mbtiles) for the console's map",
        json_schema_extra={"flag": "--charts"})

    @model_validator(mode="after")
    def _link_url(self) -> Settings:
        if self.boat_protocol == "standard" and self.link == "sim":
            raise ValueError("--boat-protocol standard needs --link to a vehicle (the "
                             "simulated boat speaks usv-link 2)")
        scheme, sep, rest = self.link.partition("://")
        if sep and scheme in ("udp", "udpin"):
            host, _, port = rest.rpartition(":")
            if not host or not port.isdigit() or not 0 < int(port) < 65536:
                raise ValueError(f"--link {self.link}: expected {scheme}://HOST:PORT")
        return self

    @field_validator("nmea")
    @classmethod
    def _nmea_urls(cls, urls: list[str]) -> list[str]:
        from usvstation.shipinputs.readers import parse_source

        for url in urls:
            parse_source(url)
        return urls


class ExposureError(ValueError):
    """The settings would expose boat control without authentication."""


def is_loopback(host: str) -> bool:
    """True for addresses that only this machine can reach."""
    if host in ("localhost", ""):
        return host == "localhost"
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        try:
            return all(ipaddress.ip_address(a[4][0]).is_loopback
                       for a in socket.getaddrinfo(host, None))
        except (OSError, ValueError):
            return False


def resolve_token(settings: Settings) -> str:
    """The bearer token: --token / USV_STATION_TOKEN, else the one generated in data_dir.

    An empty token turns authentication off, which is refused unless the
    station binds to a loopback address only.
    """
    token = settings.token
    if token is None:
        path = settings.data_dir / "token"
        if path.exists():
            token = path.read_text(encoding="utf-8").strip()
        else:
            token = secrets.token_urlsafe(24)
            settings.data_dir.mkdir(parents=True, exist_ok=True)
            fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
            with os.fdopen(fd, "w", encoding="utf-8") as f:
                f.write(token + "\n")
    if not is_loopback(settings.host):
        if not token:
            raise ExposureError(
                f"refusing to bind {settings.host} without a token: set --token "
                "(or USV_STATION_TOKEN) or bind to 127.0.0.1"
            )
        if len(token) < MIN_TOKEN_LENGTH:
            raise ExposureError(
                f"refusing to bind {settings.host} with a token of {len(token)} characters: "
                f"use at least {MIN_TOKEN_LENGTH}"
            )
    return token


class LinkKeyError(ValueError):
    """The link's signing settings are contradictory or the key file is unusable."""


def resolve_link_key(settings: Settings) -> bytes | None:
    """The usv-link signing key: --link-key, else with the simulated boat a key generated
    in data_dir (link.key), so signing is on by default; None only with --insecure-link."""
    from usvstation.link.wire import read_key, write_key

    if settings.insecure_link:
        if settings.link_key is not None:
            raise LinkKeyError("--link-key and --insecure-link contradict each other")
        return None
    if settings.boat_id == settings.station_id:
        raise LinkKeyError(f"boat_id and station_id are both {settings.boat_id}")
    path = settings.link_key
    if path is None:
        if settings.link != "sim":
            raise LinkKeyError("a boat link needs --link-key PATH (usv-station link-key new "
                               "PATH) or, knowingly, --insecure-link")
        path = settings.data_dir / "link.key"
        if not path.exists():
            settings.data_dir.mkdir(parents=True, exist_ok=True)
            write_key(path)
    try:
        return read_key(path)
    except OSError as exc:
        raise LinkKeyError(f"link key {path}: {exc.strerror}") from None
