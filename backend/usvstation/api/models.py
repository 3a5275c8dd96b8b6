"""The request and response models of the HTTP API (its OpenAPI schemas)."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

from usvstation.api.planners import PlannerName
from usvstation.records import (  # the response shapes are the station's records
    PlanJob,
    PlanSummary,
    RunRow,
    StationHealth,
    StoredTelemetryRow,
)
from usvstation.scenario import Scenario

__all__ = ["Accepted", "CommandRequest", "MissionRequest", "PlanJob", "PlanRequest",
           "PlanSummary", "RunRow", "StationHealth", "StoredTelemetryRow"]


class PlanRequest(BaseModel):
    """Plan a scenario (default: the working scenario) with a planner and seed."""

    model_config = ConfigDict(extra="forbid")
    scenario: Scenario | None = None
    planner: PlannerName = "iga"
    seed: int | None = Field(None, ge=0, le=2**31 - 1)
    from_boat: bool = Field(
        False, description="plan from the boat's latest telemetry (position, heading, speed), "
        "obstacles propagated to that instant of the running mission",
    )
    time_budget_s: float | None = Field(
        None, gt=0.0, le=600.0, description="wall-clock safety net of this plan, s (default: "
        "the scenario's planner.time_budget_s, else 5)")
    max_evaluations: int | None = Field(
        None, ge=1, le=50_000_000, description="deterministic budget of this plan: candidate "
        "paths evaluated (default: the scenario's planner.max_evaluations, else the planner's)")


class Accepted(BaseModel):
    id: str
    status: str


class MissionRequest(BaseModel):
    """Upload a finished plan to the boat."""

    model_config = ConfigDict(extra="forbid")
    plan_id: str = Field(min_length=1, max_length=64)


class CommandRequest(BaseModel):
    """A boat command; START needs a verified mission, ABORT stops the propellers."""

    model_config = ConfigDict(extra="forbid")
    command: Literal["start", "hold", "resume", "abort"]
    mission_id: str | None = Field(None, min_length=1, max_length=64,
                                   description="START: the mission to start (required)")
