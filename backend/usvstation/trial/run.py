"""`usv-station trial SPEC.toml --out DIR`: every episode of the spec once, on a process pool
or Ray, resumable.

Each finished episode is appended (one JSON line, flushed) to DIR/episodes.jsonl as it
completes; a re-run skips every key already there, so a killed trial resumes where it
stopped. An episode is a function of the spec's seed and its index alone (trial/episode.py),
so the pool and Ray give the same lines, in whatever order they finish.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from usvstation.campaign.run import append_rows, done_keys, pool_results, ray_results
from usvstation.clock import Stopwatch
from usvstation.trial.episode import Episode, draw_episode, run_episode
from usvstation.trial.spec import TrialSpec, load_spec


def episodes(spec: TrialSpec) -> list[Episode]:
    return [draw_episode(spec, i) for i in range(spec.episodes)]


def run_trial(spec_path: Path, out: Path, ray: str | None = None, workers: int | None = None,
              progress: bool = True) -> dict[str, Any]:
    """Run the episodes of SPEC not yet in OUT; a summary (counts, where the lines are)."""
    spec = load_spec(spec_path)
    out.mkdir(parents=True, exist_ok=True)
    (out / "spec.json").write_text(spec.model_dump_json(indent=2) + "\n", encoding="utf-8")
    log = out / "episodes.jsonl"
    all_eps = episodes(spec)
    done = done_keys(log)
    todo = [ep for ep in all_eps if ep.key not in done]
    workers = workers or os.cpu_count() or 1
    results = (ray_results(run_episode, todo, ray, workers) if ray
               else pool_results(run_episode, todo, workers))
    watch = Stopwatch()
    ran = append_rows(log, results, total=len(all_eps), initial=len(all_eps) - len(todo),
                      desc=spec.name, progress=progress)
    return {"name": spec.name, "episodes": len(all_eps), "skipped": len(all_eps) - len(todo),
            "ran": ran, "elapsed_s": round(watch.elapsed(), 3), "lines": str(log),
            "backend": f"ray:{ray}" if ray else f"pool:{workers}"}
