"""`GET` and `PUT /api/scenario`: the working scenario."""

from __future__ import annotations

from fastapi import (
    APIRouter,
)

from usvstation.api.deps import Auth, Read, StationDep
from usvstation.scenario import Scenario

router = APIRouter()


@router.get("/api/scenario", tags=["scenario"], dependencies=Read)
async def get_scenario(station: StationDep) -> Scenario:
    return await station.working_scenario()


@router.put("/api/scenario", tags=["scenario"], dependencies=Auth)
async def put_scenario(station: StationDep, scenario: Scenario) -> Scenario:
    await station.set_working_scenario(scenario)
    return scenario
