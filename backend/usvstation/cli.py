"""`usv-station`: the single command-line entry point (shared/DESIGN.md "Command line").

Exit codes: 0 success, 2 invalid input (one line on stderr naming the field),
3 no feasible plan (one line with the reason), 1 an unexpected error.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path
from typing import TYPE_CHECKING, Any

from usvstation import __version__
from usvstation.runtime import tune_allocator

if TYPE_CHECKING:
    from usvstation.planning.model import Plan

EXIT_OK, EXIT_ERROR, EXIT_INVALID, EXIT_INFEASIBLE = 0, 1, 2, 3
# planning.registry's names, listed here so that --help does not import NumPy (tested equal)
PLANNER_NAMES = ["iga", "colregs-ga", "replan-ga", "de-apf", "rrt-star", "bspline-rrt-star",
                 "vpf-rrt-star"]


class CliError(Exception):
    """An error reported as one line on stderr with an exit code."""

    def __init__(self, message: str, code: int) -> None:
        super().__init__(message)
        self.code = code


def _parse_setting(text: str) -> tuple[str, Any]:
    """KEY=VALUE with VALUE as JSON (numbers, true/false, strings)."""
    key, sep, raw = text.partition("=")
    if not sep or not key:
        raise argparse.ArgumentTypeError(f"expected KEY=VALUE, got {text!r}")
    try:
        value = json.loads(raw)
    except json.JSONDecodeError:
        value = raw
    return key.strip(), value


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="usv-station",
        description="Shore station for USV stern-ramp recovery (IGA planning, boat link, console).",
    )
    parser.add_argument("--version", action="version", version=f"usv-station {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    plan = sub.add_parser(
        "plan",
        help="plan a scenario with the IGA",
        description=(
            "Plan a scenario file (or a bundled scenario by name: case1..case4). "
            "Prints the plan JSON when --json is given or stdout is not a terminal, "
            "else a readable summary. Exit 2: invalid input; exit 3: no feasible plan."
        ),
    )
    plan.add_argument("scenario", help="scenario JSON file, or the name of a bundled scenario")
    plan.add_argument("--planner", default="iga", choices=PLANNER_NAMES,
                      help="planner (default iga; docs/planners.md)")
    plan.add_argument("--seed", type=int, default=None,
                      help="random seed (default: the scenario's, else 1)")
    plan.add_argument("--json", action="store_true", help="print the plan as JSON")
    plan.add_argument("--out", type=Path, help="also write the plan JSON to this file")
    plan.add_argument("--time-budget", type=float, default=None, metavar="S",
                      help="wall-clock safety net of the command in seconds "
                      "(planner.time_budget_s, default 5): past it the best valid plan so "
                      "far, with a warning, or exit 3")
    plan.add_argument("--max-evaluations", type=int, default=None, metavar="N",
                      help="deterministic budget (planner.max_evaluations): candidate paths "
                      "evaluated over all attempts; the plan does not depend on the "
                      "machine's load (docs/planners.md \"Budget\")")
    plan.add_argument(
        "--set", dest="settings", action="append", default=[], type=_parse_setting,
        metavar="KEY=VALUE", help="override a planner option, e.g. --set population=120",
    )

    serve = sub.add_parser(
        "serve", help="run the station: API, console, live telemetry, boat link",
        description=(
            "Start the station. --link sim (default) attaches a simulated boat through a "
            "pseudo-terminal; a device (/dev/ttyUSB0) or pyserial URL (socket://host:port) "
            "attaches a real one. Every option can also be set as USV_STATION_<NAME>."
        ),
    )
    add_settings_flags(serve)

    sim = sub.add_parser(
        "sim", help="run the simulated boat on a serial port",
        description=(
            "Run the simulated boat (the boat side of the usv-link protocol driving the 3-DOF "
            "vessel model with compensated AV-LOS guidance) on a serial device or pyserial URL; "
            "--link pty creates a pseudo-terminal and prints the device path for the station "
            "to open."
        ),
    )
    sim.add_argument("--link", required=True,
                     help="serial device (/dev/ttyUSB0), pyserial URL (socket://host:port) or pty")
    sim.add_argument("--baud", type=int, default=57600, help="baud rate (default 57600)")
    sim.add_argument("--sim-speed", type=float, default=1.0,
                     help="boat time runs this many times faster than the wall clock")
    sim.add_argument("--telemetry-hz", type=float, default=5.0,
                     help="telemetry rate, up to 50 (default 5)")
    sim.add_argument("--failsafe-s", type=float, default=3.0,
                     help="hold station after this long without the station (default 3)")
    sim.add_argument("--scenario", default="case1",
                     help="scenario giving the origin and start pose (default case1)")
    sim.add_argument("--seed", type=int, default=0, help="GPS noise seed")
    sim.add_argument("--vehicle", choices=["dynamic", "kinematic"], default="dynamic",
                     help="dynamic: 3-DOF Otter model with AV-LOS (default); kinematic: follows "
                     "the mission exactly")
    sim.add_argument("--sea-state", type=int, default=0, choices=range(0, 7), metavar="0-6",
                     help="waves of this sea state running with the scenario's wind (default 0)")
    sim.add_argument("--guidance", default="avlos_comp",
                     choices=["avlos_comp", "avlos", "los", "ilos", "alos", "sliding_curve"],
                     help="dynamic vehicle's guidance law (default avlos_comp)")
    sim.add_argument("--controller", default="pid", choices=["pid", "pid_mrac", "drnn_pi", "pi"],
                     help="dynamic vehicle's autopilot (default pid)")
    sim.add_argument("--duration", type=float, default=None,
                     help="stop after this many seconds (default: run until interrupted)")
    sim.add_argument("--boat-id", type=int, default=1, help="boat system id (default 1)")
    sim.add_argument("--station-id", type=int, default=255,
                     help="system id of the paired station (default 255)")
    sim.add_argument("--link-key", type=Path, metavar="PATH",
                     help="signing key file shared with the station")
    sim.add_argument("--insecure-link", action="store_true",
                     help="accept unsigned frames (only without --link-key)")
    sim.add_argument("--nv-file", type=Path, metavar="PATH",
                     help="the boat's non-volatile memory (signing replay floor) across "
                     "restarts, like the STM32's flash (default: KEY.boatN.floor beside "
                     "the --link-key file, created on first use)")

    _add_hil_parser(sub)

    link_key = sub.add_parser("link-key", help="manage usv-link signing keys")
    link_key_sub = link_key.add_subparsers(dest="key_command", required=True)
    key_new = link_key_sub.add_parser("new", help="write a new random 32-byte key (mode 0600)")
    key_new.add_argument("path", type=Path, help="key file to create (must not exist)")

    bench = sub.add_parser("bench", help="run a benchmark and print its figures")
    bench.add_argument("name", choices=["planner", "tracking", "link", "server", "live",
                                        "compare", "arrival"],
                       help="which benchmark")
    bench.add_argument("--json", action="store_true", help="print one JSON object (default)")
    bench.add_argument("--scenarios", type=Path, help="folder of scenarios (default: public suite)")
    bench.add_argument("--seeds", type=int, default=5, help="seeds per scenario (default 5)")
    bench.add_argument("--random", type=int, default=100,
                       help="random scenarios for the validity rate (default 100, 0 to skip)")
    bench.add_argument("--base-port", type=int, metavar="N",
                       help="server: fixed ports, the station on N and its 3D view on N+1 "
                       "(default: any free ports)")
    bench.add_argument("--quick", action="store_true",
                       help="fewer repetitions, for a smoke test (figures not for the record)")
    bench.add_argument("--episodes", type=int, default=50,
                       help="live: seeded episodes of the simulated sea (default 50)")
    bench.add_argument("--manoeuvres", action="store_true",
                       help="tracking: add turning circle, zig-zags, pull-out and heading steps")
    bench.add_argument("--markdown", type=Path, metavar="JSON",
                       help="print the tables for RESULTS.md from a saved --json result")
    bench.add_argument("--planners", help="compare: comma-separated planner names (default all)")
    bench.add_argument("--families", help="compare: comma-separated families (default all: "
                       "recovery, transit, dense, colregs, traps); arrival: perturbation "
                       "families (default all)")
    bench.add_argument("--plan-seeds", metavar="SEEDS",
                       help="arrival: comma-separated plan seeds (default 21,22,23,24, on "
                       "which nothing was tuned)")
    bench.add_argument("--workers", type=int, default=1,
                       help="arrival: processes running the episodes (default 1; the figures "
                       "do not depend on it)")
    bench.add_argument("--hidden", type=int, default=6,
                       help="compare: seeded hidden scenarios per family beside the public ones")
    bench.add_argument("--hidden-from", type=int, default=1000, metavar="SEED",
                       help="compare: seed of the first hidden scenario (default 1000)")
    bench.add_argument("--first-seed", type=int, default=1, metavar="SEED",
                       help="compare: first planner seed (default 1)")
    bench.add_argument("--no-track", action="store_true",
                       help="compare: skip sailing the plans with the simulated boat")
    bench.add_argument("--plots", type=Path, help="compare: folder for the SVG figures")
    bench.add_argument("--ompl", action="store_true",
                       help="compare: add OMPL's RRT*, Informed RRT* and BIT* (pip install ompl)")
    bench.add_argument("--sweep", metavar="COUNTS",
                       help="compare: difficulty sweep of paper 004's map over these obstacle "
                       "counts, e.g. 40,120,200,280 (rrt-star's path/straight-line ratio)")
    bench.add_argument("--sweep-maps", type=int, default=30, metavar="N",
                       help="compare: maps per obstacle count in the sweep (default 30)")
    bench.add_argument("--curves", metavar="BUDGETS",
                       help="compare: cost-versus-time curves at these CPU-time budgets (s), "
                       "e.g. 0.05,0.2,1: our RRT* (with --ompl: against OMPL's RRT*, BIT*, PRM*)")
    bench.add_argument("--curve-maps", type=int, default=4, metavar="N",
                       help="compare: maps of the curves (default 4)")
    _add_campaign_parser(sub)
    _add_trial_parser(sub)
    return parser


def add_settings_flags(parser: argparse.ArgumentParser) -> None:
    """One flag per Settings field (config.py holds the names, types, defaults, bounds
    and help texts): --field-name, bools as --x/--no-x, lists comma-separated or, marked
    `repeat`, repeated; every default is None so only the flags given override the
    USV_STATION_* variables."""
    from typing import Literal, get_args, get_origin

    from usvstation.config import Settings

    for name, field in Settings.model_fields.items():
        extra = field.json_schema_extra if isinstance(field.json_schema_extra, dict) else {}
        flag = str(extra.get("flag", "--" + name.replace("_", "-")))
        default = field.get_default(call_default_factory=True)
        if isinstance(default, bool):
            default = "on" if default else "off"
        shown = f" (default {default})" if default not in (None, [], "") else ""
        kw: dict[str, object] = {"dest": name, "default": None,
                                 "help": (field.description or name) + shown}
        if "metavar" in extra:
            kw["metavar"] = extra["metavar"]
        kinds = [a for a in get_args(field.annotation) or (field.annotation,) if a is not None
                 and a is not type(None)]
        kind = kinds[0] if kinds else str
        if kind is bool:
            kw["action"] = argparse.BooleanOptionalAction
        elif get_origin(field.annotation) is Literal:
            kw["choices"] = list(get_args(field.annotation))
        elif get_origin(kind) is list or get_origin(field.annotation) is list:
            if extra.get("repeat"):
                kw["action"] = "append"
            else:
                kw["type"] = _comma_list
        else:
            kw["type"] = kind if kind in (int, float, Path) else str
        parser.add_argument(flag, **kw)  # type: ignore[arg-type]


def _comma_list(value: str) -> list[str]:
    return [item for item in value.split(",") if item]


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    if args.command not in ("serve", "sim"):
        # planning in this process: keep freed heap pages (runtime.py); not for `serve`,
        # whose memory must come back after a burst of requests (its plan workers tune
        # their own allocator), nor for the simulated boat
        tune_allocator()
    try:
        command = {"serve": _cmd_serve, "plan": _cmd_plan, "bench": _cmd_bench,
                   "sim": _cmd_sim, "hil": _cmd_hil, "link-key": _cmd_link_key,
                   "campaign": _cmd_campaign, "trial": _cmd_trial}.get(args.command)
        if command is not None:
            return command(args)
    except CliError as exc:
        print(f"usv-station {args.command}: {exc}", file=sys.stderr)
        return exc.code
    except KeyboardInterrupt:
        print("usv-station: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # the reader of our output went away (e.g. `| head`)
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return EXIT_OK
    return EXIT_ERROR


def _cmd_plan(args: argparse.Namespace) -> int:
    # --time-budget counts the process's CPU time from here (planning/budget.py), so that the
    # command, the planner's imports included, keeps within it
    started = time.process_time()
    from pydantic import ValidationError

    from usvstation.scenario import ScenarioError, format_validation_error, load_scenario

    try:  # validate input before NumPy and SciPy are imported, so bad input fails fast
        scenario = load_scenario(args.scenario)
        overrides = dict(args.settings)
        if args.time_budget is not None:
            overrides["time_budget_s"] = args.time_budget
        if args.max_evaluations is not None:
            overrides["max_evaluations"] = args.max_evaluations
        if args.planner == "iga":
            scenario.planner_options(**overrides)
    except ScenarioError as exc:
        raise CliError(f"invalid scenario: {exc}", EXIT_INVALID) from None
    except ValidationError as exc:
        raise CliError(f"invalid option: planner.{format_validation_error(exc)}",
                       EXIT_INVALID) from None
    from usvstation.planning.errors import NoFeasiblePlan
    from usvstation.planning.registry import PlannerOptionError, plan_with

    try:
        plan = plan_with(scenario, args.planner, args.seed, started=started, **overrides)
    except PlannerOptionError as exc:
        raise CliError(f"invalid option: {exc}", EXIT_INVALID) from None
    except ScenarioError as exc:
        raise CliError(f"invalid scenario: {exc}", EXIT_INVALID) from None
    except ValidationError as exc:
        raise CliError(f"invalid option: planner.{format_validation_error(exc)}",
                       EXIT_INVALID) from None
    except NoFeasiblePlan as exc:
        raise CliError(str(exc), EXIT_INFEASIBLE) from None
    text = json.dumps(plan.to_document(), indent=2)
    if args.out:
        try:
            args.out.write_text(text + "\n", encoding="utf-8")
        except OSError as exc:
            raise CliError(f"cannot write {args.out}: {exc.strerror}", EXIT_INVALID) from None
    if args.json or not sys.stdout.isatty():
        print(text)
    else:
        print(format_plan(plan))
    return EXIT_OK


def format_plan(plan: Plan) -> str:
    """A readable summary of a plan for a terminal."""
    m = plan.metrics
    clearance = "n/a" if m.min_clearance_m is None else f"{m.min_clearance_m:.2f} m"
    lines = [
        f"{plan.scenario}: {plan.planner} plan, seed {plan.seed}: "
        f"{len(plan.waypoints)} waypoints, {m.length_m:.1f} m in {m.duration_s:.1f} s, "
        f"min clearance {clearance}",
        (f"fitness {m['fitness']:.4f} (Fit_d {m['fit_d']:.3f}, Fit_T {m['fit_t']:.2f} s, "
         f"Fit_ang {m['fit_ang']:.3f}, Fit_mal {m['fit_mal']:.2f} m); "
         f"{m['generations']} generations in {m['elapsed_s'] * 1000:.0f} ms ({m['stop_reason']})")
        if "fit_d" in m else
        (f"normalisation index {m.get('normalization_index', 0):.3f}, total turn "
         f"{m.get('total_turn_deg', 0):.1f} deg; planned in {m['elapsed_s'] * 1000:.0f} ms"),
        "",
        f"{'#':>3} {'x (m)':>9} {'y (m)':>9} {'t (s)':>8} {'speed (m/s)':>12} "
        f"{'heading (deg)':>14}",
    ]
    for i, w in enumerate(plan.waypoints):
        lines.append(
            f"{i:>3} {w.x:>9.2f} {w.y:>9.2f} {w.t:>8.2f} {w.speed:>12.2f} "
            f"{w.heading_deg:>14.1f}"
        )
    return "\n".join(lines)


def _cmd_serve(args: argparse.Namespace) -> int:
    from pydantic import ValidationError

    from usvstation.config import ExposureError, LinkKeyError, Settings
    from usvstation.scenario import format_validation_error

    flags = {k: getattr(args, k) for k in Settings.model_fields
             if getattr(args, k, None) is not None}
    try:
        settings = Settings(**flags)
    except ValidationError as exc:
        raise CliError(f"invalid setting: {format_validation_error(exc)}", EXIT_INVALID) from None
    from usvstation.server import StartError, serve

    try:
        return serve(settings, announce=lambda msg: print(msg, flush=True))
    except (ExposureError, StartError) as exc:
        raise CliError(str(exc), EXIT_INVALID) from None
    except LinkKeyError as exc:
        raise CliError(str(exc), EXIT_INVALID) from None


def _cmd_sim(args: argparse.Namespace) -> int:
    import asyncio

    from usvstation.sim.cli import run_sim

    try:
        return asyncio.run(run_sim(args))
    except ValueError as exc:
        raise CliError(str(exc), EXIT_INVALID) from None


def _add_hil_parser(sub: Any) -> None:
    hil = sub.add_parser(
        "hil", help="run the boat's firmware binary in QEMU against the vessel model",
        description=(
            "Hardware in the loop: the STM32 firmware (protocol/c/boat, built with `make qemu` "
            "when needed) runs in QEMU's emulated Cortex-M3 (stm32vldiscovery); its "
            "navigation and thrust go over USART2 as MAVLink HIL messages to the 3-DOF vessel "
            "model in the scenario's current, and its radio (USART1) is served on a TCP port "
            "on 127.0.0.1 or a new pty for `serve --link socket://127.0.0.1:PORT`."),
    )
    where = hil.add_mutually_exclusive_group(required=True)
    where.add_argument("--port", type=int, help="serve the radio on this TCP port of 127.0.0.1 "
                       "(0: any free port, printed)")
    where.add_argument("--pty", action="store_true",
                       help="serve the radio on a new pseudo-terminal (its device is printed)")
    hil.add_argument("--scenario", default="case1",
                     help="scenario file or bundled name: origin, start pose, current (case1)")
    hil.add_argument("--link-key", type=Path, metavar="PATH",
                     help="signing key file shared with the station (radio and HIL frames)")
    hil.add_argument("--insecure-link", action="store_true",
                     help="provision the boat without a key (unsigned link)")
    hil.add_argument("--sim-speed", type=float, default=1.0,
                     help="the firmware's clock runs this many times the wall clock, 0.1-20 "
                     "(its link timeouts stay in wall time; default 1)")
    hil.add_argument("--boat-id", type=int, default=1, help="boat system id (default 1)")
    hil.add_argument("--station-id", type=int, default=255,
                     help="system id of the paired station (default 255)")
    hil.add_argument("--telemetry-hz", type=float, default=5.0,
                     help="telemetry rate in boat time, 0.2-50 (default 5)")
    hil.add_argument("--failsafe-s", type=float, default=3.0,
                     help="hold station after this long without the station (default 3)")
    hil.add_argument("--start-radius", type=float, default=10.0,
                     help="START refused farther than this from waypoint 0, m (default 10)")
    hil.add_argument("--seed", type=int, default=0, help="GPS noise seed")
    hil.add_argument("--no-gnss-time", action="store_true",
                     help="the GNSS gives no UTC: the boat's replay floor comes from its "
                     "flash page alone")
    hil.add_argument("--nv-file", type=Path, metavar="PATH",
                     help="the chip's signing-floor flash page image, kept across runs "
                     "(default: a file that lives as long as this run)")
    hil.add_argument("--image", type=Path, metavar="ELF",
                     help="firmware image (default: build protocol/c/boat/build/"
                     "usv_boat_qemu.elf)")
    hil.add_argument("--qemu-monitor", type=Path, metavar="PATH",
                     help="also serve QEMU's monitor on this Unix socket")
    hil.add_argument("--duration", type=float, default=None,
                     help="stop after this many seconds (default: run until interrupted)")


def _cmd_hil(args: argparse.Namespace) -> int:
    import asyncio
    import signal
    import time

    from usvstation.hil.bridge import HilBridge
    from usvstation.hil.provision import Provision
    from usvstation.hil.qemu import MACHINE, ImageError, build_image
    from usvstation.hil.runner import HilError, HilRun, run_hil
    from usvstation.link.wire import read_key
    from usvstation.scenario import ScenarioError, load_scenario
    from usvstation.sim.sensors import GpsNoise

    if args.port is not None and not 0 <= args.port <= 65535:
        raise CliError(f"--port: {args.port} is not a TCP port", EXIT_INVALID)
    if not 0.1 <= args.sim_speed <= 20:
        raise CliError(f"--sim-speed: {args.sim_speed:g} outside 0.1..20", EXIT_INVALID)
    if not 0.2 <= args.telemetry_hz <= 50:
        raise CliError(f"--telemetry-hz: {args.telemetry_hz:g} outside 0.2..50", EXIT_INVALID)
    if (args.link_key is None) == (not args.insecure_link):
        raise CliError("the boat needs --link-key PATH (the station's key) or, knowingly, "
                       "--insecure-link (not both)", EXIT_INVALID)
    try:
        scenario = load_scenario(args.scenario)
        key = read_key(args.link_key) if args.link_key is not None else None
        bridge = HilBridge.for_scenario(scenario, GpsNoise(seed=args.seed), boat_id=args.boat_id,
                                        key=key, gnss_time=not args.no_gnss_time)
        provision = Provision(
            boat_id=args.boat_id, station_id=args.station_id, key=key,
            telemetry_period_ms=round(1000 / args.telemetry_hz),
            link_timeout_ms=round(args.failsafe_s * 1000), start_radius_m=args.start_radius,
            max_speed_mps=bridge.vessel.params.top_speed, clock_speedup=args.sim_speed,
            nv_path=str(args.nv_file.resolve()) if args.nv_file is not None else "")
        provision.to_bytes()
        image = args.image if args.image is not None else build_image()
        if not image.is_file():
            raise ValueError(f"--image {image}: no such file")
    except ScenarioError as exc:
        raise CliError(f"invalid scenario: {exc}", EXIT_INVALID) from None
    except OSError as exc:
        raise CliError(f"link key {args.link_key}: {exc.strerror}", EXIT_INVALID) from None
    except (ValueError, ImageError) as exc:
        raise CliError(str(exc), EXIT_INVALID) from None

    def announce(where: str) -> None:
        print(f"usv-station hil: boat {args.boat_id} on {where} (firmware {image} in QEMU "
              f"{MACHINE}, {'signed' if key else 'UNSIGNED'}, sim speed {args.sim_speed:g}, "
              f"start of {scenario.name})", flush=True)

    def log(text: str) -> None:
        print(f"usv-station hil: {text}", file=sys.stderr, flush=True)

    async def main() -> str:
        stop = asyncio.Event()
        loop = asyncio.get_running_loop()
        for sig in (signal.SIGINT, signal.SIGTERM):
            loop.add_signal_handler(sig, stop.set)
        if args.duration is not None:
            loop.call_later(args.duration, stop.set)
        return await run_hil(HilRun(image, provision, None if args.pty else args.port,
                                    args.qemu_monitor), bridge, unix_time=time.time,
                             announce=announce, log=log, stop=stop)

    try:
        why = asyncio.run(main())
    except HilError as exc:
        raise CliError(str(exc), EXIT_INVALID) from None
    st = bridge.stats
    log(f"{why}: firmware time {st.firmware_time_s:.1f} s, {st.fixes} fixes, "
        f"{st.resets} resets, refused {dict(st.refused) or 0}")
    return EXIT_OK if why == "stopped" else EXIT_ERROR  # QEMU or a UART ended on its own


def _cmd_link_key(args: argparse.Namespace) -> int:
    from usvstation.link.wire import write_key

    try:
        write_key(args.path)
    except FileExistsError:
        raise CliError(f"{args.path} exists; refusing to overwrite a key", EXIT_INVALID) from None
    except OSError as exc:
        raise CliError(f"cannot write {args.path}: {exc.strerror}", EXIT_INVALID) from None
    print(f"wrote a new link key to {args.path}; give the same file to the boat")
    return EXIT_OK


def _cmd_bench(args: argparse.Namespace) -> int:
    if args.name == "live":
        from usvstation.bench.live import run_live_bench

        if args.episodes < 1:
            raise CliError(f"--episodes: must be at least 1 (got {args.episodes})", EXIT_INVALID)
        result = run_live_bench(episodes=args.episodes,
                                progress=lambda msg: print(msg, file=sys.stderr, flush=True))
        print(json.dumps(result, indent=2))
        return EXIT_OK
    if args.name == "compare":
        return _cmd_bench_compare(args)
    if args.name == "server":
        from usvstation.bench.server import run_server_bench

        result = run_server_bench(quick=args.quick, base_port=args.base_port,
                                  progress=lambda msg: print(msg, file=sys.stderr, flush=True))
        print(json.dumps(result, indent=2))
        return EXIT_OK
    if args.name == "link":
        from usvstation.bench.link import run_link_bench

        result = run_link_bench(quick=args.quick,
                                progress=lambda msg: print(msg, file=sys.stderr, flush=True))
        print(json.dumps(result, indent=2))
        return EXIT_OK
    if args.name == "arrival":
        return _cmd_bench_arrival(args)
    if args.name == "tracking":
        from usvstation.bench.tracking import run_tracking_bench

        result = run_tracking_bench(progress=lambda msg: print(msg, file=sys.stderr, flush=True),
                                    with_manoeuvres=args.manoeuvres, quick=args.quick)
        print(json.dumps(result, indent=2))
        return EXIT_OK
    from usvstation.bench.planner import render_markdown, run_planner_bench

    if args.markdown:
        return _print_markdown(render_markdown, args.markdown)
    try:
        result = run_planner_bench(
            folder=args.scenarios, seeds=args.seeds, random_count=args.random, quick=args.quick,
            progress=lambda msg: print(msg, file=sys.stderr, flush=True),
        )
    except (FileNotFoundError, ValueError) as exc:
        raise CliError(str(exc), EXIT_INVALID) from None
    print(json.dumps(result, indent=2))
    return EXIT_OK


def _cmd_bench_arrival(args: argparse.Namespace) -> int:
    from usvstation.bench.arrival import render_markdown, run_arrival_bench

    if args.markdown:
        return _print_markdown(render_markdown, args.markdown)
    if args.workers < 1:
        raise CliError(f"--workers: must be at least 1 (got {args.workers})", EXIT_INVALID)
    families = tuple(f.strip() for f in args.families.split(",")) if args.families else None
    seeds: dict[str, Any] = {}
    if args.plan_seeds:
        try:
            seeds["seeds"] = tuple(int(s) for s in args.plan_seeds.split(","))
        except ValueError:
            raise CliError(f"--plan-seeds: comma-separated integers (got {args.plan_seeds!r})",
                           EXIT_INVALID) from None
    try:
        result = run_arrival_bench(families=families, quick=args.quick, workers=args.workers,
                                   progress=lambda msg: print(msg, file=sys.stderr, flush=True),
                                   **seeds)
    except ValueError as exc:
        raise CliError(str(exc), EXIT_INVALID) from None
    print(json.dumps(result, indent=2))
    return EXIT_OK


def _print_markdown(render: Any, saved: Path) -> int:
    """Print a benchmark's RESULTS.md tables from its saved --json output."""
    try:
        print(render(json.loads(saved.read_text(encoding="utf-8"))), end="")
    except (OSError, ValueError, KeyError) as exc:
        raise CliError(f"cannot render {saved}: {exc}", EXIT_INVALID) from None
    return EXIT_OK


def _cmd_bench_compare(args: argparse.Namespace) -> int:
    from usvstation.bench.compare import render_markdown, run_compare

    if args.markdown:
        return _print_markdown(render_markdown, args.markdown)
    try:
        result = run_compare(
            planners=args.planners.split(",") if args.planners else None,
            families=args.families.split(",") if args.families else None,
            seeds=args.seeds if args.seeds != 5 else 2, hidden=args.hidden, plots=args.plots,
            ompl=args.ompl, first_seed=args.first_seed, hidden_from=args.hidden_from,
            track=not args.no_track,
            sweep=[int(c) for c in args.sweep.split(",")] if args.sweep else None,
            sweep_maps=args.sweep_maps,
            curves=[float(b) for b in args.curves.split(",")] if args.curves else None,
            curve_maps=args.curve_maps,
            progress=lambda msg: print(msg, file=sys.stderr, flush=True))
    except ValueError as exc:
        raise CliError(str(exc), EXIT_INVALID) from None
    print(json.dumps(result, indent=2))
    return EXIT_OK


def _add_campaign_parser(sub: Any) -> None:
    camp = sub.add_parser(
        "campaign", help="run or report a campaign of many planning episodes",
        description=("run SPEC.toml: the product of planners, families, seeds and disturbances, "
                     "on a local process pool (default) or Ray; resumable; results in one "
                     "Parquet file. report DIR: success table with confidence intervals."))
    csub = camp.add_subparsers(dest="action", metavar="ACTION", required=True)
    run = csub.add_parser("run", help="run (or resume) a campaign")
    run.add_argument("spec", type=Path, help="campaign TOML file (docs/planners.md)")
    run.add_argument("--out", type=Path, required=True, help="campaign folder")
    run.add_argument("--ray", metavar="auto|local|ADDRESS",
                     help="run on Ray: 'local' starts one here, 'auto' or an address joins one")
    run.add_argument("--workers", type=int, default=None, help="pool size (default CPU count)")
    run.add_argument("--no-progress", action="store_true", help="no progress bar")
    rep = csub.add_parser("report", help="tables with confidence intervals")
    rep.add_argument("dir", type=Path, help="campaign folder")
    rep.add_argument("--json", action="store_true", help="print JSON")
    rep.add_argument("--plots", action="store_true", help="also write SVG box plots into DIR")


def _cmd_campaign(args: argparse.Namespace) -> int:
    from usvstation.campaign.report import format_report, report
    from usvstation.campaign.run import CampaignError, run_campaign

    try:
        if args.action == "run":
            summary = run_campaign(args.spec, args.out, ray=args.ray, workers=args.workers,
                                   progress=not args.no_progress)
            print(json.dumps(summary, indent=2))
            return EXIT_OK
        result = report(args.dir, plots=args.plots)
    except CampaignError as exc:
        raise CliError(str(exc), EXIT_INVALID) from None
    print(json.dumps(result, indent=2) if args.json else format_report(result))
    return EXIT_OK


def _add_trial_parser(sub: Any) -> None:
    trial = sub.add_parser(
        "trial", help="sea trials: many complete recoveries in simulated time",
        usage="usv-station trial SPEC.toml --out DIR [--ray local|ADDRESS] [--workers N]\n"
              "       usv-station trial report DIR [--json]",
        description=("SPEC.toml --out DIR: run (or resume) the spec's seeded episodes, each a "
                     "whole recovery at sea (planner, signed link, simulated boat, telemetry, "
                     "monitor, re-plan, arrival) in simulated time, on a process pool or Ray; "
                     "one JSON line per episode in DIR/episodes.jsonl. report DIR: outcome "
                     "counts and arrival percentiles with 95 %% intervals (docs/trials.md)."))
    trial.add_argument("target", nargs="+", metavar="SPEC.toml | report DIR")
    trial.add_argument("--out", type=Path, help="trial folder (with SPEC.toml)")
    trial.add_argument("--ray", metavar="auto|local|ADDRESS",
                       help="run on Ray: 'local' starts one here, 'auto' or an address joins one")
    trial.add_argument("--workers", type=int, default=None, help="pool size (default CPU count)")
    trial.add_argument("--no-progress", action="store_true", help="no progress bar")
    trial.add_argument("--json", action="store_true", help="report: print JSON")


def _cmd_trial(args: argparse.Namespace) -> int:
    from usvstation.trial.report import format_report, report
    from usvstation.trial.run import run_trial
    from usvstation.trial.spec import TrialError

    target = args.target
    try:
        if target[0] == "report":
            if len(target) != 2:
                raise CliError("report takes one folder: usv-station trial report DIR",
                               EXIT_INVALID)
            result = report(Path(target[1]))
            print(json.dumps(result, indent=2) if args.json else format_report(result))
            return EXIT_OK
        if len(target) != 1 or args.out is None:
            raise CliError("usage: usv-station trial SPEC.toml --out DIR", EXIT_INVALID)
        summary = run_trial(Path(target[0]), args.out, ray=args.ray, workers=args.workers,
                            progress=not args.no_progress)
    except TrialError as exc:
        raise CliError(str(exc), EXIT_INVALID) from None
    print(json.dumps(summary, indent=2))
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
