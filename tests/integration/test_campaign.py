"""Campaigns and sea trials: pool and Ray give the same episodes; a re-run skips finished
work. One local Ray serves the module (it takes many seconds to start)."""

import json

import pyarrow.parquet as pq
import pytest

from usvstation.campaign.report import report, wilson
from usvstation.campaign.run import run_campaign

SPEC = """
planners = ["rrt-star", "vpf-rrt-star"]
families = ["traps", "recovery"]
seeds = 2
hidden = 0
disturbances = [0.0]
options = { "rrt-star" = { iterations = 400 }, "vpf-rrt-star" = { iterations = 400 } }
"""
COMPARED = ("key", "success", "length_m", "normalization_index", "duration_s",
            "min_clearance_m", "total_turn_deg", "waypoints")


def _rows(folder):
    rows = pq.read_table(folder / "results.parquet").to_pylist()
    return {r["key"]: tuple(r[k] for k in COMPARED) for r in rows}


@pytest.fixture(scope="module")
def pool_run(tmp_path_factory):
    d = tmp_path_factory.mktemp("camp")
    spec = d / "spec.toml"
    spec.write_text(SPEC)
    summary = run_campaign(spec, d / "pool", workers=2, progress=False)
    return spec, d, summary


def test_pool_campaign_runs_every_episode_once_and_resumes(pool_run):
    spec, d, summary = pool_run
    assert summary["episodes"] == 28 and summary["ran"] == 28 and summary["skipped"] == 0
    again = run_campaign(spec, d / "pool", workers=2, progress=False)
    assert again["ran"] == 0 and again["skipped"] == 28
    assert len(_rows(d / "pool")) == 28


def test_interrupted_campaign_resumes_without_repeating(pool_run):
    spec, d, _ = pool_run
    part = d / "part"
    part.mkdir()
    lines = (d / "pool" / "episodes.jsonl").read_text().splitlines()
    (part / "episodes.jsonl").write_text("\n".join(lines[:11]) + "\n" + lines[11][:20])
    resumed = run_campaign(spec, part, workers=2, progress=False)
    assert resumed["skipped"] == 11 and resumed["ran"] == 17
    assert _rows(part) == _rows(d / "pool")


@pytest.fixture(scope="module")
def local_ray():
    """Ray on this machine, started once; the runners use it as it is (`--ray local` starts
    one only when none runs)."""
    ray = pytest.importorskip("ray")
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False,
             _system_config={"worker_niceness": 0})  # as `--ray local` starts it
    try:
        yield ray
    finally:
        ray.shutdown()


# Ray on a machine at load 11: past the suite's 300 s
@pytest.mark.timeout(1200)
def test_ray_local_campaign_equals_pool(tmp_path, local_ray):
    spec = tmp_path / "spec.toml"
    # 20 episodes: 2 planners x 5 recoveries (4 public + 1 seeded random) x 2 seeds
    spec.write_text(SPEC.replace('families = ["traps", "recovery"]', 'families = ["recovery"]')
                    .replace("hidden = 0", "hidden = 1"))
    pool = run_campaign(spec, tmp_path / "pool", workers=2, progress=False)
    ray_run = run_campaign(spec, tmp_path / "ray", ray="local", workers=2, progress=False)
    assert pool["episodes"] == ray_run["episodes"] == ray_run["ran"] == 20
    assert _rows(tmp_path / "ray") == _rows(tmp_path / "pool")


# Ray on a machine at load 11: past the suite's 300 s
@pytest.mark.timeout(1200)
def test_ray_local_trial_gives_the_pool_lines(tmp_path, local_ray):
    from usvstation.trial.run import run_trial

    spec = tmp_path / "trial.toml"
    spec.write_text('name = "tiny"\nepisodes = 2\nseed = 3\nbase = ["case3"]\n'
                    'time_limit_s = 120\n[families]\ncurrent_speed = [0.0, 0.2]\n',
                    encoding="utf-8")
    run_trial(spec, tmp_path / "pool", workers=1, progress=False)
    assert run_trial(spec, tmp_path / "ray", ray="local", workers=2, progress=False)["ran"] == 2

    def lines(folder):
        return sorted((folder / "episodes.jsonl").read_text().splitlines())

    assert lines(tmp_path / "ray") == lines(tmp_path / "pool")


def test_report_has_success_table_with_intervals(pool_run):
    _, d, _ = pool_run
    rep = report(d / "pool")
    assert rep["episodes"] == 28
    entry = {(e["planner"], e["family"]): e for e in rep["table"]}
    e = entry[("rrt-star", "recovery")]
    assert e["episodes"] == 8
    lo, hi = e["success_ci95"]
    assert lo <= e["success_rate"] <= hi
    assert json.loads(json.dumps(rep)) == rep


def test_wilson_interval_known_value():
    lo, hi = wilson(9, 10)
    assert (round(lo, 4), round(hi, 4)) == (0.5958, 0.9821)
