"""Parallel map over per-object work, with a progress bar for long runs."""

from __future__ import annotations

import multiprocessing
import os
from concurrent.futures import ProcessPoolExecutor
from typing import Callable, Iterable, TypeVar

from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

from realsim.alloc import reuse_freed_memory

T = TypeVar("T")
R = TypeVar("R")


def worker_count(n_items: int, max_workers: int | None = None) -> int:
    """Workers to use: all cores (or ``$REALSIM_WORKERS``), never more than the items."""
    cores = int(os.environ.get("REALSIM_WORKERS", os.cpu_count() or 1))
    if max_workers is not None:
        cores = min(cores, max_workers)
    return max(1, min(cores, n_items))


def parallel_map(
    fn: Callable[[T], R],
    items: Iterable[T],
    *,
    description: str = "working",
    max_workers: int | None = None,
    progress: bool = False,
) -> list[R]:
    """``[fn(x) for x in items]`` in worker processes, results in input order.

    ``fn`` must be a picklable top-level function. With one worker (or one item) it runs in
    this process. Exceptions from ``fn`` propagate.
    """
    items = list(items)
    workers = worker_count(len(items), max_workers)
    columns = (TextColumn("{task.description}"), BarColumn(), TextColumn("{task.completed}/{task.total}"), TimeElapsedColumn())
    with Progress(*columns, disable=not progress, transient=True) as bar:
        task = bar.add_task(description, total=len(items))
        if workers == 1:
            results = []
            for item in items:
                results.append(fn(item))
                bar.advance(task)
            return results
        # forkserver: workers never inherit OpenMP state (CoACD, Open3D) that breaks after fork.
        with ProcessPoolExecutor(max_workers=workers, mp_context=multiprocessing.get_context("forkserver"),
                                 initializer=reuse_freed_memory) as pool:
            futures = [pool.submit(fn, item) for item in items]
            results = []
            for fut in futures:
                results.append(fut.result())
                bar.advance(task)
            return results
