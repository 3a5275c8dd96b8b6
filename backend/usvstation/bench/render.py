"""What the benchmarks' and campaigns' reports are made of: markdown tables and SVG box plots.

Matplotlib is imported by the callers (lazily, with the Agg backend); these helpers take its
axes and figures.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any


def markdown_table(header: Sequence[str], rows: Iterable[Sequence[object]]) -> list[str]:
    """The lines of a markdown table: the header, its rule and a line per row (cells as
    `str` gives them)."""
    lines = [_row(header), "|" + "---|" * len(header)]
    lines += [_row(r) for r in rows]
    return lines


def _row(cells: Sequence[object]) -> str:
    return "| " + " | ".join(str(c) for c in cells) + " |"


def box_plot(ax: Any, groups: Sequence[Sequence[float]], labels: Sequence[str], title: str, *,
             rotation: float, fontsize: float) -> None:
    """One box per group on `ax`, labelled below; an empty group draws no box (NaN)."""
    ax.boxplot([list(g) or [float("nan")] for g in groups])
    ax.set_xticks(range(1, len(labels) + 1), labels, rotation=rotation, fontsize=fontsize)
    ax.set_title(title)


def save_svg(fig: Any, path: Path) -> str:
    """Write the figure as SVG, close it and give its path."""
    import matplotlib.pyplot as plt

    fig.savefig(path, format="svg")
    plt.close(fig)
    return str(path)
