"""`usv-station bench live`: the live loop on seeded episodes of the simulated sea.

Each episode: the mother ship under way at 1-2 m/s with a stern ramp; in its ship-fixed
ramp frame the water flows past at -V_ship, and the plan is made for that apparent
current. The boat is the simulated boat of `serve` (sim/boat.py BoatProtocol driving the
3-DOF Otter with compensated AV-LOS, sim/dynamic.py) on the far end of usv-link 2 from
the station's StationProtocol, both on one simulated clock over a lossless in-memory line
(`LinkedBoat`): it sails still water over ground and tracks its plan in the moving ramp
frame from the station's USV_RAMP_POSE stream; the plan is uploaded, started and every
re-plan hot-swapped over the signed link. One vessel, scripted after the plan was made,
turns (and changes speed) at t_m so that, kept to, it meets the boat on its planned path
at t_p. The station's plan
monitor (world/monitor.py) runs on every position report the boat sends (5 Hz; the ramp
pose and the traffic are the truth: perfect own-ship and AIS input); under policy `auto`
every warning re-plans (world/replan.py, the station's IGA in this process) from the
boat's predicted state SWAP_LEAD_S (2 s) ahead: the boat sails on for the measured
planning time, then the plan is uploaded as a hot swap at that instant; an instant that
passed during planning and upload is denied by the boat and the old plan runs on (a
failure). Under `off` the boat keeps its plan.

Figures per policy: `contacts` (episodes with hull contact, true clearance <= 0),
`margin_violations` (true clearance below the compensation radius R_c), the minimum true
clearance, `arrival_ok_share` (within 2 m and 5 degrees of the moving ramp at arrival),
re-plans and their latency (warning to the boat's acceptance of the swap: planning wall
time plus the upload's simulated link time).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from usvstation.clock import Stopwatch
from usvstation.dynamics import Environment
from usvstation.geo import RampFrame
from usvstation.geometry import MS
from usvstation.link.mission import mission_from_plan
from usvstation.link.protocol import (
    LinkConfig,
    RampPoseSample,
    StationProtocol,
    Telemetry,
    TelemetryReceived,
    UploadResult,
)
from usvstation.planning.errors import NoFeasiblePlan
from usvstation.planning.plan import plan_scenario
from usvstation.scenario import Scenario, parse_scenario
from usvstation.sim.boat import S_RUNNING, BoatConfig, BoatProtocol
from usvstation.sim.dynamic import DynamicVehicle
from usvstation.sim.frame import RampMotion
from usvstation.sim.sensors import GpsNoise
from usvstation.sim.vehicle import Waypoint
from usvstation.world.model import compass_to_enu
from usvstation.world.monitor import AlertTracker, BoatState, MonitorConfig, TargetState, assess
from usvstation.world.replan import ReplanImpossible, ReplanState, decide, replan_scenario

MONITOR_EVERY = 0.2  # s, the boat's telemetry rate (BoatConfig.telemetry_hz 5)
TIMEOUT_S = 60.0  # after the plan's end
ARRIVAL_OFFSET_M, ARRIVAL_HEADING_DEG = 2.0, 5.0


@dataclass(frozen=True)
class Traffic:
    """A target in the ship-fixed ramp frame: velocity v1 until t_m, then v2."""

    x0: float
    y0: float
    v1: tuple[float, float]
    v2: tuple[float, float]
    t_m: float
    radius: float

    def at(self, t: float) -> tuple[float, float, float, float]:
        t1 = min(t, self.t_m)
        x = self.x0 + self.v1[0] * t1 + self.v2[0] * max(0.0, t - self.t_m)
        y = self.y0 + self.v1[1] * t1 + self.v2[1] * max(0.0, t - self.t_m)
        v = self.v1 if t < self.t_m else self.v2
        return x, y, v[0], v[1]


def episode_scenario(rng: np.random.Generator, ship_speed: float) -> Scenario:
    return parse_scenario({
        "name": "live-episode", "origin": {"lat": 30.5, "lon": 122.0, "ramp_bearing_deg": 180.0},
        "start": {"x": float(rng.uniform(70, 90)), "y": float(rng.uniform(-15, 15)),
                  "heading_deg": 180.0, "speed": 0.5},
        # the boat that sails it: the Otter (2 m), planned at most 80 % of its 3.09 m/s top
        # speed through the water; the ship's way takes 1-2 m/s of that (issue 12's rule)
        "vessel": {"length": 2.0, "speed_min": 0.2, "speed_max": 2.47, "accel_max": 0.5,
                   "turn_max_deg": 60.0, "compensation_radius": 1.0},
        # the ship makes way along -x (the ramp points astern): water flows to +x past it
        "environment": {"current_speed": ship_speed, "current_dir_deg": 0.0},
    })


def make_traffic(rng: np.random.Generator, plan: dict[str, Any]) -> Traffic:
    """A vessel that, after turning at t_m, meets the planned boat at t_p (a collision)."""
    wps = plan["waypoints"]
    wt = np.array([w["t"] for w in wps])
    wx, wy = np.array([w["x"] for w in wps]), np.array([w["y"] for w in wps])
    end = float(wt[-1])
    t_p = float(rng.uniform(0.45, 0.7)) * end
    t_m = float(rng.uniform(0.15, 0.3)) * end
    px, py = float(np.interp(t_p, wt, wx)), float(np.interp(t_p, wt, wy))
    side = float(rng.choice([-1.0, 1.0]))
    dist = float(rng.uniform(18.0, 30.0))
    ang = math.radians(float(rng.uniform(-30.0, 30.0)))
    mx, my = px + dist * math.sin(ang), py + side * dist * math.cos(ang)  # beside the path
    v2 = ((px - mx) / (t_p - t_m), (py - my) / (t_p - t_m))
    turn = math.radians(float(rng.uniform(40.0, 70.0))) * float(rng.choice([-1.0, 1.0]))
    slow = float(rng.uniform(0.5, 1.0))  # a speed-up at the turn as well
    c, s = math.cos(turn), math.sin(turn)
    v1 = (slow * (c * v2[0] - s * v2[1]), slow * (s * v2[0] + c * v2[1]))
    return Traffic(mx - v1[0] * t_m, my - v1[1] * t_m, v1, v2, t_m,
                   float(rng.uniform(1.5, 3.0)))


def to_waypoints(plan: dict[str, Any]) -> list[Waypoint]:
    return [Waypoint(w["x"], w["y"], w["t"], w["speed"], math.radians(w["heading_deg"]))
            for w in plan["waypoints"]]


LINK_DT = 0.02  # s, the in-memory line's step (both sides polled, frames delivered whole)
POSE_PERIOD_S = 0.25  # the station's world hands the link a fresh ramp pose this often
SWAP_LEAD_S = 2.0  # the re-plan starts, and the boat swaps, this long after the warning
KEY = bytes(range(1, 33))  # the bench link's signing key
UNIX0 = 1.7e9


class LinkedBoat:
    """The simulated boat (BoatProtocol + DynamicVehicle in still water) and the station's
    StationProtocol on a lossless in-memory line with one simulated clock (boat time = link
    time): missions, START and the hot swap go over usv-link 2, signed, and the station
    streams the ramp pose of the ship under way (its truth: perfect own-ship input)."""

    def __init__(self, scenario: Scenario, ship_speed: float) -> None:
        o = scenario.origin
        assert o is not None
        self.frame = RampFrame(o.lat, o.lon, o.ramp_bearing_deg)
        self.ship_speed = ship_speed
        self.truth = RampMotion(vx=-ship_speed)  # the ramp frame (the sea's at t = 0) moves
        start = scenario.start
        # the boat kept station on the ship before: it starts relative to the moving ramp
        self.vehicle = DynamicVehicle(start.x, start.y, math.radians(start.heading_deg),
                                      speed=start.speed, env=Environment.with_current(0, 0),
                                      accel=scenario.vessel.accel_max, frame=self.truth)
        self.boat = BoatProtocol(self.vehicle, self.frame, BoatConfig(), key=KEY,
                                 gps=GpsNoise(bias_std_m=0.0, white_std_m=0.0), now=0.0,
                                 unix_time=UNIX0, boot_id=1)
        self.station = StationProtocol(LinkConfig(), 0.0, key=KEY, unix_time=UNIX0, session=1)
        ve, vn = self.frame.ramp_to_enu(-ship_speed, 0.0)
        self._v = (float(vn), float(ve))
        self.t = 0.0
        self.next_pose = 0.0
        self.mission_id = 0

    def step(self) -> list[Any]:
        self.t = t = self.t + LINK_DT
        if t >= self.next_pose:
            self.next_pose = t + POSE_PERIOD_S
            lat, lon = self.frame.to_geodetic(self.truth.at(t).x, 0.0)
            self.station.set_ramp_pose(RampPoseSample(t, float(lat), float(lon),
                                                      self.frame.ramp_bearing_deg, *self._v))
        self.boat.update(t)
        down = self.boat.data_to_send(t)
        events = self.station.receive_data(down, t) if down else self.station.poll(t)
        up = self.station.data_to_send()
        if up:
            self.boat.receive_data(up, t)
        return events

    def in_ramp(self) -> tuple[float, float, float]:
        """The boat's true ramp-frame x, y and heading (rad) now."""
        s = self.vehicle.state
        f = self.truth.at(self.t)
        x, y = f.to_ramp(s.x, s.y)
        return x, y, s.heading - f.theta

    def telemetry_state(self, tel: Telemetry, t0: float) -> BoatState:
        """What the station's monitor makes of a position report (the true ramp pose)."""
        f = self.truth.at(tel.time_s)
        x, y = self.frame.to_ramp(tel.lat, tel.lon)
        rx, ry = f.to_ramp(float(x), float(y))
        ve, vn = compass_to_enu(tel.speed, tel.course_deg)
        vx, vy = self.frame.vector_to_ramp(ve, vn)
        return BoatState(rx, ry, float(vx) - f.vx, float(vy) - f.vy, tel.time_s - t0,
                         float(self.frame.compass_to_heading_deg(tel.heading_deg)))

    def upload(self, plan: dict[str, Any], swap_at_ms: int = 0,
               on_step: Callable[[], None] | None = None) -> UploadResult:
        """Upload a plan (a hot swap at `swap_at_ms`); steps until the boat's answer."""
        self.mission_id += 1
        mission = mission_from_plan(plan["waypoints"], self.frame, self.mission_id)
        self.station.start_upload(mission, self.t, swap_at_ms)
        while True:
            for ev in self.step():
                if isinstance(ev, UploadResult) and ev.mission_id == mission.mission_id:
                    self.last_mission = mission
                    return ev
            if on_step is not None:
                on_step()

    def until(self, done: Callable[[], bool], limit_s: float, what: str) -> None:
        end = self.t + limit_s
        while not done():
            if self.t > end:
                raise RuntimeError(f"bench live: no {what} after {limit_s:g} s")
            self.step()


def run_episode(scenario: Scenario, plan: dict[str, Any], traffic: Traffic, policy: str,
                ship_speed: float) -> dict[str, Any]:
    v = scenario.vessel
    link = LinkedBoat(scenario, ship_speed)
    link.until(lambda: link.station.link_up and link.station.boat_uptime_ms(link.t)
               is not None and link.boat.ramp_poses > 0, 10.0, "link")
    if not link.upload(plan).ok:
        raise RuntimeError("bench live: the boat refused the initial mission")
    m = link.last_mission
    link.station.send_command("start", link.t, m.mission_id, m.crc)
    link.until(lambda: link.boat.state == S_RUNNING, 5.0, "start")
    t_start = t0 = link.boat.activations[-1][0]  # boat time of the plan's t = 0
    config = MonitorConfig(clearance_margin_m=v.length / 2 + v.compensation_radius,
                           clearance_warning_m=v.compensation_radius, time_margin_s=5.0)
    tracker, state = AlertTracker(config), ReplanState()
    waypoints = np.array([[w["x"], w["y"], w["t"]] for w in plan["waypoints"]])
    end = t0 + float(waypoints[-1, 2])
    min_clear = math.inf
    latencies: list[float] = []
    links: list[float] = []  # the upload's part of each latency (simulated link time)
    replans = failed = 0

    def truth() -> None:
        nonlocal min_clear
        x, y, _ = link.in_ramp()
        tx, ty, _, _ = traffic.at(link.t - t_start)
        min_clear = min(min_clear, math.hypot(x - tx, y - ty) - traffic.radius - v.length / 2)

    while not link.vehicle.state.mission_complete and link.t < end + TIMEOUT_S:
        events = link.step()
        truth()
        if policy == "off":
            continue
        for tel in (e.telemetry for e in events if isinstance(e, TelemetryReceived)):
            bs = link.telemetry_state(tel, t0)
            tx, ty, tvx, tvy = traffic.at(tel.time_s - t_start)
            targets = [TargetState("sim:1", tx, ty, tvx, tvy, traffic.radius)]
            a = assess(waypoints, bs, targets, v.length, config)
            for event in tracker.update(a):
                if not event.rose or decide("auto", event.level, event.kind, state,
                                            tel.time_s) != "apply":
                    continue
                state = ReplanState(last_t=tel.time_s)
                watch = Stopwatch()
                try:
                    problem, _ = replan_scenario(scenario, a, targets, max(math.hypot(
                        bs.vx, bs.vy), 0.5), lead_s=SWAP_LEAD_S, seed=replans + 1)
                    new = plan_scenario(problem).to_document()
                except (NoFeasiblePlan, ReplanImpossible, ValueError):
                    failed += 1
                    continue
                planning = watch.elapsed()
                for _ in range(max(1, round(planning / LINK_DT))):  # sails on meanwhile
                    link.step()
                    truth()
                t_up = link.t
                swap_at = tel.time_s + SWAP_LEAD_S
                result = link.upload(new, MS.to_wire(swap_at), truth)
                if not result.ok:  # the instant passed: the old plan runs on
                    failed += 1
                    continue
                latencies.append(planning + link.t - t_up)
                links.append(link.t - t_up)
                replans += 1
                waypoints = np.array([[w["x"], w["y"], w["t"]] for w in new["waypoints"]])
                t0, end = swap_at, swap_at + float(waypoints[-1, 2])
                tracker = AlertTracker(config)
                break
    x, y, heading = link.in_ramp()
    complete = link.vehicle.state.mission_complete
    heading_err = abs((math.degrees(heading) - 180.0 + 180.0) % 360.0 - 180.0)
    offset = math.hypot(x, y)
    return {"contact": min_clear <= 0.0, "violation": min_clear < v.compensation_radius,
            "min_clearance_m": min_clear, "arrived": complete,
            "arrival_ok": complete and offset <= ARRIVAL_OFFSET_M
            and heading_err <= ARRIVAL_HEADING_DEG,
            "arrival_offset_m": offset, "arrival_heading_err_deg": heading_err,
            "replans": replans, "replan_failures": failed, "latencies_ms":
            [1000 * x for x in latencies], "link_ms": [1000 * x for x in links]}


def summarise(rows: list[dict[str, Any]], with_latency: bool) -> dict[str, Any]:
    lat = [x for r in rows for x in r["latencies_ms"]]
    out = {
        "contacts": sum(r["contact"] for r in rows),
        "margin_violations": sum(r["violation"] for r in rows),
        "min_true_clearance_m": round(min(r["min_clearance_m"] for r in rows), 3),
        "arrival_ok_share": round(sum(r["arrival_ok"] for r in rows) / len(rows), 3),
        "arrived_share": round(sum(r["arrived"] for r in rows) / len(rows), 3),
        "arrival_offset_m_p95": round(float(np.percentile(
            [r["arrival_offset_m"] for r in rows], 95)), 3),
        "arrival_heading_err_deg_p95": round(float(np.percentile(
            [r["arrival_heading_err_deg"] for r in rows], 95)), 2),
        "replans": sum(r["replans"] for r in rows),
        "replan_failures": sum(r["replan_failures"] for r in rows),
    }
    if with_latency:
        link = [x for r in rows for x in r["link_ms"]]
        out["replan_p50_ms"] = round(float(np.percentile(lat, 50)), 1) if lat else None
        out["replan_p99_ms"] = round(float(np.percentile(lat, 99)), 1) if lat else None
        # of which the upload over the link (simulated time; the rest is planning, wall)
        out["replan_link_p99_ms"] = round(float(np.percentile(link, 99)), 1) if link else None
    return out


def run_live_bench(episodes: int = 50, seed: int = 1000,
                   progress: Callable[[str], None] | None = None) -> dict[str, Any]:
    rows: dict[str, list[dict[str, Any]]] = {"off": [], "auto": []}
    skipped = 0
    for k in range(episodes):
        rng = np.random.default_rng(seed + k)
        ship_speed = float(rng.uniform(1.0, 2.0))
        scenario = episode_scenario(rng, ship_speed)
        try:
            plan = plan_scenario(scenario, seed=1).to_document()
        except NoFeasiblePlan:
            skipped += 1
            continue
        traffic = make_traffic(rng, plan)
        for policy in rows:
            rows[policy].append(run_episode(scenario, plan, traffic, policy, ship_speed))
        if progress:
            progress(f"episode {k + 1}/{episodes}: off contact "
                     f"{rows['off'][-1]['contact']}, auto contact {rows['auto'][-1]['contact']}"
                     f" ({rows['auto'][-1]['replans']} re-plans)")
    return {
        "episodes": len(rows["off"]), "seeds": [seed, seed + episodes - 1],
        "skipped_no_initial_plan": skipped,
        "setup": {"mother_ship_speed_m_s": [1.0, 2.0], "boat": "otter 3-DOF, compensated "
                  "AV-LOS, still water, tracking in the moving ramp frame",
                  "monitor_hz": 1 / MONITOR_EVERY, "swap": "usv-link 2 hot swap "
                  "over a lossless in-memory line (the boat sails on for the measured "
                  "planning time, then the upload; swap 2 s after the warning)"},
        "policies": {"off": summarise(rows["off"], False),
                     "auto": summarise(rows["auto"], True)},
    }
