"""The console's static files beside the API: index at /, assets, vendored npm libraries."""

import asyncio
import re

import httpx
import pytest
from fastapi import FastAPI
from serverutil import TOKEN, running_station

from usvstation.api.console import REQUIRED, default_frontend_dir, frontend_problem, mount_console
from usvstation.config import Settings

FRONTEND = default_frontend_dir()
needs_frontend = pytest.mark.skipif(
    frontend_problem(FRONTEND) is not None,
    reason=f"{frontend_problem(FRONTEND)} (make setup installs it)")


@pytest.fixture(scope="module")
def station(tmp_path_factory):
    settings = Settings(data_dir=tmp_path_factory.mktemp("data"), token=TOKEN)
    with running_station(settings) as (url, _), httpx.Client(base_url=url, timeout=30) as client:
        yield client


@needs_frontend
def test_console_is_served_with_its_libraries(station):
    index = station.get("/")
    assert index.status_code == 200 and index.headers["content-type"].startswith("text/html")
    assert index.headers["cache-control"] == "no-cache"
    page = index.text
    for url in ("/vendor/leaflet/leaflet-src.esm.js", "/vendor/uplot/uPlot.esm.js",
                "/assets/main.js", "/assets/console.css", "/vendor/leaflet/leaflet.css"):
        assert url in page
        r = station.get(url)
        assert r.status_code == 200, url
        kind = "css" if url.endswith(".css") else "javascript"
        assert kind in r.headers["content-type"], url
    # nothing the page loads comes from elsewhere: every src and href is a local path
    links = re.findall(r'(?:src|href)="([^"]*)"', page)
    assert len(links) >= 8 and all(link.startswith(("/", "#")) for link in links), links


@needs_frontend
def test_api_paths_keep_working_beside_the_console(station):
    assert station.get("/api/health").json()["status"] == "ok"
    assert station.get("/openapi.json").status_code == 200
    assert station.post("/api/plans", json={}).status_code == 401
    assert station.get("/assets/nothing.js").status_code == 404
    # only the libraries' dist/ folders are exposed, not node_modules or the package files
    assert station.get("/vendor/leaflet/leaflet.js").status_code == 200
    assert station.get("/vendor/leaflet/package.json").status_code == 404


def test_missing_console_files_answer_503_with_the_reason(tmp_path):
    app = FastAPI()

    @app.get("/api/ping")
    def ping() -> dict:
        return {"ok": True}

    mount_console(app, tmp_path)

    async def fetch() -> tuple[httpx.Response, httpx.Response]:
        async with httpx.AsyncClient(transport=httpx.ASGITransport(app=app),
                                     base_url="http://station") as client:
            return await client.get("/"), await client.get("/api/ping")

    r, pong = asyncio.run(fetch())
    assert r.status_code == 503
    assert f"index.html, {REQUIRED[1]}" in r.text and str(tmp_path) in r.text
    assert "USV_STATION_FRONTEND_DIR" in r.text
    assert pong.json() == {"ok": True}


def test_problem_names_npm_when_only_the_packages_are_missing(tmp_path):
    (tmp_path / "app").mkdir()
    (tmp_path / "index.html").write_text("<!doctype html>")
    (tmp_path / "app" / "main.js").write_text("")
    problem = frontend_problem(tmp_path)
    assert "node_modules/leaflet/dist/leaflet-src.esm.js" in problem
    assert "npm ci" in problem


def test_frontend_dir_setting_from_the_environment(tmp_path, monkeypatch):
    monkeypatch.setenv("USV_STATION_FRONTEND_DIR", str(tmp_path))
    assert Settings(data_dir=tmp_path).frontend_dir == tmp_path
