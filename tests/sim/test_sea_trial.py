"""Whole recoveries at sea in simulated time: the station in-process (planner, signed link,
simulated boat, telemetry, monitor, re-plan policy, hot swap), judged on the truth."""

from __future__ import annotations

import json

import pytest

from usvstation.cli import main
from usvstation.trial.episode import draw_episode, run_episode
from usvstation.trial.spec import TrialSpec


def _turning_target(base: str) -> TrialSpec:
    """A target that turns onto the boat's way after the plan was made (an AIS class A
    ship), the re-plan policy auto: the monitor warns, re-plans and the boat hot-swaps."""
    return TrialSpec(name="turning", episodes=1, base=[base], replan="auto",
                     families={"traffic": ["turning"]})


@pytest.mark.parametrize("base", ["case1", "case2"])
def test_a_target_turning_onto_the_plan_is_replanned_around_and_the_boat_arrives(base):
    """plan -> upload -> START -> a crossing AIS target -> re-plan -> hot swap -> arrival,
    in simulated time; the same episode twice gives the same line, field for field."""
    episode = draw_episode(_turning_target(base), 0)
    first, second = run_episode(episode), run_episode(episode)
    assert first == second
    assert first["outcome"] == "arrived", first
    assert first["replans_applied"] >= 1
    assert first["min_hull_clearance_m"] > 0.0
    assert first["states"] == ["IDLE", "READY", "RUNNING", "DONE"]
    assert first["arrival_offset_m"] <= 0.5 and first["arrival_heading_deg"] <= 8.0


def test_radio_silence_sends_the_boat_to_failsafe_and_the_mate_resumes_it():
    """A 4 s radio silence mid-run (the boat fails safe after 3 s without the station);
    the link comes back, the mate resumes, the boat finishes."""
    spec = TrialSpec(name="silence", episodes=1, base=["case1"], families={
        "link_loss": ["burst"]})
    episode = draw_episode(spec, 0)
    cond = episode.conditions.__class__(**{**episode.conditions.__dict__,
                                           "link_loss": (8.0, 4.0)})
    line = run_episode(episode.__class__(**{**episode.__dict__, "conditions": cond}))
    assert "FAILSAFE" in line["states"]
    assert line["states"][-1] == "DONE" and line["outcome"] == "arrived"


def _spec(tmp_path, episodes: int) -> str:
    path = tmp_path / "spec.toml"
    path.write_text(f'name = "tiny"\nepisodes = {episodes}\nseed = 3\nbase = ["case2"]\n'
                    'time_limit_s = 200\n[families]\ntraffic = ["none", "crossing"]\n'
                    'current_speed = [0.0, 0.2]\n', encoding="utf-8")
    return str(path)


def test_trial_runs_resumes_and_reports(tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["trial", _spec(tmp_path, 2), "--out", str(out), "--no-progress",
                 "--workers", "1"]) == 0
    assert json.loads(capsys.readouterr().out)["ran"] == 2
    lines = (out / "episodes.jsonl").read_text().splitlines()
    assert main(["trial", _spec(tmp_path, 3), "--out", str(out), "--no-progress",
                 "--workers", "1"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert (summary["skipped"], summary["ran"]) == (2, 1)  # a killed trial resumes
    assert (out / "episodes.jsonl").read_text().splitlines()[:2] == lines
    assert main(["trial", "report", str(out), "--json"]) == 0
    rep = json.loads(capsys.readouterr().out)
    assert rep["episodes"] == 3
    assert set(rep["outcomes"]) == {"arrived", "go_around", "aborted", "contact", "failsafe"}
    assert sum(rep["outcomes"].values()) == 3
    assert set(rep["arrival"]) >= {"p50_offset_m", "p95_offset_m", "p95_heading_deg"}


def test_trial_errors_are_one_line(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text('episodes = 2\n[families]\ntraffic = ["pirates"]\n', encoding="utf-8")
    assert main(["trial", str(bad), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.endswith("families.traffic: unknown value 'pirates'; available: none, crossing, "
                        "head_on, overtaking, turning")
    assert "\n" not in err
    assert main(["trial", "report", str(tmp_path / "nothing")]) == 2
    assert "no episodes.jsonl" in capsys.readouterr().err
    assert main(["trial", str(bad)]) == 2  # no --out
    assert "usage: usv-station trial SPEC.toml --out DIR" in capsys.readouterr().err

