"""Alerts: `GET /api/alerts` (newest last) and `POST /api/alerts/{id}/ack` (operator)."""

from __future__ import annotations

from dataclasses import asdict
from typing import Annotated

from fastapi import APIRouter, Depends, HTTPException, Path, Request
from pydantic import BaseModel

from usvstation.api.auth import require_token
from usvstation.services.alerts import Level

router = APIRouter(tags=["alerts"])


class AlertOut(BaseModel):
    id: int
    time: str
    level: Level
    kind: str
    message: str
    target_id: str | None
    run_id: int | None
    acknowledged: bool


@router.get("/api/alerts")
async def list_alerts(request: Request) -> list[AlertOut]:
    return [AlertOut(**asdict(a)) for a in request.app.state.station.alerts.alerts]


@router.post("/api/alerts/{alert_id}/ack", dependencies=[Depends(require_token)])
async def ack_alert(request: Request,
                    alert_id: Annotated[int, Path(ge=1, le=2**63 - 1)]) -> AlertOut:
    alert = request.app.state.station.alerts.acknowledge(alert_id)
    if alert is None:
        raise HTTPException(404, detail=f"no alert {alert_id}")
    return AlertOut(**asdict(alert))
