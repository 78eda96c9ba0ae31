"""visibility_score(settle=k): the scores of casting every ray, clipped to [-k, k], with fewer rays."""

from __future__ import annotations

import numpy as np
import pytest

from realsim.perception.visibility import OccupancyGrid, visibility_score


def _scene(rng: np.random.Generator, step: float) -> np.ndarray:
    """A floor, two boxes pressed together and a hollow cylinder: patches seen from one side,
    both sides, and sides that cannot tell."""
    g = np.arange(-0.2, 0.2, step)
    gx, gy = np.meshgrid(g, g)
    floor = np.stack([gx.ravel(), gy.ravel(), np.zeros(gx.size)], axis=1)
    box = rng.uniform(0.0, 0.1, size=(6000, 3))  # a 10 cm cube's faces: one coordinate at 0 or 0.1
    box[np.arange(len(box)), rng.integers(0, 3, len(box))] = np.where(rng.random(len(box)) < 0.5, 0.0, 0.1)
    box -= [0.2, 0.05, 0.0]
    other = box + [0.1, 0.0, 0.0]  # pressed against the first
    ang = rng.uniform(0, 2 * np.pi, 3000)
    cyl = np.stack([0.1 + 0.04 * np.cos(ang), 0.1 + 0.04 * np.sin(ang), rng.uniform(0, 0.09, 3000)], axis=1)
    return np.vstack([floor, box, other, cyl])


@pytest.mark.parametrize("seed", [0, 1])
def test_settled_scores_are_the_clipped_full_scores(seed: int) -> None:
    rng = np.random.default_rng(seed)
    step = 0.005
    pts = _scene(rng, step)
    grid = OccupancyGrid(pts, step)
    probe = pts[rng.choice(len(pts), 600, replace=False)]
    normals = rng.normal(size=probe.shape)
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    full = visibility_score(grid, probe, normals, step, 0.3)
    assert full.min() <= -3 and full.max() >= 3 and (np.abs(full) < 2).any()  # every case occurs
    for settle in (1, 2, 5):
        assert np.array_equal(visibility_score(grid, probe, normals, step, 0.3, settle=settle), np.clip(full, -settle, settle))
    grouped = visibility_score(grid, probe, normals, step, 0.3, group=2 * step)
    assert np.array_equal(visibility_score(grid, probe, normals, step, 0.3, group=2 * step, settle=2), np.clip(grouped, -2, 2))
