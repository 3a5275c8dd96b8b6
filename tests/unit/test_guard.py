"""The front door's pure decisions: roles by path, Host names, non-finite numbers, log redaction."""

import logging

import pytest
from hypothesis import given
from hypothesis import strategies as st

from usvstation.api.auth import Role, Tokens, token_from_headers
from usvstation.api.guard import (
    GuardConfig,
    RedactTokens,
    first_non_finite,
    host_allowed,
    needed_role,
    origin_allowed,
)

CFG = GuardConfig(tokens=Tokens("operator-token-0123456789", "viewer-token-0123456789"),
                  bound_host="station.local", allowed_hosts=frozenset({"boat.example"}))


def test_roles_by_path_and_method():
    assert needed_role("/api/health", "GET") is None
    assert needed_role("/", "GET") is None and needed_role("/assets/main.js", "GET") is None
    assert needed_role("/api/telemetry", "GET") is Role.VIEWER
    assert needed_role("/api/plans/x", "DELETE") is Role.OPERATOR
    assert needed_role("/api/scenario", "PUT") is Role.OPERATOR
    assert needed_role("/ws/live", "GET") is Role.VIEWER
    assert needed_role("/3d/", "GET") is Role.VIEWER


def test_tokens_and_where_they_come_from():
    t = CFG.tokens
    assert t.role("operator-token-0123456789") is Role.OPERATOR
    assert t.role("viewer-token-0123456789") is Role.VIEWER
    assert t.role("nope") is None and t.role(None) is None
    assert Tokens("").role(None) is Role.OPERATOR  # authentication off (loopback only)
    assert token_from_headers({"authorization": "Bearer abc"}) == "abc"
    assert token_from_headers({"cookie": "a=1; usv_token=xyz; b=2"}) == "xyz"
    assert token_from_headers({"authorization": "Basic abc"}) is None


@pytest.mark.parametrize(("host", "ok"), [
    ("127.0.0.1:8000", True), ("[::1]:8000", True), ("10.0.0.7", True), ("localhost:8000", True),
    ("station.local:8000", True), ("boat.example", True), ("evil.example", False),
    ("evil.example:8000", False), ("127.0.0.1.evil.example", False), (None, True),
])
def test_host_names(host, ok):
    assert host_allowed(host, CFG) is ok


def test_origins():
    assert origin_allowed(None, "127.0.0.1:8000", CFG)
    assert origin_allowed("http://127.0.0.1:8000", "127.0.0.1:8000", CFG)
    assert not origin_allowed("http://evil.example", "127.0.0.1:8000", CFG)
    assert not origin_allowed("http://127.0.0.1:9999", "127.0.0.1:8000", CFG)


json_values = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False, allow_infinity=False)
    | st.text(max_size=5),
    lambda children: st.lists(children, max_size=4) | st.dictionaries(st.text(max_size=4),
                                                                      children, max_size=4),
    max_leaves=20)


@given(json_values)
def test_finite_documents_pass(value):
    assert first_non_finite(value) is None


def test_non_finite_numbers_are_found_with_their_path():
    doc = {"a": [1, 2, {"b": float("inf")}], "c": 1.0}
    assert first_non_finite(doc) == ("a", 2, "b")
    assert first_non_finite([0.0, float("nan")]) == (1,)
    assert first_non_finite(float("-inf")) == ()


def test_tokens_are_redacted_from_log_records():
    record = logging.LogRecord("uvicorn.access", logging.INFO, "", 0, '%s - "%s %s"',
                               ("127.0.0.1", "GET", "/?token=secret&tab=map"), None)
    RedactTokens().filter(record)
    assert "secret" not in record.getMessage() and "token=***&tab=map" in record.getMessage()
