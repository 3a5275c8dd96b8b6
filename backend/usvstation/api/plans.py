"""`/api/plans`: plan jobs (submit, list, read, cancel)."""

from __future__ import annotations

from fastapi import APIRouter

from usvstation.api.deps import Auth, Read, StationDep, found
from usvstation.api.models import (
    Accepted,
    PlanJob,
    PlanRequest,
    PlanSummary,
)
from usvstation.services.plans import (
    scenario_from_boat,
)

router = APIRouter()


@router.post("/api/plans", status_code=202, tags=["plans"], dependencies=Auth,
          responses={429: {"description": "the plan queue is full (Retry-After)"}})
async def post_plan(station: StationDep, req: PlanRequest | None = None) -> Accepted:
    req = req or PlanRequest()
    working = await station.working_scenario()
    scenario = req.scenario or working
    if req.from_boat:
        handler = station.boat.handler
        scenario = scenario_from_boat(scenario, handler and handler.telemetry,
                                      handler and handler.run_t0)
    scenario = scenario.with_budget(req.time_budget_s, req.max_evaluations)
    # the working scenario, or one made from it (from the boat, /api/world/scenario): its
    # plan stays uploadable until the working scenario itself changes
    basis = working if scenario.name == working.name else None
    job = await station.plans.submit(scenario, req.planner, req.seed, basis)
    return Accepted(id=job["id"], status=job["status"])


@router.get("/api/plans", tags=["plans"], dependencies=Read)
async def list_plans(station: StationDep) -> list[PlanSummary]:
    return [station.plans.summary(j) for j in station.plans.jobs.values()]


@router.delete("/api/plans/{plan_id}", tags=["plans"], dependencies=Auth,
            responses={404: {"description": "no such plan"},
                       409: {"description": "the plan already ended"}})
async def cancel_plan(station: StationDep, plan_id: str) -> PlanSummary:
    """Cancel a queued or running plan: it ends `cancelled`, its worker is replaced."""
    job = await station.plans.cancel(plan_id)
    return station.plans.summary(found(job, f"plan {plan_id!r}"))


@router.get("/api/plans/{plan_id}", tags=["plans"], dependencies=Read)
async def get_plan(station: StationDep, plan_id: str) -> PlanJob:
    return found(station.plans.get(plan_id), f"plan {plan_id!r}")
