"""parallel_map in worker processes (the suite may run with REALSIM_WORKERS=1 under pytest-xdist,
so the process pool is exercised here on purpose)."""

from __future__ import annotations

import os

import pytest

from realsim.parallel import parallel_map, worker_count


def _square_and_pid(x: int) -> tuple[int, int]:
    if x < 0:
        raise ValueError(f"negative: {x}")
    return x * x, os.getpid()


def test_worker_count_follows_the_setting_and_the_items(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("REALSIM_WORKERS", "3")
    assert worker_count(10) == 3 and worker_count(2) == 2 and worker_count(10, max_workers=2) == 2 and worker_count(0) == 1


def test_two_workers_keep_input_order_and_raise_errors(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("REALSIM_WORKERS", "2")
    results = parallel_map(_square_and_pid, range(6))
    assert [r for r, _ in results] == [0, 1, 4, 9, 16, 25]
    assert os.getpid() not in {pid for _, pid in results}  # the work ran in worker processes
    with pytest.raises(ValueError, match="negative: -2"):
        parallel_map(_square_and_pid, [1, -2, 3])
