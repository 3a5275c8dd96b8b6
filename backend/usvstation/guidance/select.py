"""Guidance laws by name, for the simulated boat (`--guidance`) and `bench tracking`."""

from __future__ import annotations

from typing import Any

from usvstation.dynamics.params import VesselParams
from usvstation.guidance.compensation import CompensatedAVLOS, DriftModel
from usvstation.guidance.integral_los import AdaptiveLOS, IntegralLOS
from usvstation.guidance.los import AVLOSGuidance, LOSGuidance
from usvstation.guidance.sliding_curve import SlidingCurveGuidance
from usvstation.guidance.trajectory import Trajectory

GUIDANCE_METHODS = ("avlos_comp", "avlos", "los", "ilos", "alos", "sliding_curve")


def make_guidance(method: str, trajectory: Trajectory, params: VesselParams, drift: DriftModel,
                  *, lookahead: float = 8.0, accel: float | None = 0.5,
                  overrun: float = 0.0, path_check: Any = None) -> Any:
    """The guidance object for `method` on `trajectory`; `drift` feeds avlos_comp.

    los: classic LOS (paper 000 Fig. 9a); avlos: AV-LOS (eq. 13 with the
    acceleration refinements when `accel` is set); avlos_comp: AV-LOS with
    the drift compensation of sec. 3.1 on `drift`; ilos / alos: integral and
    adaptive LOS headings with the AV-LOS speed; sliding_curve: paper 002.
    """
    common = {"speed_max": params.top_speed, "overrun": overrun}
    if method == "los":
        return LOSGuidance(trajectory, lookahead, **common)
    if method == "avlos":
        return AVLOSGuidance(trajectory, lookahead, accel=accel, **common)
    if method == "avlos_comp":
        return CompensatedAVLOS(trajectory, drift, lookahead, accel=accel,
                                path_check=path_check, **common)
    if method == "ilos":
        return IntegralLOS(trajectory, lookahead, accel=accel, **common)
    if method == "alos":
        return AdaptiveLOS(trajectory, lookahead, accel=accel, gamma=0.01, **common)
    if method == "sliding_curve":
        return SlidingCurveGuidance(trajectory, lookahead, **common)
    raise ValueError(f"guidance: unknown method {method!r}; "
                     f"available: {', '.join(GUIDANCE_METHODS)}")
