"""Benchmarks run by `usv-station bench NAME`; results are recorded in benchmarks/RESULTS.md."""
