"""SVG figures of `bench compare`: paths overlaid per scenario and box plots per family."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from usvstation.bench.render import box_plot, save_svg
from usvstation.scenario import Scenario


def write_plots(rows: list[dict[str, Any]], folder: Path,
                scenarios: dict[str, Scenario]) -> list[str]:
    """`scenarios` by name: those the rows were planned on (for the obstacles drawn)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    folder.mkdir(parents=True, exist_ok=True)
    written = []
    scen = scenarios
    for name in ("case2", "transit-002-3", "dense-0-0", "colregs-head-on",
                 "colregs-crossing-give-way-b", "trap-u-shape"):
        sel = [r for r in rows if r["scenario"] == name and r["success"] and r["seed"] == 1]
        if not sel or name not in scen:
            continue
        fig, ax = plt.subplots(figsize=(6, 6))
        for o in scen[name].obstacles:
            ax.add_patch(plt.Circle((o.x, o.y), o.radius, color="grey", alpha=0.5))
            if o.vx or o.vy:
                ax.arrow(o.x, o.y, o.vx * 20, o.vy * 20, color="grey", width=0.2)
        for r in sel:
            xy = r["path"]
            ax.plot([p[0] for p in xy], [p[1] for p in xy], label=r["planner"], lw=1.2)
        ax.set_aspect("equal")
        ax.set_title(f"{name}: plans (seed 1)")
        ax.legend(fontsize=7)
        written.append(save_svg(fig, folder / f"compare-paths-{name}.svg"))
    for metric in ("normalization_index", "plan_time_ms", "track_mean_dev_m"):
        fams = sorted({r["family"] for r in rows})
        fig, axes = plt.subplots(1, len(fams), figsize=(4 * len(fams), 4), squeeze=False)
        for ax, fam in zip(axes[0], fams, strict=True):
            pls = sorted({r["planner"] for r in rows if r["family"] == fam})
            box_plot(ax, [[r[metric] for r in rows if r["family"] == fam and r["planner"] == p
                           and r["success"] and r.get(metric) is not None] for p in pls],
                     pls, f"{fam}: {metric}", rotation=60, fontsize=7)
            if metric == "plan_time_ms":
                ax.set_yscale("log")
        fig.tight_layout()
        written.append(save_svg(fig, folder / f"compare-box-{metric}.svg"))
    return written


def write_curves(curves: dict[str, Any], folder: Path) -> str:
    """Cost (path / straight line, median over maps) versus CPU-time budget, one line per
    planner, as SVG; returns the file's path."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    folder.mkdir(parents=True, exist_ok=True)
    fig, ax = plt.subplots(figsize=(6, 4))
    for name, c in curves["planners"].items():
        pts = [(b, m) for b, m in zip(curves["budgets_s"], c["median_ratio"], strict=True)
               if m is not None]
        if pts:
            ax.plot(*zip(*pts, strict=True), marker="o", label=name)
    ax.set_xscale("log")
    ax.set_xlabel("budget (s of CPU time)")
    ax.set_ylabel("path length / straight line (median)")
    ax.set_title(f"Paper 004 map, {curves['maps']} maps: cost versus budget")
    ax.legend()
    path = folder / "cost-vs-time.svg"
    fig.savefig(path, format="svg", bbox_inches="tight")
    plt.close(fig)
    return str(path)
