"""Memory allocation tuned for numpy temporaries (glibc only; elsewhere nothing changes).

glibc serves every block above its mmap threshold (128 KiB, raised only as blocks are freed)
with a fresh ``mmap`` and returns it on ``free``, and it trims the heap top back to the system.
A conversion makes millions of temporaries of 0.1-60 MB, so each one is page-faulted in again,
4 KiB at a time: on a VM with free-page reporting (this machine) that cost 5-6x the arithmetic
(``(pts @ eq.T + d).max(1)`` on 3000 x 124: 13.7 ms -> 2.3 ms wall). Keeping freed blocks below
64 MB in the heap for reuse removes it; output is unchanged (only where memory comes from).
"""

from __future__ import annotations

import ctypes
import sys

M_TRIM_THRESHOLD = -1
M_MMAP_THRESHOLD = -3
MMAP_THRESHOLD = 64 << 20  # bytes: blocks below this come from the heap and are reused
TRIM_THRESHOLD = 128 << 20  # bytes of free heap top kept before returning memory to the system

_done: list[bool] = []


def reuse_freed_memory() -> bool:
    """Raise glibc's mmap and trim thresholds once per process; True when they are set."""
    if _done:
        return _done[0]
    ok = False
    if sys.platform.startswith("linux"):
        try:
            mallopt = ctypes.CDLL(None).mallopt  # absent in musl: nothing to tune
            mallopt.argtypes, mallopt.restype = [ctypes.c_int, ctypes.c_int], ctypes.c_int
            ok = bool(mallopt(M_MMAP_THRESHOLD, MMAP_THRESHOLD)) and bool(mallopt(M_TRIM_THRESHOLD, TRIM_THRESHOLD))
        except (OSError, AttributeError):
            ok = False
    _done.append(ok)
    return ok
