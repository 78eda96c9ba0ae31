"""Objects resting on a flat top split from the cluster they merged into; containers and lying
bodies never split; a resting object's foot taken back from its base (realsim.perception.stack_split)."""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from realsim.perception.stack_split import give_resting_base, split_resting

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


def _noisy(points: np.ndarray, sigma: float = 0.002, seed: int = 5) -> np.ndarray:
    return points + np.random.default_rng(seed).normal(0.0, sigma, points.shape)


def _can(centre: tuple[float, float], radius: float, z0: float, height: float) -> np.ndarray:
    """A standing can's wall and top, points one cell apart, its bottom at ``z0``."""
    angle = np.linspace(0, 2 * np.pi, int(2 * np.pi * radius / CELL), endpoint=False)
    aa, zz = np.meshgrid(angle, np.arange(z0, z0 + height, CELL / 2), indexing="ij")
    wall = np.c_[centre[0] + radius * np.cos(aa.ravel()), centre[1] + radius * np.sin(aa.ravel()), zz.ravel()]
    rr, tt = np.meshgrid(np.arange(CELL / 2, radius, CELL), angle, indexing="ij")
    top = np.c_[centre[0] + rr.ravel() * np.cos(tt.ravel()), centre[1] + rr.ravel() * np.sin(tt.ravel()),
                np.full(rr.size, z0 + height)]
    return np.vstack([wall, top])


def test_a_can_on_a_box_gets_back_its_foot_above_the_top() -> None:
    box = _noisy(_box((0.0, 0.0, 0.0), (0.24, 0.16, 0.06))[0])
    can = _noisy(_can((0.12, 0.08), 0.034, 0.06, 0.10), seed=6)
    points = np.vstack([box, can])
    truth = np.repeat([1, 2], [len(box), len(can)])
    labels = truth.copy()
    foot = (truth == 2) & (points[:, 2] < 0.06 + 0.02)  # the segments gave the can's lowest 2 cm to the box
    labels[foot] = 1
    out = give_resting_base(points, labels, {1: None, 2: 1}, band=0.004, reach=0.03, step=CELL)
    # more than the band and a point spacing of the wall (CELL / 2) above the top: nearer the can than the top
    clear = foot & (points[:, 2] > 0.06 + 0.004 + CELL / 2 + 0.002)
    assert clear.sum() >= 10 and (out[clear] == 2).all()
    assert (out[truth == 1] == 1).all()  # nothing of the box (its top, its sides) moves
    assert (out[(truth == 2) & ~foot] == 2).all()
    assert (give_resting_base(points, labels, {1: None, 2: None}, 0.004, 0.03, CELL) == labels).all()  # nothing rests


def test_a_base_without_a_level_top_keeps_its_points() -> None:
    """A ridge (two faces sloping 45 degrees) has no level top: what rises inside an outline on it is its own slope."""
    yy, xx = np.meshgrid(np.linspace(-0.04, 0.04, 40), np.arange(0.0, 0.20, CELL / 3), indexing="ij")
    ridge = np.c_[xx.ravel(), yy.ravel(), 0.08 - np.abs(yy.ravel())]
    block = _box((0.06, -0.02, 0.08), (0.12, 0.02, 0.11))[0]
    points = np.vstack([ridge, block])
    labels = np.repeat([1, 2], [len(ridge), len(block)])
    assert (give_resting_base(points, labels, {2: 1}, band=0.004, reach=0.03, step=CELL) == labels).all()


def test_a_relief_of_the_top_under_a_resting_object_stays_with_the_base() -> None:
    """A cap's dome under what rests on it rises above the top's layer but lies nearer the top than the object."""
    box = _box((0.0, 0.0, 0.0), (0.24, 0.16, 0.06))[0]
    xx, yy = np.meshgrid(np.arange(0.105, 0.136, 0.004), np.arange(0.065, 0.096, 0.004), indexing="ij")
    dome = np.c_[xx.ravel(), yy.ravel(), 0.06 + 0.008 - 40 * ((xx.ravel() - 0.12) ** 2 + (yy.ravel() - 0.08) ** 2)]
    can = _can((0.12, 0.08), 0.034, 0.07, 0.10)
    points = _noisy(np.vstack([box, dome, can]), sigma=0.0005)
    labels = np.repeat([1, 1, 2], [len(box), len(dome), len(can)])
    out = give_resting_base(points, labels, {2: 1}, band=0.002, reach=0.03, step=0.004)
    assert (out[: len(box) + len(dome)] == 1).all()
