"""Generated MAVLink codec of usv-link 2 (protocol/generate.py)."""
