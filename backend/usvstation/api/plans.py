"""`/api/plans`: plan jobs (submit, list, read, cancel)."""

from __future__ import annotations

from fastapi import (
    APIRouter,
    HTTPException,
)

from usvstation.api.deps import Auth, Read, StationDep, found
from usvstation.api.models import (
    Accepted,
    PlanJob,
    PlanRequest,
    PlanSummary,
)
from usvstation.services.plans import (
    PlanNotCancellable,
    PlanQueueFull,
    scenario_from_boat,
)

PLAN_RETRY_AFTER_S = 5


router = APIRouter()


@router.post("/api/plans", status_code=202, tags=["plans"], dependencies=Auth,
          responses={429: {"description": "the plan queue is full (Retry-After)"}})
async def post_plan(station: StationDep, req: PlanRequest | None = None) -> Accepted:
    req = req or PlanRequest()
    scenario = req.scenario or await station.working_scenario()
    if req.from_boat:
        try:
            handler = station.boat.handler
            scenario = scenario_from_boat(scenario, handler and handler.telemetry,
                                          handler and handler.run_t0)
        except ValueError as exc:
            raise HTTPException(409, detail=str(exc)) from None
    scenario = scenario.with_budget(req.time_budget_s, req.max_evaluations)
    try:
        job = await station.plans.submit(scenario, req.planner, req.seed)
    except PlanQueueFull as exc:
        raise HTTPException(429, detail=str(exc),
                            headers={"Retry-After": str(PLAN_RETRY_AFTER_S)}) from None
    return Accepted(id=job["id"], status=job["status"])


@router.get("/api/plans", tags=["plans"], dependencies=Read)
async def list_plans(station: StationDep) -> list[PlanSummary]:
    return [station.plans.summary(j) for j in station.plans.jobs.values()]


@router.delete("/api/plans/{plan_id}", tags=["plans"], dependencies=Auth,
            responses={404: {"description": "no such plan"},
                       409: {"description": "the plan already ended"}})
async def cancel_plan(station: StationDep, plan_id: str) -> PlanSummary:
    """Cancel a queued or running plan: it ends `cancelled`, its worker is replaced."""
    try:
        job = await station.plans.cancel(plan_id)
    except PlanNotCancellable as exc:
        raise HTTPException(409, detail=str(exc)) from None
    return station.plans.summary(found(job, f"plan {plan_id!r}"))


@router.get("/api/plans/{plan_id}", tags=["plans"], dependencies=Read)
async def get_plan(station: StationDep, plan_id: str) -> PlanJob:
    return found(station.plans.get(plan_id), f"plan {plan_id!r}")
