"""An object's base on a coarse grid is a length, not a count of points (object_relations)."""

from __future__ import annotations

import numpy as np

from realsim.perception.object_relations import base_height, filter_by_size, support_relations
from realsim.perception.segment import SegmentParams, SegmentResult
from realsim.perception.segment_scene import at_resolution
from realsim.scene import SupportPlane

TABLE_Z = 0.9
CELL = 0.021  # m: a 50k-point room's working resolution


def _table() -> SupportPlane:
    polygon = np.array([[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]])
    return SupportPlane(id=1, kind="table", normal=np.array([0.0, 0.0, 1.0]), height=TABLE_Z, polygon=polygon,
                        rect_center=np.zeros(2), rect_size=np.array([1.0, 1.0]), rect_yaw=0.0, inlier_count=1000)


def _box_cells(lo: np.ndarray, hi: np.ndarray, rng: np.random.Generator, hidden: int = 0) -> np.ndarray:
    """Voxel centres (``CELL`` grid) of a box's visible faces sampled a cell apart (a sparse phone
    cloud): its top and sides, but the first ``hidden`` sides (pressed against a neighbour's)."""
    size, spacing = hi - lo, CELL
    faces = [(2, hi[2])] + [(a, v) for a in (1, 0) for v in (lo[a], hi[a])][hidden:]
    pts = []
    for axis, value in faces:
        other = [i for i in range(3) if i != axis]
        count = int(np.prod(size[other]) / spacing**2) + 1
        p = np.empty((count, 3))
        p[:, other] = lo[other] + rng.uniform(0, 1, (count, 2)) * size[other]
        p[:, axis] = value
        pts.append(p)
    cloud = np.concatenate(pts)
    cloud = cloud[cloud[:, 2] > TABLE_Z + 0.008]  # the foreground: 8 mm over the table
    _, inverse = np.unique(np.floor(cloud / CELL), axis=0, return_inverse=True)
    inverse = inverse.ravel()
    return np.stack([np.bincount(inverse, cloud[:, i]) for i in range(3)], axis=1) / np.bincount(inverse)[:, None]


def test_a_lone_stray_is_no_base_but_a_sparse_bottom_is() -> None:
    heights = np.array([0.0127, 0.0144, 0.0152, 0.0247, 0.0314, 0.05, 0.07])
    assert base_height(heights, gap=CELL) == 0.0127  # three points near the table are its base
    assert base_height(heights) == 0.0314  # a count (the 5th lowest) would put the base a cell higher
    stray = np.r_[0.01, heights + 0.03]  # a point more than a cell beneath the rest is a stray
    assert base_height(stray, gap=CELL) == 0.0427
    assert base_height(np.array([0.3]), gap=CELL) == 0.3


def test_sparse_standing_can_stands_floating_speck_does_not() -> None:
    """A 10 x 5.5 x 8 cm can sampled about a cell apart, one long side against a neighbour's (in
    that one's cluster), stands on the table at every seed; a cluster 6 cm up with nothing under
    it is noise."""
    params = at_resolution(SegmentParams(), CELL)
    floating_by_count = 0
    for seed in range(12):
        rng = np.random.default_rng(seed)
        can = _box_cells(np.array([0.0, 0.0, TABLE_Z]), np.array([0.10, 0.055, TABLE_Z + 0.08]), rng, hidden=1)
        floating_by_count += base_height(can[:, 2] - TABLE_Z) > params.stack_min_height
        speck = _box_cells(np.array([0.3, 0.0, TABLE_Z + 0.06]), np.array([0.36, 0.06, TABLE_Z + 0.12]), rng)
        points = np.concatenate([can, speck])
        labels = np.r_[np.full(len(can), 1), np.full(len(speck), 2)].astype(np.int32)
        out = filter_by_size(points, SegmentResult(labels, {1: 1, 2: 1}, {1: None, 2: None}), [_table()], params)
        assert np.all(out.labels[: len(can)] == 1), seed
        assert np.all(out.labels[len(can):] == -1), seed
    assert floating_by_count > 0  # the 5th-lowest point calls some of them floating


def test_sparse_object_on_a_box_rests_on_it() -> None:
    """A can on a 6 cm box, both sampled about a cell apart: the can rests on the box (what lies
    under its lowest cells is a cell away, farther than a dense cloud's 1.5 cm)."""
    params = at_resolution(SegmentParams(), CELL)
    for seed in range(12):
        rng = np.random.default_rng(seed)
        box = _box_cells(np.array([-0.1, -0.1, TABLE_Z]), np.array([0.1, 0.1, TABLE_Z + 0.06]), rng)
        can = _box_cells(np.array([-0.03, -0.03, TABLE_Z + 0.06]), np.array([0.03, 0.03, TABLE_Z + 0.14]), rng)
        points = np.concatenate([box, can])
        labels = np.r_[np.full(len(box), 1), np.full(len(can), 2)].astype(np.int32)
        support = np.zeros(len(points), dtype=np.int64)
        _, resting = support_relations(points, labels, support, points[:, 2] - TABLE_Z, [_table()], params)
        assert resting == {1: None, 2: 1}, seed


def test_a_bottle_on_a_box_whose_top_was_not_seen_rests_on_the_box() -> None:
    """A sweep at table height sees a lying box's four walls, not its top: a bottle standing on it
    has nothing under its foot, yet its foot lies inside the box's footprint at the height its
    walls top out: it rests on the box (not floating noise). A bottle beside the box does not."""
    params = at_resolution(SegmentParams(), CELL)
    rng = np.random.default_rng(3)
    lo, hi = np.array([-0.1, -0.08, TABLE_Z]), np.array([0.1, 0.08, TABLE_Z + 0.06])
    walls = _box_cells(lo, hi, rng)
    walls = walls[walls[:, 2] < hi[2] - 1e-9]  # no top
    bottle = _box_cells(np.array([-0.03, -0.03, hi[2] + 0.002]), np.array([0.03, 0.03, hi[2] + 0.2]), rng)
    beside = _box_cells(np.array([0.3, -0.03, hi[2] + 0.002]), np.array([0.36, 0.03, hi[2] + 0.2]), rng)
    points = np.concatenate([walls, bottle, beside])
    labels = np.r_[np.full(len(walls), 1), np.full(len(bottle), 2), np.full(len(beside), 3)].astype(np.int32)
    support = np.zeros(len(points), dtype=np.int64)
    _, resting = support_relations(points, labels, support, points[:, 2] - TABLE_Z, [_table()], params)
    assert resting == {1: None, 2: 1, 3: None}
