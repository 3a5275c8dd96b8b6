"""Telemetry log export as CSV, GPX 1.1, GeoJSON or JSON Lines, streamed chunk by chunk.

Rows are read in chunks from their own SQLite connection, so a run of a
million points is exported without holding it in memory. Every format holds
exactly the rows `/api/telemetry` returns for the run. GPX and GeoJSON also
carry the run's planned route (GPX `rte`, a second GeoJSON feature).
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Iterator
from xml.sax.saxutils import escape

from usvstation.geo import RampFrame
from usvstation.planning.model import Plan
from usvstation.records import PlanJob, RoutePoint, RunRow, StoredTelemetryRow
from usvstation.store.db import TELEMETRY_COLUMNS

FORMATS = {
    "csv": ("text/csv", "csv"),
    "gpx": ("application/gpx+xml", "gpx"),
    "geojson": ("application/geo+json", "geojson"),
    "jsonl": ("application/x-ndjson", "jsonl"),
}
COLUMNS = ("id", *TELEMETRY_COLUMNS)


def planned_route(plan_job: PlanJob | None) -> list[RoutePoint]:
    """The plan's waypoints with lat/lon (empty when there is no plan or no origin)."""
    document = plan_job["plan"] if plan_job else None
    origin = plan_job["scenario"].get("origin") if plan_job else None
    if document is None or not isinstance(origin, dict):
        return []
    frame = RampFrame(origin["lat"], origin["lon"], origin["ramp_bearing_deg"])
    out: list[RoutePoint] = []
    for i, w in enumerate(Plan.from_document(document).waypoints):
        lat, lon = frame.to_geodetic(w.x, w.y)
        out.append({"index": i, "lat": float(lat), "lon": float(lon), "t": w.t,
                    "speed": w.speed,
                    "heading_deg": float(frame.heading_to_compass_deg(w.heading_deg))})
    return out


Chunks = Iterator[list[StoredTelemetryRow]]


def export_chunks(fmt: str, chunks: Chunks, run: RunRow | None,
                  route: list[RoutePoint]) -> Iterator[str]:
    """Text pieces of the export in format `fmt`."""
    return {"csv": _csv, "jsonl": _jsonl, "gpx": _gpx, "geojson": _geojson}[fmt](
        chunks, run, route
    )


def _csv(chunks: Chunks, run: RunRow | None, route: list[RoutePoint]) -> Iterator[str]:
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(COLUMNS)
    for rows in chunks:
        for r in rows:
            writer.writerow(["" if r[c] is None else r[c] for c in COLUMNS])
        yield buf.getvalue()
        buf.seek(0)
        buf.truncate()
    yield buf.getvalue()


def _jsonl(chunks: Chunks, run: RunRow | None, route: list[RoutePoint]) -> Iterator[str]:
    for rows in chunks:
        yield "".join(json.dumps(r, separators=(",", ":")) + "\n" for r in rows)


def _gpx(chunks: Chunks, run: RunRow | None, route: list[RoutePoint]) -> Iterator[str]:
    name = f"run {run['id']}" if run else "telemetry"
    yield ('<?xml version="1.0" encoding="UTF-8"?>\n'
           '<gpx version="1.1" creator="usv-station" xmlns="http://www.topografix.com/GPX/1/1">\n'
           f"<metadata><name>{escape(name)}</name></metadata>\n")
    if route:
        yield "<rte><name>planned route</name>\n"
        yield "".join(
            f'<rtept lat="{p["lat"]:.8f}" lon="{p["lon"]:.8f}"><name>wp{p["index"]}</name>'
            f'<desc>t={p["t"]:.2f} s, speed={p["speed"]:.2f} m/s, '
            f'heading={p["heading_deg"]:.1f} deg</desc></rtept>\n' for p in route
        )
        yield "</rte>\n"
    yield f"<trk><name>{escape(name)}</name><trkseg>\n"
    for rows in chunks:
        yield "".join(_trkpt(r) for r in rows)
    yield "</trkseg></trk>\n</gpx>\n"


def _trkpt(r: StoredTelemetryRow) -> str:
    lat = r["lat"] if r["lat"] is not None else 0.0
    lon = r["lon"] if r["lon"] is not None else 0.0
    extra = ""
    if r["satellites"] is not None:
        extra += f"<sat>{int(r['satellites'])}</sat>"
    if r["hdop"] is not None:
        extra += f"<hdop>{r['hdop']:.2f}</hdop>"
    return (f'<trkpt lat="{lat:.8f}" lon="{lon:.8f}"><time>{r["time"]}</time>{extra}'
            "</trkpt>\n")


def _geojson(chunks: Chunks, run: RunRow | None, route: list[RoutePoint]) -> Iterator[str]:
    props = {"name": f"run {run['id']}" if run else "telemetry", "kind": "track"}
    if run:
        props.update(run=run["id"], started_at=run["started_at"], ended_at=run["ended_at"])
    yield ('{"type":"FeatureCollection","features":[{"type":"Feature","properties":'
           + json.dumps(props) + ',"geometry":{"type":"LineString","coordinates":[')
    first = True
    for rows in chunks:
        parts = [f"[{json.dumps(r['lon'])},{json.dumps(r['lat'])}]" for r in rows]
        if parts:
            yield ("" if first else ",") + ",".join(parts)
            first = False
    yield "]}}"
    if route:
        plan = {"type": "Feature", "properties": {"name": "planned route", "kind": "plan",
                                                  "times_s": [p["t"] for p in route]},
                "geometry": {"type": "LineString",
                             "coordinates": [[p["lon"], p["lat"]] for p in route]}}
        yield "," + json.dumps(plan)
    yield "]}\n"
