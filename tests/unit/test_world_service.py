"""The world service: sentences in, `world` events out, silent tracks aged out."""

from __future__ import annotations

from usvstation.clock import SimClock, run_simulated
from usvstation.scenario import load_scenario
from usvstation.services.hub import LiveHub
from usvstation.services.world import WorldService

AIS = b"!AIVDM,1,1,,A,139>JhOP1T8fQ7PAMCl4lSh1P000,0*02"


def test_world_events_and_ageing() -> None:
    """In simulated time: the target is published once, nothing while nothing changes, and
    it is gone once it has been silent longer than max_age_s."""
    hub = LiveHub()
    events: list[dict] = []
    hub.observers.append(lambda kind, data: events.append(data) if kind == "world" else None)

    async def main(clock: SimClock) -> None:
        svc = WorldService(hub, [], clock=clock)
        await svc.start(load_scenario("case1"))
        svc.feed(AIS)
        svc.feed(b"$junk")
        while not any(any(t["id"] == "ais:211000001" for t in e["targets"]) for e in events):
            await clock.sleep(0.05)
        n = len(events)
        await clock.sleep(0.7)
        assert len(events) == n  # nothing changed: nothing published
        await clock.sleep(svc.world.config.max_age_s + 1)
        assert len(events) == n + 1
        await svc.stop()

    run_simulated(main)
    first = next(e for e in events if any(t["id"] == "ais:211000001" for t in e["targets"]))
    assert first["stats"]["sentences"] == 2 and first["stats"]["bad"] == 1
    assert {t["source"] for t in first["targets"]} == {"ais", "manual"}
    last = events[-1]
    assert [t["source"] for t in last["targets"]] == ["manual"] * 4  # case1's obstacles stay
    assert last["ramp"]["source"] == "origin" and last["own_ship"] is None


def test_ramp_pose_stream_of_the_own_ship_fix() -> None:
    """The pose handed to the boat link: nothing for a fixed origin, the ramp at the last
    own-ship fix's instant once the ship reports, the origin at rest once the fix is gone."""
    import pytest

    from usvstation.world.model import World

    samples: list = []

    async def main(clock: SimClock) -> None:
        svc = WorldService(LiveHub(), [], clock=clock)
        svc.pose_listeners.append(samples.append)
        await svc.start(load_scenario("case1"))  # origin 30.5135, 114.4182, ramp bearing 90
        await clock.sleep(50.0 - clock.now())
        while not samples:
            await clock.sleep(0.05)
        assert samples[-1] is None and svc.current_frame() is None  # the shore trial
        # the ship heads 270 (stern ramp +x east), 20 m west (forward) of the ramp end, 1 kn
        svc.world.update_own(49.0, lat=30.5135, lon=114.4182 - 20.0 / 95_917.0,
                             heading_deg=270.0, course_deg=270.0, speed=0.5144)
        n = len(samples)
        while len(samples) == n:
            await clock.sleep(0.05)
        s = samples[-1]
        assert s.t == 49.0 and s.bearing_deg == pytest.approx(90.0)
        assert s.lat == pytest.approx(30.5135, abs=1e-6)
        assert s.lon == pytest.approx(114.4182, abs=2e-6)
        assert (s.vn, s.ve) == pytest.approx((0.0, -0.5144), abs=1e-6)
        assert svc.current_frame() is not None
        svc.world = World(anchor=svc.world.anchor)  # the fix is gone (a new sea)
        n = len(samples)
        while len(samples) == n:
            await clock.sleep(0.05)
        s = samples[-1]
        assert (s.lat, s.lon, s.vn, s.ve) == (30.5135, 114.4182, 0.0, 0.0)
        assert 50.0 <= s.t <= clock.now()  # stamped at its tick: the origin at rest, now
        await svc.stop()

    run_simulated(main)
