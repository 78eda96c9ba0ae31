"""A value computed on a thread beside this one: begun now, taken later (numpy releases the GIL in its loops).

For work that reads only what nothing changes in between and that the caller needs later; its
exception, if any, is raised where the value is taken. With ``$REALSIM_WORKERS=1`` the work is
done where the value is taken (one core: a thread would only interleave with this one).
"""

from __future__ import annotations

import os
import threading
from typing import Callable, Generic, TypeVar

T = TypeVar("T")


class Beside(Generic[T]):
    """``fn()`` begun on a thread (see the module docstring); :meth:`result` waits for it and returns it."""

    def __init__(self, fn: Callable[[], T]) -> None:
        self.fn = fn
        self.value: list[T] = []
        self.failed: list[BaseException] = []
        self.thread: threading.Thread | None = None
        if int(os.environ.get("REALSIM_WORKERS", os.cpu_count() or 1)) > 1:
            self.thread = threading.Thread(target=self._run, name="realsim-beside", daemon=True)
            self.thread.start()

    def _run(self) -> None:
        try:
            self.value.append(self.fn())
        except BaseException as exc:  # raised by result(), on the caller's thread
            self.failed.append(exc)

    def result(self) -> T:
        """The value of ``fn()`` (computed here when no thread was begun)."""
        if self.thread is None:
            return self.fn()
        self.thread.join()
        if self.failed:
            raise self.failed[0]
        return self.value[0]
