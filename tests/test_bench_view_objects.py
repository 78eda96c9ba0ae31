"""bench/bench_view_objects.py's ``failure_cause``: why a true object of a view is not one segment alone.
A 6x8 view of a flat surface 1 m away, 2 mm pixels; the true object fills columns 1-6."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "bench"))
from bench_view_objects import failure_cause  # noqa: E402

SHAPE = (6, 8)


def _view(step: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Points (48, 3) of the view, columns 4-7 moved back by ``step`` (m), and the truth: object 1 in columns 1-6."""
    v, u = np.mgrid[0:SHAPE[0], 0:SHAPE[1]]
    points = np.stack([u * 0.002, v * 0.002, 1.0 + np.where(u >= 4, step, 0.0)], axis=-1).reshape(-1, 3)
    gt = np.where((u >= 1) & (u <= 6), 1, 0).ravel()
    return points, gt


def _pred(left: int, right: int) -> np.ndarray:
    """Segments: ``left`` in columns 1-3, ``right`` in columns 4-6, support elsewhere."""
    u = np.mgrid[0:SHAPE[0], 0:SHAPE[1]][1]
    return np.where((u >= 1) & (u <= 3), left, np.where((u >= 4) & (u <= 6), right, 0)).ravel()


def test_found_once_has_no_cause() -> None:
    points, gt = _view()
    assert failure_cause(gt, _pred(1, 1), points, 1, SHAPE) == ""


def test_split_at_a_fold_or_a_depth_jump() -> None:
    points, gt = _view()
    assert failure_cause(gt, _pred(1, 2), points, 1, SHAPE) == "split at a fold"
    points, gt = _view(step=0.05)
    assert failure_cause(gt, _pred(1, 2), points, 1, SHAPE) == "split at a depth jump"


def test_parted_by_a_nearer_object() -> None:
    points, gt = _view()
    pred = _pred(1, 2)
    pred[np.arange(48) % 8 == 4] = 3  # column 4: a nearer object's segment (truth 0 there would not matter)
    gt[np.arange(48) % 8 == 4] = 2
    assert failure_cause(gt, pred, points, 1, SHAPE) == "parted by a nearer object"


def test_merged_absorbed_dropped_hidden() -> None:
    points, gt = _view()
    pred = _pred(1, 1)
    pred[np.arange(48) % 8 == 7] = 1  # the segment also takes column 7, another true object's
    gt2 = np.where(np.arange(48) % 8 == 7, 2, gt)
    assert failure_cause(gt2, pred, points, 1, SHAPE) == "merged with a neighbour"
    assert failure_cause(gt, _pred(0, 0), points, 1, SHAPE) == "absorbed by the support"
    assert failure_cause(gt, _pred(-1, -1), points, 1, SHAPE) == "dropped as too small"
    assert failure_cause(gt, _pred(1, 1), points, 5, SHAPE) == "hidden"


def test_part_taken_by_a_neighbour() -> None:
    points, gt = _view()
    pred = _pred(1, 2)
    gt2 = np.where(np.arange(48) % 8 == 7, 2, gt)
    pred[np.arange(48) % 8 == 7] = 2  # segment 2 holds columns 4-6 of object 1 and column 7 ... of object 2
    gt2[(np.arange(48) % 8 >= 5) & (np.arange(48) % 8 <= 6)] = 2  # ... and columns 5-6 are object 2's too
    assert failure_cause(gt2, pred, points, 1, SHAPE) == "part taken by a neighbour"
