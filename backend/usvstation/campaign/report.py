"""`campaign report`: success and path tables with 95 % confidence intervals."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from usvstation.bench.render import box_plot, save_svg
from usvstation.campaign.spec import CampaignError


def wilson(k: int, n: int, z: float = 1.959964) -> tuple[float, float]:
    """Wilson score interval of a success rate k/n."""
    if n == 0:
        return (0.0, 1.0)
    p = k / n
    d = 1 + z * z / n
    c = (p + z * z / (2 * n)) / d
    h = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / d
    return (max(0.0, c - h), min(1.0, c + h))


def mean_ci(values: list[float]) -> tuple[float | None, float | None, float | None]:
    """Mean and Student-t 95 % interval."""
    from scipy import stats

    if not values:
        return (None, None, None)
    a = np.asarray(values, float)
    m = float(a.mean())
    if a.size < 2:
        return (m, m, m)
    h = float(stats.t.ppf(0.975, a.size - 1) * a.std(ddof=1) / math.sqrt(a.size))
    return (m, m - h, m + h)


def report(folder: Path, plots: bool = False) -> dict[str, Any]:
    path = folder / "results.parquet"
    if not path.exists():
        raise CampaignError(f"{folder}: no results.parquet (run `usv-station campaign run` first)")
    import pyarrow.parquet as pq

    rows = pq.read_table(path).to_pylist()
    groups: dict[tuple[str, str], list[dict]] = {}
    for r in rows:
        groups.setdefault((r["planner"], r["family"]), []).append(r)
    table = []
    for (pl, fam), rs in sorted(groups.items()):
        ok = [r for r in rs if r["success"]]
        lo, hi = wilson(len(ok), len(rs))
        ni = mean_ci([r["normalization_index"] for r in ok])
        ln = mean_ci([r["length_m"] for r in ok])
        pt = [r["plan_time_ms"] for r in rs]
        table.append({"planner": pl, "family": fam, "episodes": len(rs),
                      "success_rate": round(len(ok) / len(rs), 4),
                      "success_ci95": [round(lo, 4), round(hi, 4)],
                      "normalization_index": _rt(ni), "length_m": _rt(ln),
                      "plan_time_ms_p50": round(float(np.median(pt)), 2)})
    result = {"folder": str(folder), "episodes": len(rows), "table": table}
    if plots:
        result["plots"] = _plots(rows, folder)
    return result


def _rt(t: tuple) -> dict[str, float | None]:
    return {k: (None if v is None else round(v, 4)) for k, v in zip(("mean", "lo", "hi"), t,
                                                                     strict=True)}


def format_report(result: dict[str, Any]) -> str:
    lines = [f"{result['episodes']} episodes in {result['folder']}", "",
             f"{'planner':<18} {'family':<10} {'n':>5} {'success':>8} {'95% CI':>15} "
             f"{'NI mean':>8} {'NI 95% CI':>17} {'plan ms p50':>11}"]
    for e in result["table"]:
        ni = e["normalization_index"]
        ci = "-" if ni["mean"] is None else f"[{ni['lo']:.3f}, {ni['hi']:.3f}]"
        nim = "-" if ni["mean"] is None else f"{ni['mean']:.3f}"
        lines.append(
            f"{e['planner']:<18} {e['family']:<10} {e['episodes']:>5} {e['success_rate']:>8.3f} "
            f"[{e['success_ci95'][0]:.3f}, {e['success_ci95'][1]:.3f}] {nim:>8} {ci:>17} "
            f"{e['plan_time_ms_p50']:>11.1f}")
    return "\n".join(lines)


def _plots(rows: list[dict], folder: Path) -> list[str]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = []
    for metric in ("normalization_index", "plan_time_ms"):
        keys = sorted({(r["planner"], r["family"]) for r in rows})
        fig, ax = plt.subplots(figsize=(max(6, len(keys) * 0.6), 4))
        box_plot(ax, [[r[metric] for r in rows if (r["planner"], r["family"]) == k and r["success"]]
                      for k in keys],
                 [f"{p}\n{f}" for p, f in keys], metric, rotation=70, fontsize=6)
        fig.tight_layout()
        out.append(save_svg(fig, folder / f"report-{metric}.svg"))
    return out
