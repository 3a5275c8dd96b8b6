"""Offline charts: MBTiles packages (SQLite, MBTiles 1.3) served from `--charts DIR`.

`GET /api/charts` lists the packages in the folder with their metadata;
`GET /api/charts/{name}/{z}/{x}/{y}` answers one tile (XYZ numbering as Leaflet
asks; MBTiles stores TMS rows, so y is flipped), 404 when the package has none.
Files are opened read-only, in a worker thread, so the event loop never waits on disk.
"""

from __future__ import annotations

import asyncio
import re
import sqlite3
from pathlib import Path as FsPath
from typing import Annotated

from fastapi import APIRouter, HTTPException, Path, Request
from fastapi.responses import Response
from pydantic import BaseModel

router = APIRouter(tags=["charts"])
NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9._-]{0,99}$")
MEDIA = {"png": "image/png", "jpg": "image/jpeg", "jpeg": "image/jpeg", "webp": "image/webp",
         "pbf": "application/x-protobuf"}


class ChartPackage(BaseModel):
    name: str
    title: str
    format: str
    minzoom: int | None
    maxzoom: int | None
    bounds: list[float] | None  # west, south, east, north (degrees)
    attribution: str | None
    tiles: str  # URL template for Leaflet


def _connect(path: FsPath) -> sqlite3.Connection:
    return sqlite3.connect(f"file:{path}?mode=ro", uri=True)


def read_package(path: FsPath) -> ChartPackage:
    """One package's metadata; raises sqlite3.Error for a file that is not MBTiles."""
    with _connect(path) as db:
        meta = dict(db.execute("SELECT name, value FROM metadata").fetchall())
    bounds = [float(v) for v in meta["bounds"].split(",")] if meta.get("bounds") else None

    def zoom(key: str) -> int | None:
        return int(meta[key]) if meta.get(key) not in (None, "") else None

    return ChartPackage(name=path.stem, title=meta.get("name", path.stem),
                        format=meta.get("format", "png"), minzoom=zoom("minzoom"),
                        maxzoom=zoom("maxzoom"), bounds=bounds,
                        attribution=meta.get("attribution"),
                        tiles=f"/api/charts/{path.stem}/{{z}}/{{x}}/{{y}}")


def read_tile(path: FsPath, z: int, x: int, y: int) -> bytes | None:
    with _connect(path) as db:
        row = db.execute("SELECT tile_data FROM tiles WHERE zoom_level=? AND tile_column=? "
                         "AND tile_row=?", (z, x, (1 << z) - 1 - y)).fetchone()
    return None if row is None else bytes(row[0])


def _charts_dir(request: Request) -> FsPath | None:
    return request.app.state.station.settings.charts_dir


def _package(request: Request, name: str) -> FsPath:
    folder = _charts_dir(request)
    path = folder / f"{name}.mbtiles" if folder is not None and NAME.match(name) else None
    if path is None or not path.is_file():
        raise HTTPException(404, detail=f"no chart package {name!r}")
    return path


def _list(folder: FsPath | None) -> list[ChartPackage]:
    if folder is None or not folder.is_dir():
        return []
    out = []
    for path in sorted(folder.glob("*.mbtiles")):
        if NAME.match(path.stem):
            try:
                out.append(read_package(path))
            except (sqlite3.Error, KeyError, ValueError):
                continue  # not an MBTiles file: not offered
    return out


@router.get("/api/charts")
async def list_charts(request: Request) -> list[ChartPackage]:
    return await asyncio.to_thread(_list, _charts_dir(request))


@router.get("/api/charts/{name}/{z}/{x}/{y}")
async def chart_tile(request: Request, name: str, z: Annotated[int, Path(ge=0, le=30)],
                     x: Annotated[int, Path(ge=0)], y: Annotated[int, Path(ge=0)]) -> Response:
    path = _package(request, name)
    if x >= 1 << z or y >= 1 << z:
        raise HTTPException(404, detail=f"no tile {z}/{x}/{y}")
    meta, data = await asyncio.gather(asyncio.to_thread(read_package, path),
                                      asyncio.to_thread(read_tile, path, z, x, y))
    if data is None:
        raise HTTPException(404, detail=f"chart {name!r} has no tile {z}/{x}/{y}")
    return Response(data, media_type=MEDIA.get(meta.format, "application/octet-stream"),
                    headers={"Cache-Control": "max-age=3600"})
