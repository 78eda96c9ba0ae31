"""Footprints: standing pieces that share a footprint are one object; stacked or adjacent ones are not."""

from __future__ import annotations

import numpy as np

from realsim.perception.footprints import merge_shared_footprints


def _ring(r: float, z1: float, centre: tuple[float, float], step: float = 0.004) -> np.ndarray:
    a, z = np.meshgrid(np.arange(0.0, 2 * np.pi, step / r), np.arange(0.0, z1, step))
    return np.stack([centre[0] + r * np.cos(a.ravel()), centre[1] + r * np.sin(a.ravel()), z.ravel()], axis=1)


def _box(lo: tuple[float, float, float], hi: tuple[float, float, float], n: int, seed: int) -> np.ndarray:
    return np.random.default_rng(seed).uniform(lo, hi, (n, 3))


def test_inside_and_outside_of_a_bowl_join_stacked_and_neighbours_stay() -> None:
    """A bowl cut into its outer wall and its inside (two standing clusters, one inside the
    other's hull) becomes one; a box stacked on a box (not standing) and a box standing next to
    them keep their own labels."""
    outer = _ring(0.08, 0.06, (0.0, 0.0))
    inner = _ring(0.07, 0.05, (0.0, 0.0))
    lower = _box((0.2, -0.05, 0.0), (0.3, 0.05, 0.06), 800, 1)
    upper = _box((0.22, -0.03, 0.06), (0.28, 0.03, 0.1), 300, 2)  # on the lower box: inside its hull
    beside = _box((0.3, 0.06, 0.0), (0.36, 0.12, 0.05), 300, 3)  # touches the lower box's corner
    clusters = [outer, inner, lower, upper, beside]
    points = np.concatenate(clusters)
    labels = np.concatenate([np.full(len(c), k) for k, c in enumerate(clusters)])
    standing = np.array([True, True, True, False, True])
    out = merge_shared_footprints(points[:, :2], labels, np.zeros(len(points), dtype=np.int64), standing, 0.006)
    assert len(np.unique(out[labels <= 1])) == 1  # the bowl
    assert len(np.unique(out)) == 4
    for k in (2, 3, 4):
        assert np.all(out[labels == k] == k)
    # on different supports, nothing joins
    other = np.where(labels == 1, 1, 0)
    assert len(np.unique(merge_shared_footprints(points[:, :2], labels, other, standing, 0.006))) == 5


def test_an_object_in_the_bay_of_an_l_shaped_one_stays_apart() -> None:
    """A can standing in the bay of an L-shaped object (a lying drill: body and grip) lies inside
    the L's convex hull but beside its footprint: it keeps its own label, whatever the grid."""
    body = _box((0.0, 0.0, 0.0), (0.2, 0.05, 0.06), 3000, 4)
    grip = _box((0.0, 0.05, 0.0), (0.05, 0.2, 0.05), 2000, 5)
    can = _ring(0.035, 0.1, (0.1, 0.11))
    points = np.concatenate([body, grip, can])
    labels = np.concatenate([np.zeros(len(body) + len(grip), dtype=np.int64), np.ones(len(can), dtype=np.int64)])
    standing = np.array([True, True])
    for cell in (0.004, 0.01, 0.02):
        out = merge_shared_footprints(points[:, :2], labels, np.zeros(len(points), dtype=np.int64), standing, cell)
        assert np.array_equal(out, labels)


def test_walls_are_tall_columns_objects_beside_them_are_not() -> None:
    """A wall rising 1 m above the support is structure before segmentation; a 30 cm bottle
    standing 3 cm from it is not."""
    from realsim.perception.segment import SegmentParams
    from realsim.perception.segment_scene import _in_tall_columns

    rng = np.random.default_rng(0)
    wall = rng.uniform([-0.5, 0.0, 0.01], [0.5, 0.004, 0.99], (5000, 3))
    bottle = rng.uniform([-0.04, -0.11, 0.01], [0.04, -0.03, 0.3], (2000, 3))
    points = np.concatenate([wall, bottle])
    tall = _in_tall_columns(points, np.zeros(len(points), dtype=np.int64), points[:, 2], SegmentParams())
    assert tall[: len(wall)].all()
    assert not tall[len(wall):].any()


def test_a_bottle_on_a_lying_box_stays_apart_though_a_few_of_its_points_reach_down() -> None:
    """A bottle standing on a lying box whose cluster took a strip of the box's side down to the
    support "stands" by it and lies in the box's footprint, but nearly all of it lies above the
    box's top: it rests there and is not joined; a bowl's inside (below its rim) still is."""
    box = _box((0.0, 0.0, 0.0), (0.2, 0.15, 0.06), 3000, 6)
    bottle = _ring(0.04, 0.2, (0.1, 0.075)) + np.array([0.0, 0.0, 0.062])
    strip = _box((0.0, 0.07, 0.0), (0.004, 0.08, 0.06), 40, 7)  # the box's side, taken by the bottle's cluster
    points = np.concatenate([box, bottle, strip])
    labels = np.concatenate([np.zeros(len(box)), np.ones(len(bottle) + len(strip))]).astype(np.int64)
    support = np.zeros(len(points), dtype=np.int64)
    standing = np.array([True, True])
    joined = merge_shared_footprints(points[:, :2], labels, support, standing, 0.006)
    assert len(np.unique(joined)) == 1  # by the footprint alone, one object
    out = merge_shared_footprints(points[:, :2], labels, support, standing, 0.006, height=points[:, 2])
    assert np.array_equal(out, labels)
    outer, inner = _ring(0.08, 0.06, (0.0, 0.0)), _ring(0.07, 0.05, (0.0, 0.0)) + np.array([0.0, 0.0, 0.004])
    bowl = np.concatenate([outer, inner])
    bowl_labels = np.concatenate([np.zeros(len(outer)), np.ones(len(inner))]).astype(np.int64)
    out = merge_shared_footprints(bowl[:, :2], bowl_labels, np.zeros(len(bowl), dtype=np.int64), standing, 0.006,
                                  height=bowl[:, 2])
    assert len(np.unique(out)) == 1


def _wall(x0: float, y0: float, x1: float, y1: float, z1: float, step: float = 0.004) -> np.ndarray:
    """Points on a vertical wall from (x0, y0) to (x1, y1), 0 .. z1 high."""
    t, z = np.meshgrid(np.linspace(0.0, 1.0, int(np.hypot(x1 - x0, y1 - y0) / step) + 1), np.arange(0.0, z1, step))
    return np.stack([x0 + t.ravel() * (x1 - x0), y0 + t.ravel() * (y1 - y0), z.ravel()], axis=1)


def test_two_halves_of_a_box_ring_join_two_touching_cans_stay() -> None:
    """A lying box seen without its top (four walls) cut at two corners into two L-shaped clusters:
    together they close around its inside, so they are one body; two cans touching close nothing."""
    first = np.vstack([_wall(0.0, 0.0, 0.2, 0.0, 0.06), _wall(0.2, 0.0, 0.2, 0.15, 0.06)])
    second = np.vstack([_wall(0.2, 0.15, 0.0, 0.15, 0.06), _wall(0.0, 0.15, 0.0, 0.0, 0.06)])
    cans = [_ring(0.033, 0.1, (0.5, 0.0)), _ring(0.033, 0.1, (0.566, 0.0))]
    clusters = [first, second, *cans]
    points = np.concatenate(clusters)
    labels = np.concatenate([np.full(len(c), k) for k, c in enumerate(clusters)])
    out = merge_shared_footprints(points[:, :2], labels, np.zeros(len(points), dtype=np.int64), np.ones(4, dtype=bool),
                                  0.006, height=points[:, 2])
    assert len(np.unique(out[labels <= 1])) == 1
    assert np.array_equal(out[labels >= 2], labels[labels >= 2])


def test_two_pieces_resting_on_one_box_in_one_place_join_a_can_beside_them_stays() -> None:
    """A pitcher on a lying box, cut at its handle's crease into its body and a strip of wall with
    the handle, both resting on the box (they cannot stand in the same place on it either); a can
    resting on the box beside them and the box itself keep their own labels."""
    from realsim.perception.segment import _join_footprints_on_objects

    box = _box((-0.1, -0.08, 0.0), (0.2, 0.08, 0.06), 2000, 4)
    body = _ring(0.05, 0.15, (0.0, 0.0)) + [0.0, 0.0, 0.06]
    strip = body[body[:, 0] > 0.045]  # the wall's handle side, one piece of the same footprint
    body = body[body[:, 0] <= 0.045]
    can = _ring(0.03, 0.1, (0.14, 0.0)) + [0.0, 0.0, 0.06]
    clusters = [box, body, strip, can]
    points = np.concatenate(clusters)
    labels = np.concatenate([np.full(len(c), k + 1) for k, c in enumerate(clusters)])
    height = points[:, 2]
    out = _join_footprints_on_objects(points, labels, {1: None, 2: 1, 3: 1, 4: 1}, height, 0.006)
    assert np.all(out[labels == 3] == out[labels == 2][0])  # the handle strip is the pitcher's
    for k in (1, 2, 4):
        assert np.all(out[labels == k] == k)
    # resting on different objects (or on the support), nothing joins
    assert np.array_equal(_join_footprints_on_objects(points, labels, {1: None, 2: 1, 3: None, 4: 1}, height, 0.006), labels)
