"""3-DOF vessel model, environment forces and the paper's kinematic boat (pure, no I/O)."""

from usvstation.dynamics.environment import (
    Environment,
    Push,
    WaveField,
    Wind,
    current_force,
    drift_coefficients,
    wave_drift_force,
    wind_force,
)
from usvstation.dynamics.kinematic import KinematicBoat
from usvstation.dynamics.params import (
    HullMismatch,
    Thrusters,
    VesselParams,
    otter,
    trimaran,
    vessel_preset,
)
from usvstation.dynamics.vessel import ThrustCommand, Vessel, VesselState

__all__ = [
    "Environment",
    "HullMismatch",
    "KinematicBoat",
    "Push",
    "ThrustCommand",
    "Thrusters",
    "Vessel",
    "VesselParams",
    "VesselState",
    "WaveField",
    "Wind",
    "current_force",
    "drift_coefficients",
    "otter",
    "trimaran",
    "vessel_preset",
    "wave_drift_force",
    "wind_force",
]
