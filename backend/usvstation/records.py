"""The station's records as they are stored, served and published on the websocket.

Each is a TypedDict: at run time the plain JSON object the store writes and the API and the
live hub send, for a reader and a type checker the exact keys and types. The services build
them, the store keeps them, api/models.py declares the same shapes as response models for
the OpenAPI document. Units are SI, degrees end in `_deg`, times are ISO 8601 UTC strings
(`time`, `created_at`, ...) or seconds of boat time (`boat_time`).
"""

from __future__ import annotations

from typing import (
    Literal,
    NotRequired,  # pydantic reads these on 3.11
)

from pydantic import ConfigDict, JsonValue, with_config
from typing_extensions import TypedDict

# A JSON document passed through whole (a scenario as the planner saw it): its schema is the
# Scenario model's (scenario/); the services never read inside it but for `name` and `origin`.
JsonObject = dict[str, JsonValue]

PlanStatus = Literal["queued", "running", "done", "failed", "cancelled"]


@with_config(ConfigDict(extra="allow"))  # planners add keys: kept
class Waypoint(TypedDict):
    """One timed waypoint of a plan, in the ramp frame (shared/DESIGN.md "Plan output")."""

    x: float
    y: float
    t: float
    speed: float
    heading_deg: float
    course_deg: NotRequired[float]


@with_config(ConfigDict(extra="allow"))  # planners add keys: kept
class PlanMetrics(TypedDict):
    """What every planner reports; the IGA adds its fitness terms (eqs. 10-14), others
    their own figures (tree length, iterations, ...)."""

    fitness: float | None  # the IGA's eq. 10 fitness; None for planners without one
    fit_d: NotRequired[float]
    fit_t: NotRequired[float]
    fit_mal: NotRequired[float]
    fit_ang: NotRequired[float]
    length_m: float
    duration_s: float
    min_clearance_m: float | None  # None when there is no obstacle
    collision_free: bool
    generations: int
    elapsed_s: float


@with_config(ConfigDict(extra="allow"))  # planners add keys: kept
class PlanDocument(TypedDict):
    """A planner's output; planners may add keys (a smoothed path, a history)."""

    planner: str
    scenario: str
    seed: int
    waypoints: list[Waypoint]
    metrics: PlanMetrics


class PlanJob(TypedDict):
    """A plan request and its result (the store's plans table, `GET /api/plans/{id}`)."""

    id: str
    created_at: str
    status: PlanStatus
    planner: str
    seed: int | None
    scenario: JsonObject
    plan: PlanDocument | None
    error: str | None
    # the working scenario the plan was asked against, a digest per top-level field (a plan
    # from the boat or from the live world changes the start, obstacles or current of it)
    basis: dict[str, str] | None


class PlanSummary(TypedDict):
    """A plan job without its documents (`GET /api/plans`, the websocket's `plan`)."""

    id: str
    status: PlanStatus
    created_at: str
    planner: str
    seed: int | None
    error: str | None
    scenario: str
    fitness: float | None


class PlansHealth(TypedDict):
    queued: int
    running: int
    workers: int
    workers_alive: int
    worker_pids: list[int]
    workers_replaced: int
    queue_max: int
    timeout_s: float


class WriterHealth(TypedDict):
    received: int
    committed: int
    queued: int
    dropped: int
    retries: int
    error: str | None


class LoopLag(TypedDict):
    worst_last_minute: float  # ms, worst event-loop lag of the last minute
    worst_since_start: float  # ms


class HeartbeatGap(TypedDict):
    """The boat link's own measure (on its own loop): the worst interval between two
    HEARTBEATs it wrote to the port (the schedule is 250 ms; the boat fails safe after 3 s)."""

    worst_last_minute: float  # ms
    worst_since_start: float  # ms
    heartbeats: int  # intervals measured
    late: list[tuple[str, float]]  # the latest intervals over 375 ms: (when, ms)


class StationHealth(TypedDict):
    """`GET /api/health`: open without a token, so no boat data."""

    version: NotRequired[str]
    status: Literal["ok", "degraded"]
    reasons: list[str]
    telemetry_writer: WriterHealth
    plans: PlansHealth
    websocket_clients: int
    link_up: bool
    loop_lag_ms: LoopLag
    link_heartbeat_gap_ms: HeartbeatGap
    link_on_own_loop: bool  # serve: the link runs on a thread and loop of its own
    link_nice: int | None  # that thread's raised priority (nice), None when not allowed
    viser_port: NotRequired[int | None]


class TelemetryRow(TypedDict):
    """One position report as stored (the `telemetry` table) and published."""

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


class StoredTelemetryRow(TelemetryRow):
    """A telemetry row read back: `id` orders the rows and is the paging cursor."""

    id: int


class StatusText(TypedDict):
    """A STATUSTEXT the boat sent."""

    time: str
    severity: str
    text: str


class LinkStatus(TypedDict):
    """The link's part of `GET /api/boat` (only `up`, `device` and `simulated` while no
    link exists)."""

    up: bool
    device: str
    simulated: NotRequired[bool]
    signed: NotRequired[bool]
    warning: NotRequired[str | None]
    boat_id: NotRequired[int]
    station_id: NotRequired[int]
    session: NotRequired[int | None]
    heartbeat_age_s: NotRequired[float | None]
    telemetry_age_s: NotRequired[float | None]
    frames: NotRequired[int]
    other_systems: NotRequired[dict[str, int]]
    refused: NotRequired[dict[str, int]]
    frames_bad: NotRequired[int]
    frames_lost: NotRequired[int]
    rtt_s: NotRequired[float | None]
    error: NotRequired[str | None]
    protocol: NotRequired[str]  # "standard": a stock autopilot (usv-link 2 otherwise)
    profile: NotRequired[str]
    vehicle_mode: NotRequired[str | None]
    armed: NotRequired[bool]
    duplicate: NotRequired[DuplicateBoat | None]


class DuplicateBoat(TypedDict):
    """Two boats answer as the paired boat id: their boot ids alternate in its reports."""

    boot_ids: list[int]  # every boot id heard in the last minute, the first one first
    detected_at: str  # ISO 8601 UTC
    switches: int  # changes of boot id in the last minute


class BoatState(TypedDict):
    """The boat's latest USV_MISSION_STATE as it reported it."""

    state: str
    mission_id: int
    mission_crc32: int
    uptime_s: float
    boot_id: int
    staging: int
    staged_id: int
    swap_at_ms: int
    rejected: int


class Progress(TypedDict):
    sent: int
    acked: int
    total: int


class MissionView(TypedDict):
    """A mission as `GET /api/missions/{id}` and the websocket's `mission` show it."""

    id: str
    plan_id: str
    state: str
    progress: Progress
    error: str | None
    created_at: str
    wire_id: int
    crc32: int | None
    run: int | None


class RampOrigin(TypedDict):
    """Where the ramp frame sits on the chart (a scenario's `origin`)."""

    lat: float
    lon: float
    ramp_bearing_deg: float


class MissionRow(TypedDict):
    """A mission as the store keeps it (its items as sent, to verify and restart)."""

    id: str
    plan_id: str
    wire_id: int
    created_at: str
    state: str
    progress: Progress
    error: str | None
    run: int | None
    origin: RampOrigin
    items: list[dict[str, int]]


class BoatSnapshot(TypedDict):
    """`GET /api/boat`: the link, the boat's word, its latest telemetry and texts, the run
    and the mission in hand."""

    link: LinkStatus
    boat: BoatState | None
    telemetry: TelemetryRow | None
    status: list[StatusText]
    run: NotRequired[int | None]
    mission: NotRequired[MissionView | None]


class ItemDifference(TypedDict):
    seq: int
    sent: dict[str, int]
    boat: dict[str, int]


class Readback(TypedDict):
    """`GET /api/missions/{id}/verify`: the boat's copy against what was sent."""

    id: str
    wire_id: int
    count: int
    identical: bool
    differences: list[ItemDifference]


class CommandAnswer(TypedDict):
    """The boat's answer to a command (`POST /api/boat/command`)."""

    command: str
    result: str
    reason: str | None
    state: str | None
    mission: str | None


class RunRow(TypedDict):
    id: int
    mission_id: str | None
    plan_id: str | None
    started_at: str
    ended_at: str | None
    state: str
    points: int


class RunEvent(TypedDict):
    """The websocket's `run`: a run opened (`active`) or ended (its final state)."""

    id: int
    mission: str
    state: str


class RoutePoint(TypedDict):
    """A planned waypoint placed on the map (exports)."""

    index: int
    lat: float
    lon: float
    t: float
    speed: float
    heading_deg: float


AlertLevel = Literal["advisory", "caution", "warning", "alarm"]


class Alert(TypedDict):
    """One alert: one cause (kind, target) of one run (or of the station: own ship, link),
    changed in place as its level changes, `active` until its condition ends."""

    id: str
    time: str  # first raised
    level: AlertLevel
    kind: str
    message: str
    target_id: str | None
    run_id: int | None
    acknowledged: bool
    active: bool
    updated_at: str  # the last change of level, message or state
    announced_at: str  # the last time it asked for attention (a new alert or a rise)
    ended_at: str | None


class TargetAssessment(TypedDict):
    id: str
    min_clearance_m: float
    t_min_s: float
    dcpa_m: float
    tcpa_s: float
    encounter: str
    known: bool  # the running plan was made around it
    moving: bool  # it makes way over ground


class MonitorAssessment(TypedDict):
    """The monitor's latest look at the running plan (websocket `monitor`)."""

    run: int | None
    plan_time_s: float
    slip_s: float
    cross_track_m: float
    min_clearance_m: float | None
    targets: list[TargetAssessment]
    path: list[list[float]]
    levels: dict[str, int]  # "kind" or "kind:target" -> level index in world/monitor.LEVELS
    margin_m: float  # the hull clearance the plan keeps: half the hull + R_c (eq. 7)


class MonitorView(TypedDict):
    """`GET /api/monitor`."""

    policy: str
    run: int | None
    frames: int
    assessment: MonitorAssessment | None


ReplanState = Literal["planning", "proposed", "planned", "applied", "rejected", "failed"]


class Replan(TypedDict):
    """A re-plan and its fate (`GET /api/replans`, the websocket's `replan`)."""

    id: str
    created_at: str
    run_id: int | None
    alert_id: str
    plan_id: str | None
    policy: str
    state: ReplanState
    error: str | None
    latency_ms: float | None
    mission_id: str | None
    dropped_targets: list[str]
    swap_at_ms: NotRequired[int]
    attempts: NotRequired[int]
    proposed_plan_id: NotRequired[str | None]


class OwnShip(TypedDict):
    """The mother ship as its sensors report it, predicted to the snapshot's instant."""

    lat: float
    lon: float
    heading_deg: float | None
    course_deg: float | None
    speed: float | None
    age_s: float
    stale: bool  # no fix for more than world.model.OWN_SHIP_STALE_S: dead-reckoned
    jump_m: float | None  # the last fix that jumped further than the speed allows
    jump_age_s: float | None  # how long ago


class RampPose(TypedDict):
    """The ramp's pose: on the moving ship (`own_ship`) or the scenario's fixed origin."""

    lat: float
    lon: float
    ramp_bearing_deg: float
    vx: float
    vy: float
    speed: float
    course_deg: float
    source: Literal["own_ship", "origin"]
    stale: bool  # from an own ship without a fix for a while: dead-reckoned


class ShipShape(TypedDict):
    """The mother ship as the console draws it, in the ramp frame (the ship-fixed frame)."""

    length: float
    beam: float | None
    ramp_width: float
    outline: list[list[float]] | None  # the hull polygon (scenario/hull.py), None: no shape
    reference: list[float]  # the ship's position reference (GNSS antenna), [x, y]


class Target(TypedDict):
    """A track of the world model; x, y, velocities in the ramp frame (rvx, rvy relative
    to the ramp, vx, vy over ground)."""

    id: str
    source: str
    mmsi: int | None
    name: str | None
    lat: float
    lon: float
    x: float
    y: float
    vx: float
    vy: float
    rvx: float
    rvy: float
    radius: float
    age_s: float
    speed: float
    course_deg: float
    heading_deg: float | None
    length: float | None
    ais_class: str | None  # "A" or "B" for AIS targets
    lost: bool  # silent for more than world.model.LOST_AFTER_S


class InputSource(TypedDict):
    url: str
    state: str
    port: int | None


class InputStats(TypedDict):
    sentences: int
    bad: int
    ignored: int
    bad_reasons: dict[str, int]
    sources: list[InputSource]


class WorldSnapshot(TypedDict):
    """`GET /api/world` and the websocket's `world`."""

    time: str
    own_ship: OwnShip | None
    ramp: RampPose | None
    ship: ShipShape | None  # the working scenario's mother ship, if it has one
    targets: list[Target]
    stats: InputStats


class WorldScenario(TypedDict):
    """`GET /api/world/scenario`: the working scenario against the live world."""

    scenario: JsonObject
    dropped: list[str]
