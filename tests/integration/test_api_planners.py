"""GET /api/planners and POST /api/plans with a registry planner, on a real server."""

import time

import httpx
import pytest
from serverutil import TOKEN, running_station

from usvstation.config import Settings
from usvstation.planning.validate import plan_violations
from usvstation.scenario import load_scenario


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    settings = Settings(data_dir=tmp_path_factory.mktemp("data"), token=TOKEN, plan_workers=2)
    with running_station(settings) as (url, _), httpx.Client(
            base_url=url, timeout=30, headers={"Authorization": f"Bearer {TOKEN}"}) as c:
        yield c


def test_get_planners_lists_names_papers_capabilities(client):
    r = client.get("/api/planners")
    assert r.status_code == 200
    body = r.json()
    assert [p["name"] for p in body] == ["iga", "colregs-ga", "replan-ga", "de-apf", "rrt-star",
                                         "bspline-rrt-star", "vpf-rrt-star"]
    for p in body:
        assert set(p) == {"name", "paper", "title", "capabilities"}
        assert p["paper"] in {"000", "001", "002", "003", "004"}


def test_post_plan_with_a_seed_planner(client):
    sc = load_scenario("case2")
    r = client.post("/api/plans", json={"scenario": sc.model_dump(), "planner": "vpf-rrt-star",
                                        "seed": 2})
    assert r.status_code == 202
    plan_id = r.json()["id"]
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        job = client.get(f"/api/plans/{plan_id}").json()
        if job["status"] in ("done", "failed"):
            break
        time.sleep(0.1)
    assert job["status"] == "done", job.get("error")
    assert job["plan"]["planner"] == "vpf-rrt-star"
    assert plan_violations(job["plan"], sc) == []
    listed = {p["id"]: p for p in client.get("/api/plans").json()}
    assert listed[plan_id]["planner"] == "vpf-rrt-star"


def test_post_plan_with_unknown_planner_is_422(client):
    r = client.post("/api/plans", json={"planner": "nope"})
    assert r.status_code == 422
    assert "unknown planner 'nope'" in r.text
