"""`bench live` on two seeded episodes: the traffic's manoeuvre makes contact without
re-planning, and `auto` re-plans around it."""

from usvstation.bench.live import run_live_bench
from usvstation.cli import main


def test_two_episodes_off_contacts_auto_clear() -> None:
    out = run_live_bench(episodes=2)
    assert out["episodes"] == 2
    off, auto = out["policies"]["off"], out["policies"]["auto"]
    assert off["contacts"] + off["margin_violations"] > 0 and off["replans"] == 0
    assert auto["contacts"] == 0 and auto["replans"] >= 2
    assert auto["min_true_clearance_m"] > 0 and auto["replan_p99_ms"] > 0
    assert set(off) | {"replan_p50_ms", "replan_p99_ms", "replan_link_p99_ms"} == set(auto)
    assert 0 < auto["replan_link_p99_ms"] < auto["replan_p99_ms"]


def test_bench_live_refuses_zero_episodes(capsys) -> None:
    assert main(["bench", "live", "--episodes", "0"]) == 2
    assert capsys.readouterr().err == \
        "usv-station bench: --episodes: must be at least 1 (got 0)\n"
