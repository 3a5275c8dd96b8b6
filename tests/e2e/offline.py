"""A browser context that reaches the station only: every other request is aborted and
recorded, so a test can show that a page works with no network."""

from __future__ import annotations

VIEWPORT = {"width": 1280, "height": 800}


def station_only_context(browser, station_url: str):
    """(context, blocked): `blocked` lists the URLs the pages tried outside the station."""
    context = browser.new_context(viewport=VIEWPORT)
    blocked: list[str] = []

    def only_the_station(route):
        if route.request.url.startswith(station_url):
            route.continue_()
        else:
            blocked.append(route.request.url)
            route.abort()

    context.route("**/*", only_the_station)
    return context, blocked
