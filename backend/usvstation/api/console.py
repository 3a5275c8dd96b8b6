"""The operator console: static files from frontend/ served beside the API.

`/` is frontend/index.html, `/assets/` is frontend/app/ (the console's own
modules and CSS) and `/vendor/NAME/` is the `dist/` folder of an npm package
installed in frontend/node_modules, so the console needs no internet on a
ship. The folder is the `frontend_dir` setting (USV_STATION_FRONTEND_DIR),
by default frontend/ of the source checkout this package runs from.
"""

from __future__ import annotations

from collections.abc import Awaitable, Callable
from pathlib import Path

from fastapi import FastAPI
from fastapi.openapi.docs import get_redoc_html, get_swagger_ui_html
from fastapi.responses import FileResponse, HTMLResponse, PlainTextResponse, Response
from fastapi.staticfiles import StaticFiles

VENDOR = {"leaflet": "leaflet/dist", "uplot": "uplot/dist"}
DOCS_VENDOR = {"swagger-ui": "swagger-ui-dist", "redoc": "redoc/bundles"}
REQUIRED = ("index.html", "app/main.js", "node_modules/leaflet/dist/leaflet-src.esm.js",
            "node_modules/uplot/dist/uPlot.esm.js")
NO_CACHE = {"Cache-Control": "no-cache"}


def default_frontend_dir() -> Path:
    """frontend/ beside backend/ in a source checkout (editable install)."""
    return Path(__file__).resolve().parents[3] / "frontend"


def frontend_problem(frontend_dir: Path) -> str | None:
    """Why the console cannot be served from `frontend_dir`, or None when it can."""
    missing = [name for name in REQUIRED if not (frontend_dir / name).is_file()]
    if not missing:
        return None
    hint = ("run `npm ci` in frontend/ (`make setup` does)" if (frontend_dir / "index.html")
            .is_file() else "set USV_STATION_FRONTEND_DIR to the console's folder")
    return (f"operator console not available: {', '.join(missing)} missing under "
            f"{frontend_dir}; {hint}")


def mount_console(app: FastAPI, frontend_dir: Path) -> None:
    """Serve the console at `/`; when its files are missing, `/` answers 503 with the reason.

    Mount after the API routes: the mounts only take /assets and /vendor.
    """
    problem = frontend_problem(frontend_dir)
    if problem is not None:
        @app.get("/", include_in_schema=False)
        async def console_missing() -> Response:
            return PlainTextResponse(problem + "\n", status_code=503)
        return

    index = frontend_dir / "index.html"

    @app.get("/", include_in_schema=False)
    async def console_index() -> FileResponse:
        return FileResponse(index, media_type="text/html", headers=NO_CACHE)

    app.mount("/assets", StaticFiles(directory=frontend_dir / "app"), name="assets")
    for name, sub in VENDOR.items():
        app.mount(f"/vendor/{name}", StaticFiles(directory=frontend_dir / "node_modules" / sub),
                  name=f"vendor-{name}")


# The API docs pages may load nothing from outside the station: ReDoc's bundle asks a CDN
# for its logo, which a browser at sea would wait on (and which leaks that the page is open).
DOCS_CSP = ("default-src 'self'; img-src 'self' data: blob:; font-src 'self' data:; "
            "style-src 'self' 'unsafe-inline'; script-src 'self' 'unsafe-inline' blob:; "
            "worker-src 'self' blob:; connect-src 'self'")


def _docs_page(page: HTMLResponse) -> HTMLResponse:
    page.headers["Content-Security-Policy"] = DOCS_CSP
    return page


def mount_docs(app: FastAPI, frontend_dir: Path) -> None:
    """`/docs` (Swagger UI) and `/redoc` from the npm packages in frontend/node_modules, so the
    API documentation needs no internet; 503 with the reason when they are not installed."""
    modules = frontend_dir / "node_modules"
    swagger, redoc = modules / "swagger-ui-dist", modules / "redoc" / "bundles"
    title = f"{app.title} - API"
    missing = [str(p) for p in (swagger / "swagger-ui-bundle.js", redoc / "redoc.standalone.js")
               if not p.is_file()]

    spec, icon = app.openapi_url or "/openapi.json", "/vendor/swagger-ui/favicon-32x32.png"
    pages = {
        "/docs": lambda: get_swagger_ui_html(
            openapi_url=spec, title=title, swagger_favicon_url=icon,
            swagger_js_url="/vendor/swagger-ui/swagger-ui-bundle.js",
            swagger_css_url="/vendor/swagger-ui/swagger-ui.css"),
        "/redoc": lambda: get_redoc_html(
            openapi_url=spec, title=title, redoc_favicon_url=icon, with_google_fonts=False,
            redoc_js_url="/vendor/redoc/redoc.standalone.js"),
    }

    def page(render: Callable[[], HTMLResponse]) -> Callable[[], Awaitable[Response]]:
        async def serve() -> Response:
            if missing:
                return PlainTextResponse(f"API docs not available: {', '.join(missing)} "
                                         "missing; run `npm ci` in frontend/\n", status_code=503)
            return _docs_page(render())
        return serve

    for path, render in pages.items():
        app.add_api_route(path, page(render), methods=["GET"], include_in_schema=False)

    if not missing:
        for name, sub in DOCS_VENDOR.items():
            app.mount(f"/vendor/{name}", StaticFiles(directory=modules / sub),
                      name=f"vendor-{name}")
