"""`usv-station plan`: exit codes, one-line errors without tracebacks, JSON output."""

import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

SCRIPT = Path(sys.executable).parent / "usv-station"


def run(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess:
    return subprocess.run(
        [str(SCRIPT), *args], capture_output=True, text=True, timeout=60, cwd=cwd
    )


def write(tmp_path: Path, data) -> Path:
    path = tmp_path / "scenario.json"
    path.write_text(json.dumps(data) if not isinstance(data, str) else data)
    return path


def test_help_lists_the_commands():
    out = run("--help")
    assert out.returncode == 0
    assert "plan" in out.stdout and "bench" in out.stdout


def test_plan_prints_the_plan_json(tmp_path):
    out = run("plan", "case1", "--json", "--seed", "3", "--out", str(tmp_path / "p.json"))
    assert out.returncode == 0, out.stderr
    plan = json.loads(out.stdout)
    assert plan["scenario"] == "case1" and plan["seed"] == 3
    assert json.loads((tmp_path / "p.json").read_text()) == plan


def test_plan_of_a_file_with_an_option_override(tmp_path):
    data = {"name": "mine", "start": {"x": 50.0, "y": -8.0},
            "obstacles": [{"x": 25.0, "y": -4.0, "radius": 2.0}]}
    out = run("plan", str(write(tmp_path, data)), "--set", "population=40")
    assert out.returncode == 0, out.stderr
    plan = json.loads(out.stdout)  # piped output is JSON even without --json
    assert plan["scenario"] == "mine"
    assert abs(plan["waypoints"][-1]["heading_deg"] - 180.0) <= 10.0


def assert_one_line_error(out: subprocess.CompletedProcess, code: int, *fragments: str):
    assert out.returncode == code
    assert out.stdout == ""
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1, out.stderr
    assert "Traceback" not in out.stderr
    for fragment in fragments:
        assert fragment in lines[0]


def test_invalid_field_exits_2(tmp_path):
    data = {"name": "bad", "start": {"x": 50.0, "y": 0.0},
            "obstacles": [{"x": 20.0, "y": 0.0, "radius": -1}]}
    assert_one_line_error(run("plan", str(write(tmp_path, data))), 2,
                          "obstacles[0].radius", "greater than 0")


def test_wrong_type_and_unknown_field_exit_2(tmp_path):
    data = {"name": "bad", "start": {"x": "far", "y": 0.0}, "wind": 3}
    assert_one_line_error(run("plan", str(write(tmp_path, data))), 2,
                          "start.x", "wind: unknown field")


def test_bad_json_and_missing_file_exit_2(tmp_path):
    assert_one_line_error(run("plan", str(write(tmp_path, "{oops"))), 2, "not valid JSON")
    assert_one_line_error(run("plan", str(tmp_path / "missing.json")), 2, "no such scenario file")


def test_bad_option_exits_2():
    assert_one_line_error(run("plan", "case1", "--set", "population=1"), 2,
                          "planner.population", "greater than or equal to 4")
    assert_one_line_error(run("plan", "case1", "--set", "colour=red"), 2, "planner.colour")


def test_enclosed_goal_exits_3(tmp_path):
    ring = [{"x": round(9 * math.cos(2 * math.pi * i / 10), 3),
             "y": round(9 * math.sin(2 * math.pi * i / 10), 3), "radius": 3.0} for i in range(10)]
    data = {"name": "enclosed", "kind": "transit", "start": {"x": 60.0, "y": 5.0},
            "goal": {"x": 0.0, "y": 0.0}, "obstacles": ring}
    assert_one_line_error(run("plan", str(write(tmp_path, data))), 3,
                          "no feasible plan", "the goal is enclosed")


@pytest.mark.parametrize("argv", [["plan"], ["plan", "case1", "--planner", "rrt"], ["fly"]])
def test_usage_errors_exit_2(argv):
    out = run(*argv)
    assert out.returncode == 2 and "usage:" in out.stderr


def test_every_setting_is_a_serve_flag_and_flags_reach_the_settings():
    from usvstation.cli import build_parser
    from usvstation.config import Settings

    args = build_parser().parse_args([
        "serve", "--plan-queue", "5", "--no-sim-gnss-error", "--allowed-hosts", "a.local,b",
        "--nmea", "udp://0.0.0.0:10110", "--nmea", "tcp://127.0.0.1:2000", "--replan", "auto",
        "--charts", "charts", "--insecure-link", "--keep-alive-s", "2.5"])
    given = {k: getattr(args, k) for k in Settings.model_fields if getattr(args, k) is not None}
    assert given == {"plan_queue": 5, "sim_gnss_error": False, "allowed_hosts": ["a.local", "b"],
                     "nmea": ["udp://0.0.0.0:10110", "tcp://127.0.0.1:2000"],
                     "replan": "auto", "charts_dir": Path("charts"), "insecure_link": True,
                     "keep_alive_s": 2.5}
    s = Settings(**given)
    assert (s.plan_queue, s.sim_gnss_error, s.keep_alive_s) == (5, False, 2.5)
    help_text = run("serve", "--help").stdout
    flags = {f"--{name.replace('_', '-')}" for name in Settings.model_fields} - {"--charts-dir"}
    assert all(flag in help_text for flag in flags | {"--charts"})
    assert "plans queued or running at most (then 429) (default 32)" in " ".join(
        help_text.split())
