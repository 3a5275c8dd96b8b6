"""Autopilots (PID, paper 002's PID-MRAC, paper 004's DRNN-PI and PI), thrust allocation and
the closed tracking loop (pure, no I/O)."""

from usvstation.control.allocation import Allocation, allocate
from usvstation.control.autopilot import Autopilot, AutopilotGains
from usvstation.control.drnn import DRNNPI, HeadingPI
from usvstation.control.loop import TrackingLoop
from usvstation.control.mrac import PIDMRAC
from usvstation.control.pid import PID

__all__ = ["DRNNPI", "PID", "PIDMRAC", "Allocation", "Autopilot", "AutopilotGains", "HeadingPI",
           "TrackingLoop", "allocate"]
