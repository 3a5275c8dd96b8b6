"""`usv-station bench planner`: plan times, ablations EG1-EG4, random validity, DEAP baseline.

Every figure comes from one run of this process, so ratios compare like
with like on a machine whose absolute speed drifts.
"""

from __future__ import annotations

import datetime as dt
import os
import platform
import statistics
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from usvstation.bench.deap_baseline import run_deap
from usvstation.bench.scenarios import random_recovery, random_transit
from usvstation.planning.encoding import GeneLayout
from usvstation.planning.fitness import Evaluator
from usvstation.planning.iga import _foundation, run_iga
from usvstation.planning.options import IGAOptions
from usvstation.planning.plan import NoFeasiblePlan, plan_scenario
from usvstation.planning.problem import Problem
from usvstation.planning.validate import plan_violations
from usvstation.scenario import Scenario, bundled_scenario_dir, load_scenario

TERMS = ("fitness", "fit_d", "fit_t", "fit_ang", "fit_mal")
Progress = Callable[[str], None]


def run_planner_bench(
    folder: Path | None = None, seeds: int = 5, random_count: int = 100, quick: bool = False,
    progress: Progress = lambda _msg: None,
) -> dict[str, Any]:
    """Run the whole planner benchmark and return its figures."""
    scenarios = load_folder(folder or bundled_scenario_dir())
    seed_list = list(range(1, max(seeds, 1) + 1))
    ablation_seeds = seed_list[: 1 if quick else 3]
    deap_seeds = seed_list[: 1 if quick else 3]
    deap_max = 20 if quick else 500
    out: dict[str, Any] = {
        "command": "usv-station bench planner --json" + (" --quick" if quick else ""),
        "machine": machine_info(),
        "scenarios": [],
        "ablation": {"seeds": ablation_seeds},
        "baseline": {"library": "deap", "seeds": deap_seeds, "max_generations": deap_max,
                     "runs": []},
    }
    ablation_rows = []
    for scenario in scenarios:
        progress(f"planning {scenario.name} with {len(seed_list)} seeds")
        out["scenarios"].append(bench_scenario(scenario, seed_list))
        progress(f"ablations EG1-EG4 on {scenario.name}")
        ablation_rows.append(bench_ablations(scenario, ablation_seeds))
        progress(f"DEAP baseline on {scenario.name}")
        out["baseline"]["runs"].extend(bench_deap(scenario, deap_seeds, deap_max))
    out["ablation"].update(ablation_tables(ablation_rows))
    out["baseline"]["summary"] = baseline_summary(out["baseline"]["runs"])
    if random_count > 0:
        progress(f"validity on {random_count} random recoveries and transits")
        out["random"] = bench_random(random_count, max(2, random_count // 10))
    return out


def load_folder(folder: Path) -> list[Scenario]:
    folder = Path(folder)
    if not folder.is_dir():
        raise FileNotFoundError(f"{folder}: no such scenario folder")
    files = sorted(folder.glob("*.json"))
    if not files:
        raise ValueError(f"{folder}: no scenario files (*.json)")
    return [load_scenario(f) for f in files]


def machine_info() -> dict[str, Any]:
    cpu = platform.processor() or ""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return {
        "date": dt.datetime.now(dt.UTC).strftime("%Y-%m-%d"),
        "cpu": cpu, "cores": os.cpu_count(), "python": platform.python_version(),
        "numpy": np.__version__,
    }


def timed_plan(scenario: Scenario, seed: int, **overrides: Any) -> tuple[float, dict | None]:
    t0 = time.perf_counter()
    try:
        plan = plan_scenario(scenario, seed=seed, **overrides)
    except NoFeasiblePlan:
        plan = None
    return time.perf_counter() - t0, plan


def bench_scenario(scenario: Scenario, seeds: list[int]) -> dict[str, Any]:
    """Median plan time over seeds and the plan's figures (medians over seeds)."""
    runs = [timed_plan(scenario, s) for s in seeds]
    plans = [p for _, p in runs if p is not None]
    times = [t for t, _ in runs]
    row: dict[str, Any] = {
        "scenario": scenario.name,
        "plan_time_ms_median": round(1000 * statistics.median(times), 2),
        "plan_time_ms": [round(1000 * t, 2) for t in times],
        "valid": sum(1 for p in plans if not plan_violations(p, scenario)),
        "seeds": len(seeds),
    }
    for key in (*TERMS, "length_m", "duration_s", "min_clearance_m", "generations"):
        values = [p["metrics"][key] for p in plans]
        row[key] = round(statistics.median(values), 4) if values else None
    return row


def _ablation_opts(name: str, **extra: Any) -> dict[str, Any]:
    return {**IGAOptions.ablation(name).model_dump(exclude_defaults=True), **extra}


def bench_ablations(scenario: Scenario, seeds: list[int]) -> dict[str, Any]:
    """IGA and EG1-EG4 on one scenario: terms, time, generations; EG2/EG4 time to IGA's level."""
    row: dict[str, Any] = {"case": scenario.name}
    iga_fit: dict[int, float] = {}
    for name in ("IGA", "EG1", "EG2", "EG3", "EG4"):
        runs = [(s, *timed_plan(scenario, s, **_ablation_opts(name))) for s in seeds]
        plans = [p for _, _, p in runs if p is not None]
        key = name.lower()
        row[f"time_{key}_s"] = round(statistics.median(t for _, t, _ in runs), 4)
        row[f"valid_{key}"] = sum(1 for p in plans if not plan_violations(p, scenario))
        for term in (*TERMS, "generations"):
            vals = [p["metrics"][term] for p in plans]
            row[f"{term}_{key}"] = round(statistics.mean(vals), 4) if vals else None
        initial = [p["history"]["elite_mean"][0] for p in plans]
        at20 = [p["history"]["elite_mean"][min(20, len(p["history"]["elite_mean"]) - 1)]
                for p in plans]
        row[f"elite_initial_{key}"] = round(statistics.mean(initial), 4) if initial else None
        row[f"elite_gen20_{key}"] = round(statistics.mean(at20), 4) if at20 else None
        if name == "IGA":
            iga_fit = {s: p["metrics"]["fitness"] for s, _, p in runs if p is not None}
    # Table 3 as in the paper: time for EG2 and EG4 to reach 98 % of the IGA's fitness
    for name in ("IGA", "EG2", "EG4"):
        times, reached = [], 0
        for s, target in iga_fit.items():
            t, p = timed_plan(scenario, s, **_ablation_opts(
                name, fitness_target=0.98 * target, stall_generations=500, smoothing=False))
            times.append(t)
            reached += bool(p and p["metrics"]["stop_reason"] == "fitness_target")
        key = name.lower()
        row[f"to_target_time_{key}_s"] = round(statistics.median(times), 4) if times else None
        row[f"to_target_reached_{key}"] = reached
    return row


def ablation_tables(rows: list[dict[str, Any]]) -> dict[str, Any]:
    """The ablation rows arranged as paper 000 Tables 2-4 plus the EG1 preheating figures."""
    def pick(row: dict, *keys: str) -> dict:
        return {"case": row["case"], **{k: row.get(k) for k in keys}}

    return {
        "table2": [pick(r, "fit_ang_iga", "fit_ang_eg3", "fit_mal_iga", "fit_mal_eg3",
                        "valid_eg3") for r in rows],
        "table3": [pick(r, "time_iga_s", "time_eg2_s", "time_eg4_s", "generations_iga",
                        "generations_eg2", "generations_eg4", "to_target_time_iga_s",
                        "to_target_time_eg2_s", "to_target_time_eg4_s",
                        "to_target_reached_iga", "to_target_reached_eg2",
                        "to_target_reached_eg4") for r in rows],
        "table4": [pick(r, *(f"{t}_{v}" for t in ("fit_ang", "fit_mal", "fit_d", "fit_t")
                             for v in ("iga", "eg2", "eg4"))) for r in rows],
        "eg1_preheating": [pick(r, "elite_initial_iga", "elite_initial_eg1", "elite_gen20_iga",
                                "elite_gen20_eg1", "fitness_iga", "fitness_eg1",
                                "generations_iga", "generations_eg1", "time_iga_s",
                                "time_eg1_s") for r in rows],
        "rows": rows,
    }


def bench_deap(scenario: Scenario, seeds: list[int], max_generations: int) -> list[dict[str, Any]]:
    """IGA against DEAP on the same encoding and fitness, to the IGA's fitness."""
    rows = []
    problem = Problem.from_scenario(scenario)
    for seed in seeds:
        opts = scenario.planner_options(seed=seed)
        layout = GeneLayout.build(problem, opts)
        evaluator = Evaluator(problem, opts, layout.segment_x_range())
        result = run_iga(problem, opts, layout)
        target = float(result.evaluation.fitness[0])
        levels, _, _ = _foundation(layout, problem, opts, np.random.default_rng(seed))
        for init, bits in (("random", None), ("preheated", layout.encode(levels))):
            run = run_deap(layout, evaluator, population=opts.population, seed=seed,
                           target=target, max_generations=max_generations, initial_bits=bits)
            rows.append({
                "scenario": scenario.name, "seed": seed, "deap_init": init,
                "iga_time_s": round(result.elapsed_s, 4), "iga_fitness": round(target, 4),
                "iga_generations": result.generations,
                "deap_time_s": round(run.elapsed_s, 4), "deap_fitness": round(run.best_fitness, 4),
                "deap_generations": run.generations, "deap_reached_iga_fitness": run.reached_target,
                "time_ratio": round(run.elapsed_s / result.elapsed_s, 2),
                "fitness_ratio": round(run.best_fitness / target, 4) if target > 0 else None,
            })
    return rows


def baseline_summary(rows: list[dict[str, Any]]) -> dict[str, Any]:
    summary = {}
    for init in ("random", "preheated"):
        sel = [r for r in rows if r["deap_init"] == init]
        if sel:
            summary[init] = {
                "time_ratio_median": statistics.median(r["time_ratio"] for r in sel),
                "time_ratio_min": min(r["time_ratio"] for r in sel),
                "fitness_ratio_max": max(r["fitness_ratio"] or 0.0 for r in sel),
                "reached_iga_fitness": sum(r["deap_reached_iga_fitness"] for r in sel),
                "runs": len(sel),
            }
    return summary


def bench_random(recoveries: int, transits: int) -> dict[str, Any]:
    """Validity with seed 1 on random recoveries and transits (bench/scenarios.py)."""
    out = {}
    for kind, make, n in (("recovery", random_recovery, recoveries),
                          ("transit", random_transit, transits)):
        times, valid, failures = [], 0, []
        for i in range(n):
            scenario = make(i)
            t, plan = timed_plan(scenario, 1)
            times.append(t)
            if plan is not None and not plan_violations(plan, scenario):
                valid += 1
            else:
                failures.append(scenario.name)
        out[kind] = {
            "count": n, "valid": valid, "valid_fraction": round(valid / n, 4),
            "plan_time_ms_median": round(1000 * statistics.median(times), 2),
            "plan_time_ms_p90": round(1000 * float(np.percentile(times, 90)), 2),
            "failures": failures,
        }
    return out


def render_markdown(r: dict[str, Any]) -> str:
    """The benchmark's figures as the tables of benchmarks/RESULTS.md."""
    m = r["machine"]
    lines = [
        f"Command: `{r['command']}`; machine: {m['cpu']}, {m['cores']} cores, Python "
        f"{m['python']}, NumPy {m['numpy']}; date {m['date']}.",
        "",
        "| scenario | median plan time (ms) | all seeds (ms) | valid | fitness | Fit_d | Fit_T (s) "
        "| Fit_ang | Fit_mal (m) | length (m) | duration (s) | clearance (m) | generations |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for s in r["scenarios"]:
        lines.append(
            f"| {s['scenario']} | {s['plan_time_ms_median']} | "
            f"{', '.join(f'{t:.0f}' for t in s['plan_time_ms'])} | {s['valid']}/{s['seeds']} | "
            f"{s['fitness']} | {s['fit_d']} | {s['fit_t']} | {s['fit_ang']} | {s['fit_mal']} | "
            f"{s['length_m']} | {s['duration_s']} | {s['min_clearance_m']} | {s['generations']} |"
        )
    ab = r["ablation"]
    lines += ["", f"Ablations (means over seeds {ab['seeds']}). Table 2 form (IGA vs EG3):", "",
              "| case | Fit_ang IGA | Fit_ang EG3 | Fit_mal IGA | Fit_mal EG3 | EG3 valid |",
              "|---|---|---|---|---|---|"]
    for t in ab["table2"]:
        lines.append(f"| {t['case']} | {t['fit_ang_iga']} | {t['fit_ang_eg3']} | "
                     f"{t['fit_mal_iga']} | {t['fit_mal_eg3']} | {t['valid_eg3']} |")
    lines += ["", "Table 3 form (time, s; `to 98 %`: until 98 % of the IGA's fitness, "
              "stall rule off, reached/runs):", "",
              "| case | IGA | EG2 | EG4 | gens IGA | gens EG2 | gens EG4 | to 98 % IGA | "
              "to 98 % EG2 | to 98 % EG4 |", "|---|---|---|---|---|---|---|---|---|---|"]
    n = len(ab["seeds"])
    for t in ab["table3"]:
        lines.append(
            f"| {t['case']} | {t['time_iga_s']} | {t['time_eg2_s']} | {t['time_eg4_s']} | "
            f"{t['generations_iga']} | {t['generations_eg2']} | {t['generations_eg4']} | "
            f"{t['to_target_time_iga_s']} ({t['to_target_reached_iga']}/{n}) | "
            f"{t['to_target_time_eg2_s']} ({t['to_target_reached_eg2']}/{n}) | "
            f"{t['to_target_time_eg4_s']} ({t['to_target_reached_eg4']}/{n}) |")
    lines += ["", "Table 4 form:", "",
              "| case | Fit_ang IGA/EG2/EG4 | Fit_mal IGA/EG2/EG4 | Fit_d IGA/EG2/EG4 | "
              "Fit_T IGA/EG2/EG4 |", "|---|---|---|---|---|"]
    for t in ab["table4"]:
        cells = [" / ".join(str(t[f"{term}_{v}"]) for v in ("iga", "eg2", "eg4"))
                 for term in ("fit_ang", "fit_mal", "fit_d", "fit_t")]
        lines.append(f"| {t['case']} | " + " | ".join(cells) + " |")
    lines += ["", "EG1 (no preheating), elite-group mean fitness as in Fig. 15:", "",
              "| case | initial IGA | initial EG1 | gen 20 IGA | gen 20 EG1 | final IGA | "
              "final EG1 | gens IGA | gens EG1 | time IGA (s) | time EG1 (s) |",
              "|---|---|---|---|---|---|---|---|---|---|---|"]
    for t in ab["eg1_preheating"]:
        lines.append(
            f"| {t['case']} | {t['elite_initial_iga']} | {t['elite_initial_eg1']} | "
            f"{t['elite_gen20_iga']} | {t['elite_gen20_eg1']} | {t['fitness_iga']} | "
            f"{t['fitness_eg1']} | {t['generations_iga']} | {t['generations_eg1']} | "
            f"{t['time_iga_s']} | {t['time_eg1_s']} |")
    b = r["baseline"]
    lines += ["", f"General GA library baseline ({b['library']}, same encoding and fitness, "
              f"until the IGA's fitness or {b['max_generations']} generations):", "",
              "| scenario | seed | DEAP init | IGA time (s) | DEAP time (s) | time ratio | "
              "IGA fitness | DEAP fitness | fitness ratio | DEAP gens |",
              "|---|---|---|---|---|---|---|---|---|---|"]
    for x in b["runs"]:
        lines.append(
            f"| {x['scenario']} | {x['seed']} | {x['deap_init']} | {x['iga_time_s']} | "
            f"{x['deap_time_s']} | {x['time_ratio']} | {x['iga_fitness']} | {x['deap_fitness']} | "
            f"{x['fitness_ratio']} | {x['deap_generations']} |")
    if "random" in r:
        lines += ["", "Random scenarios, seed 1 (bench/scenarios.py):", "",
                  "| kind | valid | median plan time (ms) | p90 (ms) | failures |",
                  "|---|---|---|---|---|"]
        for kind, x in r["random"].items():
            lines.append(f"| {kind} | {x['valid']}/{x['count']} | {x['plan_time_ms_median']} | "
                         f"{x['plan_time_ms_p90']} | {', '.join(x['failures']) or '-'} |")
    return "\n".join(lines) + "\n"
