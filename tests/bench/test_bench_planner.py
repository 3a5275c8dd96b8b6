"""The planner benchmark runs end to end (quick mode) and reports every figure it promises."""

import shutil

from usvstation.bench.planner import run_planner_bench
from usvstation.scenario import bundled_scenario_dir


def test_quick_planner_bench(tmp_path):
    shutil.copy(bundled_scenario_dir() / "case3.json", tmp_path / "case3.json")
    messages = []
    out = run_planner_bench(folder=tmp_path, seeds=2, random_count=2, quick=True,
                            progress=messages.append)
    assert messages and messages[0] == "planning case3 with 2 seeds"
    (row,) = out["scenarios"]
    assert row["scenario"] == "case3" and row["valid"] == 2 and len(row["plan_time_ms"]) == 2
    assert row["plan_time_ms_median"] > 0
    assert "suite_plan_time_ms_median" in out  # its arithmetic: tests/unit/test_bench_summary.py
    assert out["suite_median_cpu_ms"] > 0 and len(row["plan_cpu_ms"]) == 2
    for key in ("fit_d", "fit_t", "fit_ang", "fit_mal", "length_m", "duration_s",
                "min_clearance_m", "generations"):
        assert row[key] is not None
    ab = out["ablation"]
    assert [r["case"] for r in ab["table2"]] == ["case3"]
    assert {"fit_ang_iga", "fit_ang_eg3", "fit_mal_iga", "fit_mal_eg3"} <= ab["table2"][0].keys()
    assert {"time_iga_s", "time_eg2_s", "time_eg4_s"} <= ab["table3"][0].keys()
    assert {"elite_initial_iga", "elite_initial_eg1"} <= ab["eg1_preheating"][0].keys()
    runs = out["baseline"]["runs"]
    assert {r["deap_init"] for r in runs} == {"random", "preheated"}
    assert {r["library"] for r in runs} == {"deap", "pymoo"}
    for r in runs:
        assert r["deap_fitness"] <= r["iga_fitness"] or r["deap_reached_iga_fitness"]
        assert r["time_ratio"] > 0
    assert out["random"]["recovery"]["count"] == 2 and out["random"]["transit"]["count"] == 2
    assert out["machine"]["cores"] >= 1
    # issue 12: hidden families, re-planning, scaling, robustness, the paper's orderings
    assert set(out["hidden"]) == {"pointing_away", "strong_current", "crossing_ships",
                                  "behind_ramp", "long_wall", "dense_field", "alongside",
                                  "outline_astern_traffic"}
    assert set(out["review"]) == {"narrow_passage", "harbour_entrance", "ship_at_ramp",
                                  "head_on", "cross_current", "far_start", "goal_blocked"}
    for fam in (*out["hidden"].values(), *out["review"].values()):
        assert fam["returned_but_refused"] == []  # every plan returned passes the checker
        assert fam["clearance_diff_max_m"] <= 0.05
        assert fam["smoothed_kept"] <= fam["returned"] and fam["start_speed_kept"] <= 1
    assert out["replan"]["instants"] == 2 and out["replan"]["p99_ms"] > 0
    assert set(out["scaling"]) == {"0", "40"}
    assert set(out["robustness"]) == {"before", "after"}
    assert out["robustness"]["after"]["time_margin_s"] == 3.0
    assert all(o["verdict"] in ("holds", "holds in part", "does not hold")
               for o in out["orderings"])
