"""The HTTP API on a real server: auth, plan jobs, scenario, validation errors, restarts."""

import time

import httpx
import pytest
from serverutil import TOKEN, running_station

from usvstation.config import Settings
from usvstation.planning.validate import plan_violations
from usvstation.scenario import load_scenario, parse_scenario

AUTH = {"Authorization": f"Bearer {TOKEN}"}
VIEWER = "viewer-token-0123456789"


@pytest.fixture(scope="module")
def station(tmp_path_factory):
    settings = Settings(data_dir=tmp_path_factory.mktemp("data"), token=TOKEN, plan_workers=2,
                        viewer_token=VIEWER)
    with running_station(settings) as (url, st), httpx.Client(base_url=url, timeout=30,
                                                              headers=AUTH) as client:
        yield client, st


def wait_plan(client, plan_id, timeout=30.0):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        job = client.get(f"/api/plans/{plan_id}").json()
        if job["status"] in ("done", "failed"):
            return job
        time.sleep(0.05)
    raise AssertionError(f"plan {plan_id} still {job['status']}")


def test_health_and_openapi(station):
    client, _ = station
    health = client.get("/api/health").json()
    assert health["status"] == "ok" and health["version"]
    paths = client.get("/openapi.json").json()["paths"]
    for path in ("/api/health", "/api/scenario", "/api/plans", "/api/plans/{plan_id}",
                 "/api/runs", "/api/telemetry", "/api/telemetry/export"):
        assert path in paths


@pytest.mark.parametrize(("method", "path", "body"), [
    ("post", "/api/plans", {}),
    ("put", "/api/scenario", {"name": "x", "start": {"x": 50, "y": 0}}),
])
def test_changes_need_the_token(station, method, path, body):
    client, _ = station
    for auth in ("", "Bearer wrong", TOKEN):
        r = client.request(method, path, json=body, headers={"Authorization": auth})
        assert r.status_code == 401
        assert r.headers["www-authenticate"] == "Bearer"
        assert "bearer token" in r.json()["detail"]
    r = client.request(method, path, json=body, headers={"Authorization": f"Bearer {VIEWER}"})
    assert r.status_code == 403 and "read only" in r.json()["detail"]


READS = ("/api/scenario", "/api/plans", "/api/runs", "/api/telemetry", "/api/boat",
         "/api/missions", "/api/telemetry/export")


def test_reads_need_the_viewer_or_operator_token(station):
    client, _ = station
    assert client.get("/api/health", headers={"Authorization": ""}).status_code == 200
    for path in READS:
        assert client.get(path, headers={"Authorization": ""}).status_code == 401, path
        assert client.get(path, headers={"Authorization": f"Bearer {VIEWER}"}).status_code == 200
        assert client.get(path).status_code == 200


def test_plan_job_runs_to_a_valid_plan(station):
    client, _ = station
    r = client.post("/api/plans", json={"scenario": load_scenario("case2").model_dump(),
                                        "seed": 4}, headers=AUTH)
    assert r.status_code == 202
    assert r.json()["status"] in ("queued", "running")
    job = wait_plan(client, r.json()["id"])
    assert job["status"] == "done" and job["error"] is None
    assert plan_violations(job["plan"], load_scenario("case2")) == []
    assert job["plan"]["seed"] == 4
    listed = {j["id"]: j for j in client.get("/api/plans").json()}
    assert listed[job["id"]]["status"] == "done" and listed[job["id"]]["scenario"] == "case2"


def test_default_plan_uses_the_working_scenario(station):
    client, _ = station
    scenario = load_scenario("case3").model_dump()
    assert client.put("/api/scenario", json=scenario, headers=AUTH).status_code == 200
    assert client.get("/api/scenario").json()["name"] == "case3"
    job = wait_plan(client, client.post("/api/plans", headers=AUTH).json()["id"])
    assert job["status"] == "done" and job["plan"]["scenario"] == "case3"


def test_infeasible_plan_fails_with_the_reason(station):
    client, _ = station
    scenario = {"name": "blocked", "start": {"x": 60.0, "y": 0.0},
                "obstacles": [{"x": 7.0, "y": 0.5, "radius": 2.5}]}
    job = wait_plan(client, client.post("/api/plans", json={"scenario": scenario},
                                        headers=AUTH).json()["id"])
    assert job["status"] == "failed" and job["plan"] is None
    assert job["error"].startswith("no feasible plan: the run-in along the ramp axis is blocked")


def test_invalid_input_gets_422_with_field_errors(station):
    client, _ = station
    bad = {"scenario": {"name": "x", "start": {"x": "far", "y": 0}, "colour": 1}}
    r = client.post("/api/plans", json=bad, headers=AUTH)
    assert r.status_code == 422
    locs = {tuple(e["loc"]) for e in r.json()["detail"]}
    assert ("body", "scenario", "start", "x") in locs
    assert ("body", "scenario", "colour") in locs
    json_type = {**AUTH, "Content-Type": "application/json"}
    r = client.post("/api/plans", content=b"{not json", headers=json_type)
    assert r.status_code == 422
    r = client.put("/api/scenario", json={"name": "x", "start": {"x": 50, "y": 0},
                                          "vessel": {"speed_min": 3, "speed_max": 1}}, headers=AUTH)
    assert r.status_code == 422
    assert "speed_min: must be below speed_max" in r.text
    assert client.get("/api/scenario").json()["name"] != "x"  # nothing changed
    assert client.get("/api/plans/nope").status_code == 404


def test_restart_keeps_plans_on_the_same_data_dir(tmp_path):
    settings = Settings(data_dir=tmp_path, token=TOKEN, plan_workers=1)
    with running_station(settings) as (url, _), httpx.Client(base_url=url, headers=AUTH) as client:
        plan_id = client.post("/api/plans", json={"seed": 2}, headers=AUTH).json()["id"]
        done = wait_plan(client, plan_id)
    with running_station(settings) as (url, _), httpx.Client(base_url=url, headers=AUTH) as client:
        again = client.get(f"/api/plans/{plan_id}").json()
        assert again["status"] == "done" and again["plan"] == done["plan"]
        assert parse_scenario(again["scenario"]).name == "case1"
