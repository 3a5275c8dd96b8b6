"""The boat link inside `usv-station serve`, in real time: it opens an external boat's port
before the web app exists, and it keeps its heartbeat on its own loop while the web API is
flooded (a smoke test with generous limits; the figures are `usv-station bench server`'s)."""

from __future__ import annotations

import os
import select
import subprocess
import sys
import threading
import time

import httpx
from stationproc import TOKEN, StationProcess

from usvstation.link import wire
from usvstation.link.transport import PtyPair

EXE = os.path.join(os.path.dirname(sys.executable), "usv-station")
MB = 1 << 20


def test_serve_opens_an_external_boats_link_before_the_web_app(tmp_path):
    key_path = tmp_path / "boat.key"
    wire.write_key(key_path)
    boat = wire.Codec(1, wire.BOAT_COMPONENT, wire.read_key(key_path))
    pair = PtyPair()
    log = tmp_path / "serve.log"
    with log.open("w") as out:
        proc = subprocess.Popen(
            [EXE, "serve", "--port", "0", "--viser-port", "0", "--data-dir",
             str(tmp_path / "data"), "--token", TOKEN, "--link", pair.slave_path,
             "--link-key", str(key_path)], stdout=out, stderr=subprocess.STDOUT,
            start_new_session=True)
    try:
        heartbeat = None
        deadline = time.monotonic() + 120
        while heartbeat is None:
            assert time.monotonic() < deadline, log.read_text()[-2000:]
            ready, _, _ = select.select([pair.master_fd], [], [], 0.5)
            if ready:
                msgs, _ = boat.feed(os.read(pair.master_fd, 4096))
                heartbeat = next((m for m in msgs if m.get_type() == "HEARTBEAT"
                                  and m.get_srcSystem() == 255), None)
        while "console http" not in log.read_text():  # the web app comes after
            assert proc.poll() is None and time.monotonic() < deadline, log.read_text()
            time.sleep(0.05)
        text = log.read_text()
        assert heartbeat._signed
        opened = text.index(f"boat link open on {pair.slave_path}")
        assert opened < text.index("Application startup complete") < text.index("console")
    finally:
        proc.terminate()
        try:
            proc.wait(20)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
        pair.close()


def test_the_heartbeat_keeps_its_schedule_while_the_web_api_is_flooded(tmp_path):
    st = StationProcess(tmp_path / "data", "--sim-speed", "5")
    try:
        st.wait_link_up()
        health = st.client.get("/api/health").json()
        assert health["link_on_own_loop"] is True
        stop = threading.Event()
        answers: list[int] = []
        flood = json_flood()

        def client() -> None:
            with httpx.Client(base_url=st.url, timeout=60) as c:
                while not stop.is_set():
                    answers.append(c.post("/nope", content=flood, headers={
                        "Content-Type": "application/json"}).status_code)
                    answers.append(c.get("/api/telemetry", params={"limit": 100_000},
                                         headers={"Authorization": f"Bearer {TOKEN}"})
                                   .status_code)

        threads = [threading.Thread(target=client, daemon=True) for _ in range(8)]
        for t in threads:
            t.start()
        deadline = time.monotonic() + 8.0
        while time.monotonic() < deadline and len(answers) < 200:
            time.sleep(0.1)
        stop.set()
        for t in threads:
            t.join(60)
        gap = st.client.get("/api/health").json()["link_heartbeat_gap_ms"]
        boat = st.client.get("/api/boat").json()
    finally:
        st.stop()
    assert set(answers) <= {200, 413} and 413 in answers
    assert gap["heartbeats"] > 0
    # generous: the boat fails safe after 3 s of silence; the schedule is 250 ms
    assert gap["worst_since_start"] < 2500, gap
    assert boat["link"]["up"] and boat["boat"]["state"] != "FAILSAFE"


def json_flood() -> bytes:
    return b"[" + b",".join(b"[0.5, 1e10, \"x\"]" for _ in range(MB // 18)) + b"]"
