"""The front door in simulated time: what the guard reads (nothing, for a route that takes no
body), what it refuses (deep, non-finite, non-Unicode JSON; changes from another origin; slow
bodies), and the HTTP protocol's header timeout and per-client connection cap on a fake
transport. No sockets, no waits: a VirtualTimeLoop jumps to each timer."""

from __future__ import annotations

import asyncio
import json
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from usvstation.api.auth import Tokens
from usvstation.api.guard import MAX_JSON_DEPTH, Guard, GuardConfig, check_json_body, first_problem
from usvstation.clock import run_simulated

OPERATOR = "operator-token-0123456789"
HOST = "127.0.0.1:8000"
BODY_ROUTES = {("PUT", "/api/scenario"), ("POST", "/api/plans"), ("POST", "/api/missions")}


class App:
    """The app behind the guard: records what reached it and the body it read."""

    def __init__(self) -> None:
        self.calls: list[tuple[str, bytes]] = []

    async def __call__(self, scope: dict, receive: Any, send: Any) -> None:
        body = b""
        if scope["type"] == "http":
            while True:
                message = await receive()
                body += message.get("body", b"")
                if not message.get("more_body"):
                    break
        self.calls.append((scope["path"], body))
        await send({"type": "http.response.start", "status": 200, "headers": []})
        await send({"type": "http.response.body", "body": b"ok"})


def guard(app: App, **kw: Any) -> Guard:
    cfg = GuardConfig(tokens=Tokens(OPERATOR), takes_body=lambda m, p: (m, p) in BODY_ROUTES,
                      **kw)
    return Guard(app, cfg)


async def request(g: Guard, method: str, path: str, body: bytes | None = None,
                  headers: dict[str, str] | None = None, chunks: list[bytes] | None = None,
                  stall: bool = False) -> tuple[int, Any, int]:
    """(status, parsed body, body messages the guard read) of one request."""
    hdrs = {"host": HOST, "authorization": f"Bearer {OPERATOR}", **(headers or {})}
    if body is not None:
        hdrs["content-length"] = str(len(body))
        chunks = [body]
    elif chunks is not None:
        hdrs["transfer-encoding"] = "chunked"
    scope = {"type": "http", "method": method, "path": path, "query_string": b"",
             "headers": [(k.encode(), v.encode()) for k, v in hdrs.items()]}
    pieces = list(chunks or [])
    read = 0

    async def receive() -> dict:
        nonlocal read
        read += 1
        if stall:
            await asyncio.Event().wait()  # a body that never comes
        if pieces:
            piece = pieces.pop(0)
            return {"type": "http.request", "body": piece, "more_body": bool(pieces)}
        return {"type": "http.request", "body": b"", "more_body": False}

    out: list[dict] = []

    async def send(message: dict) -> None:
        out.append(message)

    await g(scope, receive, send)
    status = out[0]["status"]
    payload = b"".join(m.get("body", b"") for m in out[1:])
    try:
        parsed = json.loads(payload) if payload else None
    except ValueError:
        parsed = payload
    return status, parsed, read


def sim(coro_fn) -> Any:
    return run_simulated(lambda clock: coro_fn())


@pytest.mark.parametrize(("method", "path"), [("POST", "/nope"), ("POST", "/"),
                                              ("GET", "/docs"), ("POST", "/api/health"),
                                              ("POST", "/api/alerts/x/ack"),
                                              ("DELETE", "/api/plans/x")])
def test_a_body_for_a_route_that_takes_none_is_refused_unread(method, path):
    app = App()

    async def main():
        big = json.dumps([[0.5] * 1000] * 100).encode()  # a 400 kB JSON flood
        status, detail, read = await request(guard(app), method, path, big)
        assert (status, read) == (413, 0), detail
        assert detail["detail"] == f"{method} {path} takes no request body"
        # chunked, no length given: also refused before a byte
        status, _, read = await request(guard(app), method, path, chunks=[big[:10], big[10:]])
        assert (status, read) == (413, 0)
        # without a body it passes, and with the `{}` a client sends with every POST
        assert (await request(guard(app), method, path))[0] == 200
        assert (await request(guard(app), method, path, b"{}"))[0] == 200
        assert (await request(guard(app), method, path, b"[" * 17))[0] == 413

    sim(main)
    assert all(body in (b"", b"{}") for _, body in app.calls)


def test_open_paths_take_no_body_without_a_token_either():
    app = App()

    async def main():
        status, _, read = await request(guard(app), "POST", "/nope", b"{}" * 1000,
                                        headers={"authorization": ""})
        assert (status, read) == (413, 0)
        status, _, read = await request(guard(app), "PUT", "/api/scenario", b"{}",
                                        headers={"authorization": ""})
        assert (status, read) == (401, 0)

    sim(main)
    assert app.calls == []


@pytest.mark.parametrize(("body", "status", "where"), [
    (b"[" * 5000 + b"]" * 5000, 400, "nested deeper"),
    (b'{"a":' * (MAX_JSON_DEPTH + 1) + b"1" + b"}" * (MAX_JSON_DEPTH + 1), 400, "nested deeper"),
    (b'{"name": "\\ud800"}', 422, ["body", "name"]),
    (b'{"\\udfff": 1}', 422, ["body", "\udfff"]),
    (b'{"start": {"x": NaN}}', 422, ["body", "start", "x"]),
    (b'{"start": [1, 1e999]}', 422, ["body", "start", 1]),
    (b'{"name": "\xff"}', 400, "not UTF-8"),
])
def test_bad_json_is_refused_with_400_or_422_before_the_route(body, status, where):
    app = App()

    async def main():
        got, detail, _ = await request(guard(app), "PUT", "/api/scenario", body,
                                       headers={"content-type": "application/json"})
        assert got == status, detail
        if isinstance(where, str):
            assert where in detail["detail"]
        else:
            assert detail["detail"][0]["loc"] == where
        # no content type: FastAPI parses it as JSON, so the guard does too
        assert (await request(guard(app), "PUT", "/api/scenario", body))[0] == status

    sim(main)
    assert app.calls == []


def test_good_json_reaches_the_route_whole():
    app = App()
    doc = {"name": "x", "nested": [[[{"a": "é \U0001F6A4"}]]], "n": 1.5}
    body = json.dumps(doc, ensure_ascii=False).encode()

    async def main():
        assert (await request(guard(app), "PUT", "/api/scenario", body))[0] == 200
        # a text body is the route's own business (it refuses it: 422)
        text = b"[" * 5000
        assert (await request(guard(app), "PUT", "/api/scenario", text,
                              headers={"content-type": "text/plain"}))[0] == 200

    sim(main)
    assert app.calls[0] == ("/api/scenario", body)


def test_a_body_over_the_limit_and_a_stalled_body():
    app = App()

    async def main():
        g = guard(app, max_body_bytes=1024, body_timeout_s=30.0)
        status, detail, _ = await request(g, "POST", "/api/plans", chunks=[b" " * 800] * 3)
        assert status == 413 and "over the limit of 1024" in detail["detail"]
        status, detail, _ = await request(g, "POST", "/api/plans", b"{}", stall=True)
        assert status == 408 and "30 s" in detail["detail"]  # 30 simulated seconds

    sim(main)
    assert app.calls == []


@pytest.mark.parametrize(("headers", "status"), [
    ({"origin": "http://127.0.0.1:9999"}, 403),  # another port: same site, other origin
    ({"origin": "null"}, 403),
    ({"referer": "http://127.0.0.1:9999/page"}, 403),
    ({"referer": "about:blank"}, 403),
    ({"origin": "http://127.0.0.1:8000"}, 200),
    ({"referer": "http://127.0.0.1:8000/?tab=map"}, 200),
    ({"origin": "https://console.example"}, 200),  # --cors-origins
    ({}, 200),  # no browser: curl, the tests, scripts
])
def test_body_less_changes_check_their_origin(headers, status):
    app = App()

    async def main():
        g = guard(app, cors_origins=frozenset({"https://console.example"}))
        got, detail, _ = await request(g, "POST", "/api/alerts/abc/ack", headers=headers)
        assert got == status, detail
        # reading is never refused for its origin
        assert (await request(g, "GET", "/api/alerts", headers=headers))[0] == 200

    sim(main)


json_values = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False, allow_infinity=False)
    | st.text(max_size=5),
    lambda children: st.lists(children, max_size=3) | st.dictionaries(st.text(max_size=3),
                                                                      children, max_size=3),
    max_leaves=15)


@given(json_values)
def test_any_clean_document_passes_and_round_trips(value):
    assert first_problem(value) is None
    assert check_json_body(json.dumps(value).encode()) is None


@given(st.integers(1, 200))
def test_nesting_is_refused_exactly_beyond_the_limit(depth):
    doc: Any = 0
    for _ in range(depth):
        doc = [doc]
    refused = check_json_body(json.dumps(doc).encode())
    assert (refused is not None) == (depth > MAX_JSON_DEPTH)
    if refused is not None:
        assert refused.status == 400


# --- the HTTP protocol: header timeout and connections per client -------------------------

class FakeTransport(asyncio.Transport):
    def __init__(self, peer: str) -> None:
        super().__init__()
        self.peer, self.closed, self.aborted = peer, False, False
        self.protocol: Any = None
        self.written = b""

    def get_extra_info(self, name: str, default: Any = None) -> Any:
        return {"peername": (self.peer, 5000), "sockname": ("127.0.0.1", 8000)}.get(
            name, default)

    def get_protocol(self) -> Any:
        return self.protocol

    def set_protocol(self, protocol: Any) -> None:
        self.protocol = protocol

    def is_closing(self) -> bool:
        return self.closed or self.aborted

    def close(self) -> None:
        if not self.is_closing():
            self.closed = True
            asyncio.get_running_loop().call_soon(self.protocol.connection_lost, None)

    def abort(self) -> None:
        if not self.is_closing():
            self.aborted = True
            asyncio.get_running_loop().call_soon(self.protocol.connection_lost, None)

    def write(self, data: bytes) -> None:
        self.written += data

    def pause_reading(self) -> None: ...

    def resume_reading(self) -> None: ...


def protocols(n: int, peer: str, state: Any, timeout_s: float = 10.0, cap: int = 4):
    import uvicorn
    from uvicorn.server import ServerState

    from usvstation.server import HeaderTimeoutProtocol

    async def app(scope, receive, send):  # only a websocket gets this far: closed at once
        assert scope["type"] == "websocket"
        await receive()
        await send({"type": "websocket.close", "code": 1000})

    config = uvicorn.Config(app, log_level="warning", lifespan="off")
    config.load()
    HeaderTimeoutProtocol.header_timeout_s = timeout_s
    HeaderTimeoutProtocol.max_per_client = cap
    state = state or ServerState()
    out = []
    for _ in range(n):
        p = HeaderTimeoutProtocol(config, state, {}, asyncio.get_running_loop())
        t = FakeTransport(peer)
        t.protocol = p
        p.connection_made(t)
        out.append((p, t))
    return state, out


def test_half_open_connections_close_after_the_header_timeout_and_beyond_the_cap():
    async def main(clock):
        state, conns = protocols(6, "10.0.0.9", None)
        # beyond 4 from one address: closed at once, nothing read or answered
        assert [t.aborted for _, t in conns] == [False] * 4 + [True] * 2
        assert all(t.written == b"" for _, t in conns)
        _, others = protocols(2, "10.0.0.7", state)  # another client still gets in
        assert not any(t.aborted for _, t in others)
        conns[0][0].data_received(b"GET /api/health HTTP/1.1\r\nHost: x")  # never finishes
        await clock.sleep(9.9)
        assert not any(t.closed for _, t in conns[:4])
        await clock.sleep(0.2)
        assert all(t.closed for _, t in conns[:4]) and all(t.closed for _, t in others)
        await clock.sleep(0.1)
        assert len(state.connections) == 0 and not state.usv_open_per_client
        _, again = protocols(4, "10.0.0.9", state)  # the slots are free again
        assert not any(t.aborted for _, t in again)

    run_simulated(main)


def test_a_connection_upgraded_to_a_websocket_frees_its_slot():
    async def main(clock):
        state, conns = protocols(3, "10.0.0.5", None, cap=2)
        assert [t.aborted for _, t in conns] == [False, False, True]
        upgrade = (b"GET /ws/live HTTP/1.1\r\nHost: x\r\nUpgrade: websocket\r\n"
                   b"Connection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"
                   b"Sec-WebSocket-Version: 13\r\n\r\n")
        for p, _ in conns[:2]:
            p.data_received(upgrade)
        await clock.sleep(0.1)
        assert not state.usv_open_per_client  # the websockets are --max-ws-clients' business
        _, more = protocols(2, "10.0.0.5", state, cap=2)
        assert not any(t.aborted for _, t in more)

    run_simulated(main)
