"""Re-planning from the boat under way over HTTP (issue 12): POST /api/plans {"from_boat": true}."""

import time

import httpx
import pytest
from serverutil import TOKEN, running_station

from usvstation.config import Settings
from usvstation.planning.validate import plan_violations
from usvstation.scenario import load_scenario, scenario_at
from usvstation.services.errors import Conflict
from usvstation.services.plans import scenario_from_boat

AUTH = {"Authorization": f"Bearer {TOKEN}"}


@pytest.fixture(scope="module")
def station(tmp_path_factory):
    settings = Settings(data_dir=tmp_path_factory.mktemp("data"), token=TOKEN, plan_workers=1)
    with running_station(settings) as (url, st), httpx.Client(base_url=url, timeout=30,
                                                              headers=AUTH) as client:
        yield client, st


def test_plan_from_the_boats_latest_telemetry(station):
    client, st = station
    assert client.put("/api/scenario", json=load_scenario("case1").model_dump(),
                      headers=AUTH).status_code == 200
    deadline = time.monotonic() + 30.0
    while (st.boat.handler.telemetry is None or st.boat.handler.telemetry.get("x") is None) \
            and time.monotonic() < deadline:
        time.sleep(0.1)
    row = st.boat.handler.telemetry
    assert row is not None and row["x"] is not None, "no telemetry from the simulated boat"
    r = client.post("/api/plans", json={"from_boat": True, "seed": 2}, headers=AUTH)
    assert r.status_code == 202
    while True:
        job = client.get(f"/api/plans/{r.json()['id']}").json()
        if job["status"] in ("done", "failed"):
            break
        assert time.monotonic() < deadline + 30.0
        time.sleep(0.05)
    start = job["scenario"]["start"]
    assert (start["x"], start["y"]) != (85.0, 10.0)  # the boat's position, not the file's start
    if job["status"] == "done":
        first = job["plan"]["waypoints"][0]
        assert (first["x"], first["y"]) == pytest.approx((start["x"], start["y"]))
        sc = scenario_at(load_scenario("case1"), start["x"], start["y"], start["heading_deg"],
                         start["speed"], 0.0)
        assert plan_violations(job["plan"], sc) == []
    else:  # the boat may sit where no plan exists (e.g. on the ramp): a clear reason
        assert job["error"].startswith("no feasible plan")


def test_from_boat_without_telemetry_is_one_clear_line():
    """The route answers 409 with this Conflict's text (no boat position yet)."""
    with pytest.raises(Conflict, match=r"^from_boat: no telemetry with a ramp-frame position"):
        scenario_from_boat(load_scenario("case1"), None, None)
    with pytest.raises(Conflict, match=r"^from_boat: no telemetry"):
        scenario_from_boat(load_scenario("case1"), {"x": None, "ramp_heading_deg": None}, 3.0)
