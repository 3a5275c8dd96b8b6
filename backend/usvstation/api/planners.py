"""`GET /api/planners`: the planners the station offers (planning.registry)."""

from __future__ import annotations

from typing import Annotated, Any

from fastapi import APIRouter
from pydantic import AfterValidator, BaseModel

from usvstation.planning.registry import describe_planners, planner_names


def _known_planner(name: str) -> str:
    if name not in planner_names():
        raise ValueError(f"unknown planner {name!r}; available: {', '.join(planner_names())}")
    return name


PlannerName = Annotated[str, AfterValidator(_known_planner)]


class PlannerDescription(BaseModel):
    """One planner: registry name, seed paper (000-004), title and capabilities."""

    name: str
    paper: str
    title: str
    capabilities: list[str]


def planners_router(dependencies: list[Any] | None = None) -> APIRouter:
    """The router; `dependencies` carries the read-token check of the app (viewer or operator)."""
    router = APIRouter(dependencies=dependencies or [])

    @router.get("/api/planners", tags=["plans"])
    async def list_planners() -> list[PlannerDescription]:
        return [PlannerDescription(**p) for p in describe_planners()]

    return router
