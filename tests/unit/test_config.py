"""Access token generation and refusal to expose boat control without one."""

import stat

import pytest

from usvstation.config import ExposureError, Settings, is_loopback, resolve_token


def test_token_is_generated_once_and_private(tmp_path):
    token = resolve_token(Settings(data_dir=tmp_path))
    assert len(token) >= 24
    mode = (tmp_path / "token").stat().st_mode
    assert stat.S_IMODE(mode) == 0o600
    assert resolve_token(Settings(data_dir=tmp_path)) == token


def test_explicit_token_wins(tmp_path):
    assert resolve_token(Settings(data_dir=tmp_path, token="abc")) == "abc"
    assert not (tmp_path / "token").exists()


@pytest.mark.parametrize("host", ["0.0.0.0", "192.168.1.20", "::"])
def test_network_binding_needs_a_real_token(tmp_path, host):
    with pytest.raises(ExposureError, match=f"refusing to bind {host} without a token"):
        resolve_token(Settings(data_dir=tmp_path, host=host, token=""))
    with pytest.raises(ExposureError, match="token of 5 characters"):
        resolve_token(Settings(data_dir=tmp_path, host=host, token="short"))
    assert resolve_token(Settings(data_dir=tmp_path, host=host, token="x" * 20)) == "x" * 20


def test_loopback_may_run_without_a_token(tmp_path):
    assert resolve_token(Settings(data_dir=tmp_path, host="127.0.0.1", token="")) == ""
    assert is_loopback("localhost") and is_loopback("::1") and not is_loopback("0.0.0.0")


def test_environment_variables(tmp_path, monkeypatch):
    monkeypatch.setenv("USV_STATION_PORT", "9001")
    monkeypatch.setenv("USV_STATION_SIM_SPEED", "5")
    s = Settings(data_dir=tmp_path)
    assert s.port == 9001 and s.sim_speed == 5.0


def test_standard_boat_protocol_needs_a_vehicle_link_and_udp_urls_a_port():
    import pytest
    from pydantic import ValidationError

    from usvstation.config import Settings

    with pytest.raises(ValidationError, match="needs --link to a vehicle"):
        Settings(boat_protocol="standard")
    with pytest.raises(ValidationError, match="expected udp://HOST:PORT"):
        Settings(link="udp://127.0.0.1")
    with pytest.raises(ValidationError, match="expected udpin://HOST:PORT"):
        Settings(link="udpin://0.0.0.0:99999")
    s = Settings(boat_protocol="standard", link="udpin://0.0.0.0:14550",
                 vehicle_profile="px4")
    assert (s.boat_protocol, s.vehicle_profile, s.standard_guided) == ("standard", "px4", True)
