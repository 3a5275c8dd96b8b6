"""The console on a station that drives a stock autopilot (`serve --boat-protocol standard`,
a vehicle of MAVSDK's server plugins over UDP, unsigned): the link pill says plainly that
the link is unsigned, and the vehicle's telemetry shows (its state, the boat on the map,
the telemetry age)."""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect
from stationproc import StationProcess
from test_mavsdk_vehicle import MavsdkVehicle, free_udp_port, start_position


@pytest.fixture(scope="module")
def station(tmp_path_factory):
    """Overrides conftest's simulated-boat station for this module."""
    port = free_udp_port()
    vehicle = MavsdkVehicle(port, *start_position())
    st = None
    try:
        vehicle.wait(lambda: vehicle.of("ready"), 60, "start")
        st = StationProcess(tmp_path_factory.mktemp("data"), "--boat-protocol", "standard",
                            "--vehicle-profile", "px4", "--link", f"udp://127.0.0.1:{port}",
                            "--insecure-link")
        st.wait_link_up(60)
        yield st
    finally:
        if st is not None:
            st.stop()
        vehicle.stop()


def test_console_states_the_unsigned_link_and_shows_the_vehicle(page, station):
    page.goto(f"{station.url}/?token={station.token}")
    expect(page.locator("#live-state")).to_have_text("live: connected")
    expect(page.locator("#link-state")).to_contain_text("unsigned link", timeout=10_000)
    expect(page.locator("#link-state")).to_contain_text("anyone with a radio")
    expect(page.locator("#boat-state")).to_have_text("IDLE", timeout=10_000)
    expect(page.locator(".boat-marker")).to_be_visible(timeout=10_000)
    expect(page.locator("#tm-age")).to_have_text(re.compile(r"^\d\.\d$"))
    assert page.errors == []
