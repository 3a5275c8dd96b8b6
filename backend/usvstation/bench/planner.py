"""`usv-station bench planner`: plan times, ablations EG1-EG4, random validity, DEAP baseline.

Every figure comes from one run of this process, so ratios compare like
with like on a machine whose absolute speed drifts.
"""

from __future__ import annotations

import datetime as dt
import itertools
import os
import platform
import statistics
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from usvstation.bench.checker import check_plan
from usvstation.bench.deap_baseline import run_deap
from usvstation.bench.pymoo_baseline import run_pymoo
from usvstation.bench.render import markdown_table
from usvstation.bench.scenarios import (
    HIDDEN_FAMILIES,
    REVIEW_FAMILIES,
    crossing_ships,
    dense_field,
    random_recovery,
    random_transit,
)
from usvstation.clock import Stopwatch
from usvstation.planning.encoding import GeneLayout
from usvstation.planning.fitness import Evaluator
from usvstation.planning.iga import _foundation, run_iga
from usvstation.planning.plan import NoFeasiblePlan, plan_scenario, replan_from
from usvstation.planning.problem import Problem
from usvstation.planning.validate import plan_violations
from usvstation.records import PlanDocument
from usvstation.scenario import (
    Scenario,
    bundled_scenario_dir,
    load_scenario,
    parse_scenario,
    scenario_at,
)
from usvstation.scenario.options import IGAOptions

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
        "baseline": {"library": "deap and pymoo", "seeds": deap_seeds, "max_generations": deap_max,
                     "runs": []},
    }
    from usvstation.planning.warm import warm

    warm()  # once, as a plan worker does: the plan times below are plans alone
    ablation_rows = []
    for scenario in scenarios:
        progress(f"planning {scenario.name} with {len(seed_list)} seeds")
        out["scenarios"].append(bench_scenario(scenario, seed_list))
        progress(f"ablations EG1-EG4 on {scenario.name}")
        ablation_rows.append(bench_ablations(scenario, ablation_seeds))
        progress(f"DEAP and pymoo baselines on {scenario.name}")
        out["baseline"]["runs"].extend(bench_deap(scenario, deap_seeds, deap_max))
    if not quick:  # two fresh processes, one compiling: seconds
        progress("cold start of the compiled kernel")
        out["cold_start"] = cold_start()
    out["suite_plan_time_ms_median"] = pooled_median(out["scenarios"], "plan_time_ms")
    out["suite_median_cpu_ms"] = pooled_median(out["scenarios"], "plan_cpu_ms")
    out["ablation"].update(ablation_tables(ablation_rows))
    out["baseline"]["summary"] = baseline_summary(out["baseline"]["runs"])
    if random_count > 0:
        progress(f"validity on {random_count} random recoveries and transits")
        out["random"] = bench_random(random_count, max(2, random_count // 10))
    per_family = 1 if quick else 20
    progress(f"hidden families, {per_family} scenarios each")
    out["hidden"] = bench_hidden(per_family)
    progress(f"the review's kinds, {per_family} scenarios each")
    out["review"] = bench_hidden(per_family, REVIEW_FAMILIES)
    progress("re-planning from a boat under way")
    out["replan"] = bench_replan(scenarios, 2 if quick else 20)
    progress("scaling with the obstacle count")
    out["scaling"] = bench_scaling([0, 40] if quick else [0, 40, 160, 320, 1000],
                                   1 if quick else 3)
    progress("robustness to running early or late")
    out["robustness"] = bench_robustness(2 if quick else 20)
    out["orderings"] = paper_orderings(out)
    return out


_COLD = """
from usvstation.clock import Stopwatch
watch = Stopwatch()
from usvstation.planning import kernel
from usvstation.planning.plan import plan_scenario
from usvstation.planning.warm import warm
from usvstation.scenario import load_scenario
t1, c1 = watch.elapsed(), watch.cpu()
warm()
t2, c2 = watch.elapsed(), watch.cpu()
plan_scenario(load_scenario("case1"), seed=1)
t3, c3 = watch.elapsed(), watch.cpu()
plan_scenario(load_scenario("case1"), seed=2)
t4, c4 = watch.elapsed(), watch.cpu()
print(kernel.AVAILABLE, t1, t2 - t1, t3 - t2, t4 - t3, c2 - c1, c3 - c2)
"""


def cold_start() -> dict[str, Any]:
    """The compiled kernels' first use: a fresh process with an empty numba cache (compile),
    then one that finds the cache (`cache=True`): import, `warm()` (what a plan worker
    does once; outside a plan's budget), first and second plan of case1, ms (wall; warm and
    first plan also CPU)."""
    import subprocess
    import sys
    import tempfile

    out: dict[str, Any] = {}
    with tempfile.TemporaryDirectory() as cache:
        env = {**os.environ, "NUMBA_CACHE_DIR": cache}
        for label in ("compile", "cached"):
            res = subprocess.run([sys.executable, "-c", _COLD], capture_output=True, text=True,
                                 env=env, timeout=300, check=False)
            fields = res.stdout.split()
            if res.returncode != 0 or len(fields) != 7:
                return {"error": (res.stderr.strip().splitlines() or ["no output"])[-1]}
            out["kernel"] = fields[0] == "True"
            ms = [round(1000 * float(f), 1) for f in fields[1:]]
            out[label] = {"import_ms": ms[0], "warm_ms": ms[1], "first_plan_ms": ms[2],
                          "second_plan_ms": ms[3], "warm_cpu_ms": ms[4],
                          "first_plan_cpu_ms": ms[5]}
    return out


def pooled_median(rows: list[dict[str, Any]], key: str) -> float:
    """Median of every row's list under `key`, pooled (the suite's plan time: every
    scenario's every seed), to 2 decimals."""
    return round(statistics.median(v for row in rows for v in row[key]), 2)


def bench_hidden(count: int, families: dict[str, Callable[[int], Scenario]] | None = None,
                 ) -> dict[str, Any]:
    """Each hidden family: share planned and valid by the independent checker (bench/checker.py);
    plans returned but refused by it (must be 0); |min_clearance_m - checker| at most; plans
    that keep their smoothed path (`smoothed_kept`, of the plans returned) and that start
    from the scenario's speed over ground (`start_speed_kept`)."""
    out = {}
    for name, make in (families or HIDDEN_FAMILIES).items():
        times, valid, refused, failures, diff = [], 0, [], [], 0.0
        smoothed = repaired = kept = 0
        for i in range(count):
            scenario = make(i)
            t, plan = timed_plan(scenario, 1)
            times.append(t)
            if plan is None:
                failures.append(scenario.name)
                continue
            smoothed += plan.get("smoothed") is not None
            repaired += bool((plan.get("smoothed") or {}).get("repaired"))
            v = scenario.vessel
            own = min(max(scenario.start.speed, v.speed_min), v.speed_max)
            kept += abs(plan["waypoints"][0]["speed"] - own) <= 1e-6
            rep = check_plan(plan, scenario)
            if rep.ok:
                valid += 1
            else:
                refused.append(f"{scenario.name}: {rep.problems[0]}")
            if rep.clearance_m is not None and plan["metrics"]["min_clearance_m"] is not None:
                diff = max(diff, abs(rep.clearance_m - plan["metrics"]["min_clearance_m"]))
        out[name] = {
            "count": count, "planned_valid": valid, "share": round(valid / count, 4),
            "returned_but_refused": refused, "not_planned": failures,
            "clearance_diff_max_m": round(diff, 4),
            "smoothed_kept": smoothed, "smoothed_repaired": repaired, "start_speed_kept": kept,
            "returned": count - len(failures),
            "plan_time_ms_median": round(1000 * statistics.median(times), 2),
            "plan_time_ms_max": round(1000 * max(times), 2),
        }
    return out


def boat_state_at(plan: dict[str, Any], t: float) -> tuple[float, float, float, float]:
    """(x, y, heading_deg, speed) of a boat following the plan at time t (linear in time)."""
    wps = plan["waypoints"]
    for a, b in itertools.pairwise(wps):
        if a["t"] <= t <= b["t"]:
            s = (t - a["t"]) / (b["t"] - a["t"])
            return (a["x"] + s * (b["x"] - a["x"]), a["y"] + s * (b["y"] - a["y"]),
                    a["heading_deg"], a["speed"] + s * (b["speed"] - a["speed"]))
    w = wps[-1]
    return w["x"], w["y"], w["heading_deg"], w["speed"]


def bench_replan(scenarios: list[Scenario], instants: int) -> dict[str, Any]:
    """Plan from a boat under way at random instants of each public plan (seed 1)."""
    rng = np.random.default_rng(7)
    times, valid, tried, failures = [], 0, 0, []
    for scenario in scenarios:
        plan = plan_scenario(scenario, seed=1).to_document()
        duration = plan["waypoints"][-1]["t"]
        for t in rng.uniform(0.0, 0.8 * duration, size=instants):
            x, y, h, v = boat_state_at(plan, float(t))
            tried += 1
            watch = Stopwatch()
            try:
                again = replan_from(scenario, x, y, h, v, float(t), seed=1).to_document()
            except (NoFeasiblePlan, ValueError) as exc:
                times.append(watch.elapsed())
                failures.append(f"{scenario.name} t={t:.1f}: {str(exc)[:100]}")
                continue
            times.append(watch.elapsed())
            valid += not plan_violations(again, _moved(scenario, x, y, h, v, float(t)))
    return {
        "instants": tried, "valid": valid,
        "p50_ms": round(1000 * float(np.percentile(times, 50)), 2),
        "p99_ms": round(1000 * float(np.percentile(times, 99)), 2),
        "failures": failures,
    }


def _moved(scenario: Scenario, x: float, y: float, h: float, v: float, t: float) -> Scenario:
    return scenario_at(scenario, x, y, h, v, t)


def bench_scaling(counts: list[int], seeds: int) -> dict[str, Any]:
    """Median plan time (ms) and share planned validly against the obstacle count (dense
    fields of bench/scenarios.py, 300 m x 300 m)."""
    out = {}
    for n in counts:
        times, cpu, valid = [], [], 0
        for s in range(seeds):
            scenario = dense_field(s, count=n)
            t, c, plan = cpu_timed_plan(scenario, 1)
            times.append(t)
            cpu.append(c)
            valid += plan is not None and check_plan(plan, scenario).ok
        out[str(n)] = {"plan_time_ms_median": round(1000 * statistics.median(times), 2),
                       "plan_cpu_ms_median": round(1000 * statistics.median(cpu), 2),
                       "valid": valid, "seeds": seeds}
    return out


def bench_robustness(count: int) -> dict[str, Any]:
    """Share of plans against crossing, head-on and overtaking ships whose hull stays clear
    when the boat runs early or late by up to 3 s and up to 10 s: planned without a timing
    margin (before) and with the default 3 s margin (after)."""
    out = {}
    for label, margin in (("before", 0.0), ("after", 3.0)):
        clear3 = clear10 = planned = 0
        for i in range(count):
            data = crossing_ships(i).model_dump()
            data["vessel"]["time_margin_s"] = margin
            scenario = parse_scenario(data)
            _, plan = timed_plan(scenario, 1)
            if plan is None:
                continue
            planned += 1
            clear3 += check_plan(plan, scenario, time_margin_s=3.0).ok
            clear10 += check_plan(plan, scenario, time_margin_s=10.0).ok
        out[label] = {"time_margin_s": margin, "planned": planned, "count": count,
                      "clear_within_3s": clear3, "clear_within_10s": clear10,
                      "share_3s": round(clear3 / max(planned, 1), 4),
                      "share_10s": round(clear10 / max(planned, 1), 4)}
    return out


def paper_orderings(r: dict[str, Any]) -> list[dict[str, Any]]:
    """Which of paper 000's orderings (Tables 2-4, Fig. 15) hold on this run, in words."""
    rows = r["ablation"]["rows"]

    def holds(pred: Any) -> tuple[int, int]:
        ok = sum(1 for row in rows if _safe(pred, row))
        return ok, len(rows)

    checks = [
        ("Table 2: the IGA turns less than EG3 (Fit_ang IGA < EG3)",
         lambda w: w["fit_ang_iga"] < w["fit_ang_eg3"]),
        ("Table 2: the IGA keeps closer to the ramp axis than EG3 (Fit_mal IGA < EG3)",
         lambda w: w["fit_mal_iga"] < w["fit_mal_eg3"]),
        ("Table 3: the IGA reaches its fitness faster than EG2 (no SSIH)",
         lambda w: w["to_target_time_iga_s"] < w["to_target_time_eg2_s"]),
        ("Table 3: the IGA reaches its fitness faster than EG4 (no elite group)",
         lambda w: w["to_target_time_iga_s"] < w["to_target_time_eg4_s"]),
        ("Table 4: the IGA's fitness is at least EG2's and EG4's",
         lambda w: w["fitness_iga"] >= max(w["fitness_eg2"], w["fitness_eg4"])),
        ("Fig. 15: preheating starts from a fitter elite group than EG1",
         lambda w: w["elite_initial_iga"] > (w["elite_initial_eg1"] or 0.0)),
        ("Fig. 15: the IGA ends fitter than EG1",
         lambda w: w["fitness_iga"] > (w["fitness_eg1"] or 0.0)),
    ]
    out = []
    for text, pred in checks:
        ok, n = holds(pred)
        verdict = "holds" if ok == n else ("does not hold" if ok == 0 else "holds in part")
        out.append({"ordering": text, "cases_holding": ok, "cases": n, "verdict": verdict})
    return out


def _safe(pred: Any, row: dict[str, Any]) -> bool:
    try:
        return bool(pred(row))
    except TypeError:  # a term missing because no plan was found
        return False


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


def timed_plan(scenario: Scenario, seed: int, **overrides: Any
               ) -> tuple[float, PlanDocument | None]:
    """Plan time and the plan, in the stable format the bench's checker reads."""
    wall, _, plan = cpu_timed_plan(scenario, seed, **overrides)
    return wall, plan


def cpu_timed_plan(scenario: Scenario, seed: int, **overrides: Any
                   ) -> tuple[float, float, PlanDocument | None]:
    """Wall time, CPU time of this process (what the planner got, whatever else runs on
    the machine) and the plan."""
    watch = Stopwatch()
    try:
        plan: PlanDocument | None = plan_scenario(scenario, seed=seed, **overrides).to_document()
    except NoFeasiblePlan:
        plan = None
    return watch.elapsed(), watch.cpu(), plan


def bench_scenario(scenario: Scenario, seeds: list[int]) -> dict[str, Any]:
    """Median plan time over seeds and the plan's figures (medians over seeds)."""
    runs = [cpu_timed_plan(scenario, s) for s in seeds]
    plans = [p for _, _, p in runs if p is not None]
    times = [t for t, _, _ in runs]
    cpu = [c for _, c, _ in runs]
    row: dict[str, Any] = {
        "scenario": scenario.name,
        "plan_time_ms_median": round(1000 * statistics.median(times), 2),
        "plan_time_ms": [round(1000 * t, 2) for t in times],
        "plan_cpu_ms_median": round(1000 * statistics.median(cpu), 2),
        "plan_cpu_ms": [round(1000 * c, 2) for c in cpu],
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
        for (lib, runner), (init, bits) in itertools.product(
                (("deap", run_deap), ("pymoo", run_pymoo)),
                (("random", None), ("preheated", layout.encode(levels)))):
            run = runner(layout, evaluator, population=opts.population, seed=seed,
                         target=target, max_generations=max_generations, initial_bits=bits)
            rows.append({
                "scenario": scenario.name, "seed": seed, "library": lib, "deap_init": init,
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
    for lib, init in itertools.product(("deap", "pymoo"), ("random", "preheated")):
        sel = [r for r in rows if r["deap_init"] == init and r.get("library", "deap") == lib]
        if sel:
            summary[f"{lib}_{init}"] = {
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
    ]
    lines += markdown_table(
        ["scenario", "median plan time (ms)", "all seeds (ms)", "valid", "fitness", "Fit_d",
         "Fit_T (s)", "Fit_ang", "Fit_mal (m)", "length (m)", "duration (s)", "clearance (m)",
         "generations"],
        ([s["scenario"], s["plan_time_ms_median"],
          ", ".join(f"{t:.0f}" for t in s["plan_time_ms"]), f"{s['valid']}/{s['seeds']}",
          s["fitness"], s["fit_d"], s["fit_t"], s["fit_ang"], s["fit_mal"], s["length_m"],
          s["duration_s"], s["min_clearance_m"], s["generations"]] for s in r["scenarios"]))
    if "suite_median_cpu_ms" in r:
        lines += ["", f"Public-suite median CPU time of a plan: {r['suite_median_cpu_ms']} ms."]
    cold = r.get("cold_start", {})
    if "compile" in cold and "cached" in cold:
        lines += ["", "Cold start (fresh process; `planning.warm.warm()` then case1 twice, ms): "
                  + "; ".join(f"{label}: warm {cold[label]['warm_ms']} (CPU "
                              f"{cold[label]['warm_cpu_ms']}), first plan "
                              f"{cold[label]['first_plan_ms']}, second "
                              f"{cold[label]['second_plan_ms']}"
                              for label in ("compile", "cached")) + "."]
    if "suite_plan_time_ms_median" in r:
        lines += ["", f"Median plan time over the whole suite (every scenario and seed): "
                      f"{r['suite_plan_time_ms_median']} ms."]
    ab = r["ablation"]
    lines += ["", f"Ablations (means over seeds {ab['seeds']}). Table 2 form (IGA vs EG3):", ""]
    lines += markdown_table(
        ["case", "Fit_ang IGA", "Fit_ang EG3", "Fit_mal IGA", "Fit_mal EG3", "EG3 valid"],
        ([t["case"], t["fit_ang_iga"], t["fit_ang_eg3"], t["fit_mal_iga"], t["fit_mal_eg3"],
          t["valid_eg3"]] for t in ab["table2"]))
    lines += ["", "Table 3 form (time, s; `to 98 %`: until 98 % of the IGA's fitness, "
              "stall rule off, reached/runs):", ""]
    n = len(ab["seeds"])
    lines += markdown_table(
        ["case", "IGA", "EG2", "EG4", "gens IGA", "gens EG2", "gens EG4", "to 98 % IGA",
         "to 98 % EG2", "to 98 % EG4"],
        ([t["case"], t["time_iga_s"], t["time_eg2_s"], t["time_eg4_s"], t["generations_iga"],
          t["generations_eg2"], t["generations_eg4"],
          *(f"{t[f'to_target_time_{v}_s']} ({t[f'to_target_reached_{v}']}/{n})"
            for v in ("iga", "eg2", "eg4"))] for t in ab["table3"]))
    lines += ["", "Table 4 form:", ""]
    lines += markdown_table(
        ["case", "Fit_ang IGA/EG2/EG4", "Fit_mal IGA/EG2/EG4", "Fit_d IGA/EG2/EG4",
         "Fit_T IGA/EG2/EG4"],
        ([t["case"], *(" / ".join(str(t[f"{term}_{v}"]) for v in ("iga", "eg2", "eg4"))
                       for term in ("fit_ang", "fit_mal", "fit_d", "fit_t"))]
         for t in ab["table4"]))
    lines += ["", "EG1 (no preheating), elite-group mean fitness as in Fig. 15:", ""]
    lines += markdown_table(
        ["case", "initial IGA", "initial EG1", "gen 20 IGA", "gen 20 EG1", "final IGA",
         "final EG1", "gens IGA", "gens EG1", "time IGA (s)", "time EG1 (s)"],
        ([t["case"], t["elite_initial_iga"], t["elite_initial_eg1"], t["elite_gen20_iga"],
          t["elite_gen20_eg1"], t["fitness_iga"], t["fitness_eg1"], t["generations_iga"],
          t["generations_eg1"], t["time_iga_s"], t["time_eg1_s"]]
         for t in ab["eg1_preheating"]))
    b = r["baseline"]
    lines += ["", f"General GA library baseline ({b['library']}, same encoding and fitness, "
              f"until the IGA's fitness or {b['max_generations']} generations):", ""]
    lines += markdown_table(
        ["scenario", "seed", "library", "init", "IGA time (s)", "library time (s)",
         "time ratio", "IGA fitness", "library fitness", "fitness ratio", "library gens"],
        ([x["scenario"], x["seed"], x.get("library", "deap"), x["deap_init"], x["iga_time_s"],
          x["deap_time_s"], x["time_ratio"], x["iga_fitness"], x["deap_fitness"],
          x["fitness_ratio"], x["deap_generations"]] for x in b["runs"]))
    if "random" in r:
        lines += ["", "Random scenarios, seed 1 (bench/scenarios.py):", ""]
        lines += markdown_table(
            ["kind", "valid", "median plan time (ms)", "p90 (ms)", "failures"],
            ([kind, f"{x['valid']}/{x['count']}", x["plan_time_ms_median"],
              x["plan_time_ms_p90"], ", ".join(x["failures"]) or "-"]
             for kind, x in r["random"].items()))
    lines += _issue12_markdown(r)
    return "\n".join(lines) + "\n"


def _issue12_markdown(r: dict[str, Any]) -> list[str]:
    lines: list[str] = []
    for key, title in (("hidden", "Hidden families"), ("review", "The review's kinds")):
        if key not in r:
            continue
        lines += ["", f"{title} (seed 1; valid = passes the independent checker "
                  "bench/checker.py: hull clearance, first turn, speed through the water, "
                  "timing margin; smoothed = plans that keep their smoothed path, of those "
                  "returned, repaired in brackets; start speed = plans whose first waypoint "
                  "speed is the scenario's speed over ground):", ""]
        lines += markdown_table(
            ["family", "planned and valid", "returned but refused", "clearance diff max (m)",
             "smoothed", "start speed", "median (ms)", "max (ms)"],
            ([name, f"{x['planned_valid']}/{x['count']}", len(x["returned_but_refused"]),
              x["clearance_diff_max_m"],
              f"{x.get('smoothed_kept', '-')}/{x.get('returned', '-')} "
              f"({x.get('smoothed_repaired', 0)})",
              f"{x.get('start_speed_kept', '-')}/{x.get('returned', '-')}",
              x["plan_time_ms_median"], x["plan_time_ms_max"]]
             for name, x in r[key].items()))
    if "replan" in r:
        x = r["replan"]
        lines += ["", f"Re-plan from a boat under way: {x['valid']}/{x['instants']} valid, "
                  f"p50 {x['p50_ms']} ms, p99 {x['p99_ms']} ms."]
    if "scaling" in r:
        lines += [""]
        lines += markdown_table(["obstacles", "median plan time (ms)", "valid"],
                                ([n, x["plan_time_ms_median"], f"{x['valid']}/{x['seeds']}"]
                                 for n, x in r["scaling"].items()))
    if "robustness" in r:
        lines += [""]
        lines += markdown_table(
            ["crossing ships", "timing margin (s)", "planned", "clear when <= 3 s off",
             "clear when <= 10 s off"],
            ([label, x["time_margin_s"], f"{x['planned']}/{x['count']}", x["share_3s"],
              x["share_10s"]] for label, x in r["robustness"].items()))
    if "orderings" in r:
        lines += ["", "Paper 000's orderings on this run:", ""]
        for x in r["orderings"]:
            lines.append(f"- {x['ordering']}: {x['verdict']} "
                         f"({x['cases_holding']}/{x['cases']} cases).")
    return lines
