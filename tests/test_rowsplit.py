"""split_rows: row-independent numpy work halved between two threads gives the whole bit for bit."""

from __future__ import annotations

import threading

import numpy as np
import pytest

from realsim.rowsplit import split_rows


def _work(data: np.ndarray, seen: list[tuple[int, int, int]]) -> "callable":
    def fn(rows: slice) -> np.ndarray:
        seen.append((rows.start, rows.stop, threading.get_ident()))
        block = data[rows]
        return np.asarray(np.einsum("ij,ij->i", block, block) / 3.0 + block.argmin(axis=1))
    return fn


def test_two_threads_each_take_half_and_the_rows_are_the_whole(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("REALSIM_WORKERS", "2")
    data = np.random.default_rng(1).normal(size=(50001, 12)).astype(np.float32)
    seen: list[tuple[int, int, int]] = []
    out = split_rows(_work(data, seen), len(data))
    assert sorted((a, b) for a, b, _ in seen) == [(0, 25000), (25000, 50001)]
    assert len({t for _, _, t in seen}) == 2 and threading.get_ident() in {t for _, _, t in seen}
    assert out.tobytes() == _work(data, [])(slice(0, len(data))).tobytes()


def test_few_rows_or_one_worker_are_one_call_here(monkeypatch: pytest.MonkeyPatch) -> None:
    data = np.ones((30000, 3))
    for workers, n in (("2", 100), ("1", 30000)):
        monkeypatch.setenv("REALSIM_WORKERS", workers)
        seen: list[tuple[int, int, int]] = []
        split_rows(_work(data, seen), n)
        assert seen == [(0, n, threading.get_ident())]


def test_an_error_in_the_second_half_is_raised_here(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("REALSIM_WORKERS", "2")

    def fn(rows: slice) -> np.ndarray:
        if rows.start:
            raise ValueError("second half")
        return np.zeros(rows.stop - rows.start)

    with pytest.raises(ValueError, match="second half"):
        split_rows(fn, 40000)
