"""LOS, AV-LOS, ILOS, ALOS and sliding-curve guidance, the drift observer and station
keeping (pure, no I/O).

Paper 000 sec. 3.3 (LOS, AV-LOS eq. 13), sec. 3.1 (disturbance compensation);
paper 002 Table III (sliding curve); Fossen and Lekkas 2017 (ILOS), Fossen 2023
(ALOS). See docs/tracking.md.
"""

from usvstation.geometry import angle_diff, wrap_angle
from usvstation.guidance.compensation import (
    CompensatedAVLOS,
    DisturbancePredictor,
    DriftModel,
    EstimatedDrift,
)
from usvstation.guidance.integral_los import AdaptiveLOS, IntegralLOS
from usvstation.guidance.los import (
    AVLOSGuidance,
    GuidanceCommand,
    LookaheadTracker,
    LOSGuidance,
    avlos_speed,
    limit_correction,
)
from usvstation.guidance.observer import DriftObserver, Measurement
from usvstation.guidance.sliding_curve import SlidingCurveGuidance
from usvstation.guidance.station import StationKeeper
from usvstation.guidance.trajectory import Schedule, Trajectory

__all__ = [
    "AVLOSGuidance",
    "AdaptiveLOS",
    "CompensatedAVLOS",
    "DisturbancePredictor",
    "DriftModel",
    "DriftObserver",
    "EstimatedDrift",
    "GuidanceCommand",
    "IntegralLOS",
    "LOSGuidance",
    "LookaheadTracker",
    "Measurement",
    "Schedule",
    "SlidingCurveGuidance",
    "StationKeeper",
    "Trajectory",
    "angle_diff",
    "avlos_speed",
    "limit_correction",
    "wrap_angle",
]
