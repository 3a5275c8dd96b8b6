"""The live world around the recovery: the mother ship, its ramp and the traffic (pure)."""
