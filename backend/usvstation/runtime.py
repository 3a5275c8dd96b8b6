"""Process-level tuning applied at the edges (CLI, plan worker processes), never in the core."""

from __future__ import annotations

import ctypes
import ctypes.util
import sys

_M_TRIM_THRESHOLD = -1
_M_TOP_PAD = -2
_M_MMAP_THRESHOLD = -3
_tuned = False


def tune_allocator() -> bool:
    """Keep freed heap pages instead of returning them to the OS after every array.

    The planner allocates and frees thousands of ~100 kB NumPy temporaries per
    plan; with glibc's defaults each free at the heap top trims the heap and
    the next allocation page-faults it back, which triples the planner's run
    time. Raising the trim and mmap thresholds (glibc mallopt) avoids that.
    Returns True when applied; a no-op on other C libraries.
    """
    global _tuned
    if _tuned:
        return True
    if not sys.platform.startswith("linux"):
        return False
    name = ctypes.util.find_library("c")
    try:
        libc = ctypes.CDLL(name or "libc.so.6")
        mallopt = libc.mallopt
    except (OSError, AttributeError):
        return False
    mallopt.argtypes = [ctypes.c_int, ctypes.c_int]
    ok = all(
        mallopt(param, value)
        for param, value in (
            (_M_TRIM_THRESHOLD, 256 << 20),
            (_M_TOP_PAD, 64 << 20),
            (_M_MMAP_THRESHOLD, 32 << 20),
        )
    )
    _tuned = ok
    return ok


_libc: ctypes.CDLL | None = None


def release_memory() -> bool:
    """Hand the C heap's free pages back to the OS (glibc `malloc_trim(0)`, every arena):
    after a burst of large responses the process returns to its size (the threads that
    encoded them each keep an arena otherwise). A no-op (False) on other C libraries."""
    global _libc
    if not sys.platform.startswith("linux"):
        return False
    try:
        if _libc is None:
            _libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
        trim = _libc.malloc_trim
    except (OSError, AttributeError):
        return False
    trim.argtypes = [ctypes.c_size_t]
    trim(0)
    return True
