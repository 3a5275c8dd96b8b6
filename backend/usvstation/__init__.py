"""USV stern-ramp recovery shore station (paper 000): planning, boat link, telemetry, console."""

__version__ = "0.1.0"
