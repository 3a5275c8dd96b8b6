"""LOS, AV-LOS and sliding-curve guidance on timed trajectories (pure, no I/O).

Paper 000 sec. 3.3 (LOS, AV-LOS eq. 13), sec. 3.1 (disturbance compensation);
paper 002 Table III (sliding curve). See docs/tracking.md.
"""

from usvstation.guidance.angles import angle_diff, wrap_angle, wrap_angles
from usvstation.guidance.compensation import CompensatedAVLOS, DisturbancePredictor
from usvstation.guidance.los import (
    AVLOSGuidance,
    GuidanceCommand,
    LookaheadTracker,
    LOSGuidance,
    avlos_speed,
    limit_correction,
)
from usvstation.guidance.sliding_curve import SlidingCurveGuidance
from usvstation.guidance.trajectory import Schedule, Trajectory

__all__ = [
    "AVLOSGuidance",
    "CompensatedAVLOS",
    "DisturbancePredictor",
    "GuidanceCommand",
    "LOSGuidance",
    "LookaheadTracker",
    "Schedule",
    "SlidingCurveGuidance",
    "Trajectory",
    "angle_diff",
    "avlos_speed",
    "limit_correction",
    "wrap_angle",
    "wrap_angles",
]
