"""``[fn(i) for i in range(n)]`` shared with one forked helper process: the same results, less wall time.

The helper is a fork of this process, so it starts with everything already imported and computed
(no pickling of inputs, no imports: a forkserver pool paid 1.45 s of imports per worker for 5.7 s
of work). This process and the helper take items in turn from a shared counter, so neither waits
while the other has a long one. Only results are pickled back, all in one message at the end. The
helper must run pure numpy / scipy work: nothing that uses OpenMP, which may hang after a fork.
Whatever the helper does not deliver (it failed, died, or is not done ``timeout`` after this
process) is computed here, so the results never depend on it: an exception is raised here, with
its own traceback.
Elsewhere than Linux, with ``$REALSIM_WORKERS=1``, inside a helper or a pool's worker, for fewer
than two items, or when no process, pipe or semaphore can be had, it is the plain loop.
"""

from __future__ import annotations

import multiprocessing
import os
import sys
from multiprocessing.connection import Connection
from typing import Any, Callable, Generic, TypeVar

from realsim.alloc import release_free_memory

R = TypeVar("R")

TIMEOUT = 120.0  # s: a helper not done this long after this process ran out of items is given up
_in_helper: list[bool] = []


def _workers() -> int:
    return int(os.environ.get("REALSIM_WORKERS", os.cpu_count() or 1))


def can_fork() -> bool:
    """Whether :func:`fork_map` forks: Linux, more than one worker allowed, not inside a helper nor in a
    worker of a process pool (the pool already shares out the cores)."""
    return sys.platform.startswith("linux") and _workers() > 1 and not _in_helper and multiprocessing.parent_process() is None


def _claim(counter: Any, n: int) -> int | None:
    with counter.get_lock():
        i = int(counter.value)
        if i >= n:
            return None
        counter.value = i + 1
        return i


def _helper(fn: Callable[[int], Any], n: int, counter: Any, send: Connection) -> None:
    """Take items until none is left, then send all the results in one message (never blocking on a
    full pipe while there is work: the parent reads only when it asks for the results)."""
    _in_helper.append(True)
    release_free_memory()  # the free heap's pages are then the parent's alone: its temporaries write them in place
    done: dict[int, Any] = {}
    try:
        while (i := _claim(counter, n)) is not None:
            try:
                done[i] = fn(i)
            except BaseException:  # computed again by the parent, which raises it with its traceback
                break
        send.send(done)
    finally:
        send.close()


def _receive(recv: Connection, timeout: float) -> dict[int, Any]:
    """The helper's results (its one message; waiting up to ``timeout``), none when it died or stayed silent."""
    try:
        if recv.poll(timeout):
            return dict(recv.recv())
    except (EOFError, OSError):
        pass
    return {}


def fork_map(fn: Callable[[int], R], n: int, timeout: float = TIMEOUT, least: int = 2) -> list[R]:
    """``[fn(i) for i in range(n)]``, the items shared with a forked helper (see the module docstring);
    fewer than ``least`` items (too little work to pay for a fork): the plain loop."""
    return Ahead(fn, n, timeout, least=max(least, 2)).results()


class Ahead(Generic[R]):
    """``[fn(i) for i in range(n)]`` begun now by a forked helper, while this process does other work
    that changes nothing ``fn`` reads; :meth:`results` takes the items left here too and returns
    them all in order (see the module docstring). Fewer than ``least`` items: no helper. As a context
    manager, a helper whose results were never asked for (an error in between) is stopped on exit."""

    def __init__(self, fn: Callable[[int], R], n: int, timeout: float = TIMEOUT, least: int = 1) -> None:
        self.fn, self.n, self.timeout = fn, n, timeout
        self.helper: Any = None
        if n < least or not can_fork():
            return
        ctx = multiprocessing.get_context("fork")
        try:  # a shared counter needs a semaphore (/dev/shm), the helper a process and a pipe
            self.counter = ctx.Value("l", 0)
            self.recv, send = ctx.Pipe(duplex=False)
            self.helper = ctx.Process(target=_helper, args=(fn, n, self.counter, send), daemon=True)
            self.helper.start()
        except OSError:  # none to be had here: the plain loop
            self.helper = None
            return
        send.close()

    def results(self) -> list[R]:
        """Every item's result, in order (call once)."""
        fn, n, helper = self.fn, self.n, self.helper
        if helper is None:
            return [fn(i) for i in range(n)]
        results: dict[int, Any] = {}
        try:
            while (i := _claim(self.counter, n)) is not None:
                results[i] = fn(i)
            results.update(_receive(self.recv, self.timeout))
        finally:
            self.stop(kill=len(results) < n)
        return [results[i] if i in results else fn(i) for i in range(n)]

    def stop(self, kill: bool = True) -> None:
        """Close the pipe and wait for the helper (killed first unless ``kill`` is False); then none is left."""
        if self.helper is None:
            return
        self.recv.close()
        if kill and self.helper.is_alive():
            self.helper.kill()
        self.helper.join()
        self.helper = None

    def __enter__(self) -> Ahead[R]:
        return self

    def __exit__(self, *_: object) -> None:
        self.stop()
