"""`usv-station bench compare` end to end on a small cut: the JSON it promises, the tables."""

import json
from pathlib import Path

import numpy as np

from usvstation.cli import main


def test_bench_compare_json_and_markdown(tmp_path, capsys):
    rc = main(["bench", "compare", "--planners", "replan-ga,rrt-star", "--families",
               "recovery,traps", "--seeds", "1", "--hidden", "1", "--hidden-from", "1003",
               "--sweep", "40", "--sweep-maps", "2", "--curves", "0.3", "--curve-maps", "1"])
    assert rc == 0
    out = capsys.readouterr()
    result = json.loads(out.out)
    assert "traps trap-hidden-1003-obstacle-on-line rrt-star seed 1: ok" in out.err
    assert (result["seeds"], result["first_seed"], result["hidden"], result["hidden_from"]) == \
        (1, 1, 1, 1003)
    for planner in ("replan-ga", "rrt-star"):
        for family, episodes in (("recovery", 5), ("traps", 4)):
            e = result["summary"][planner][family]
            assert e["episodes"] == episodes
            assert e["public_success"] is not None and e["hidden_success"] is not None
            assert e["track_mean_dev_m"] is not None and e["track_mean_dev_m"] >= 0.0
    rows = result["rows"]
    assert sum(r["hidden"] for r in rows) == 4  # one hidden scenario per family and planner
    for r in rows:
        if r["success"]:
            assert r["track_max_dev_m"] >= r["track_mean_dev_m"] >= 0.0
    assert {"vpf_over_rrt_length", "bspline_over_rrt_length", "paper", "raw", "finished"} <= \
        set(result["table_004"])
    for family in ("recovery", "traps"):  # the shortest plan's path/straight-line ratio
        d = result["difficulty"][family]
        assert d["n"] >= 4 and d["ratio_median"] >= 1.0 and len(d["ratio_ci95"]) == 2
    (sweep,) = result["difficulty_sweep"]
    assert sweep["count"] == 40 and sweep["maps"] == 2 and sweep["ratio_median"] >= 1.0
    curves = result["cost_curves"]  # OMPL's lines too with --ompl
    # how far a CPU-time budget gets depends on the machine: the shape, not the values
    assert curves["budgets_s"] == [0.3] and curves["planners"]["rrt-star"]["solved"] in ([0], [1])
    from usvstation.bench.compare_plots import write_curves

    assert Path(write_curves(curves, tmp_path)).read_text().startswith("<?xml")
    e = result["summary"]["rrt-star"]["recovery"]
    lo, hi = e["success_ci95"]
    assert lo <= e["success_rate"] <= hi
    assert {"p50_ms", "p99_ms"} <= set(result["replan_002"])
    assert {"starboard_ok", "cases"} <= set(result["colregs_001"])

    saved = tmp_path / "compare.json"
    saved.write_text(out.out)
    assert main(["bench", "compare", "--markdown", str(saved)]) == 0
    table = capsys.readouterr().out
    assert "| planner | family | episodes | success | public | hidden |" in table
    assert "| rrt-star | traps | 4 |" in table


def test_bench_compare_refuses_an_unknown_planner(capsys):
    assert main(["bench", "compare", "--planners", "rrt", "--families", "traps"]) == 2
    assert "planners: unknown planner 'rrt'; available: iga, colregs-ga" in capsys.readouterr().err


def test_walls_and_encounters_families_are_the_papers_settings():
    """walls: 004's map whose straight line three walls cut (a slalom); encounters: 001's
    five classes at its scale, one each, then seeded ones; both seeded."""
    from usvstation.bench.compare import ENCOUNTERS_001, family_scenarios, walls_004
    from usvstation.planning.seeds.common import World

    (sc,) = family_scenarios("walls", hidden=1, dense_maps=0, hidden_from=5)
    assert sc == walls_004(1, 5) and len(sc.obstacles) > 150
    world = World.from_scenario(sc)
    line = np.linspace([sc.start.x, sc.start.y], [sc.goal.x, sc.goal.y], 400)
    blocked = ~world.points_free(line, 0.0)
    assert np.count_nonzero(np.diff(blocked.astype(int)) == 1) >= 3  # three walls in the way
    public = family_scenarios("encounters", hidden=2)
    assert [s.name.split("-", 3)[-1] for s in public[:5]] == list(ENCOUNTERS_001)
    assert len(public) == 7 and all(s.vessel.speed_max == 28.0 for s in public)
    assert all(len(s.obstacles) >= 1 for s in public)


def test_orderings_are_judged_on_their_intervals():
    from usvstation.bench.compare import paper_orderings

    t = {"pairs": 30, "family": "walls", "raw": {}, "finished": {
        "vpf_over_rrt_length": {"mean": 0.95, "ci95": [0.93, 0.97], "n": 30},
        "vpf_over_rrt_tta": {"mean": 1.01, "ci95": [0.9, 1.1], "n": 30},
        "bspline_over_rrt_length": {"mean": 0.99, "ci95": [0.98, 0.995], "n": 30}}}
    out = {(o["basis"], o["ordering"]): o for o in paper_orderings({"table_004_walls": t})}
    assert out[("finished", "VPF-RRT* is shorter than RRT*")]["verdict"] == "holds"
    assert out[("finished", "VPF-RRT* is shorter than RRT*")]["in_paper_range"]
    assert out[("finished", "VPF-RRT* turns less than RRT*")]["verdict"].startswith("undecided")
    assert out[("finished", "B-spline-RRT* is longer than RRT*")]["verdict"] == "does not hold"
    assert out[("raw", "B-spline-RRT* is longer than RRT*")]["verdict"] == "not measured"
