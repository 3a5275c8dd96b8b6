"""The request and response models of the HTTP API (its OpenAPI schemas)."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field

from usvstation.api.planners import PlannerName
from usvstation.scenario import Scenario


class TelemetryRow(BaseModel):
    """One stored telemetry frame (`id` orders the rows and is the paging cursor)."""

    id: int
    run: int | None
    time: str
    boat_time: float | None
    lat: float | None
    lon: float | None
    x: float | None
    y: float | None
    heading_deg: float | None
    course_deg: float | None
    speed: float | None
    ramp_heading_deg: float | None
    yaw_rate_dps: float | None
    fix_type: int | None
    satellites: int | None
    hdop: float | None
    thrust_left: float | None
    thrust_right: float | None
    battery_v: float | None
    waypoint_index: int | None
    cross_track_m: float | None
    state: str | None


class WriterHealth(BaseModel):
    received: int
    committed: int
    queued: int
    dropped: int
    retries: int
    error: str | None


class PlansHealth(BaseModel):
    queued: int
    running: int
    workers: int
    workers_alive: int
    worker_pids: list[int]
    workers_replaced: int
    queue_max: int
    timeout_s: float


class LoopLag(BaseModel):
    worst_last_minute: float = Field(description="ms, worst event-loop lag of the last minute")
    worst_since_start: float = Field(description="ms")


class Health(BaseModel):
    """Station health; no boat data (open without a token)."""

    version: str
    status: Literal["ok", "degraded"]
    reasons: list[str]
    telemetry_writer: WriterHealth
    plans: PlansHealth
    websocket_clients: int
    link_up: bool
    loop_lag_ms: LoopLag
    viser_port: int | None


class PlanSummary(BaseModel):
    id: str
    status: Literal["queued", "running", "done", "failed", "cancelled"]
    created_at: str
    planner: str
    seed: int | None
    error: str | None
    scenario: str
    fitness: float | None


class PlanJob(BaseModel):
    id: str
    status: Literal["queued", "running", "done", "failed", "cancelled"]
    plan: dict[str, Any] | None = Field(description="the plan (shared/DESIGN.md 'Plan output')")
    error: str | None
    created_at: str
    planner: str
    seed: int | None
    scenario: dict[str, Any]


class RunRow(BaseModel):
    id: int
    mission_id: str | None
    plan_id: str | None
    started_at: str
    ended_at: str | None
    state: str
    points: int


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
