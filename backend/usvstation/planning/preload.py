"""Imported by the plan workers' forkserver before it forks the first worker
(services/plans.py): the planners, numpy and scipy imported and the compiled kernels loaded
(planning/warm.py) once in the forkserver, so a worker, a replacement after a death,
timeout or cancel included, starts with them instead of loading them itself."""

from __future__ import annotations

import usvstation.planning.registry  # noqa: F401  (the planners, numpy, scipy)
from usvstation.planning.warm import warm

warm()
