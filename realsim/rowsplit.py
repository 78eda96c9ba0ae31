"""Row-independent numpy work shared between this thread and one more: the same rows, less wall time.

``fn(rows)`` computes the result rows of a slice of its input rows, each row from its own input row
alone (no sum or order across rows), so the halves computed apart and joined are bit for bit the
whole computed at once. numpy releases the GIL inside its loops over large arrays (gathers,
arithmetic, ``einsum``, ``argmin``), so the second thread runs on the second core while this one
computes the first half. A plain thread per call (no pool): it is safe in a forked helper too.
Fewer than ``least`` rows or ``$REALSIM_WORKERS=1``: one call on this thread.
"""

from __future__ import annotations

import os
import threading
from typing import Callable

import numpy as np

LEAST_ROWS = 20000  # fewer rows: a thread's start-up costs more than the half it takes


def _workers() -> int:
    return int(os.environ.get("REALSIM_WORKERS", os.cpu_count() or 1))


def split_rows(fn: Callable[[slice], np.ndarray], n: int, least: int = LEAST_ROWS) -> np.ndarray:
    """``fn(slice(0, n))``, its first and second half of the rows computed on two threads (see the
    module docstring); an exception in either half is raised here."""
    if n < max(least, 2) or _workers() < 2:
        return fn(slice(0, n))
    half = n // 2
    second: list[np.ndarray] = []
    failed: list[BaseException] = []

    def run() -> None:
        try:
            second.append(fn(slice(half, n)))
        except BaseException as exc:  # raised on this thread below
            failed.append(exc)

    thread = threading.Thread(target=run, name="realsim-rows", daemon=True)
    thread.start()
    try:
        first = fn(slice(0, half))
    finally:
        thread.join()
    if failed:
        raise failed[0]
    return np.concatenate([first, second[0]])
