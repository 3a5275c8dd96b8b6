"""Browser tests: Playwright drives Debian's Chromium (never a downloaded browser) against
`usv-station serve` with the simulated boat.

Without Chromium, Playwright or the console's npm packages the tests skip with the reason;
under CI=true they fail instead, so CI cannot pass without having run them.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from stationproc import StationProcess

from usvstation.api.console import default_frontend_dir, frontend_problem

CHROMIUM = Path(os.environ.get("USV_STATION_CHROMIUM", "/usr/bin/chromium"))
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                 "--no-first-run", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync"]
ARTIFACTS = Path(__file__).parents[2] / "test-artifacts" / "e2e"
DESKTOP = {"width": 1280, "height": 800}


def _unavailable(reason: str) -> None:
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail(f"browser tests cannot run under CI: {reason}", pytrace=False)
    pytest.skip(reason)


@pytest.fixture(scope="module")
def browser():
    """Chromium for one test module. Playwright's sync API keeps an asyncio loop running
    in this thread while it is open, so it must close before other tests call asyncio.run."""
    if not CHROMIUM.exists():
        _unavailable(f"Chromium not found at {CHROMIUM}: `apt-get install chromium` "
                     "(.ci/run does; the tests never download a browser)")
    problem = frontend_problem(default_frontend_dir())
    if problem is not None:
        _unavailable(problem)
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        _unavailable("the playwright package is missing: `make setup` installs it")
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
        yield browser
        browser.close()


# endpoints the console asks for and does without (it hides the control) when absent
OPTIONAL = ("/api/planners",)


def _optional_404(msg) -> bool:
    """Chromium logs every 404 fetch as an error; an optional endpoint's 404 is expected."""
    url = (msg.location or {}).get("url", "")
    return "404" in msg.text and any(url.endswith(path) for path in OPTIONAL)


@pytest.fixture(scope="session")
def artifacts() -> Path:
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    return ARTIFACTS


@pytest.fixture(scope="module")
def station(tmp_path_factory):
    st = StationProcess(tmp_path_factory.mktemp("data"), "--sim-speed", "5")
    st.wait_link_up()
    yield st
    st.stop()


@pytest.fixture
def page(browser, station, artifacts, request):
    """A fresh browser context on the console, with page errors collected; a screenshot
    of the page as the test left it is saved as an artifact."""
    context = browser.new_context(viewport=DESKTOP, accept_downloads=True)
    pg = context.new_page()
    pg.errors = []
    pg.on("pageerror", lambda exc: pg.errors.append(str(exc)))
    pg.on("console", lambda msg: msg.type == "error" and not _optional_404(msg)
          and pg.errors.append(msg.text))
    yield pg
    pg.screenshot(path=artifacts / f"{request.node.name}-end.png")
    context.close()
