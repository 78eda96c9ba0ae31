"""Memory allocation tuned for numpy temporaries (glibc only; elsewhere nothing changes).

glibc serves every block above its mmap threshold (128 KiB, raised only as blocks are freed)
with a fresh ``mmap`` and returns it on ``free``, and it trims the heap top back to the system.
A conversion makes millions of temporaries of 0.1-60 MB, so each one is page-faulted in again,
4 KiB at a time: on a VM with free-page reporting (this machine) that cost 5-6x the arithmetic
(``(pts @ eq.T + d).max(1)`` on 3000 x 124: 13.7 ms -> 2.3 ms wall). Keeping freed blocks below
64 MB in the heap for reuse removes it; output is unchanged (only where memory comes from).

A forked helper (:mod:`realsim.forkmap`) shares every page with its parent copy-on-write, the kept
free heap too: each page the parent's temporaries then write is copied into a fresh page first
(test55: ~60k copies, ~0.1 s of the parent's system time). The helper lets go of its view of the free
heap as it starts (:func:`release_free_memory`), so those pages are the parent's alone again and
written in place; the helper's own temporaries get fresh pages, as its copies would have been.
"""

from __future__ import annotations

import ctypes
import sys

M_TRIM_THRESHOLD = -1
M_MMAP_THRESHOLD = -3
MMAP_THRESHOLD = 64 << 20  # bytes: blocks below this come from the heap and are reused
TRIM_THRESHOLD = 128 << 20  # bytes of free heap top kept before returning memory to the system

_done: list[bool] = []


def release_free_memory() -> bool:
    """Hand this process's free heap pages back to the system (glibc's ``malloc_trim(0)``: the
    inside of every free chunk, whatever the trim threshold); True when it ran. What is allocated
    and every value stay as they are."""
    if not sys.platform.startswith("linux"):
        return False
    try:
        trim = ctypes.CDLL(None).malloc_trim  # absent in musl
    except (OSError, AttributeError):
        return False
    trim.argtypes, trim.restype = [ctypes.c_size_t], ctypes.c_int
    trim(0)
    return True


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
