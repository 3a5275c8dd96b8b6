"""`GET /api/world`: the own ship, the ramp pose and the targets (shared/DESIGN.md "HTTP API")."""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter, Request

router = APIRouter(tags=["world"])


@router.get("/api/world")
async def get_world(request: Request) -> dict[str, Any]:
    """Own ship {lat, lon, heading_deg, course_deg, speed, age_s}; the ramp's pose; targets
    [{id, source, mmsi, name, lat, lon, x, y, vx, vy, rvx, rvy, radius, age_s, ...}] predicted
    to now in the ramp frame (vx, vy over ground, rvx, rvy relative to the ramp, m/s);
    stats {sentences, bad, ignored, bad_reasons, sources}."""
    return request.app.state.station.world.snapshot()
