"""The planner bench's summary figures are plain arithmetic over its rows."""

from usvstation.bench.planner import suite_median_ms


def test_the_suite_median_pools_every_scenario_and_seed():
    rows = [{"plan_time_ms": [10.0, 30.0, 20.0]}, {"plan_time_ms": [40.0, 50.0]}]
    assert suite_median_ms(rows) == 30.0  # of 10, 20, 30, 40, 50
    assert suite_median_ms([rows[0], {"plan_time_ms": [40.0]}]) == 25.0  # even count
    assert suite_median_ms([{"plan_time_ms": [1.234567]}]) == 1.23
