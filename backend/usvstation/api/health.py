"""`GET /api/health`: open without a token, no boat data."""

from __future__ import annotations

from fastapi import (
    APIRouter,
)

from usvstation import __version__
from usvstation.api.deps import StationDep
from usvstation.api.models import (
    StationHealth,
)

router = APIRouter()


@router.get("/api/health", tags=["station"])
async def health(station: StationDep) -> StationHealth:
    return {"version": __version__, **station.health(), "viser_port": station.view.port}
