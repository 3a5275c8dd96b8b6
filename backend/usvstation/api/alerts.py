"""Alerts, the plan monitor and re-plans (shared/DESIGN.md "HTTP API": /api/alerts)."""

from __future__ import annotations

import asyncio
from typing import Annotated, Any

from fastapi import APIRouter, Depends, HTTPException, Path, Query, Request

from usvstation.api.auth import require_token

router = APIRouter(tags=["alerts"])
Auth = [Depends(require_token)]
Id = Annotated[str, Path(min_length=1, max_length=64)]


@router.get("/api/alerts")
async def list_alerts(
    request: Request,
    run: Annotated[int | None, Query(ge=1, le=2**63 - 1)] = None,
    limit: Annotated[int, Query(ge=1, le=100_000)] = 1000,
) -> list[dict[str, Any]]:
    """Alerts, newest first: {id, time, level (advisory|caution|warning), kind, message,
    target_id, run_id, acknowledged}; of one run with `run`."""
    station = request.app.state.station
    return await asyncio.to_thread(station.alerts.alerts, run, limit)


@router.post("/api/alerts/{alert_id}/ack", dependencies=Auth,
             responses={404: {"description": "no such alert"}})
async def ack_alert(request: Request, alert_id: Id) -> dict[str, Any]:
    """Acknowledge an alert (idempotent); the acknowledged record goes out on the websocket."""
    station = request.app.state.station
    record = await asyncio.to_thread(station.alerts.acknowledge, alert_id)
    if record is None:
        raise HTTPException(404, detail=f"no alert {alert_id!r}")
    station.hub.publish("alert", record)
    return record


@router.get("/api/monitor")
async def monitor(request: Request) -> dict[str, Any]:
    """The latest assessment of the running plan: slip, cross-track, per-target DCPA, TCPA,
    encounter class and predicted clearance, the predicted path; null fields when idle."""
    m = request.app.state.station.monitor
    return {"policy": m.replan.policy, "run": m.run, "frames": m.frames,
            "assessment": m.last}


@router.get("/api/replans")
async def list_replans(
    request: Request, run: Annotated[int | None, Query(ge=1, le=2**63 - 1)] = None,
) -> list[dict[str, Any]]:
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
async def confirm_replan(request: Request, replan_id: Id) -> dict[str, Any]:
    """The operator accepts a proposed re-plan: it is hot-swapped onto the boat."""
    return await request.app.state.station.monitor.replan.confirm(replan_id)


@router.post("/api/replans/{replan_id}/reject", dependencies=Auth,
             responses={404: {"description": "no such re-plan"},
                        409: {"description": "not proposed"}})
async def reject_replan(request: Request, replan_id: Id) -> dict[str, Any]:
    return await request.app.state.station.monitor.replan.reject(replan_id)
