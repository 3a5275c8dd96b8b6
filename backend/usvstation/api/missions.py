"""`/api/missions` and `/api/boat`: uploads, readback, commands, the boat's state."""

from __future__ import annotations

from fastapi import (
    APIRouter,
    HTTPException,
)

from usvstation.api.deps import Auth, Read, StationDep, found
from usvstation.api.models import (
    CommandRequest,
    MissionRequest,
)
from usvstation.records import BoatSnapshot, CommandAnswer, MissionView, Readback
from usvstation.services.plans import (
    outdated_by,
)

router = APIRouter()


@router.post("/api/missions", status_code=202, tags=["boat"], dependencies=Auth,
          responses={409: {"description": "plan not done, no origin, or a mission running"},
                     503: {"description": "the boat link is down"}})
async def post_mission(station: StationDep, req: MissionRequest) -> MissionView:
    job = station.plans.get(req.plan_id)
    if job is not None:  # a plan of the working scenario, which changed since: refused
        changed = outdated_by(job, await station.working_scenario())
        if changed:
            raise HTTPException(409, detail=(
                f"plan {req.plan_id} was made for scenario {job['scenario']['name']!r} as it "
                f"was before it changed ({', '.join(changed)}): plan again"))
    return await station.boat.create_mission(req.plan_id)


@router.get("/api/missions", tags=["boat"], dependencies=Read)
async def list_missions(station: StationDep) -> list[MissionView]:
    return [rec.public() for rec in station.boat.missions.values()]


@router.get("/api/missions/{mission_id}", tags=["boat"], dependencies=Read)
async def get_mission(station: StationDep, mission_id: str) -> MissionView:
    return found(station.boat.get_mission(mission_id), f"mission {mission_id!r}")


@router.get("/api/missions/{mission_id}/verify", tags=["boat"], dependencies=Read,
         responses={404: {"description": "no such mission"},
                    409: {"description": "the boat does not hold it"},
                    503: {"description": "the boat link is down"},
                    504: {"description": "the boat did not answer the readback"}})
async def verify_mission(station: StationDep, mission_id: str) -> Readback:
    """Read the boat's copy back and compare it item by item."""
    return await station.boat.verify(mission_id)


@router.post("/api/boat/command", tags=["boat"], dependencies=Auth,
          responses={409: {"description": "no verified mission, or the boat refused"},
                     503: {"description": "the boat link is down"},
                     504: {"description": "the boat did not acknowledge in time"}})
async def boat_command(station: StationDep, req: CommandRequest) -> CommandAnswer:
    return await station.boat.command(req.command, req.mission_id)


@router.get("/api/boat", tags=["boat"], dependencies=Read)
async def boat(station: StationDep) -> BoatSnapshot:
    return station.boat.snapshot()
