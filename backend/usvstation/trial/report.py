"""`usv-station trial report DIR`: outcome counts with 95 % intervals, arrival percentiles
with bootstrap intervals, and the outcomes by each family's drawn value."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from usvstation.campaign.report import wilson
from usvstation.campaign.run import read_rows
from usvstation.trial.spec import TrialError

OUTCOMES = ("arrived", "go_around", "aborted", "contact", "failsafe")
BOOTSTRAP = 2000
BOOTSTRAP_SEED = 12345  # the intervals are the same every time the report is made


def percentile_ci(values: list[float], q: float) -> dict[str, float | None]:
    """The q-th percentile of `values` and its 95 % bootstrap interval (fixed seed)."""
    if not values:
        return {"value": None, "lo": None, "hi": None}
    a = np.asarray(values, float)
    rng = np.random.default_rng(BOOTSTRAP_SEED)
    draws = np.percentile(a[rng.integers(0, a.size, (BOOTSTRAP, a.size))], q, axis=1)
    return {"value": round(float(np.percentile(a, q)), 3),
            "lo": round(float(np.percentile(draws, 2.5)), 3),
            "hi": round(float(np.percentile(draws, 97.5)), 3)}


def report(folder: Path) -> dict[str, Any]:
    rows = sorted(read_rows(folder), key=lambda r: r["index"])
    if not rows:
        raise TrialError(f"{folder}: no episodes.jsonl with episodes (run `usv-station trial "
                         "SPEC.toml --out DIR` first)")
    n = len(rows)
    counts = {o: sum(1 for r in rows if r["outcome"] == o) for o in OUTCOMES}
    arrived = [r for r in rows if r["outcome"] == "arrived"]
    offsets = [r["arrival_offset_m"] for r in arrived]
    headings = [r["arrival_heading_deg"] for r in arrived]
    clearances = [r["min_hull_clearance_m"] for r in rows
                  if r["min_hull_clearance_m"] is not None]
    p50, p95 = percentile_ci(offsets, 50), percentile_ci(offsets, 95)
    h95 = percentile_ci(headings, 95)
    return {
        "folder": str(folder), "episodes": n, "outcomes": counts,
        "outcome_ci95": {o: [round(x, 4) for x in wilson(k, n)] for o, k in counts.items()},
        "arrival": {"p50_offset_m": p50["value"], "p95_offset_m": p95["value"],
                    "p95_heading_deg": h95["value"],
                    "within_0_3m_5deg": sum(1 for r in rows if r["within_0_3m_5deg"]),
                    "ci95": {"p50_offset_m": [p50["lo"], p50["hi"]],
                             "p95_offset_m": [p95["lo"], p95["hi"]],
                             "p95_heading_deg": [h95["lo"], h95["hi"]]}},
        "min_hull_clearance_m": min(clearances) if clearances else None,
        "touched": _touched(rows),
        "alerts_per_episode": round(float(np.mean([r["alerts"] for r in rows])), 2),
        "replans": sum(r["replans"] for r in rows),
        "replans_applied": sum(r["replans_applied"] for r in rows),
        "slip_s_p50": percentile_ci([r["slip_s"] for r in rows if r["slip_s"] is not None],
                                    50)["value"],
        "by_family": _by_family(rows),
    }


def _touched(rows: list[dict[str, Any]]) -> dict[str, int]:
    """How many episodes' hulls touched each ship or obstacle (negative clearance)."""
    out: dict[str, int] = {}
    for r in rows:
        if (r["min_hull_clearance_m"] or 0.0) < 0.0:
            name = r.get("closest") or "unknown"
            out[name] = out.get(name, 0) + 1
    return dict(sorted(out.items()))


def _by_family(rows: list[dict[str, Any]]) -> dict[str, dict[str, dict[str, int]]]:
    """For each drawn condition with more than one value: outcome counts per value."""
    out: dict[str, dict[str, dict[str, int]]] = {}
    for key in rows[0]["conditions"]:
        values = sorted({_label(r["conditions"][key]) for r in rows})
        if len(values) < 2 or key in ("current_dir_deg", "current_change_s"):
            continue
        out[key] = {v: {o: sum(1 for r in rows if _label(r["conditions"][key]) == v
                               and r["outcome"] == o) for o in OUTCOMES} for v in values}
    return out


def _label(value: Any) -> str:
    """A drawn value as a family label (a window drawn for a burst or a hold: 'yes')."""
    if isinstance(value, list):
        return "yes"
    return "no" if value is None else str(value)


def format_report(result: dict[str, Any]) -> str:
    a = result["arrival"]
    lines = [f"{result['episodes']} episodes in {result['folder']}", ""]
    for o, k in result["outcomes"].items():
        lo, hi = result["outcome_ci95"][o]
        lines.append(f"  {o:<10} {k:>5}   95% CI [{lo:.3f}, {hi:.3f}]")
    lines += ["", f"arrival offset p50 {a['p50_offset_m']} m, p95 {a['p95_offset_m']} m; "
                  f"heading p95 {a['p95_heading_deg']} deg; within 0.3 m / 5 deg: "
                  f"{a['within_0_3m_5deg']}",
              f"minimum hull clearance {result['min_hull_clearance_m']} m"
              + (f" (touched: {', '.join(f'{k} {v}' for k, v in result['touched'].items())})"
                 if result["touched"] else "") + "; "
              f"{result['alerts_per_episode']} alerts an episode; "
              f"{result['replans_applied']} of {result['replans']} re-plans applied"]
    return "\n".join(lines)
