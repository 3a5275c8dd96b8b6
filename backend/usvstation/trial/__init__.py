"""Sea trials: many complete recoveries at sea in simulated time (docs/trials.md)."""
