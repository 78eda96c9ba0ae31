"""SLIC's assignments halved between two threads (realsim.rowsplit): the labels of the plain loop."""

from __future__ import annotations

import numpy as np
import pytest

import realsim.perception.supervoxels as supervoxels


def _plain_slic(features: np.ndarray, candidates: np.ndarray, labels: np.ndarray, iterations: int) -> np.ndarray:
    """Local k-means written as one loop over all points (the reference)."""
    features = features.astype(np.float32)
    n_seeds = int(candidates.max()) + 1
    cand = np.where(candidates >= 0, candidates, 0)
    for _ in range(iterations):
        count = np.bincount(labels, minlength=n_seeds).astype(np.float32)
        centres = np.stack([np.bincount(labels, features[:, f], minlength=n_seeds) for f in range(features.shape[1])], axis=1)
        centres = (centres / np.maximum(count, 1.0)[:, None]).astype(np.float32)
        dist = np.empty(cand.shape, dtype=np.float32)
        for c in range(cand.shape[1]):
            diff = features - centres[cand[:, c]]
            dist[:, c] = np.einsum("ij,ij->i", diff, diff)
        dist[(candidates < 0) | (count[cand] == 0)] = np.inf
        labels = cand[np.arange(len(cand)), dist.argmin(axis=1)]
    return labels


def test_slic_on_two_threads_gives_the_plain_labels(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("REALSIM_WORKERS", "2")
    rows: list[int] = []
    split = supervoxels.split_rows
    monkeypatch.setattr(supervoxels, "split_rows", lambda fn, n: rows.append(n) or split(fn, n))
    rng = np.random.default_rng(4)
    m = 60000
    features = rng.normal(size=(m, 12))
    candidates = rng.integers(-1, 2000, (m, 9))
    candidates[:, 4] = rng.integers(0, 2000, m)
    labels = candidates[:, 4].copy()
    out = supervoxels._slic(features, candidates, labels, 4)
    assert rows == [m] * 4  # every assignment halved between the threads
    assert out.tobytes() == _plain_slic(features, candidates, labels, 4).tobytes()
