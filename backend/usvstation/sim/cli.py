"""`usv-station sim`: the simulated boat on a serial port, a pyserial URL or a new pty."""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import signal
import sys

from usvstation.geo import RampFrame
from usvstation.link.transport import PtyPair
from usvstation.sim.boat import BoatConfig
from usvstation.sim.runner import (
    SimulatedBoat,
    default_nv_path,
    load_nv,
    make_boat,
    make_vehicle,
    serve_on_url,
)


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
    key = _link_key(args)
    config = BoatConfig(boat_id=args.boat_id, station_id=args.station_id,
                        telemetry_hz=args.telemetry_hz, failsafe_timeout_s=args.failsafe_s,
                        sim_speed=args.sim_speed, baud=args.baud)
    vehicle = make_vehicle(args.vehicle, scenario, args.sea_state,
                           guidance=args.guidance, controller=args.controller)
    # the signing floor: --nv-file, else beside the key (an unsigned boat has none)
    nv_path = args.nv_file if args.nv_file is not None else \
        default_nv_path(args.link_key, args.boat_id) if key is not None else None
    nv = load_nv(nv_path) if nv_path is not None else None
    boat = make_boat(frame, config=config, seed=args.seed, vehicle=vehicle, key=key, nv=nv,
                     x=scenario.start.x, y=scenario.start.y,
                     heading_deg=scenario.start.heading_deg)
    stop = asyncio.Event()
    for sig in (signal.SIGINT, signal.SIGTERM):  # a clean stop: the floor written exact
        with contextlib.suppress(NotImplementedError, RuntimeError):
            asyncio.get_running_loop().add_signal_handler(sig, stop.set)
    if args.duration is not None:
        asyncio.get_running_loop().call_later(args.duration, stop.set)
    detail = (f"boat id {args.boat_id}, station {args.station_id}, "
              f"{'signed' if key else 'UNSIGNED'}, {args.vehicle} vehicle, {args.baud} baud, "
              f"sim speed {args.sim_speed:g}, "
              f"telemetry {args.telemetry_hz:g} Hz, failsafe {args.failsafe_s:g} s, "
              f"signing floor {nv_path if nv_path is not None else 'none'}, "
              f"start ({scenario.start.x:g}, {scenario.start.y:g}) of {scenario.name}")
    if args.link == "pty":
        pair = PtyPair()
        _say(f"boat on {pair.slave_path} ({detail})")
        try:
            await SimulatedBoat(boat, _say, nv_path).run(pair.master_stream(), stop)
        finally:
            pair.close()
        return 0
    _say(f"boat on {args.link} ({detail})")
    with contextlib.suppress(asyncio.CancelledError):
        await serve_on_url(boat, args.link, args.baud, log=_say, stop=stop,
                           nv_path=nv_path)
    return 0


def _link_key(args: argparse.Namespace) -> bytes | None:
    from usvstation.link.wire import read_key

    if args.link_key is not None and args.insecure_link:
        raise ValueError("--link-key and --insecure-link contradict each other")
    if args.link_key is None:
        if not args.insecure_link:
            raise ValueError("the boat needs --link-key PATH (the station's key) or, "
                             "knowingly, --insecure-link")
        return None
    try:
        return read_key(args.link_key)
    except OSError as exc:
        raise ValueError(f"link key {args.link_key}: {exc.strerror}") from None


if __name__ == "__main__":  # pragma: no cover
    sys.exit("use: usv-station sim --link URL")
