"""`usv-station sim`: the simulated boat on a serial port, a pyserial URL or a new pty."""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import sys

from usvstation.geo import RampFrame
from usvstation.link.transport import PtyPair
from usvstation.sim.boat import BoatConfig
from usvstation.sim.runner import SimulatedBoat, make_boat, make_vehicle, serve_on_url


def _say(text: str) -> None:
    print(f"usv-station sim: {text}", flush=True)


async def run_sim(args: argparse.Namespace) -> int:
    """Serve until interrupted or --duration elapses; returns the exit code."""
    from usvstation.scenario import ScenarioError, load_scenario

    try:
        scenario = load_scenario(args.scenario)
    except ScenarioError as exc:
        raise ValueError(f"invalid scenario: {exc}") from None
    origin = scenario.origin
    if origin is None:
        raise ValueError(f"scenario {args.scenario} has no origin (lat, lon) to place the boat")
    frame = RampFrame(origin.lat, origin.lon, origin.ramp_bearing_deg)
    config = BoatConfig(telemetry_hz=args.telemetry_hz, failsafe_timeout_s=args.failsafe_s,
                        sim_speed=args.sim_speed)
    vehicle = make_vehicle(args.vehicle, scenario, args.sea_state,
                           guidance=args.guidance, controller=args.controller)
    boat = make_boat(frame, config=config, seed=args.seed, vehicle=vehicle)
    stop = asyncio.Event()
    if args.duration is not None:
        asyncio.get_running_loop().call_later(args.duration, stop.set)
    detail = (f"{args.vehicle} vehicle, {args.baud} baud, sim speed {args.sim_speed:g}, "
              f"telemetry {args.telemetry_hz:g} Hz, failsafe {args.failsafe_s:g} s, "
              f"start ({scenario.start.x:g}, {scenario.start.y:g}) of {scenario.name}")
    if args.link == "pty":
        pair = PtyPair()
        _say(f"boat on {pair.slave_path} ({detail})")
        try:
            await SimulatedBoat(boat, _say).run(pair.master_stream(), stop)
        finally:
            pair.close()
        return 0
    _say(f"boat on {args.link} ({detail})")
    with contextlib.suppress(asyncio.CancelledError):
        await serve_on_url(boat, args.link, args.baud, log=_say, stop=stop)
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit("use: usv-station sim --link URL")
