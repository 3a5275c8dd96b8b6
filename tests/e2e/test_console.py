"""The operator console in Chromium against a real station with the simulated boat:
edit, plan, upload, start, watch the boat and its track, download the log, open the 3D view."""

from __future__ import annotations

import csv
import io
import json
import math
import re
import time

from offline import station_only_context
from playwright.sync_api import expect

from usvstation.geo import RampFrame
from usvstation.geometry import inflated_radius, position_at
from usvstation.planning.validate import plan_violations
from usvstation.scenario import parse_scenario

NEW_OBSTACLE = (70.0, -5.0)


def open_console(page, station, token=True):
    query = f"/?token={station.token}" if token else "/"
    page.goto(station.url + query)
    expect(page.locator("#live-state")).to_have_text("live: connected")
    expect(page.locator("#obstacle-rows tr").first).to_be_visible()


def boat_centre(page) -> tuple[float, float]:
    box = page.locator(".boat-marker").bounding_box()
    return box["x"] + box["width"] / 2, box["y"] + box["height"] / 2


def wait_until_moved(page, before, pixels, timeout=20.0):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        now = boat_centre(page)
        if math.dist(before, now) > pixels:
            return now
        page.wait_for_timeout(100)
    return now


def test_plan_upload_run_and_download(page, station, artifacts):
    open_console(page, station)
    # the station traded the token in the address bar for an HttpOnly, SameSite=Strict cookie
    assert "token" not in page.url
    (cookie,) = [c for c in page.context.cookies() if c["name"] == "usv_token"]
    assert cookie["value"] == station.token and cookie["httpOnly"]
    assert cookie["sameSite"] == "Strict"
    assert "usv_token" not in page.evaluate("document.cookie")
    expect(page.locator("#link-state")).to_contain_text("link up")
    expect(page.locator("#frames-lost")).to_have_text("0")
    expect(page.locator("#hb-age")).to_have_text(re.compile(r"^\d\.\d$"))
    n_before = page.locator("#obstacle-rows tr").count()

    # add an obstacle by clicking the map, then give it a radius and a velocity
    page.check("input[name=click-mode][value=obstacle]")
    point = page.evaluate("([x, y]) => usvConsole.map.rampToContainerPoint(x, y)", NEW_OBSTACLE)
    page.locator("#map").click(position=point)
    expect(page.locator("#obstacle-rows tr")).to_have_count(n_before + 1)
    n = n_before + 1
    page.fill(f"[aria-label='obstacle {n} radius (m)']", "2.5")
    page.fill(f"[aria-label='obstacle {n} vy (m/s)']", "0.3")
    expect(page.locator("#scenario-status")).to_contain_text("saved", timeout=10_000)
    scenario = station.client.get("/api/scenario").json()
    added = scenario["obstacles"][-1]
    assert len(scenario["obstacles"]) == n
    assert math.dist((added["x"], added["y"]), NEW_OBSTACLE) < 0.3
    assert (added["radius"], added["vx"], added["vy"]) == (2.5, 0.0, 0.3)

    # plan: the path is drawn leg by leg, the metrics are shown with units
    page.click("#plan")
    expect(page.locator("[data-metric=length_m] dd")).to_have_text(re.compile(r"^\d+\.\d m$"),
                                                                  timeout=30_000)
    plan_id = station.client.get("/api/plans").json()[-1]["id"]
    job = station.client.get(f"/api/plans/{plan_id}").json()
    plan = job["plan"]
    assert plan_violations(plan, parse_scenario(scenario)) == []
    waypoints = plan["waypoints"]
    expect(page.locator("path.plan-segment")).to_have_count(len(waypoints) - 1)
    expect(page.locator("path.smoothed-path")).to_have_count(1)
    duration = page.locator("[data-metric=duration_s] dd").inner_text()
    assert duration == f"{plan['metrics']['duration_s']:.1f} s"
    for key in ("fitness", "fit_d", "fit_t", "fit_ang", "fit_mal", "min_clearance_m"):
        expect(page.locator(f"[data-metric={key}] dd")).not_to_be_empty()
    page.screenshot(path=artifacts / "console-planned.png")

    # upload: every waypoint acknowledged, one progress cell each
    page.click("#upload")
    expect(page.locator("#mission-state")).to_contain_text("verified", timeout=30_000)
    expect(page.locator("#upload-items li.acked")).to_have_count(len(waypoints))
    expect(page.locator("#upload-text")).to_have_text(
        f"{len(waypoints)} of {len(waypoints)} waypoints acknowledged ({len(waypoints)} sent)")

    # start: the boat marker moves and its track grows
    before = boat_centre(page)
    page.click("#cmd-start")  # START always asks first
    page.click("#start-confirm")
    expect(page.locator("#command-result")).to_have_text("START: ACCEPTED, boat RUNNING")
    expect(page.locator("#mission-state")).to_contain_text("active", timeout=20_000)
    track = page.locator("#track-points")
    expect(track).not_to_have_text("0", timeout=10_000)
    first = int(track.inner_text())
    page.wait_for_function(f"Number(document.getElementById('track-points').textContent) > "
                           f"{first + 20}", timeout=20_000)
    # the instruments during the run: behind or ahead of the plan's schedule, cross-track
    expect(page.locator("#boat-slip")).to_have_text(re.compile(r"^[+-]\d+\.\d$"))
    expect(page.locator("#boat-xte")).to_have_text(re.compile(r"^-?\d+\.\d$"))
    moved = wait_until_moved(page, before, 40)
    assert math.dist(before, moved) > 40  # pixels, about 4 m at this zoom
    # the real track is drawn (Leaflet simplifies a polyline at the screen's resolution,
    # so its vertex count follows the map's zoom, not the number of fixes)
    expect(page.locator("path.real-track")).to_have_attribute("d", re.compile(r"(L[^L]+){3}"),
                                                              timeout=20_000)
    page.screenshot(path=artifacts / "console-running.png")

    # the run completes at the ramp; planned and real on map and charts
    expect(page.locator("#mission-state")).to_contain_text(
        "completed", timeout=int(plan["metrics"]["duration_s"] / 5 * 1000) + 30_000)
    runs = station.client.get("/api/runs").json()
    run = runs[-1]
    expect(page.locator(f"#run-rows tr[data-run='{run['id']}'] td").nth(1)).to_have_text(
        "completed")
    page.wait_for_timeout(700)  # the charts redraw twice a second
    page.screenshot(path=artifacts / "console-planned-and-real.png")

    # download the run as CSV from its link: every stored point
    with page.expect_download() as download:
        page.click(f"a[aria-label='download run {run['id']} as CSV']")
    text = download.value.path().read_text()
    rows = list(csv.DictReader(io.StringIO(text)))
    assert download.value.suggested_filename == f"run-{run['id']}.csv"
    points = station.client.get("/api/runs").json()[-1]["points"]
    assert len(rows) == points > 50
    assert {"time", "lat", "lon", "x", "y", "speed"} <= set(rows[0])
    assert math.hypot(float(rows[-1]["x"]), float(rows[-1]["y"])) < 3.0
    assert page.errors == []


def test_the_3d_view_opens_from_the_console(page, station, artifacts):
    open_console(page, station)
    link = page.locator("#viser-link")
    expect(link).to_have_attribute("href", "/3d/")  # viser, proxied behind the same token
    with page.expect_popup() as popup:
        link.click()
    view = popup.value
    # a small window: the scene is drawn by WebGL in software (SwiftShader), every frame
    view.set_viewport_size({"width": 640, "height": 400})
    expect(view.get_by_text("Planned path", exact=True)).to_be_visible(timeout=30_000)
    expect(view.get_by_text("Follow the live run")).to_be_visible()
    expect(view.locator("canvas").first).to_be_visible()
    # the scene arrived over viser's websocket: the time readout is the server's markdown
    expect(view.get_by_text(re.compile(r"t = \d+\.\d s")).first).to_be_visible()
    view.wait_for_timeout(1500)  # let WebGL draw a few frames
    view.screenshot(path=artifacts / "viser-view.png")
    view.close()


def test_api_errors_show_next_to_their_control(page, station):
    page.context.clear_cookies()
    page.goto(station.url + "/")  # no token in the address, no cookie
    page.evaluate("sessionStorage.clear()")
    page.click("#cmd-hold")
    expect(page.locator("#command-error")).to_contain_text("bearer token")
    expect(page.locator("#command-error")).to_contain_text("?token=")
    # the token entered under Settings is sent from then on
    page.fill("#token", station.token)
    page.click("#token-form button")
    expect(page.locator("#live-state")).to_have_text("live: connected", timeout=30_000)
    page.reload()  # the cookie now set, the console loads what it could not read before
    page.click("#plan")  # planning works; with no verified mission, START is refused
    expect(page.locator("[data-metric=length_m] dd")).to_be_visible(timeout=30_000)
    page.click("#cmd-start")
    page.click("#start-confirm")
    # after the reload the console knows the earlier test's finished mission: the boat's refusal
    expect(page.locator("#command-error")).to_have_text(re.compile(
        r"no verified mission to start: upload a plan first|the boat refused START"))
    # a start inside an obstacle: the station's reason, next to the scenario editor
    obstacle = station.client.get("/api/scenario").json()["obstacles"][0]
    page.fill("#start-x", str(obstacle["x"]))
    page.fill("#start-y", str(obstacle["y"]))
    expect(page.locator("#scenario-error")).to_contain_text(
        "start: (", timeout=10_000)
    expect(page.locator("#scenario-error")).to_contain_text("lies inside obstacle 1")
    expect(page.locator("#plan-stale")).to_be_visible()
    expect(page.locator("#upload")).to_be_disabled()
    page.click("#plan")
    expect(page.locator("#plan-error")).to_contain_text("the scenario is not saved")
    page.fill("#start-x", "")
    expect(page.locator("#scenario-error")).to_have_text("start.x: enter a number")
    page.fill("#start-x", "85")
    page.fill("#start-y", "10")
    expect(page.locator("#scenario-error")).to_be_empty(timeout=10_000)


def test_abort_asks_for_confirmation(page, station):
    open_console(page, station)
    dialog = page.locator("#abort-dialog")
    page.click("#cmd-abort")
    expect(dialog).to_be_visible()
    expect(dialog.get_by_role("button", name="Keep going")).to_be_focused()
    page.keyboard.press("Escape")
    expect(dialog).to_be_hidden()
    assert page.locator("#command-result").inner_text() == ""
    page.click("#cmd-abort")
    page.click("#abort-confirm")
    expect(page.locator("#command-result")).to_have_text(re.compile(r"^ABORT: ACCEPTED"))


def test_keyboard_and_tablet_width(page, station, artifacts):
    page.set_viewport_size({"width": 768, "height": 1024})
    open_console(page, station)
    # nothing wider than the screen, and the map, commands and charts are all there
    assert page.evaluate("document.documentElement.scrollWidth") <= 768
    for sel in ("#map", "#cmd-start", "#cmd-abort", "#plan", "#chart-heading canvas"):
        box = page.locator(sel).first.bounding_box()
        assert box and box["width"] > 0 and box["x"] >= 0 and box["x"] + box["width"] <= 768
    page.screenshot(path=artifacts / "console-tablet.png", full_page=True)
    # Tab reaches the controls in order, Enter presses them (earlier tests on this station
    # leave runs and alerts, each with its own focusable controls, before the plan card)
    reached = []
    for _ in range(400):
        page.keyboard.press("Tab")
        reached.append(page.evaluate("document.activeElement.id"))
        if reached[-1] == "plan":
            break
    assert "cmd-start" in reached and "start-x" in reached and reached[-1] == "plan"
    page.keyboard.press("Enter")
    expect(page.locator("[data-metric=length_m] dd")).to_be_visible(timeout=30_000)


def test_map_geometry_matches_the_station(page, station):
    """The console's WGS-84 ramp frame (geo.js) agrees with the station's (geo.py)."""
    open_console(page, station)
    cases = [(30.5135, 114.4182, 90.0), (-33.9, 18.4, 217.5), (59.3, 10.6, 3.0)]
    points = [(0.0, 0.0), (85.0, 10.0), (-40.0, 300.0), (2500.0, -1800.0)]
    got = page.evaluate("""async ([cases, points]) => {
        const { RampFrame } = await import('/assets/geo.js');
        return cases.map(([lat, lon, b]) => {
            const f = new RampFrame(lat, lon, b);
            return points.map(([x, y]) => { const ll = f.toLatLon(x, y);
                                            return [ll, f.toRamp(...ll)]; });
        });
    }""", [cases, points])
    for (lat, lon, bearing), results in zip(cases, got, strict=True):
        frame = RampFrame(lat, lon, bearing)
        for (x, y), ((js_lat, js_lon), (js_x, js_y)) in zip(points, results, strict=True):
            py_lat, py_lon = frame.to_geodetic(x, y)
            assert abs(js_lat - py_lat) < 1e-10 and abs(js_lon - py_lon) < 1e-10
            assert abs(js_x - x) < 1e-6 and abs(js_y - y) < 1e-6
    assert json.dumps(got)  # plain numbers, no NaN


def test_map_plan_position_and_inflation_match_the_station(page, station):
    """map.js's position on a timed plan and eq. 7 radius agree with geometry.py."""
    open_console(page, station)
    wps = [{"x": 80.0, "y": 10.0, "t": 0.0}, {"x": 40.0, "y": 0.0, "t": 20.0},
           {"x": 40.0, "y": 0.0, "t": 20.0}, {"x": 0.0, "y": -3.5, "t": 31.5}]
    times = [-5.0, 0.0, 7.3, 20.0, 25.0, 31.5, 40.0]
    scenario = {"vessel": {"length": 1.7, "compensation_radius": 0.8}}
    got = page.evaluate("""async ([wps, times, scenario]) => {
        const { planPositionAt, inflatedRadius } = await import('/assets/map.js');
        return [times.map((t) => { const p = planPositionAt(wps, t); return [p.x, p.y]; }),
                inflatedRadius(scenario, { radius: 3.25 })];
    }""", [wps, times, scenario])
    ts, xs, ys = ([w[k] for w in wps] for k in ("t", "x", "y"))
    for t, (js_x, js_y) in zip(times, got[0], strict=True):
        py_x, py_y = position_at(ts, xs, ys, t)
        assert abs(js_x - py_x) < 1e-9 and abs(js_y - py_y) < 1e-9, t
    assert got[1] == inflated_radius(3.25, 1.7, 0.8)


def test_api_docs_render_in_the_browser_with_the_network_blocked(browser, station, artifacts):
    """/docs (Swagger UI) and /redoc draw the station's own API from local assets only."""
    context, blocked = station_only_context(browser, station.url)
    page = context.new_page()
    errors: list[str] = []
    page.on("pageerror", lambda exc: errors.append(str(exc)))
    try:
        open_console(page, station)  # trades the token for the session cookie
        page.goto(station.url + "/docs")
        expect(page.locator(".swagger-ui .info .title")).to_contain_text("USV")
        expect(page.locator(".opblock-summary-path", has_text="/api/health").first)\
            .to_be_visible()
        page.screenshot(path=artifacts / "api-docs-swagger.png")
        page.goto(station.url + "/redoc")
        expect(page.locator("h1").first).to_contain_text("USV", timeout=20_000)
        expect(page.get_by_text("/api/health").first).to_be_attached()
        page.screenshot(path=artifacts / "api-docs-redoc.png")
        assert blocked == [] and errors == []
    finally:
        context.close()
