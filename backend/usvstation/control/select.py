"""Autopilots by name, for the simulated boat (`--controller`) and `bench tracking`."""

from __future__ import annotations

from usvstation.control.autopilot import Autopilot
from usvstation.control.drnn import DRNNPI, HeadingPI
from usvstation.control.mrac import PIDMRAC
from usvstation.dynamics.params import VesselParams

CONTROLLERS = ("pid", "pid_mrac", "drnn_pi", "pi")


def make_controller(name: str, params: VesselParams, seed: int = 1) -> Autopilot:
    """pid: the pole-placed PID autopilot; pid_mrac: paper 002; drnn_pi / pi: paper 004."""
    if name == "pid":
        return Autopilot(params)
    if name == "pid_mrac":
        return PIDMRAC(params)
    if name == "drnn_pi":
        return DRNNPI(params, seed=seed)
    if name == "pi":
        return HeadingPI(params)
    raise ValueError(f"controller: unknown {name!r}; available: {', '.join(CONTROLLERS)}")
