"""The base band of unorganized clouds is looked for only near object footprints (segment_scene._near_cells)."""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from realsim.perception.segment_scene import _near_cells


def test_near_cells_keeps_every_point_within_reach_and_drops_far_ones() -> None:
    rng = np.random.default_rng(3)
    cell, reach = 0.005, 0.0125
    objects = rng.uniform(-0.2, 0.2, size=(300, 2))
    cells = np.floor(objects / cell).astype(np.int64)
    xy = rng.uniform(-0.6, 0.6, size=(40_000, 2))
    xy[::97] = np.nan  # missing points are never near
    mask = _near_cells(xy, cells, cell, reach)
    finite = np.isfinite(xy).all(axis=1)
    dist = np.full(len(xy), np.inf)
    dist[finite] = cKDTree(objects).query(xy[finite])[0]
    assert mask[dist < reach].all()  # a superset of what the KD query can reach
    assert not mask[~finite].any()
    # and no wider than the dilation (ceil(reach / cell) + 1 cells each way, a cell's diagonal more)
    assert not mask[dist > (np.ceil(reach / cell) + 2) * np.sqrt(2) * cell].any()
    assert 0 < mask.sum() < 0.5 * len(xy)


def test_near_cells_with_nothing_to_be_near() -> None:
    assert not _near_cells(np.zeros((4, 2)), np.zeros((0, 2), dtype=np.int64), 0.01, 0.02).any()
