"""PID heading/speed autopilot, thrust allocation and the closed tracking loop (pure, no I/O)."""

from usvstation.control.allocation import Allocation, allocate
from usvstation.control.autopilot import Autopilot, AutopilotGains
from usvstation.control.loop import TrackingLoop
from usvstation.control.pid import PID

__all__ = ["PID", "Allocation", "Autopilot", "AutopilotGains", "TrackingLoop", "allocate"]
