"""Imported by the plan workers' forkserver before it forks the first worker
(services/plans.py): the planners, numpy and scipy imported and the compiled kernels loaded
(planning/warm.py) once in the forkserver, so a worker, a replacement after a death,
timeout or cancel included, starts with them instead of loading them itself."""

from __future__ import annotations

# the planners import scipy where they use it (serve starts without it): the workers have it
import scipy.interpolate
import scipy.ndimage
import scipy.optimize
import scipy.spatial  # noqa: F401

import usvstation.planning.registry  # noqa: F401  (the planners, numpy)
from usvstation.planning.warm import warm

warm()
