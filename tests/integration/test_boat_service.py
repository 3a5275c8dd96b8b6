"""BoatService refusal paths and mission states with an injected link: a real BoatLink and
a real simulated boat (BoatProtocol) joined by an in-memory byte pipe the test can cut."""

from __future__ import annotations

import asyncio
import math

import pytest

from usvstation.config import Settings
from usvstation.geo import RampFrame
from usvstation.link import wire
from usvstation.link.mavlink import usv_recovery as mav
from usvstation.services.boat import BoatService
from usvstation.services.errors import (
    Conflict,
    LinkUnavailable,
    MissionMismatch,
    NoAnswer,
    NotFound,
)
from usvstation.services.hub import LiveHub
from usvstation.services.missions import (
    TRANSITIONS,
    MissionStatus,
    Seen,
    next_status,
)
from usvstation.sim.boat import BoatConfig
from usvstation.sim.runner import SimulatedBoat, make_boat
from usvstation.store.db import Store

FRAME = RampFrame(30.5135, 114.4182, 90.0)
ORIGIN = {"lat": 30.5135, "lon": 114.4182, "ramp_bearing_deg": 90.0}


class Pipe:
    """One direction-pair of an in-memory serial line; `drop` filters frames to the boat."""

    def __init__(self) -> None:
        self.to_boat: asyncio.Queue[bytes] = asyncio.Queue()
        self.to_station: asyncio.Queue[bytes] = asyncio.Queue()
        self.drop = lambda frame: False
        self.cut = False  # the boat hears nothing and says nothing

    def station_end(self) -> _End:
        return _End(self, self.to_station, self.to_boat, filter_out=True)

    def boat_end(self) -> _End:
        return _End(self, self.to_boat, self.to_station, filter_out=False)


class _End:
    def __init__(self, pipe: Pipe, rx: asyncio.Queue, tx: asyncio.Queue, filter_out: bool):
        self.pipe, self.rx, self.tx, self.filter_out = pipe, rx, tx, filter_out

    async def read(self) -> bytes:
        while True:
            item = await self.rx.get()
            if not isinstance(item, _End):
                return item
            if item is self:  # closed: the end of this reader (another end's mark is skipped)
                return b""

    async def write(self, data: bytes) -> None:
        if self.pipe.cut:
            return
        if self.filter_out:
            data = b"".join(f for f in wire.split_frames(data) if not self.pipe.drop(f))
        if data:
            self.tx.put_nowait(data)

    async def close(self) -> None:
        self.rx.put_nowait(self)


class Plans:
    """Finished plans by id (the PlanService's read side, which is all BoatService uses)."""

    def __init__(self, store: Store) -> None:
        self.jobs: dict[str, dict] = {}
        self.store = store

    def add(self, plan_id: str, y_offset: float = 0.0) -> None:
        with self.store.conn as c:  # the missions table refers to its plan
            c.execute("INSERT OR IGNORE INTO plans (id, created_at, status, planner, scenario) "
                      "VALUES (?, 't', 'done', 'iga', '{}')", (plan_id,))
        wps = [{"x": 85.0 - 10 * i, "y": 10.0 + y_offset * math.sin(i), "t": 8.0 * i,
                "speed": 1.25, "heading_deg": 180.0} for i in range(6)]
        self.jobs[plan_id] = {"status": "done", "scenario": {"origin": ORIGIN},
                              "plan": {"waypoints": wps}}

    def get(self, plan_id: str) -> dict | None:
        return self.jobs.get(plan_id)


@pytest.fixture
def service(tmp_path):
    """(service, pipe, boat) on a running event loop; the test body is a coroutine."""
    key_path = tmp_path / "link.key"
    wire.write_key(key_path)

    def run(body, *, boat_on: bool = True):
        async def main():
            pipe = Pipe()
            store = Store(tmp_path)
            store.start()
            settings = Settings(link="injected", data_dir=tmp_path, link_key=key_path)
            plans = Plans(store)
            svc = BoatService(settings, store, LiveHub(), plans,
                              stream_factory=lambda: _ready(pipe.station_end()))
            boat = make_boat(FRAME, config=BoatConfig(), key=wire.read_key(key_path))
            stop = asyncio.Event()
            task = asyncio.get_running_loop().create_task(
                SimulatedBoat(boat).run(pipe.boat_end(), stop)) if boat_on else None
            from usvstation.scenario import load_scenario

            await svc.start(load_scenario("case1"))
            try:
                if boat_on:
                    for _ in range(200):
                        if svc.link_up and svc.link.report is not None:
                            break
                        await asyncio.sleep(0.02)
                await body(svc, pipe, boat, plans)
            finally:
                await svc.stop()
                stop.set()
                if task is not None:
                    await task
                store.close()

        asyncio.run(main())

    return run


async def _ready(end):
    return end


async def _wait(cond, timeout: float = 10.0) -> None:
    for _ in range(int(timeout / 0.02)):
        if cond():
            return
        await asyncio.sleep(0.02)
    raise AssertionError("timed out")


async def _upload(svc, plans, plan_id: str, **kw) -> str:
    plans.add(plan_id, **kw)
    rec = await svc.create_mission(plan_id)
    await _wait(lambda: svc.missions[rec["id"]].state != MissionStatus.UPLOADING)
    return rec["id"]


def test_link_down_is_503(service):
    async def body(svc, pipe, boat, plans):
        plans.add("p")
        for call in (svc.command("hold"), svc.create_mission("p"), svc.verify("nope")):
            with pytest.raises((LinkUnavailable, NotFound)):
                await call
        with pytest.raises(LinkUnavailable, match="link is down"):
            await svc.command("hold")

    service(body, boat_on=False)


def test_no_answer_is_504(service):
    async def body(svc, pipe, boat, plans):
        pipe.drop = lambda f: f[7] == mav.MAVLINK_MSG_ID_COMMAND_INT  # commands never arrive
        with pytest.raises(NoAnswer, match="did not acknowledge HOLD"):
            await svc.command("hold")

    service(body)


def test_start_names_its_mission_and_409s_for_no_mission_or_another(service):
    async def body(svc, pipe, boat, plans):
        with pytest.raises(Conflict, match="no verified mission"):
            await svc.command("start")
        a = await _upload(svc, plans, "a")
        with pytest.raises(Conflict, match="send mission_id"):
            await svc.command("start")
        with pytest.raises(NotFound, match="no mission 'zzz'"):
            await svc.command("start", "zzz")
        assert svc.missions[a].state == MissionStatus.VERIFIED
        b = await _upload(svc, plans, "b", y_offset=2.0)
        await _wait(lambda: svc.missions[a].state == MissionStatus.GONE)
        with pytest.raises(MissionMismatch, match="holds another mission"):
            await svc.command("start", a)
        answer = await svc.command("start", b)
        assert answer["result"] == "ACCEPTED" and answer["mission"] == b
        await _wait(lambda: svc.missions[b].state == MissionStatus.ACTIVE)
        await svc.command("abort")
        await _wait(lambda: svc.missions[b].state == MissionStatus.ABORTED)
        with pytest.raises(MissionMismatch, match="holds no mission"):
            await svc.command("start", b)

    service(body)


def test_one_upload_at_a_time_and_verify_compares_item_by_item(service):
    async def body(svc, pipe, boat, plans):
        plans.add("a")
        plans.add("b")
        first = await svc.create_mission("a")
        with pytest.raises(Conflict, match="one upload at a time"):
            await svc.create_mission("b")
        await _wait(lambda: svc.missions[first["id"]].state == MissionStatus.VERIFIED)
        report = await svc.verify(first["id"])
        assert report["identical"] and report["count"] == 6 and report["differences"] == []

    service(body)


def test_boat_reboot_makes_a_verified_mission_gone(service):
    async def body(svc, pipe, boat, plans):
        a = await _upload(svc, plans, "a")
        assert svc.missions[a].state == MissionStatus.VERIFIED
        boat.boot_id ^= 0x5A5A  # what a reboot looks like on the wire: a new boot, no mission
        boat.active, boat.state = None, 0
        await _wait(lambda: svc.missions[a].state == MissionStatus.GONE, 3.0)
        assert "no longer holds" in svc.missions[a].error

    service(body)


def test_station_restart_mid_run_rederives_the_mission_and_hold_acts(service, tmp_path):
    async def body(svc, pipe, boat, plans):
        a = await _upload(svc, plans, "a")
        await svc.command("start", a)
        await _wait(lambda: svc.missions[a].run is not None and svc.missions[a].run > 0)
        first_run = svc.missions[a].run
        await svc.stop()  # the station process ends; the boat runs on
        again = BoatService(svc.settings, svc.store, LiveHub(), plans,
                            stream_factory=lambda: _ready(pipe.station_end()))
        from usvstation.scenario import load_scenario

        await again.start(load_scenario("case1"))
        try:
            await _wait(lambda: again.link_up and a in again.missions
                        and again.missions[a].state == MissionStatus.ACTIVE
                        and (again.missions[a].run or 0) > first_run)
            answer = await again.command("hold")
            assert answer["result"] == "ACCEPTED" and answer["state"] == "HOLD"
            assert boat.state == 3 and boat.session == again.link.protocol.session
            await _wait(lambda: boat.vehicle.state.speed < 0.5, 3.0)
        finally:
            await again.stop()

    service(body)


def test_the_mission_state_table():
    assert next_status(MissionStatus.FAILED, Seen.HELD_READY) == MissionStatus.VERIFIED
    assert next_status(MissionStatus.VERIFIED, Seen.NOT_HELD) == MissionStatus.GONE
    assert next_status(MissionStatus.ACTIVE, Seen.DROPPED_BY_ABORT) == MissionStatus.ABORTED
    assert next_status(MissionStatus.COMPLETED, Seen.NOT_HELD) == MissionStatus.COMPLETED
    assert next_status(MissionStatus.UPLOADING, Seen.NOT_HELD) == MissionStatus.UPLOADING
    assert all(isinstance(k[0], MissionStatus) and isinstance(v, MissionStatus)
               for k, v in TRANSITIONS.items())


class Bus:
    """One radio channel shared by a station and several boats (what a second boat with the
    same id and key does to the link): every frame the station sends reaches every boat,
    every boat's frame reaches the station."""

    def __init__(self) -> None:
        self.to_station: asyncio.Queue[bytes] = asyncio.Queue()
        self.to_boats: list[asyncio.Queue[bytes]] = []

    def station_end(self) -> _BusEnd:
        return _BusEnd(self.to_station, lambda data: [q.put_nowait(data)
                                                      for q in self.to_boats])

    def boat_end(self) -> _BusEnd:
        q: asyncio.Queue[bytes] = asyncio.Queue()
        self.to_boats.append(q)
        return _BusEnd(q, self.to_station.put_nowait)


class _BusEnd:
    def __init__(self, rx, tx) -> None:
        self.rx, self.tx = rx, tx

    async def read(self) -> bytes:
        return await self.rx.get()

    async def write(self, data: bytes) -> None:
        self.tx(data)

    async def close(self) -> None:
        self.rx.put_nowait(b"")


def test_a_second_boat_with_the_same_id_raises_an_alert_within_5_s(tmp_path):
    from usvstation.clock import run_simulated
    from usvstation.scenario import load_scenario
    from usvstation.services.alerts import LinkAlerts

    key_path = tmp_path / "link.key"
    wire.write_key(key_path)
    key = wire.read_key(key_path)

    async def main(clock):
        bus = Bus()
        store = Store(tmp_path)
        store.start()
        plans = Plans(store)
        alerts: list = []
        svc = BoatService(Settings(link="injected", data_dir=tmp_path, link_key=key_path),
                          store, LiveHub(), plans, clock=clock,
                          stream_factory=lambda: _ready(bus.station_end()))
        svc.on_duplicate = LinkAlerts(alerts.append).on_duplicate
        stops, tasks = [], []

        def boat(boot_id: int):
            b = make_boat(FRAME, config=BoatConfig(), key=key, clock=clock, boot_id=boot_id)
            stops.append(asyncio.Event())
            tasks.append(asyncio.get_running_loop().create_task(
                SimulatedBoat(b, clock=clock).run(bus.boat_end(), stops[-1])))
            return b

        boat(0x1111)
        await svc.start(load_scenario("case1"))
        try:
            while not (svc.link_up and svc.link.report is not None):
                await clock.sleep(0.05)
            a = await _upload_sim(svc, plans, clock, "a")
            assert svc.snapshot()["link"]["duplicate"] is None and alerts == []
            t0 = clock.now()
            boat(0x2222)  # a second boat, same id and key, switched on
            while not alerts:
                await clock.sleep(0.05)
                assert clock.now() - t0 <= 5.0, "no alert within 5 s"
            (alert,) = alerts
            assert (alert.level, alert.kind) == ("warning", "duplicate_boat")
            assert "0x00001111" in alert.message and "0x00002222" in alert.message
            dup = svc.snapshot()["link"]["duplicate"]
            assert set(dup["boot_ids"]) == {0x1111, 0x2222} and dup["switches"] >= 2
            stops[1].set()  # the intruder goes away: a minute later one boat again
            await tasks[1]
            await clock.sleep(65.0)
            assert svc.snapshot()["link"]["duplicate"] is None
            assert svc.missions[a].state == MissionStatus.VERIFIED  # boat 1 holds it
            assert len(alerts) == 1
        finally:
            await svc.stop()
            stops[0].set()
            await tasks[0]
            store.close()

    run_simulated(main)


async def _upload_sim(svc, plans, clock, plan_id: str) -> str:
    plans.add(plan_id)
    rec = await svc.create_mission(plan_id)
    while svc.missions[rec["id"]].state == MissionStatus.UPLOADING:
        await clock.sleep(0.05)
    assert svc.missions[rec["id"]].state == MissionStatus.VERIFIED
    return rec["id"]
