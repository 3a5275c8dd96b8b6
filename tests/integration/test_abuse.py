"""Abuse of a real `usv-station serve` on 127.0.0.1: it refuses before it works and stays up.

Timings (how fast a refusal comes, health latency under abuse) are figures of
`usv-station bench server`; these tests check the answers.
"""

from __future__ import annotations

import json
import re
import socket
import time
from urllib.parse import urlsplit

import httpx
import pytest
from stationproc import TOKEN, StationProcess
from websockets.exceptions import InvalidStatus
from websockets.sync.client import connect

VIEWER = "viewer-token-abcdefghijklmnop"
MB = 1 << 20


@pytest.fixture(scope="module")
def station(tmp_path_factory):
    st = StationProcess(tmp_path_factory.mktemp("data"), "--viewer-token", VIEWER,
                        "--sim-speed", "5", "--max-ws-clients", "3",
                        env={"USV_STATION_HEADER_TIMEOUT_S": "2"})
    yield st
    st.stop()


def raw(url: str, request: bytes, body_bytes: int = 0) -> tuple[int, dict[str, str], bytes]:
    """Send `request` (and `body_bytes` zero bytes, as far as the server reads them) on a
    fresh connection; the status, headers and body of the answer."""
    parts = urlsplit(url)
    with socket.create_connection((parts.hostname, parts.port), timeout=30) as s:
        s.sendall(request)
        sent = 0
        s.setblocking(False)
        data = b""
        while sent < body_bytes:
            try:
                sent += s.send(b"\0" * min(64 * 1024, body_bytes - sent))
            except BlockingIOError:
                pass  # the server stopped reading: look for its answer
            except (BrokenPipeError, ConnectionResetError):
                break
            try:
                chunk = s.recv(65536)
                data += chunk
                if not chunk or b"\r\n\r\n" in data:
                    break
            except BlockingIOError:
                continue
        s.setblocking(True)
        while b"\r\n\r\n" not in data:
            chunk = s.recv(65536)
            if not chunk:
                break
            data += chunk
        head, _, body = data.partition(b"\r\n\r\n")
        lines = head.decode("latin-1").split("\r\n")
        headers = {k.lower(): v.strip() for k, _, v in (x.partition(":") for x in lines[1:])}
        length = int(headers.get("content-length", "0"))
        while len(body) < length:
            chunk = s.recv(65536)
            if not chunk:
                break
            body += chunk
        return int(lines[0].split()[1]), headers, body


def host_of(url: str) -> str:
    return urlsplit(url).netloc


def test_a_50_mb_body_without_a_token_is_refused_before_it_is_read(station):
    host = host_of(station.url)
    head = (f"PUT /api/scenario HTTP/1.1\r\nHost: {host}\r\nContent-Type: application/json\r\n"
            f"Content-Length: {50 * MB}\r\n\r\n").encode()
    status, _, body = raw(station.url, head, 50 * MB)
    assert status == 401 and "bearer token" in json.loads(body)["detail"]
    # with the token the declared size alone is refused
    head = head.replace(b"\r\n\r\n", f"\r\nAuthorization: Bearer {TOKEN}\r\n\r\n".encode(), 1)
    status, _, body = raw(station.url, head, 50 * MB)
    assert status == 413 and "over the limit of 1048576 bytes" in json.loads(body)["detail"]
    assert station.client.get("/api/health").json()["status"] == "ok"


def test_a_chunked_body_over_the_limit_is_cut_off_while_it_streams(station):
    def chunks():
        for _ in range(3):
            yield b" " * MB

    r = station.client.put("/api/scenario", content=chunks(),
                           headers={"Content-Type": "application/json"})
    assert r.status_code == 413


def test_roles(station):
    anonymous = {"Authorization": ""}
    viewer = {"Authorization": f"Bearer {VIEWER}"}
    c = station.client
    assert c.get("/api/telemetry", headers=anonymous).status_code == 401
    assert c.get("/api/telemetry", params={"limit": 5}, headers=viewer).status_code == 200
    assert c.get("/api/plans", headers=viewer).status_code == 200
    r = c.post("/api/boat/command", json={"command": "hold"}, headers=viewer)
    assert r.status_code == 403 and "read only" in r.json()["detail"]
    assert c.post("/api/plans", json={}, headers=viewer).status_code == 403
    assert c.delete("/api/plans/nope", headers=viewer).status_code == 403
    health = c.get("/api/health", headers=anonymous)
    assert health.status_code == 200 and "boat" not in health.json()
    assert c.get("/3d/", headers=anonymous).status_code == 401


def test_websocket_needs_a_token_and_the_stations_origin(station):
    ws_url = station.url.replace("http", "ws") + "/ws/live"
    with pytest.raises(InvalidStatus) as refused:
        connect(ws_url, open_timeout=30)
    assert refused.value.response.status_code == 403
    with pytest.raises(InvalidStatus) as refused:
        connect(ws_url, origin="http://evil.example", open_timeout=30,
                additional_headers={"Authorization": f"Bearer {TOKEN}"})
    assert refused.value.response.status_code == 403
    for token in (TOKEN, VIEWER):
        with connect(ws_url, origin=station.url, open_timeout=30,
                     additional_headers={"Authorization": f"Bearer {token}"}) as ws:
            assert json.loads(ws.recv(timeout=30))["type"] == "hello"
            if token == VIEWER:  # outlives the 2 s header timeout of this station
                time.sleep(3)
                for _ in range(3):
                    assert json.loads(ws.recv(timeout=30))["type"]


def test_a_foreign_host_header_is_refused(station):
    r = station.client.get("/api/telemetry", headers={"Host": "evil.example"})
    assert r.status_code == 400 and "evil.example" in r.json()["detail"]
    r = station.client.get("/api/health", headers={"Host": "evil.example:80"})
    assert r.status_code == 400
    assert station.client.get("/api/health", headers={"Host": "localhost"}).status_code == 200


@pytest.mark.parametrize("number", ["NaN", "Infinity", "-Infinity", "1e999"])
def test_non_finite_numbers_get_422_naming_the_field(station, number):
    body = ('{"name": "x", "start": {"x": 50, "y": ' + number + '}}').encode()
    r = station.client.put("/api/scenario", content=body,
                           headers={"Content-Type": "application/json"})
    assert r.status_code == 422
    detail = r.json()["detail"][0]
    assert detail["loc"] == ["body", "start", "y"] and "finite" in detail["msg"]


def test_console_url_token_becomes_a_cookie_and_leaves_no_trace_in_the_log(station):
    with httpx.Client(base_url=station.url, timeout=30) as browser:
        r = browser.get(f"/?token={TOKEN}&tab=map")
        assert r.status_code == 303 and r.headers["location"] == "/?tab=map"
        cookie = r.headers["set-cookie"]
        assert cookie.startswith(f"usv_token={TOKEN};")
        assert "HttpOnly" in cookie and "SameSite=Strict" in cookie
        assert browser.get("/api/telemetry", params={"limit": 1}).status_code == 200
        assert browser.get("/?token=wrong").status_code == 401
    requests = [line for line in station.log.read_text().splitlines() if '"GET /?' in line]
    assert requests and all(TOKEN not in line and "token=***" in line for line in requests)


def test_half_open_connections_leave_the_station_answering(station):
    parts = urlsplit(station.url)
    idle = []
    try:
        for i in range(300):
            s = socket.create_connection((parts.hostname, parts.port), timeout=30)
            if i % 2:
                s.sendall(b"GET /api/health HTTP/1.1\r\nHost: x")  # headers never finished
            idle.append(s)
        for _ in range(5):
            assert station.client.get("/api/health").json()["status"] == "ok"
        # the station closes a connection whose headers never complete (2 s here)
        idle[1].settimeout(30)
        assert idle[1].recv(1024) == b""
    finally:
        for s in idle:
            s.close()


def test_a_kept_alive_connection_slow_on_its_second_request_is_closed(station):
    """The header timeout (2 s here) covers every request of a connection, not the first."""
    parts = urlsplit(station.url)
    with socket.create_connection((parts.hostname, parts.port), timeout=30) as s:
        s.sendall(f"GET /api/health HTTP/1.1\r\nHost: {parts.netloc}\r\n\r\n".encode())
        first = b""
        while b"\r\n\r\n" not in first:
            first += s.recv(65536)
        head, _, body = first.partition(b"\r\n\r\n")
        assert head.startswith(b"HTTP/1.1 200")
        length = int(re.search(rb"(?i)content-length: *(\d+)", head).group(1))
        while len(body) < length:
            body += s.recv(65536)
        s.sendall(b"GET /api/health HTTP/1.1\r\nHost: x")  # the second never finishes
        data = b""
        while True:
            piece = s.recv(65536)
            if not piece:
                break
            data += piece
        assert data == b""  # closed without an answer


def test_api_docs_are_served_from_the_station_itself(station):
    c = station.client
    for page in ("/docs", "/redoc"):
        r = c.get(page)
        assert r.status_code == 200
        assert r.headers["content-security-policy"].startswith("default-src 'self'")
        links = re.findall(r'(?:src|href|spec-url|url:\s*)=?\s*["\']([^"\']+)["\']', r.text)
        assert links and all(link.startswith("/") for link in links), links
        for link in links:
            if link.startswith("/vendor/"):
                assert c.get(link).status_code == 200, link
        assert "http://" not in r.text and "https://" not in r.text
    spec = c.get("/openapi.json").json()
    health = spec["paths"]["/api/health"]["get"]["responses"]["200"]["content"]
    assert health["application/json"]["schema"]["$ref"].endswith("/StationHealth")
    # every JSON answer is declared (the station's records), so the document is true
    undeclared = [path for path, ops in spec["paths"].items() for verb, op in ops.items()
                  if path.startswith("/api/") and not path.endswith(("/export", "{y}"))
                  and op["responses"].get("200", op["responses"].get("202", {}))
                  .get("content", {}).get("application/json", {}).get("schema") in (None, {})]
    assert undeclared == [], undeclared
    assert "delete" in spec["paths"]["/api/plans/{plan_id}"]


def test_3d_view_is_proxied_behind_the_token_and_viser_listens_on_loopback(station):
    assert urlsplit(station.viser_url).hostname == "127.0.0.1"
    c = station.client
    page = c.get("/3d/")
    assert page.status_code == 200 and "text/html" in page.headers["content-type"]
    assert c.get("/3d/", headers={"Authorization": ""}).status_code == 401
    ws_url = station.url.replace("http", "ws") + "/3d/"
    from viser import __version__ as viser_version

    with connect(ws_url, origin=station.url, open_timeout=30,
                 subprotocols=[f"viser-v{viser_version}"],
                 additional_headers={"Authorization": f"Bearer {VIEWER}"}) as ws:
        assert ws.subprotocol == f"viser-v{viser_version}"
        assert ws.recv(timeout=30)  # viser's first scene message
    with connect(ws_url[:-1], origin=station.url, open_timeout=30,  # the client drops the /
                 subprotocols=[f"viser-v{viser_version}"],
                 additional_headers={"Authorization": f"Bearer {VIEWER}"}) as ws:
        assert ws.recv(timeout=30)
    with pytest.raises(InvalidStatus):
        connect(ws_url, open_timeout=30)


def test_live_clients_beyond_the_limit_get_503(station):
    ws_url = station.url.replace("http", "ws") + "/ws/live"
    auth = {"Authorization": f"Bearer {VIEWER}"}
    clients = [connect(ws_url, open_timeout=30, additional_headers=auth) for _ in range(3)]
    try:
        for ws in clients:
            assert json.loads(ws.recv(timeout=30))["type"] == "hello"
        with pytest.raises(InvalidStatus) as refused:
            connect(ws_url, open_timeout=30, additional_headers=auth)
        assert refused.value.response.status_code == 503
    finally:
        for ws in clients:
            ws.close()


BAD_BODIES = {
    "nested": b"[" * 5000 + b"]" * 5000,
    "nested_object": b'{"a":' * 40 + b"1" + b"}" * 40,
    "surrogate": b'{"name": "\\ud800", "plan_id": "\\udfff", "command": "\\ud83d"}',
    "nan": b'{"name": "x", "start": {"x": NaN}, "plan_id": 1e999}',
    "not_utf8": b'{"name": "\xff\xfe"}',
}


def _concrete(template: str) -> str:
    return re.sub(r"\{[^}]+\}", "x", template)


def test_no_bad_body_causes_a_5xx_on_any_route_with_or_without_a_token(station):
    spec = station.client.get("/openapi.json").json()
    paths = sorted({_concrete(p) for p in spec["paths"]} | {
        "/", "/nope", "/docs", "/redoc", "/3d/", "/api", "/ws/live", "/assets/x.js"})
    body_routes = {(verb.upper(), _concrete(p)) for p, ops in spec["paths"].items()
                   for verb, op in ops.items() if "requestBody" in op}
    assert ("PUT", "/api/scenario") in body_routes and ("POST", "/api/plans") in body_routes
    tokens = {"none": "", "viewer": f"Bearer {VIEWER}", "operator": f"Bearer {TOKEN}"}
    fives = []
    with httpx.Client(base_url=station.url, timeout=30) as c:
        for path in paths:
            for method in ("GET", "POST", "PUT", "DELETE"):
                for who, auth in tokens.items():
                    for name, body in BAD_BODIES.items():
                        r = c.request(method, path, content=body, headers={
                            "Authorization": auth, "Content-Type": "application/json"})
                        if r.status_code >= 500:
                            fives.append((method, path, who, name, r.status_code))
                        elif who == "operator" and (method, path) in body_routes:
                            assert r.status_code in (400, 422), (method, path, name, r.text)
                        elif len(body) > 16 and (((method, path) not in body_routes
                                                  and who != "none")
                                                 or path in ("/", "/nope", "/docs",
                                                             "/api/health")):
                            assert r.status_code in (401, 403, 413), (method, path, who,
                                                                      r.status_code)
    assert fives == []
    assert station.client.get("/api/health").json()["status"] == "ok"


def test_open_paths_refuse_a_body_at_once_without_reading_it(station):
    host = host_of(station.url)
    for path in ("/nope", "/", "/docs", "/api/health"):
        head = (f"POST {path} HTTP/1.1\r\nHost: {host}\r\nContent-Type: application/json\r\n"
                f"Content-Length: {MB}\r\n\r\n").encode()
        status, _, body = raw(station.url, head, MB)
        assert status == 413 and "takes no request body" in json.loads(body)["detail"]


def test_a_body_less_change_from_another_origin_is_refused(station):
    c = station.client
    other = {"Origin": "http://127.0.0.1:1"}
    r = c.post("/api/alerts/nope/ack", headers=other)
    assert r.status_code == 403 and "another origin" in r.json()["detail"]
    r = c.post("/api/alerts/nope/ack", headers={"Referer": "http://127.0.0.1:1/evil.html"})
    assert r.status_code == 403
    assert c.post("/api/alerts/nope/ack", headers={"Origin": station.url}).status_code == 404
    assert c.get("/api/alerts", headers=other).status_code == 200  # reading is not a change


def _viser_messages(frame: bytes) -> list[dict]:
    """viser's server-to-client frame: sizes, zstd msgpack, then binary buffers."""
    import msgspec
    import zstandard

    size, compressed = int.from_bytes(frame[:8], "little"), int.from_bytes(frame[8:16], "little")
    inner = zstandard.ZstdDecompressor().decompress(frame[16:16 + compressed],
                                                    max_output_size=size)
    return msgspec.msgpack.decode(inner)["messages"]


def test_viser_answers_nothing_without_the_proxys_secret(station):
    parts = urlsplit(station.viser_url)
    for headers in ({}, {"Host": "evil.example", "Origin": "http://evil.example"},
                    {"X-USV-Proxy-Secret": "guess"}):
        r = httpx.get(station.viser_url + "/", headers=headers, timeout=30)
        assert (r.status_code, r.content) == (403, b"")
    from viser import __version__ as viser_version

    with pytest.raises(InvalidStatus) as refused:
        connect(f"ws://{parts.netloc}/", open_timeout=30,
                subprotocols=[f"viser-v{viser_version}"])
    assert refused.value.response.status_code == 403


def test_a_viewers_3d_gui_change_is_not_seen_by_the_operator(station):
    import msgspec
    from viser import __version__ as viser_version

    ws_url = station.url.replace("http", "ws") + "/3d/"

    def open_as(token):
        return connect(ws_url, origin=station.url, open_timeout=30, max_size=None,
                       subprotocols=[f"viser-v{viser_version}"],
                       additional_headers={"Authorization": f"Bearer {token}"})

    def gui_state(ws) -> dict[str, dict]:
        """label -> {uuid, value} of each checkbox, from the scene replayed on connecting
        (the elements as created, then every update, up to viser's ReplayDoneMessage)."""
        found: dict[str, dict] = {}
        label_of: dict[str, str] = {}
        done = False
        while not done:
            for m in _viser_messages(ws.recv(timeout=30)):
                kind = m.get("type", "")
                if kind == "GuiCheckboxMessage":
                    label = m["props"]["label"]
                    found[label] = {"uuid": m["uuid"], "value": m["value"]}
                    label_of[m["uuid"]] = label
                elif kind == "GuiUpdateMessage" and m.get("uuid") in label_of \
                        and "value" in m.get("updates", {}):
                    found[label_of[m["uuid"]]]["value"] = m["updates"]["value"]
                done = done or kind == "ReplayDoneMessage"
        return found

    with open_as(VIEWER) as viewer, open_as(TOKEN) as operator:
        follow = gui_state(viewer)["Follow the live run"]
        assert follow["value"] is True
        plane = gui_state(operator)["Time plane"]
        change = {"type": "GuiUpdateMessage", "uuid": follow["uuid"],
                  "updates": {"value": False}}
        viewer.send(msgspec.msgpack.encode(change))  # dropped by the proxy
        operator.send(msgspec.msgpack.encode({"type": "GuiUpdateMessage", "uuid":
                                              plane["uuid"], "updates": {"value": False}}))
        # the operator's change reaches the viewer (the control: changes do travel) ...
        while not any(m.get("type") == "GuiUpdateMessage" and m.get("uuid") == plane["uuid"]
                      for m in _viser_messages(viewer.recv(timeout=30))):
            pass
    # ... the viewer's never reached the shared scene: a new client replays it unchanged
    with open_as(TOKEN) as fresh:
        state = gui_state(fresh)
    assert state["Follow the live run"]["value"] is True
    assert state["Time plane"]["value"] is False
    with open_as(TOKEN) as operator:  # leave the scene as it was for the other tests
        plane = gui_state(operator)["Time plane"]
        operator.send(msgspec.msgpack.encode({"type": "GuiUpdateMessage", "uuid":
                                              plane["uuid"], "updates": {"value": True}}))


def test_3d_websockets_count_against_the_client_limit_and_a_drop_is_one_line(station):
    from viser import __version__ as viser_version

    auth = {"Authorization": f"Bearer {VIEWER}"}
    proto = [f"viser-v{viser_version}"]
    view = [connect(station.url.replace("http", "ws") + "/3d/", open_timeout=30,
                    additional_headers=auth, subprotocols=proto) for _ in range(3)]
    try:
        for ws in view:
            assert ws.recv(timeout=30)
        with pytest.raises(InvalidStatus) as refused:
            connect(station.url.replace("http", "ws") + "/ws/live", open_timeout=30,
                    additional_headers=auth)
        assert refused.value.response.status_code == 503
        with pytest.raises(InvalidStatus) as refused:
            connect(station.url.replace("http", "ws") + "/3d/", open_timeout=30,
                    additional_headers=auth, subprotocols=proto)
        assert refused.value.response.status_code == 503
        peer = view[0].socket.getsockname()
        view[0].socket.shutdown(socket.SHUT_RDWR)  # the browser's tab killed
        view[0].socket.close()

        def lines() -> list[str]:
            return [x for x in station.log.read_text().splitlines()
                    if f"3D view client {peer[0]}:{peer[1]} gone" in x]

        deadline = time.monotonic() + 30
        while not lines():
            assert time.monotonic() < deadline, "no line for the dropped client"
            time.sleep(0.05)
    finally:
        for ws in view[1:]:
            ws.close()
    assert len(lines()) == 1 and "Traceback" not in station.log.read_text()


def test_a_locked_database_is_503_not_500(station):
    import sqlite3

    scenario = station.client.get("/api/scenario").json()
    lock = sqlite3.connect(station.data_dir / "station.sqlite3", timeout=30,
                           isolation_level=None)
    try:
        lock.execute("BEGIN EXCLUSIVE")  # another process holds the write lock
        r = station.client.put("/api/scenario", json=scenario)
        assert r.status_code == 503 and "database" in r.json()["detail"], r.text
        assert r.headers["retry-after"] == "5"
    finally:
        lock.execute("ROLLBACK")
        lock.close()
    assert station.client.put("/api/scenario", json=scenario).status_code == 200
