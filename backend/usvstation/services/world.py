"""The live world: ship-input sources feeding the world model, `/api/world`, world events.

Lines from every `--nmea` source are decoded on the event loop (a sentence takes tens of
microseconds) and merged into the pure world model (world/model.py); at most
`PUBLISH_HZ` times a second a changed world goes out on the websocket as
{"type": "world", "data": <the /api/world body>}, and at least once a second while the
own ship is stale (its age and the dead-reckoned ramp move on). Silent tracks age out.
`tick_listeners` are called at every tick, changed or not (the own-ship alerts).

The ramp pose goes to `pose_listeners` `RAMP_POSE_HZ` times a second (the boat link's
USV_RAMP_POSE stream, link/protocol.py `set_ramp_pose`): the pose of the latest own-ship
fix, at that fix's instant; None while the ramp is the fixed scenario origin and nothing
was streamed yet (the shore trial: nothing to stream). Once streamed, a world without an
own-ship fix streams the fixed origin at rest, so the boat never keeps a stale moving frame.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
from collections.abc import Callable
from typing import Any

from usvstation.clock import REAL_CLOCK, Clock
from usvstation.geo import RampFrame
from usvstation.link.protocol import RampPoseSample
from usvstation.records import InputSource, ShipShape, Target, WorldSnapshot
from usvstation.scenario import Scenario
from usvstation.scenario.hull import hull_polygon
from usvstation.scenario.ships import LeverArm
from usvstation.services.hub import LiveHub
from usvstation.shipinputs.decode import SentenceDecoder, apply_reports
from usvstation.shipinputs.readers import Source, open_udp, parse_source, run_stream_source
from usvstation.sim.sea import SimulatedSea, UdpSender
from usvstation.store.db import utc_now
from usvstation.world.model import World, enu_to_compass, reference_in_ramp

log = logging.getLogger(__name__)
PUBLISH_HZ = 2.0
RAMP_POSE_HZ = 4.0  # at least twice a second (issue 15); the link sends at its own period


# decimals a served target keeps (millimetres, 0.1 mm/s, 0.01 degree)
_TARGET_DECIMALS = {"x": 3, "y": 3, "vx": 4, "vy": 4, "rvx": 4, "rvy": 4, "age_s": 3,
                    "speed": 4, "course_deg": 2}


def _rounded(target: Target) -> Target:
    """The world model's target as served: positions and velocities rounded."""
    served = target.copy()
    for key, nd in _TARGET_DECIMALS.items():
        served[key] = round(target[key], nd)  # type: ignore[literal-required]
    return served


class WorldService:
    """Owns the world model and the ship-input sources. With `simulate`, a working scenario
    with a mother ship or traffic starts the simulated sea: its sentences come over UDP
    (`sea_over_udp`, the ship's network in `serve`) or straight to `feed` (simulated time,
    where nothing waits on a socket)."""

    def __init__(self, hub: LiveHub, sources: list[str], *, simulate: bool = False,
                 sim_speed: float = 1.0, clock: Clock = REAL_CLOCK,
                 sea_over_udp: bool = True) -> None:
        self.hub, self.clock = hub, clock
        self.simulate, self.sim_speed, self.sea_over_udp = simulate, sim_speed, sea_over_udp
        self.sea: SimulatedSea | None = None
        self._sea_sender: UdpSender | None = None
        self._sea_stop: asyncio.Event | None = None
        self._sea_port: int | None = None
        self.sources: list[Source] = [parse_source(url) for url in sources]
        self.source_state: dict[str, InputSource] = {}
        self.world = World()
        self.decoder = SentenceDecoder()
        self._published = -1
        self._transports: list[asyncio.DatagramTransport] = []
        self._tasks: set[asyncio.Task] = set()
        self.listeners: list[Callable[[World, float], None]] = []
        self.tick_listeners: list[Callable[[World, float], None]] = []
        self._published_at = -1e9
        self.pose_listeners: list[Callable[[RampPoseSample | None], None]] = []
        self.ship: ShipShape | None = None
        self._pose_streamed = False

    # --- lifecycle -------------------------------------------------------------------------
    async def start(self, scenario: Scenario | None) -> None:
        for source in self.sources:
            await self.add_source(source)
        if scenario is not None:
            await self.use_scenario(scenario)
        self._spawn(self._ticker())
        self._spawn(self._pose_ticker())

    async def use_scenario(self, scenario: Scenario) -> None:
        """A new working scenario; with the simulated boat, its sea (if any) starts afresh."""
        if self.simulate:
            await self.stop_sea()
            self.world = World(config=self.world.config)
        self.set_scenario(scenario)
        if self.simulate and scenario.origin is not None and (scenario.mother_ship is not None
                                                              or scenario.traffic):
            self.sea = SimulatedSea(scenario, await self._sea_send(), sim_speed=self.sim_speed,
                                    clock=self.clock)
            self._sea_stop = asyncio.Event()
            self._spawn(self.sea.run(self._sea_stop))

    async def _sea_send(self) -> Callable[[bytes], None]:
        """Where the simulated sea's sentences go: a UDP source of ours, or `feed`."""
        if not self.sea_over_udp:
            return self.feed
        if self._sea_port is None:
            self._sea_port = await self.add_source(Source("udp", "127.0.0.1", 0))
            assert self._sea_port is not None
            self._sea_sender = UdpSender(("127.0.0.1", self._sea_port))
        assert self._sea_sender is not None
        return self._sea_sender

    async def stop_sea(self) -> None:
        """Stop the simulated sea (its sentences stop: the own ship goes silent)."""
        if self._sea_stop is not None:
            self._sea_stop.set()
            await self.clock.sleep(0)
        self.sea, self._sea_stop = None, None

    async def add_source(self, source: Source) -> int | None:
        """Open a source; for UDP returns the bound port (useful with port 0)."""
        key = str(source)
        if source.kind == "udp":
            transport, port = await open_udp(source, self.feed)
            self._transports.append(transport)
            self.source_state[key] = {"url": key, "state": "listening", "port": port}
            return port

        def state(text: str) -> None:
            self.source_state[key] = {"url": key, "state": text, "port": source.port or None}

        state("opening")
        self._spawn(run_stream_source(source, self.feed, state, self.clock))
        return None

    async def stop(self) -> None:
        await self.stop_sea()
        if self._sea_sender is not None:
            self._sea_sender.close()
        for transport in self._transports:
            transport.close()
        for task in list(self._tasks):
            task.cancel()
        for task in list(self._tasks):
            with contextlib.suppress(asyncio.CancelledError, Exception):
                await task

    def _spawn(self, coro: Any) -> None:
        task = asyncio.create_task(coro)
        self._tasks.add(task)
        task.add_done_callback(self._tasks.discard)

    # --- inputs ----------------------------------------------------------------------------
    def set_scenario(self, scenario: Scenario) -> None:
        """Anchor the ramp at the scenario origin; its obstacles become `manual` tracks."""
        ms = scenario.mother_ship
        self.world.lever_arm = ms.lever_arm if ms is not None else LeverArm()
        ring = hull_polygon(ms)
        self.ship = None if ms is None else {
            "length": ms.length, "beam": ms.beam, "ramp_width": ms.ramp_width,
            "outline": None if ring is None else [[x, y] for x, y in ring],
            "reference": [round(v, 3) for v in reference_in_ramp(ms.lever_arm)]}
        if scenario.origin is None:
            return
        o = scenario.origin
        frame = RampFrame(o.lat, o.lon, o.ramp_bearing_deg)
        self.world.anchor = frame
        self.world.set_manual(self.clock.now(), [(ob.x, ob.y, ob.radius, ob.vx, ob.vy)
                                             for ob in scenario.obstacles], frame)

    def feed(self, line: bytes) -> None:
        """One sentence from any source."""
        t = self.clock.now()
        apply_reports(self.world, t, self.decoder.feed(line, t))

    async def _ticker(self) -> None:
        while True:
            await self.clock.sleep(1.0 / PUBLISH_HZ)
            t = self.clock.now()
            self.world.expire(t)
            changed = self.world.version != self._published
            if changed or (self.world.own.stale(t) and t - self._published_at >= 1.0):
                self._published, self._published_at = self.world.version, t
                self.hub.publish("world", self.snapshot(t))
            for listener in (self.listeners if changed else []) + self.tick_listeners:
                try:
                    listener(self.world, t)
                except Exception:  # a listener's fault never stops the world
                    log.exception("world listener failed")

    async def _pose_ticker(self) -> None:
        while True:
            await self.clock.sleep(1.0 / RAMP_POSE_HZ)
            sample = self.ramp_sample(self.clock.now())
            for listener in self.pose_listeners:
                try:
                    listener(sample)
                except Exception:  # a listener's fault never stops the world
                    log.exception("ramp pose listener failed")

    # --- output ----------------------------------------------------------------------------
    def ramp_sample(self, t: float) -> RampPoseSample | None:
        """The pose to stream: the ramp at the last own-ship fix (that fix's instant: the
        boat extrapolates it in its own time), the fixed origin at rest at t once a pose
        was streamed and the fix is gone, else None (nothing to stream)."""
        own = self.world.own
        if own.has_fix and own.t_fix is not None:
            pose = self.world.ramp(own.t_fix)
            t = own.t_fix
        elif self._pose_streamed:
            pose = self.world.ramp(t)
        else:
            return None
        if pose is None:
            return None
        self._pose_streamed = True
        return RampPoseSample(t, pose.lat, pose.lon, pose.ramp_bearing_deg, pose.vn, pose.ve,
                              0.0)

    def current_frame(self) -> RampFrame | None:
        """The ramp frame of now when the ramp comes from the own ship, else None."""
        pose = self.world.ramp(self.clock.now())
        return pose.frame if pose is not None and pose.moving else None

    def snapshot(self, t: float | None = None) -> WorldSnapshot:
        """The `GET /api/world` body, everything predicted to station time t (default now)."""
        t = self.clock.now() if t is None else t
        own = self.world.own
        own_out = None
        if own.has_fix:
            lat, lon = own.position_at(t)
            own_out = {"lat": lat, "lon": lon, "heading_deg": own.heading_deg,
                       "course_deg": own.course_deg, "speed": own.speed,
                       "age_s": round(own.age(t) or 0.0, 3), "stale": own.stale(t),
                       "jump_m": None if own.jump_m is None else round(own.jump_m, 1),
                       "jump_age_s": None if own.t_jump is None else round(t - own.t_jump, 3)}
        pose = self.world.ramp(t)
        ramp_out = None
        if pose is not None:
            vx, vy = pose.frame.vector_to_ramp(pose.ve, pose.vn)
            speed, course = enu_to_compass(pose.ve, pose.vn)
            ramp_out = {"lat": pose.lat, "lon": pose.lon,
                        "ramp_bearing_deg": round(pose.ramp_bearing_deg, 3),
                        "vx": float(vx), "vy": float(vy), "speed": speed, "course_deg": course,
                        "source": "own_ship" if pose.moving else "origin",
                        "stale": pose.moving and own.stale(t)}
        targets = [_rounded(v) for v in self.world.targets(t)]
        s = self.decoder.stats
        return {"time": utc_now(self.clock), "own_ship": own_out, "ramp": ramp_out,
                "ship": self.ship, "targets": targets,
                "stats": {"sentences": s.sentences, "bad": s.bad, "ignored": s.ignored,
                          "bad_reasons": dict(s.reasons),
                          "sources": list(self.source_state.values())}}
