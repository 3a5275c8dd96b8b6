"""One sea-trial episode: drawn from the spec's families, run end to end in simulated time,
judged on the truth.

The episode is the whole station (station.py, `in_process`) on a virtual-time loop
(clock.py): the simulated boat behind the signed link, the simulated sea on the world's
input, the monitor and its re-plan policy. An `Operator` drives it through the HTTP API as
the mate would (plan, upload, START, confirm re-plans, HOLD and RESUME); a `Judge` samples
the truth (the boat's true hull, the ships, the ramp) and decides the outcome:

- `contact`: the hull touched a ship or an obstacle, or reached the ramp outside the safe
  contact of ARRIVAL_SAFE_M / ARRIVAL_SAFE_DEG;
- `arrived`: the boat finished its mission on the ramp within that safe contact;
- `go_around`: it gave up an approach (mission state GO_AROUND) and did not arrive;
- `failsafe`: it went to FAILSAFE (link loss) and did not arrive;
- `aborted`: anything else (no plan, a refused upload, ABORT, the time limit).
"""

from __future__ import annotations

import math
import random
import shutil
import tempfile
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from usvstation.clock import SimClock, run_simulated
from usvstation.config import Settings
from usvstation.scenario import Scenario, load_scenario
from usvstation.station import Station
from usvstation.trial.spec import TrialSpec

ARRIVAL_SAFE_M = 0.5  # a ramp contact within this of the ramp end is safe (issue 24)
ARRIVAL_SAFE_DEG = 8.0
ARRIVAL_GOOD_M = 0.3  # the arrival criterion of the bench (issue 13)
ARRIVAL_GOOD_DEG = 5.0
JUDGE_DT = 0.1  # s of simulated time between the judge's samples
OPERATOR_DT = 0.5  # how often the mate looks at the console
CONFIRM_DELAY_S = 4.0  # the mate's reaction to a proposed re-plan (replan = confirm)
RESUME_EVERY_S = 5.0  # how often the mate tries RESUME on a boat that stopped on its own
MAX_APPROACHES = 3  # approaches the mate tries before aborting (the first plus two)
OTTER_LENGTH_M = 2.0  # the simulated boat (dynamics/params.py otter())
OTTER_PLAN_SPEED = 2.0  # m/s: the fastest a trial plans the Otter (top speed 3.09 m/s)
TURN_RATE_DEG_S = 2.0  # how fast the mother ship changes course
CRUISE_GUESS = 1.2  # m/s: where traffic is placed on the boat's way before the plan exists
TOKEN = "trial-operator-token-0123456789abcdef"
BOAT_STATES = ("IDLE", "READY", "RUNNING", "HOLD", "DONE", "ABORTED", "FAILSAFE", "GO_AROUND")


@dataclass(frozen=True)
class Conditions:
    """What one episode drew from the families (and the continuous draws they need)."""

    base: str
    mother_ship_speed: float
    mother_ship_turn_deg: float  # the ship's course change (deg, + to starboard) ...
    mother_ship_turn_s: float  # ... begun at this time of the sea (s), at TURN_RATE_DEG_S
    traffic: str
    current: str
    current_speed: float
    current_dir_deg: float
    current_change_s: float  # after START: when a step or reversal happens
    sea_state: int
    sensor: str  # the boat's sensor profile (sim/sensors.py)
    drag_scale: float  # the true hull against the model the boat was tuned on
    thrust_scale: float
    link_loss: tuple[float, float] | None  # (after START, duration) of radio silence
    operator_hold: tuple[float, float] | None  # (after START, duration) of HOLD


@dataclass(frozen=True)
class Episode:
    key: str
    index: int
    seed: int
    planner: str
    replan: str
    time_limit_s: float
    conditions: Conditions
    scenario: dict[str, Any]  # the scenario document the station starts with


def draw_episode(spec: TrialSpec, index: int) -> Episode:
    """Episode `index` of the spec: a function of (spec.seed, index) alone."""
    rng = np.random.default_rng([spec.seed, index])
    f = spec.families

    def pick(values: list) -> Any:
        return values[int(rng.integers(len(values)))]

    base = pick(spec.base)
    cond = Conditions(
        base=base, mother_ship_speed=float(pick(f.mother_ship_speed)),
        mother_ship_turn_deg=float(pick(f.mother_ship_turn_deg)),
        mother_ship_turn_s=round(float(rng.uniform(10.0, 40.0)), 1),
        traffic=pick(f.traffic), current=pick(f.current),
        current_speed=float(pick(f.current_speed)),
        current_dir_deg=round(float(rng.uniform(0.0, 360.0)), 1),
        current_change_s=round(float(rng.uniform(10.0, 30.0)), 1),
        sea_state=int(pick(f.sea_state)), sensor=pick(f.sensor),
        drag_scale=float(pick(f.drag_scale)), thrust_scale=float(pick(f.thrust_scale)),
        link_loss=_window(rng, (5.0, 25.0), (2.0, 6.0)) if pick(f.link_loss) == "burst" else None,
        operator_hold=(_window(rng, (5.0, 25.0), (5.0, 15.0))
                       if pick(f.operator_hold) == "hold" else None))
    scenario = trial_scenario(load_scenario(base), cond, rng)
    return Episode(key=f"{spec.name}|{spec.seed}|{index}", index=index, seed=spec.seed,
                   planner=spec.planner, replan=spec.replan, time_limit_s=spec.time_limit_s,
                   conditions=cond, scenario=scenario.model_dump(mode="json"))


def _window(rng: np.random.Generator, start: tuple[float, float],
            length: tuple[float, float]) -> tuple[float, float]:
    return (round(float(rng.uniform(*start)), 1), round(float(rng.uniform(*length)), 1))


def trial_scenario(base: Scenario, cond: Conditions, rng: np.random.Generator) -> Scenario:
    """The base scenario at sea: the mother ship under way (ramp astern), the drawn steady
    current and one ship of the drawn traffic family, placed on the boat's way."""
    if base.origin is None:
        raise ValueError(f"{base.name}: a trial scenario needs an origin")
    env = base.environment.model_copy(update={"current_speed": cond.current_speed,
                                              "current_dir_deg": cond.current_dir_deg})
    heading = (base.origin.ramp_bearing_deg - 180.0) % 360.0  # a stern ramp: +x astern
    mother: dict[str, Any] = {"speed": cond.mother_ship_speed, "course_deg": round(heading, 3),
                              "turn_rate_deg_s": TURN_RATE_DEG_S}
    if cond.mother_ship_turn_deg:
        mother["manoeuvres"] = [{"t": cond.mother_ship_turn_s, "course_deg": round(
            (heading + cond.mother_ship_turn_deg) % 360.0, 3)}]
    # the boat being recovered is the simulated Otter: the mate enters its length, and plans
    # at speeds it makes good with room for the current and the ship's way
    vessel = base.vessel.model_copy(update={
        "length": OTTER_LENGTH_M, "speed_max": min(base.vessel.speed_max, OTTER_PLAN_SPEED)})
    data = base.model_dump(mode="json")
    data.update(name=f"{base.name}-trial", environment=env.model_dump(mode="json"),
                vessel=vessel.model_dump(mode="json"), mother_ship=mother,
                traffic=_traffic(base, cond, rng))
    return Scenario(**data)


def _traffic(base: Scenario, cond: Conditions, rng: np.random.Generator) -> list[dict]:
    """One ship of the family, in the ship-fixed ramp frame: it meets the boat's straight way
    from the start to the ramp about half way (crossing, head-on), overtakes it, or turns
    onto it after the plan was made (turning)."""
    if cond.traffic == "none":
        return []
    sx, sy = base.start.x, base.start.y
    dist = math.hypot(sx, sy)
    ux, uy = sx / dist, sy / dist  # from the ramp out to the start
    side = 1.0 if rng.random() < 0.5 else -1.0
    nx, ny = -uy * side, ux * side  # across the way
    t_mid = 0.5 * dist / CRUISE_GUESS
    mx, my = 0.5 * sx, 0.5 * sy
    speed = float(rng.uniform(1.5, 3.0))
    legs: list[tuple[float, float, float]] = []  # (t, rvx, rvy) relative to the ramp
    if cond.traffic == "crossing":
        start = (mx - nx * speed * t_mid, my - ny * speed * t_mid)
        legs = [(0.0, nx * speed, ny * speed)]
    elif cond.traffic == "head_on":
        start = (mx + ux * speed * t_mid, my + uy * speed * t_mid)
        legs = [(0.0, -ux * speed, -uy * speed)]
    elif cond.traffic == "overtaking":
        start = (sx + ux * 30.0, sy + uy * 30.0)
        fast = CRUISE_GUESS + speed
        legs = [(0.0, -ux * fast, -uy * fast)]
    else:  # turning: sails beside the way, turns onto it after 5 s and stops on it
        off = 25.0
        start = (mx + nx * off - ux * 15.0, my + ny * off - uy * 15.0)
        legs = [(0.0, ux * 3.0, uy * 3.0), (5.0, -nx * 3.0, -ny * 3.0),
                (5.0 + off / 3.0, 0.0, 0.0)]
    ship_v = -cond.mother_ship_speed  # the ramp frame moves along -x with the ship
    frame = base.origin
    assert frame is not None
    manoeuvres = []
    first = None
    for t, rvx, rvy in legs:
        course, spd = _world_motion(frame.ramp_bearing_deg, rvx + ship_v, rvy)
        if first is None:
            first = (course, spd)
        else:
            manoeuvres.append({"t": round(t, 2), "course_deg": course, "speed": spd})
    assert first is not None
    return [{"mmsi": 211000301, "name": cond.traffic.upper()[:20],
             "start": {"x": round(start[0], 2), "y": round(start[1], 2)},
             "course_deg": first[0], "speed": first[1], "length": 8.0,
             "manoeuvres": manoeuvres}]


def _world_motion(ramp_bearing_deg: float, vx: float, vy: float) -> tuple[float, float]:
    """A ramp-frame velocity (ramp axes; +x at compass `ramp_bearing_deg`, +y to its left)
    as compass course and speed over ground."""
    speed = math.hypot(vx, vy)
    if speed < 1e-9:
        return 0.0, 0.0
    course = (ramp_bearing_deg - math.degrees(math.atan2(vy, vx))) % 360.0
    return round(course, 3), round(speed, 4)


# ----------------------------------------------------------------------------------- judge


@dataclass(frozen=True)
class RampPose:
    """The ramp frame in the vehicle's world plane: its origin and the anticlockwise angle
    of its +x axis."""

    x: float
    y: float
    theta: float

    def to_ramp(self, x: float, y: float) -> tuple[float, float]:
        """A world-plane point in this ramp frame."""
        c, s = math.cos(self.theta), math.sin(self.theta)
        dx, dy = x - self.x, y - self.y
        return c * dx + s * dy, -s * dx + c * dy


@dataclass
class Judge:
    """Samples the truth every JUDGE_DT: the boat's true hull against the ships, the
    obstacles and the ramp; the boat's own state for the outcome."""

    station: Station
    scenario: Scenario
    clock: SimClock
    min_clearance_m: float = math.inf
    closest: str | None = None  # the ship or obstacle of min_clearance_m
    states: list[str] = field(default_factory=list)
    arrival: tuple[float, float, float] | None = None  # (t, offset m, heading error deg)
    started_at: float | None = None

    def sample(self) -> None:
        sim = self.station.sim
        assert sim is not None and hasattr(sim, "boat")
        boat = sim.boat
        state = BOAT_STATES[boat.state] if boat.state < len(BOAT_STATES) else str(boat.state)
        if not self.states or self.states[-1] != state:
            self.states.append(state)
            if state == "RUNNING" and self.started_at is None:
                self.started_at = self.clock.now()
        truth = boat.vehicle.truth  # never what the boat measures
        ramp = self._ramp_pose()
        bx, by = ramp.to_ramp(truth.x, truth.y)  # the boat in the ship-fixed ramp frame
        true_hull = getattr(boat.vehicle, "true_params", None)
        half = (true_hull.length if true_hull is not None else self.scenario.vessel.length) / 2
        for ox, oy, radius, name in self._others(ramp):
            clearance = math.hypot(bx - ox, by - oy) - half - radius
            if clearance < self.min_clearance_m:
                self.min_clearance_m, self.closest = clearance, name
        if state == "DONE" and self.arrival is None:
            heading = math.degrees(truth.heading - ramp.theta)
            heading_err = abs((heading - 180.0 + 180.0) % 360.0 - 180.0)
            self.arrival = (self.clock.now(), math.hypot(bx, by), heading_err)

    def _sea_time(self) -> float:
        sea = self.station.world.sea
        return sea.now() if sea is not None else self.clock.now()

    def _ramp_pose(self) -> RampPose:
        """Where the ramp truly is in the vehicle's world plane (the scenario origin's ramp
        frame at t = 0): its end and the angle its +x axis has turned with the ship."""
        sea = self.station.world.sea
        if sea is None:
            return RampPose(0.0, 0.0, 0.0)
        t = sea.now()
        x, y = sea.model.frame0.enu_to_ramp(*sea.model.ramp_at(t))
        turned = sea.model.ramp_bearing_at(t) - sea.model.frame0.ramp_bearing_deg
        return RampPose(float(x), float(y), -math.radians(turned))  # compass is clockwise

    def _others(self, ramp: RampPose) -> list[tuple[float, float, float, str]]:
        """(x, y, radius, name) in the ship-fixed ramp frame of every ship and obstacle now: the
        ships of the simulated sea, and the scenario's obstacles as charted hazards (fixed
        over ground where the origin puts them at t = 0, moving with their own velocity),
        as the station's world model keeps them."""
        t = self._sea_time()
        out = []
        sea = self.station.world.sea
        if sea is not None:
            for ship, truth in zip(sea.model.traffic, sea.model.traffic_at(t), strict=True):
                x, y = sea.model.frame0.enu_to_ramp(truth.east, truth.north)
                out.append((*ramp.to_ramp(float(x), float(y)), ship.length / 2.0,
                            f"ship {ship.name or ship.mmsi}"))
        for i, o in enumerate(self.scenario.obstacles):
            out.append((*ramp.to_ramp(o.x + o.vx * t, o.y + o.vy * t), o.radius,
                        f"obstacles[{i}]"))
        return out

    def outcome(self) -> str:
        if self.min_clearance_m < 0.0:
            return "contact"
        if self.arrival is not None:
            _, off, head = self.arrival
            return "arrived" if off <= ARRIVAL_SAFE_M and head <= ARRIVAL_SAFE_DEG \
                else "contact"
        if "GO_AROUND" in self.states:
            return "go_around"
        if "FAILSAFE" in self.states:
            return "failsafe"
        return "aborted"


# -------------------------------------------------------------------------------- operator


class Operator:
    """The mate at the console, through the HTTP API only."""

    def __init__(self, client: Any, clock: SimClock, episode: Episode) -> None:
        self.c, self.clock, self.ep = client, clock, episode
        self.notes: list[str] = []
        self.confirmed: set[str] = set()
        self.planned_s: float | None = None  # the plan's duration
        self.approaches = 0  # go-arounds answered (a new approach, or at the last, ABORT)
        self.standby_seen: set[tuple[str, str]] = set()

    async def _wait(self, path: str, done: Any, limit_s: float) -> dict | None:
        """GET `path` every OPERATOR_DT until `done(body)`; None after `limit_s`."""
        until = self.clock.now() + limit_s
        while self.clock.now() < until:
            r = await self.c.get(path)
            if r.status_code == 200 and done(r.json()):
                return r.json()
            await self.clock.sleep(OPERATOR_DT)
        return None

    async def prepare(self) -> str | None:
        """Plan, upload and verify; the mission id, or None (the reason in notes)."""
        if await self._wait("/api/boat", lambda b: b["link"]["up"], 30.0) is None:
            self.notes.append("the link never came up")
            return None
        # planned against the live world, as the console offers: the ships on AIS and the
        # scenario's obstacles where they are now, the ship's way as an apparent current
        world = with_final_straight((await self.c.get("/api/world/scenario")).json()[
            "scenario"])
        r = await self.c.post("/api/plans", json={"planner": self.ep.planner, "seed": 1,
                                                  "scenario": world})
        job = await self._wait(f"/api/plans/{r.json()['id']}",
                               lambda j: j["status"] not in ("queued", "running"), 120.0)
        if job is None or job["status"] != "done":
            self.notes.append(f"no plan: {job and job['error']}")
            return None
        self.planned_s = float(job["plan"]["metrics"]["duration_s"])
        r = await self.c.post("/api/missions", json={"plan_id": job["id"]})
        if r.status_code != 202:
            self.notes.append(f"upload refused: {r.json()['detail']}")
            return None
        mission = await self._wait(f"/api/missions/{r.json()['id']}",
                                   lambda m: m["state"] not in ("uploading",), 60.0)
        if mission is None or mission["state"] != "verified":
            self.notes.append(f"upload failed: {mission and mission['error']}")
            return None
        return mission["id"]

    def at_standby(self, boat: dict[str, Any]) -> bool:
        """True once for every time the boat says it waits at its standby point (a new
        STATUSTEXT "go-around: at standby ...", told apart by its time)."""
        new = {(s["time"], s["text"]) for s in boat["status"] if "at standby" in s["text"]}
        fresh = bool(new - self.standby_seen)
        self.standby_seen |= new
        return fresh

    async def new_approach(self) -> bool:
        """The station's new approach for a boat at its standby point (`new_approach`), or
        the boat's own (RESUME) when the station has none; True when one began."""
        ok, note = await new_approach(self.c, self.clock, self.ep.planner)
        if ok:
            return True
        self.notes.append(note)
        return await self.command("resume")

    async def boat(self) -> dict[str, Any]:
        """GET /api/boat: what the console shows of the boat."""
        return (await self.c.get("/api/boat")).json()

    async def command(self, name: str, mission_id: str | None = None) -> bool:
        body: dict[str, Any] = {"command": name}
        if mission_id is not None:
            body["mission_id"] = mission_id
        r = await self.c.post("/api/boat/command", json=body)
        if r.status_code != 200:
            self.notes.append(f"{name.upper()} refused: {r.json()['detail']}")
        return r.status_code == 200

    async def confirm_replans(self, seen_at: dict[str, float]) -> None:
        """replan = confirm: accept each proposal CONFIRM_DELAY_S after it appears."""
        r = await self.c.get("/api/replans")
        for rec in r.json():
            if rec["state"] != "proposed" or rec["id"] in self.confirmed:
                continue
            first = seen_at.setdefault(rec["id"], self.clock.now())
            if self.clock.now() - first >= CONFIRM_DELAY_S:
                self.confirmed.add(rec["id"])
                await self.c.post(f"/api/replans/{rec['id']}/confirm")


def with_final_straight(scenario: dict[str, Any]) -> dict[str, Any]:
    """A recovery scenario document planned with the planner's final straight along the ramp
    axis (planner option `final_straight`, docs/planner.md): what the mate asks for."""
    return {**scenario, "planner": {**(scenario.get("planner") or {}), "final_straight": True}}


async def new_approach(client: Any, clock: SimClock, planner: str = "iga",
                       seed: int = 1) -> tuple[bool, str]:
    """The station's new approach for a boat that went around and keeps station at its
    standby point (protocol/README.md, GO_AROUND): a plan from where the boat is (its
    telemetry: ramp-frame position, heading, speed) against the live world
    (`GET /api/world/scenario`: the ships on AIS and the charted obstacles where they are
    now, the ship's way as an apparent current), with the planner's final straight along
    the ramp axis, uploaded with `POST /api/missions`, which
    the boat takes as a hot swap at its standby point. (True, mission id) once the boat
    flies it; else (False, why)."""

    async def until(path: str, done: Any, limit_s: float) -> dict | None:
        end = clock.now() + limit_s
        while clock.now() < end:
            r = await client.get(path)
            if r.status_code == 200 and done(r.json()):
                return r.json()
            await clock.sleep(OPERATOR_DT)
        return None

    row = (await client.get("/api/boat")).json()["telemetry"]
    if not row or row.get("x") is None or row.get("ramp_heading_deg") is None:
        return False, "new approach: no ramp-frame telemetry"
    world = with_final_straight((await client.get("/api/world/scenario")).json()["scenario"])
    world["start"] = {"x": row["x"], "y": row["y"], "speed": row["speed"],
                      "heading_deg": row["ramp_heading_deg"] % 360.0}
    r = await client.post("/api/plans", json={"planner": planner, "seed": seed,
                                              "scenario": world})
    if r.status_code != 202:
        return False, f"new approach: plan refused: {r.json()['detail']}"
    job = await until(f"/api/plans/{r.json()['id']}",
                      lambda j: j["status"] not in ("queued", "running"), 120.0)
    if job is None or job["status"] != "done":
        return False, f"new approach: no plan: {job and job['error']}"
    r = await client.post("/api/missions", json={"plan_id": job["id"]})
    if r.status_code != 202:
        return False, f"new approach: upload refused: {r.json()['detail']}"
    mission_id = r.json()["id"]
    flown = await until(f"/api/missions/{mission_id}",
                        lambda m: m["state"] not in ("uploading", "verified"), 60.0)
    if flown is None or flown["state"] != "active":
        return False, f"new approach: not taken: {flown and (flown['error'] or flown['state'])}"
    return True, mission_id


# --------------------------------------------------------------------------------- episode


def run_episode(ep: Episode) -> dict[str, Any]:
    """Run one episode in simulated time (a fresh station in a temporary data dir); the
    episode's JSON line."""
    folder = Path(tempfile.mkdtemp(prefix="usv-trial-"))
    try:
        return run_simulated(lambda clock: _episode(clock, ep, folder))
    finally:
        shutil.rmtree(folder, ignore_errors=True)


async def _episode(clock: SimClock, ep: Episode, folder: Path) -> dict[str, Any]:
    import asyncio

    import httpx

    from usvstation.api.app import create_app
    from usvstation.dynamics.params import HullMismatch
    from usvstation.sim.runner import make_vehicle

    cond = ep.conditions
    scenario = Scenario(**ep.scenario)
    settings = Settings(data_dir=folder, token=TOKEN, replan=ep.replan, link="sim",
                        nmea=[])
    station = Station(settings, clock, in_process=True, scenario=scenario,
                      entropy=random.Random(f"{ep.key}"))
    hull = HullMismatch(cond.drag_scale, cond.thrust_scale)
    station.sim_vehicle = lambda sc: make_vehicle(
        "dynamic", sc, sea_state=cond.sea_state, sensors=cond.sensor, hull=hull,
        seed=ep.seed * 100_003 + ep.index)
    alerts: list[str] = []
    station.hub.observers.append(
        lambda kind, data: alerts.append(str(data.get("kind"))) if kind == "alert" else None)
    await station.start()
    judge = Judge(station, scenario, clock)
    stop = asyncio.Event()

    async def sample() -> None:
        while not stop.is_set():
            judge.sample()
            await clock.sleep(JUDGE_DT)

    sampler = asyncio.get_running_loop().create_task(sample())
    transport = httpx.ASGITransport(app=create_app(station))
    headers = {"Authorization": f"Bearer {TOKEN}"}
    operator = None
    try:
        async with httpx.AsyncClient(transport=transport, base_url="http://127.0.0.1:8000",
                                     headers=headers, timeout=None) as client:
            operator = Operator(client, clock, ep)
            mission = await operator.prepare()
            if mission is not None and await operator.command("start", mission):
                await _sail(clock, station, operator, judge, ep)
    finally:
        stop.set()
        await sampler
        replans = list(station.monitor.replan.replans.values())
        await station.stop()
    return _line(ep, judge, operator, alerts, replans)


async def _sail(clock: SimClock, station: Station, operator: Operator, judge: Judge,
                ep: Episode) -> None:
    """From START until the boat ends its mission (or the time limit): the episode's scripted
    events (current change, radio silence, HOLD) and the mate's answers: confirm re-plans,
    and RESUME a boat that stopped on its own (FAILSAFE, or HOLD on a stale ramp pose) once
    the console shows the link up."""
    cond = ep.conditions
    t0 = clock.now()
    seen: dict[str, float] = {}
    current_changed = radio_off = held = resumed = False
    resumed_at = -math.inf
    sim = station.sim
    assert sim is not None and hasattr(sim, "boat")
    while clock.now() - t0 < ep.time_limit_s:
        t = clock.now() - t0
        if judge.states and judge.states[-1] in ("DONE", "ABORTED", "IDLE"):
            return
        if not current_changed and cond.current != "steady" and t >= cond.current_change_s:
            current_changed = True
            _change_current(sim.boat.vehicle, cond)
        if cond.link_loss is not None:
            on, length = cond.link_loss
            off_now = on <= t < on + length
            if off_now != radio_off:
                radio_off = off_now
                sim.radio.enabled = sim.uplink.enabled = not off_now
        holding_on_purpose = False
        if cond.operator_hold is not None:
            at, length = cond.operator_hold
            holding_on_purpose = held and not resumed
            if not held and t >= at:
                held = holding_on_purpose = await operator.command("hold")
            elif held and not resumed and t >= at + length:
                resumed = await operator.command("resume")
        boat = await operator.boat()
        state = boat["boat"]["state"] if boat["boat"] else None
        if state in ("HOLD", "FAILSAFE") and boat["link"]["up"] and not holding_on_purpose \
                and clock.now() - resumed_at >= RESUME_EVERY_S:
            resumed_at = clock.now()
            await operator.command("resume")
        elif state == "GO_AROUND" and operator.at_standby(boat):
            # the boat went around and waits at its standby point: the station offers a new
            # approach (planned from there against the live world); the mate takes it up to
            # MAX_APPROACHES times, then aborts
            operator.approaches += 1
            if operator.approaches < MAX_APPROACHES:
                await operator.new_approach()
            else:
                await operator.command("abort")
                return
        if ep.replan == "confirm":
            await operator.confirm_replans(seen)
        await clock.sleep(OPERATOR_DT)
    operator.notes.append(f"time limit of {ep.time_limit_s:g} s after START")


def _change_current(vehicle: Any, cond: Conditions) -> None:
    """A step (a new direction, 90 degrees on, at 1.5 x the speed) or a reversal of the
    water's current, which the plan did not know."""
    env = getattr(vehicle, "env", None)
    if env is None:
        return
    cx, cy = env.current
    if cond.current == "reversal":
        new = (-cx, -cy)
    else:
        speed = max(math.hypot(cx, cy) * 1.5, 0.2)
        angle = math.atan2(cy, cx) + math.pi / 2.0
        new = (speed * math.cos(angle), speed * math.sin(angle))
    vehicle.env = replace(env, current=new)


def _line(ep: Episode, judge: Judge, operator: Operator | None, alerts: list[str],
          replans: list[dict]) -> dict[str, Any]:
    """The episode's JSON line; `slip_s`: how much later than planned the boat arrived."""
    arrival = judge.arrival
    started = judge.started_at
    duration = slip = None
    if arrival is not None and started is not None:
        duration = round(arrival[0] - started, 2)
        if operator is not None and operator.planned_s is not None:
            slip = round(duration - operator.planned_s, 2)
    notes = operator.notes if operator is not None else []
    return {
        "key": ep.key, "index": ep.index, "seed": ep.seed, "outcome": judge.outcome(),
        "arrival_offset_m": None if arrival is None else round(arrival[1], 3),
        "arrival_heading_deg": None if arrival is None else round(arrival[2], 2),
        "within_0_3m_5deg": bool(arrival is not None and arrival[1] <= ARRIVAL_GOOD_M
                                 and arrival[2] <= ARRIVAL_GOOD_DEG),
        "min_hull_clearance_m": (None if math.isinf(judge.min_clearance_m)
                                 else round(judge.min_clearance_m, 3)),
        "closest": judge.closest,
        "alerts": len(alerts), "alert_kinds": sorted(set(alerts)),
        "go_arounds": judge.states.count("GO_AROUND"),
        "replans": len(replans),
        "replans_applied": sum(1 for r in replans if r["state"] == "applied"),
        "duration_s": duration, "slip_s": slip, "states": judge.states, "notes": notes,
        "conditions": {k: (list(v) if isinstance(v, tuple) else v)
                       for k, v in asdict(ep.conditions).items()},
    }
