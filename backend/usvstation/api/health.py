"""`GET /api/health`: open without a token, no boat data."""

from __future__ import annotations

from typing import Any

from fastapi import (
    APIRouter,
)

from usvstation import __version__
from usvstation.api.deps import StationDep
from usvstation.api.models import (
    Health,
)

router = APIRouter()


@router.get("/api/health", tags=["station"], response_model=Health)
async def health(station: StationDep) -> dict[str, Any]:
    return {"version": __version__, **station.health(), "viser_port": station.view.port}
