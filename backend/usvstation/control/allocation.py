"""Thrust allocation for two fixed propellers at y = +/-l (body y to port).

tau_X = T_left + T_right and tau_N = l (T_right - T_left). When the request
does not fit the thrust range, the yaw moment has priority: the difference
is kept (as far as the range allows) and the common thrust gives way.
"""

from __future__ import annotations

from dataclasses import dataclass

from usvstation.dynamics.params import Thrusters
from usvstation.dynamics.vessel import ThrustCommand


@dataclass(frozen=True)
class Allocation:
    command: ThrustCommand
    surge_force: float  # achieved tau_X (N)
    yaw_moment: float  # achieved tau_N (N m)


def allocate(surge_force: float, yaw_moment: float, thrusters: Thrusters) -> Allocation:
    """Left/right thrust for (tau_X, tau_N) within [thrust_min, thrust_max] each."""
    lo, hi = thrusters.thrust_min, thrusters.thrust_max
    arm = thrusters.lever_arm
    span = hi - lo
    diff = min(max(yaw_moment / arm, -span), span)  # T_right - T_left
    half = 0.5 * abs(diff)
    common = min(max(0.5 * surge_force, lo + half), hi - half)
    left, right = common - 0.5 * diff, common + 0.5 * diff
    return Allocation(ThrustCommand(left, right), left + right, arm * (right - left))
