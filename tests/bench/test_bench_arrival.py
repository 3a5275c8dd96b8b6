"""`usv-station bench arrival`: the last 30 metres under perturbations (issue 24), in quick
mode (two families, two methods, two sensor profiles, two plans)."""

from __future__ import annotations

import contextlib
import io
import json

import pytest

from usvstation.bench.arrival import FAMILIES, QUICK, render_markdown
from usvstation.cli import build_parser, main

ROW_KEYS = {"family", "method", "sensor", "episodes", "arrived", "go_around", "bad",
            "p95_offset_m", "p95_heading_deg"}


@pytest.fixture(scope="module")
def result() -> dict:
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        assert main(["bench", "arrival", "--quick", "--json"]) == 0
    return json.loads(buf.getvalue())


def test_rows_have_exactly_the_issues_keys_and_count_episodes(result) -> None:
    rows = result["rows"]
    assert rows and all(set(r) == ROW_KEYS for r in rows)
    n = len(QUICK["seeds"]) * len(QUICK["scenarios"])
    assert {(r["family"], r["method"], r["sensor"]) for r in rows} == {
        (f, m, s) for f in QUICK["families"] for m in QUICK["methods"] for s in QUICK["sensors"]}
    for r, other in zip(rows, result["other_outcomes"], strict=True):
        assert r["episodes"] == n
        assert r["arrived"] + r["go_around"] + r["bad"] + other["marginal"] + \
            other["timeout"] == n
    assert result["conditions"]["plan_seeds"] == list(QUICK["seeds"])
    assert not set(result["conditions"]["plan_seeds"]) & set(result["conditions"]["tuning_seeds"])


def test_the_ramp_approach_never_makes_a_bad_arrival(result) -> None:
    by = {(r["family"], r["method"], r["sensor"]): r for r in result["rows"]}
    for (family, method, sensor), r in by.items():
        if method == "approach":
            assert r["bad"] == 0, (family, sensor)
    # relative RTK in the bench's conditions: every plan arrives
    assert by[("bench", "approach", "rtk-moving-base")]["arrived"] == 2
    # plain GNSS cannot be trusted to 0.3 m: the boat goes around at the first gate
    assert by[("bench", "approach", "gnss")]["go_around"] == 2
    # 2.5 m/s across the ramp: nobody arrives; the ramp approach goes around
    assert by[("beam_2.5", "approach", "rtk-moving-base")]["go_around"] == 2
    assert by[("beam_2.5", "approach", "rtk-moving-base")]["p95_offset_m"] is None


def test_markdown_and_arguments(result) -> None:
    table = render_markdown(result)
    assert table.startswith("| family | method | sensor | episodes |")
    assert table.count("\n") == len(result["rows"]) + 2
    args = build_parser().parse_args(["bench", "arrival", "--families", "bench,beam_1.5",
                                      "--workers", "2"])
    assert (args.name, args.families, args.workers) == ("arrival", "bench,beam_1.5", 2)
    assert len(FAMILIES) >= 6


def test_an_unknown_family_is_named(capsys) -> None:
    assert main(["bench", "arrival", "--families", "storm"]) == 2
    assert "unknown family 'storm'; available: bench" in capsys.readouterr().err
