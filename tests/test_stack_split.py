"""Objects resting on a flat top split from the cluster they merged into; containers and lying
bodies never split (realsim.perception.stack_split)."""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from realsim.perception.stack_split import split_resting

CELL = 0.015  # m: a sparse cloud (about 80k points over a room)


def _box(lo: tuple[float, float, float], hi: tuple[float, float, float]) -> tuple[np.ndarray, np.ndarray]:
    """Points one cell apart on a box's top and four sides (its bottom stands on something), outward normals."""
    lo_, hi_ = np.asarray(lo), np.asarray(hi)
    pts, nrm = [], []
    for axis in range(3):
        for side, value in ((-1, lo_[axis]), (1, hi_[axis])):
            if axis == 2 and side == -1:
                continue
            u, v = [k for k in range(3) if k != axis]
            gu = np.arange(lo_[u] + CELL / 2, hi_[u], CELL)
            gv = np.arange(lo_[v] + CELL / 2, hi_[v], CELL)
            uu, vv = np.meshgrid(gu, gv, indexing="ij")
            p = np.zeros((uu.size, 3))
            p[:, u], p[:, v], p[:, axis] = uu.ravel(), vv.ravel(), value
            n = np.zeros((len(p), 3))
            n[:, axis] = side
            pts.append(p)
            nrm.append(n)
    return np.vstack(pts), np.vstack(nrm)


def _cup(radius: float, height: float, floor: float = 0.03) -> tuple[np.ndarray, np.ndarray]:
    """An open cup standing on z = 0: its inner bottom ``floor`` high (level, facing up) and its
    wall from the support up (outward normals)."""
    rings = np.arange(CELL / 2, radius, CELL)
    bottom = [np.c_[r * np.cos(t), r * np.sin(t), np.full(len(t), floor)]
              for r in rings for t in [np.linspace(0, 2 * np.pi, max(6, int(2 * np.pi * r / CELL)), endpoint=False)]]
    base = np.vstack(bottom)
    angle = np.linspace(0, 2 * np.pi, int(2 * np.pi * radius / CELL), endpoint=False)
    zs = np.arange(0.0, height, CELL)
    aa, zz = np.meshgrid(angle, zs, indexing="ij")
    wall = np.c_[radius * np.cos(aa.ravel()), radius * np.sin(aa.ravel()), zz.ravel()]
    normals = np.vstack([np.tile([0.0, 0.0, 1.0], (len(base), 1)), np.c_[np.cos(aa.ravel()), np.sin(aa.ravel()), np.zeros(aa.size)]])
    return np.vstack([base, wall]), normals


def _split(points: np.ndarray, normals: np.ndarray) -> np.ndarray:
    pairs = cKDTree(points).query_pairs(1.6 * CELL, output_type="ndarray")
    return split_resting(points, normals, np.zeros(len(points), dtype=np.int64), pairs[:, 0], pairs[:, 1], CELL, 10, 0.02)


def test_a_block_on_a_box_is_split_off() -> None:
    box, box_n = _box((0.0, 0.0, 0.0), (0.24, 0.16, 0.06))
    block, block_n = _box((0.08, 0.05, 0.06), (0.155, 0.10, 0.11))
    under = (box[:, 0] > 0.08) & (box[:, 0] < 0.155) & (box[:, 1] > 0.05) & (box[:, 1] < 0.10) & (box[:, 2] > 0.059)
    box, box_n = box[~under], box_n[~under]  # the block hides the top under it
    labels = _split(np.vstack([box, block]), np.vstack([box_n, block_n]))
    top = labels[len(box):]
    assert len(np.unique(labels)) == 2
    high = block[:, 2] > 0.06 + CELL + 1e-9  # the block's foot, one cell over the top, stays with the box
    assert (top[high] != labels[0]).all() and (labels[: len(box)] == labels[0]).all()


def test_a_cup_is_not_split_at_its_inner_bottom() -> None:
    points, normals = _cup(0.045, 0.10)
    assert (_split(points, normals) == 0).all()


def test_a_box_alone_and_a_low_body_are_not_split() -> None:
    box, box_n = _box((0.0, 0.0, 0.0), (0.24, 0.16, 0.06))
    assert (_split(box, box_n) == 0).all()
    slab, slab_n = _box((0.0, 0.0, 0.0), (0.24, 0.16, 0.012))  # its top is too low to be a body's top
    block, block_n = _box((0.08, 0.05, 0.012), (0.155, 0.10, 0.06))
    assert (_split(np.vstack([slab, block]), np.vstack([slab_n, block_n])) == 0).all()
