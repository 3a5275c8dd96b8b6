"""Alerts, the plan monitor and re-plans (shared/DESIGN.md "HTTP API": /api/alerts)."""

from __future__ import annotations

import asyncio
import csv
import io
import json
from typing import Annotated, Literal

from fastapi import APIRouter, Depends, Path, Query, Request, Response

from usvstation.api.auth import require_token
from usvstation.records import Alert, MonitorView, Replan
from usvstation.store.alerts import ALERT_FIELDS

router = APIRouter(tags=["alerts"])
Auth = [Depends(require_token)]
Id = Annotated[str, Path(min_length=1, max_length=64)]


@router.get("/api/alerts")
async def list_alerts(
    request: Request,
    run: Annotated[int | None, Query(ge=1, le=2**63 - 1)] = None,
    limit: Annotated[int, Query(ge=1, le=100_000)] = 1000,
) -> list[Alert]:
    """Alerts, newest first: {id, time, level (advisory|caution|warning|alarm), kind,
    message, target_id, run_id, acknowledged, active, updated_at, announced_at, ended_at};
    of one run with `run`. One alert per cause (kind, target) of a recovery, changed in
    place; `active` until its condition ends."""
    station = request.app.state.station
    return await asyncio.to_thread(station.alerts.alerts, run, limit)


@router.get("/api/alerts/export")
async def export_alerts(
    request: Request,
    run: Annotated[int | None, Query(ge=1, le=2**63 - 1)] = None,
    format: Literal["csv", "jsonl"] = "csv",
) -> Response:
    """The alerts (of one run with `run`) as a file, oldest first, and the run's re-plans
    (jsonl only, lines with "record": "replan")."""
    station = request.app.state.station
    rows = list(reversed(await asyncio.to_thread(station.alerts.alerts, run, 1_000_000)))
    name = f"alerts-run-{run}" if run is not None else "alerts"
    if format == "csv":
        out = io.StringIO()
        writer = csv.DictWriter(out, fieldnames=list(ALERT_FIELDS), lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
        body, media = out.getvalue(), "text/csv"
    else:
        replans = await asyncio.to_thread(station.alerts.replans, run)
        body = "".join(json.dumps({"record": "alert", **r}) + "\n" for r in rows) + "".join(
            json.dumps({"record": "replan", **r}) + "\n" for r in replans)
        media = "application/x-ndjson"
    return Response(body, media_type=media, headers={
        "Content-Disposition": f'attachment; filename="{name}.{format}"'})


@router.post("/api/alerts/{alert_id}/ack", dependencies=Auth,
             responses={404: {"description": "no such alert"}})
async def ack_alert(request: Request, alert_id: Id) -> Alert:
    """Acknowledge an alert (idempotent); the acknowledged record goes out on the websocket.
    Acknowledging does not end it: it stays active while its condition holds."""
    return await request.app.state.station.monitor.acknowledge(alert_id)


@router.get("/api/monitor")
async def monitor(request: Request) -> MonitorView:
    """The latest assessment of the running plan: slip, cross-track, per-target DCPA, TCPA,
    encounter class and predicted clearance, the predicted path; null fields when idle."""
    m = request.app.state.station.monitor
    return {"policy": m.replan.policy, "run": m.run, "frames": m.frames,
            "assessment": m.last}


@router.get("/api/replans")
async def list_replans(
    request: Request, run: Annotated[int | None, Query(ge=1, le=2**63 - 1)] = None,
) -> list[Replan]:
    """Every re-plan: {id, created_at, run_id, alert_id, plan_id, policy, state (planning,
    proposed, planned, applied, rejected, failed), error, latency_ms, mission_id}."""
    m = request.app.state.station.monitor
    live = [r for r in m.replan.replans.values() if run is None or r["run_id"] == run]
    if live:
        return live
    return await asyncio.to_thread(request.app.state.station.alerts.replans, run)


@router.post("/api/replans/{replan_id}/confirm", dependencies=Auth,
             responses={404: {"description": "no such re-plan"},
                        409: {"description": "not proposed, or the swap failed"}})
async def confirm_replan(request: Request, replan_id: Id) -> Replan:
    """The operator accepts a proposed re-plan: it is hot-swapped onto the boat."""
    return await request.app.state.station.monitor.replan.confirm(replan_id)


@router.post("/api/replans/{replan_id}/reject", dependencies=Auth,
             responses={404: {"description": "no such re-plan"},
                        409: {"description": "not proposed"}})
async def reject_replan(request: Request, replan_id: Id) -> Replan:
    return await request.app.state.station.monitor.replan.reject(replan_id)
