"""Alerts for a bridge, in simulated time (issue 25): the own ship's fix stale or jumping
raises a warning outside a run too and the ramp stays dead-reckoned, never the origin; a link
alert a station left open ends when the next one starts; one alert per cause and target."""

from __future__ import annotations

import pynmea2
from simstation import SimStation, run_station
from test_live_loop import moving_scenario

from usvstation.geo import RampFrame
from usvstation.world.model import offset_geodetic


def _dm(value: float, width: int) -> str:
    """Degrees as NMEA's (d)ddmm.mmmm."""
    deg = int(abs(value))
    return f"{deg:0{width}d}{(abs(value) - deg) * 60.0:07.4f}"


def gga(lat: float, lon: float) -> bytes:
    return (str(pynmea2.GGA("GP", "GGA", (
        "120000.00", _dm(lat, 2), "N" if lat >= 0 else "S", _dm(lon, 3),
        "E" if lon >= 0 else "W", "1", "12", "0.7", "5.0", "M", "0.0", "M", "", ""))) + "\r\n"
            ).encode()


async def alerts_of(sim: SimStation, kind: str) -> list[dict]:
    return [a for a in await sim.get("/api/alerts") if a["kind"] == kind]


async def _active(sim: SimStation, kind: str) -> list[dict]:
    return [a for a in await alerts_of(sim, kind) if a["active"]]


async def _none_active(sim: SimStation, kind: str) -> bool:
    return not await _active(sim, kind)


def test_own_ship_feed_stopped_warns_within_10_s_and_the_ramp_stays_dead_reckoned(
        tmp_path) -> None:
    doc = moving_scenario()
    origin = RampFrame(doc["origin"]["lat"], doc["origin"]["lon"],
                       doc["origin"]["ramp_bearing_deg"])

    async def body(sim: SimStation) -> None:
        assert (await sim.client.put("/api/scenario", json=doc)).status_code == 200

        async def own_ship() -> dict | None:
            w = await sim.get("/api/world")
            return w if w["ramp"] and w["ramp"]["source"] == "own_ship" else None

        world = await sim.poll(own_ship, 30, "the own ship's fix")
        assert world["ramp"]["stale"] is False and world["own_ship"]["stale"] is False
        await sim.clock.sleep(5.0)
        assert await alerts_of(sim, "own_ship_stale") == []

        # a fix 60 m off where the ship is, between two good ones: a jump warning, one alert
        # that ends 30 s after the last jump (the good fix after it jumped back)
        w = await sim.get("/api/world")
        lat, lon = offset_geodetic(w["own_ship"]["lat"], w["own_ship"]["lon"], 0.0, 60.0)
        sim.station.world.feed(gga(lat, lon))

        async def jumped() -> dict | None:
            return next((a for a in await alerts_of(sim, "own_ship_jump")
                         if a["level"] == "warning"), None)

        jump = await sim.poll(jumped, 2.0, "an own-ship jump warning")
        assert "jumped 60 m" in jump["message"], jump["message"]
        await sim.clock.sleep(35.0)
        (jump,) = await alerts_of(sim, "own_ship_jump")
        assert jump["active"] is False and jump["ended_at"] is not None
        assert await alerts_of(sim, "own_ship_stale") == []
        await sim.station.world.stop_sea()  # the ship's network goes silent
        stopped = sim.clock.now()

        async def warned() -> dict | None:
            return next((a for a in await alerts_of(sim, "own_ship_stale")
                         if a["level"] == "warning"), None)

        warning = await sim.poll(warned, 10.0, "a stale own-ship warning within 10 s")
        assert sim.clock.now() - stopped <= 10.0
        assert warning["active"] and warning["run_id"] is None  # no run: raised all the same
        assert "dead-reckoned" in warning["message"]
        # one alert that rose through its levels in place
        assert len(await alerts_of(sim, "own_ship_stale")) == 1
        # two minutes and more: still the own ship's ramp, marked stale, sailing on west
        east = []
        for _ in range(3):
            await sim.clock.sleep(60.0)
            w = await sim.get("/api/world")
            assert w["ramp"]["source"] == "own_ship" and w["ramp"]["stale"] is True
            x, _ = origin.to_ramp(w["ramp"]["lat"], w["ramp"]["lon"])  # x: east (bearing 90)
            east.append(float(x))
        assert east[0] > east[1] > east[2] and east[0] - east[2] > 100.0  # 1 m/s for 120 s
        assert all(abs(x) > 50.0 for x in east)  # never back at the origin

    run_station(tmp_path / "data", body)


def test_a_link_alert_left_open_by_a_station_ends_when_the_next_one_starts(tmp_path) -> None:
    async def cut(sim: SimStation) -> dict:
        assert sim.station.sim is not None and sim.station.sim.radio is not None
        sim.station.sim.radio.enabled = False  # the boat's transmitter goes quiet

        async def lost() -> dict | None:
            return next(iter(await alerts_of(sim, "link_lost")), None)

        return await sim.poll(lost, 20.0, "the link-lost alert")

    first = run_station(tmp_path / "data", cut)  # stopped with the link down
    assert first["active"] and first["level"] == "warning"

    async def restarted(sim: SimStation) -> list[dict]:
        return await sim.get("/api/alerts")

    after = run_station(tmp_path / "data", restarted)
    (old,) = [a for a in after if a["id"] == first["id"]]
    assert old["active"] is False and old["ended_at"] is not None
    assert not [a for a in after if a["active"]]  # the link is up: nothing open


def test_the_link_alert_ends_when_the_link_is_back(tmp_path) -> None:
    async def body(sim: SimStation) -> None:
        radio = sim.station.sim.radio
        radio.enabled = False
        lost = await sim.poll(lambda: alerts_of(sim, "link_lost"), 20.0, "link lost")
        assert [a["active"] for a in lost] == [True]
        radio.enabled = True

        async def ended() -> list[dict] | None:
            alerts = await alerts_of(sim, "link_lost")
            return alerts if not alerts[0]["active"] else None

        (back,) = await sim.poll(ended, 20.0, "the link alert to end")
        assert back["id"] == lost[0]["id"] and back["ended_at"] is not None
        assert [a for a in await sim.get("/api/alerts") if a["kind"] != "link_lost"] == []

        async def cut_and_restore() -> list[dict]:
            radio.enabled = False
            alerts = await sim.poll(lambda: _active(sim, "link_lost"), 20.0, "link lost")
            radio.enabled = True
            await sim.poll(lambda: _none_active(sim, "link_lost"), 20.0, "link back")
            return alerts

        # lost again within 30 s of its end: the same alert, reopened; long after: a new one
        await cut_and_restore()
        assert [a["id"] for a in await alerts_of(sim, "link_lost")] == [lost[0]["id"]]
        await sim.clock.sleep(40.0)
        await cut_and_restore()
        ids = [a["id"] for a in await alerts_of(sim, "link_lost")]
        assert len(ids) == 2 and lost[0]["id"] in ids

    run_station(tmp_path / "data", body)



def test_a_proposal_is_withdrawn_when_its_run_ends(tmp_path) -> None:
    from test_live_loop import PARK, TARGET, first, put_scenario_and_wait_parked, scenario

    async def body(sim: SimStation) -> None:
        c = sim.client
        await put_scenario_and_wait_parked(sim, scenario(), TARGET, PARK)
        job = await sim.wait_plan((await c.post("/api/plans", json={"seed": 1})).json()["id"])
        await sim.fly(job["id"])
        proposal = await first(sim, "/api/replans", lambda p: p["state"] == "proposed", 120,
                               "a proposed re-plan")
        assert (await c.post("/api/boat/command", json={"command": "abort"})).status_code == 200

        async def withdrawn() -> dict | None:
            (p,) = [p for p in await sim.get("/api/replans") if p["id"] == proposal["id"]]
            return p if p["state"] == "failed" else None

        p = await sim.poll(withdrawn, 30, "the proposal withdrawn")
        assert p["error"] == f"run {proposal['run_id']} aborted before the re-plan was confirmed"
        confirm = await c.post(f"/api/replans/{proposal['id']}/confirm")
        assert confirm.status_code == 409
        assert not [a for a in await sim.get("/api/alerts") if a["active"]
                    and a["run_id"] is not None]

    run_station(tmp_path / "data", body, replan="confirm")
