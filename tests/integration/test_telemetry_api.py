"""Stored telemetry through the API: runs, queries, and exports that standard parsers read."""

import csv
import io
import json
import time
import xml.etree.ElementTree as ET

import httpx
import pytest
from serverutil import TOKEN, running_station

from usvstation.config import Settings

AUTH = {"Authorization": f"Bearer {TOKEN}"}
GPX = "{http://www.topografix.com/GPX/1/1}"


def row(run, i):
    return {"run": run, "time": f"2026-11-22T10:00:{i // 10:02d}.{(i % 10) * 100:03d}Z",
            "boat_time": i * 0.1, "lat": 30.5135 + i * 1e-6, "lon": 114.4182 + i * 2e-6,
            "x": 80.0 - i * 0.2, "y": 1.0, "heading_deg": 270.0, "course_deg": 271.0,
            "speed": 2.0, "ramp_heading_deg": 180.0, "fix_type": 3, "satellites": 12,
            "hdop": 0.8, "mode": "auto"}


@pytest.fixture(scope="module")
def station(tmp_path_factory):
    settings = Settings(data_dir=tmp_path_factory.mktemp("data"), token=TOKEN, plan_workers=1)
    with running_station(settings) as (url, st), httpx.Client(base_url=url, timeout=30,
                                                              headers=AUTH) as client:
        job = client.post("/api/plans", json={"seed": 1}).json()
        while client.get(f"/api/plans/{job['id']}").json()["status"] not in ("done", "failed"):
            time.sleep(0.05)
        run = st.store.open_run("m1", job["id"])
        other = st.store.open_run(None, None)
        for i in range(250):
            st.store.writer.put(row(run, i))
        for i in range(7):
            st.store.writer.put(row(other, i))
        deadline = time.monotonic() + 5
        while st.store.writer.stats.committed < 257 and time.monotonic() < deadline:
            time.sleep(0.02)
        yield client, st, run, other


def test_runs_and_queries(station):
    client, _, run, other = station
    runs = {r["id"]: r for r in client.get("/api/runs").json()}
    assert runs[run]["points"] == 250 and runs[run]["mission_id"] == "m1"
    assert runs[other]["points"] == 7
    rows = client.get("/api/telemetry", params={"run": run}).json()
    assert len(rows) == 250 and rows[0]["boat_time"] == 0.0
    assert rows[-1]["boat_time"] == pytest.approx(24.9)
    assert [r["id"] for r in rows] == sorted(r["id"] for r in rows)
    assert len(client.get("/api/telemetry", params={"run": run, "limit": 10}).json()) == 10
    window = client.get("/api/telemetry", params={
        "run": run, "since": "2026-11-22T10:00:01Z", "until": "2026-11-22T10:00:02.000Z"}).json()
    assert len(window) == 11 and window[0]["time"] == "2026-11-22T10:00:01.000Z"
    assert client.get("/api/telemetry", params={"run": "x"}).status_code == 422
    assert client.get("/api/telemetry", params={"limit": 0}).status_code == 422


def test_exports_parse_and_hold_every_point(station):
    client, _, run, _ = station
    n = len(client.get("/api/telemetry", params={"run": run}).json())

    r = client.get("/api/telemetry/export", params={"run": run, "format": "csv"})
    assert r.status_code == 200 and r.headers["content-type"].startswith("text/csv")
    assert r.headers["content-disposition"] == f'attachment; filename="run-{run}.csv"'
    table = list(csv.DictReader(io.StringIO(r.text)))
    assert len(table) == n and float(table[0]["lat"]) == pytest.approx(30.5135)

    lines = client.get("/api/telemetry/export", params={"run": run, "format": "jsonl"}).text
    assert len([json.loads(x) for x in lines.splitlines()]) == n

    gj = client.get("/api/telemetry/export", params={"run": run, "format": "geojson"}).json()
    track, plan = gj["features"]
    assert track["geometry"]["type"] == "LineString"
    assert len(track["geometry"]["coordinates"]) == n
    assert track["geometry"]["coordinates"][0] == [114.4182, 30.5135]  # lon, lat
    assert plan["properties"]["kind"] == "plan" and len(plan["geometry"]["coordinates"]) >= 3

    root = ET.fromstring(client.get("/api/telemetry/export",
                                    params={"run": run, "format": "gpx"}).content)
    assert root.tag == f"{GPX}gpx" and root.get("version") == "1.1"
    points = root.findall(f"{GPX}trk/{GPX}trkseg/{GPX}trkpt")
    assert len(points) == n
    assert points[0].find(f"{GPX}time").text == "2026-11-22T10:00:00.000Z"
    route = root.findall(f"{GPX}rte/{GPX}rtept")
    assert len(route) == len(plan["geometry"]["coordinates"])
    # the planned route starts at case1's start (85 m out along a ramp bearing of 90: east)
    assert float(route[0].get("lon")) > 114.4182 and float(route[-1].get("lon")) == \
        pytest.approx(114.4182)


def test_export_of_an_unknown_run_or_format(station):
    client, _, _, _ = station
    assert client.get("/api/telemetry/export", params={"run": 999}).status_code == 404
    assert client.get("/api/telemetry/export", params={"format": "kml"}).status_code == 422


def test_telemetry_pages_with_a_cursor(station):
    client, _, run, _ = station
    everything = client.get("/api/telemetry", params={"run": run}).json()
    assert "x-next-after" not in client.get("/api/telemetry", params={"run": run}).headers
    pages, after = [], 0
    while True:
        r = client.get("/api/telemetry", params={"run": run, "limit": 100, "after": after})
        assert r.status_code == 200
        pages.append(r.json())
        if "x-next-after" not in r.headers:
            break
        after = int(r.headers["x-next-after"])
        assert after == pages[-1][-1]["id"]
    assert [len(p) for p in pages] == [100, 100, 50]
    assert [row for p in pages for row in p] == everything
    assert client.get("/api/telemetry", params={"limit": 100_001}).status_code == 422
