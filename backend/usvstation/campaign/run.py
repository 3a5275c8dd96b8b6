"""Run a campaign: every episode once, on a process pool or Ray, resumable.

Finished episodes are appended (one JSON line each, flushed) to
DIR/episodes.jsonl as they complete, so an interrupted campaign loses at most
the episodes in flight; a re-run skips every key already there. At the end
all rows go to one Parquet file, DIR/results.parquet (pyarrow).
"""

from __future__ import annotations

import json
import os
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from pathlib import Path
from typing import Any, TypeVar

from usvstation.campaign.spec import CampaignError, CampaignSpec, load_spec
from usvstation.clock import Stopwatch

__all__ = ["CampaignError", "done_keys", "episodes", "pool_results", "ray_results",
           "run_campaign", "run_episode", "write_parquet"]
T = TypeVar("T")
R = TypeVar("R")


def episodes(spec: CampaignSpec) -> list[dict[str, Any]]:
    """The product planners x families' scenarios x seeds x disturbances, in a stable order."""
    from usvstation.bench.compare import family_scenarios

    out = []
    for fam in spec.families:
        names = [s.name for s in family_scenarios(fam, spec.hidden, spec.dense_maps)]
        for sc in names:
            for dist in spec.disturbances:
                for pl in spec.planners:
                    for seed in range(1, spec.seeds + 1):
                        key = f"{pl}|{fam}|{sc}|{seed}|{dist:g}"
                        out.append({"key": key, "planner": pl, "family": fam, "scenario": sc,
                                    "seed": seed, "current": dist,
                                    "current_dir_deg": spec.current_dir_deg,
                                    "options": spec.planner_options(pl),
                                    "hidden": spec.hidden, "dense_maps": spec.dense_maps})
    return out


_SCENARIOS: dict[tuple, Any] = {}


def run_episode(ep: dict[str, Any]) -> dict[str, Any]:
    """One episode in a worker: plan with the registry; a flat row of metrics."""
    import numpy as np

    from usvstation.bench.compare import family_scenarios
    from usvstation.planning.errors import NoFeasiblePlan
    from usvstation.planning.registry import plan_with
    from usvstation.planning.seeds.common import path_metrics

    cache_key = (ep["family"], ep["hidden"], ep["dense_maps"])
    if cache_key not in _SCENARIOS:
        _SCENARIOS[cache_key] = {s.name: s for s in family_scenarios(*cache_key)}
    sc = _SCENARIOS[cache_key][ep["scenario"]]
    if ep["current"]:
        env = sc.environment.model_copy(update={"current_speed": ep["current"],
                                                "current_dir_deg": ep["current_dir_deg"]})
        sc = sc.model_copy(update={"environment": env})
    row = {k: ep[k] for k in ("key", "planner", "family", "scenario", "seed", "current")}
    watch = Stopwatch()
    try:
        plan = plan_with(sc, ep["planner"], ep["seed"], **ep["options"])
    except NoFeasiblePlan as exc:
        return {**row, "success": False, "error": str(exc)[:300], "length_m": None,
                "normalization_index": None, "duration_s": None, "min_clearance_m": None,
                "total_turn_deg": None, "max_turn_deg": None, "waypoints": 0,
                "plan_time_ms": watch.elapsed() * 1000.0, "replans": 0}
    pts = np.array([[w.x, w.y] for w in plan.waypoints])
    pm = path_metrics(pts)
    m = plan.metrics
    return {**row, "success": True, "error": None, "length_m": pm["length_m"],
            "normalization_index": pm["normalization_index"], "duration_s": m.duration_s,
            "min_clearance_m": m.min_clearance_m, "total_turn_deg": pm["total_turn_deg"],
            "max_turn_deg": pm["max_turn_deg"], "waypoints": len(plan.waypoints),
            "plan_time_ms": watch.elapsed() * 1000.0,
            "replans": int(m.get("replans", 0))}


def done_keys(path: Path) -> set[str]:
    keys = set()
    if path.exists():
        for line in path.read_text(encoding="utf-8").splitlines():
            try:
                keys.add(json.loads(line)["key"])
            except (ValueError, KeyError):
                continue  # a line cut by an interruption is re-run
    return keys


def read_rows(folder: Path) -> list[dict[str, Any]]:
    rows, seen = [], set()
    path = folder / "episodes.jsonl"
    if path.exists():
        for line in path.read_text(encoding="utf-8").splitlines():
            try:
                r = json.loads(line)
            except ValueError:
                continue
            if r["key"] not in seen:
                seen.add(r["key"])
                rows.append(r)
    return rows


def write_parquet(folder: Path) -> Path:
    import pyarrow as pa
    import pyarrow.parquet as pq

    rows = sorted(read_rows(folder), key=lambda r: r["key"])
    out = folder / "results.parquet"
    pq.write_table(pa.Table.from_pylist(rows), out)
    return out


def pool_results(fn: Callable[[T], R], todo: Sequence[T], workers: int) -> Iterator[R]:
    """`fn` of every item on a pool of `workers` processes, as they finish."""
    import multiprocessing

    ctx = multiprocessing.get_context("forkserver")
    with ProcessPoolExecutor(workers, mp_context=ctx) as pool:
        pending = {pool.submit(fn, ep) for ep in todo}
        try:
            while pending:
                done, pending = wait(pending, return_when=FIRST_COMPLETED)
                for f in done:
                    yield f.result()
        finally:
            for f in pending:
                f.cancel()


def ray_results(fn: Callable[[T], R], todo: Sequence[T], address: str,
                workers: int | None) -> Iterator[R]:
    """`fn` of every item as Ray tasks (`address` 'local': a Ray of this machine's cores),
    as they finish."""
    try:
        import ray
    except ImportError:
        raise CampaignError("--ray: Ray is not installed (pip install ray)") from None
    started = False
    if not ray.is_initialized():
        if address == "local":
            # at the process pool's priority: Ray's default worker nice of 15 lets any busy
            # neighbour starve a local campaign (two sim episodes took over 20 min at load 11)
            ray.init(num_cpus=workers or os.cpu_count(), include_dashboard=False,
                     log_to_driver=False, _system_config={"worker_niceness": 0})
        else:
            ray.init(address=None if address == "auto" else address, log_to_driver=False)
        started = True
    try:
        remote = ray.remote(fn)
        pending = [remote.remote(ep) for ep in todo]
        while pending:
            done, pending = ray.wait(pending, num_returns=1)
            for ref in done:
                yield ray.get(ref)
    finally:
        if started:
            ray.shutdown()


def append_rows(log: Path, rows: Iterator[dict[str, Any]], *, total: int, initial: int,
                desc: str, progress: bool) -> int:
    """Append each row to the JSON-lines `log` as it comes (flushed: an interruption loses
    only what is in flight), with a progress bar on stderr; the number appended."""
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=total, initial=initial, unit="ep", desc=desc, dynamic_ncols=True)
    ran = 0
    with log.open("a", encoding="utf-8") as fh:
        if log.stat().st_size and not log.read_bytes().endswith(b"\n"):
            fh.write("\n")  # a line cut by an interruption stays apart (and is re-run)
        for row in rows:
            fh.write(json.dumps(row) + "\n")
            fh.flush()
            ran += 1
            if bar is not None:
                bar.update(1)
    if bar is not None:
        bar.close()
    return ran


def run_campaign(spec_path: Path, out: Path, ray: str | None = None, workers: int | None = None,
                 progress: bool = True) -> dict[str, Any]:
    """Run the episodes of SPEC not yet in OUT; return a summary (counts and the Parquet path)."""
    spec = load_spec(spec_path)
    out.mkdir(parents=True, exist_ok=True)
    (out / "spec.json").write_text(spec.model_dump_json(indent=2) + "\n", encoding="utf-8")
    log = out / "episodes.jsonl"
    all_eps = episodes(spec)
    done = done_keys(log)
    todo = [ep for ep in all_eps if ep["key"] not in done]
    workers = workers or os.cpu_count() or 1
    results = (ray_results(run_episode, todo, ray, workers) if ray
               else pool_results(run_episode, todo, workers))
    watch = Stopwatch()
    ran = append_rows(log, results, total=len(all_eps), initial=len(all_eps) - len(todo),
                      desc=spec.name, progress=progress)
    parquet = write_parquet(out)
    return {"name": spec.name, "episodes": len(all_eps), "skipped": len(all_eps) - len(todo),
            "ran": ran, "elapsed_s": round(watch.elapsed(), 3),
            "parquet": str(parquet), "backend": f"ray:{ray}" if ray else f"pool:{workers}"}
