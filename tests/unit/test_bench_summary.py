"""The planner bench's summary figures are plain arithmetic over its rows."""

from usvstation.bench.planner import pooled_median


def test_the_pooled_median_takes_every_value_of_every_row():
    rows = [{"n": [1, 3, 2]}, {"n": [4, 5]}]
    assert pooled_median(rows, "n") == 3  # of 1, 2, 3, 4, 5
    assert pooled_median([rows[0], {"n": [4]}], "n") == 2.5  # even count
    assert pooled_median([{"n": [1.234567]}], "n") == 1.23
