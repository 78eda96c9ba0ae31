"""Colour split: touching objects of two colours (or of one hue, one far brighter where both face
alike) in one sparse cluster become two; shading, 6-bit colours and one-colour objects cut apart
by shape do not make or keep extra objects."""

from __future__ import annotations

import numpy as np
import pytest

from realsim.perception.colour_split import brightness_classes, colour_classes, split_by_colour
from realsim.perception.supervoxels import knn_links


def _box_surface(lo: tuple[float, float, float], hi: tuple[float, float, float], spacing: float, seed: int) -> np.ndarray:
    """Points sampled uniformly on a box's five visible faces, about ``spacing`` apart."""
    lo_a, hi_a = np.asarray(lo), np.asarray(hi)
    size = hi_a - lo_a
    area = 2 * (size[0] * size[2] + size[1] * size[2]) + size[0] * size[1]
    n = max(8, int(area / spacing**2))
    rng = np.random.default_rng(seed)
    p = lo_a + rng.uniform(0, 1, (n, 3)) * size
    face = rng.integers(0, 5, n)
    p[face == 0, 0], p[face == 1, 0] = lo_a[0], hi_a[0]
    p[face == 2, 1], p[face == 3, 1] = lo_a[1], hi_a[1]
    p[face == 4, 2] = hi_a[2]
    return p


def _shaded(points: np.ndarray, rgb: tuple[float, float, float], seed: int) -> np.ndarray:
    """A flat colour lit from one side (brightness 0.6-1.0 with height and x), with 1 % noise."""
    light = 0.6 + 0.4 * (points[:, 0] - points[:, 0].min() + points[:, 2]) / max(np.ptp(points[:, 0]) + np.ptp(points[:, 2]), 1e-9)
    noise = np.random.default_rng(seed).normal(0, 0.01, (len(points), 3))
    return np.clip(np.asarray(rgb) * light[:, None] + noise, 0, 1)


def _scene(spacing: float = 0.02) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A red can-sized box touching a green bowl-sized box, and the truth of every point."""
    can = _box_surface((0.0, 0.0, 0.0), (0.1, 0.05, 0.08), spacing, 1)
    bowl = _box_surface((0.1, -0.05, 0.0), (0.26, 0.11, 0.06), spacing, 2)
    points = np.vstack([can, bowl])
    colors = np.vstack([_shaded(can, (0.75, 0.18, 0.13), 3), _shaded(bowl, (0.5, 0.7, 0.15), 4)])
    truth = np.r_[np.zeros(len(can), np.int64), np.ones(len(bowl), np.int64)]
    return points, colors, truth


def _links(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return knn_links(points, np.ones(len(points), dtype=bool), 8)


def test_two_colours_in_one_cluster_become_the_two_objects() -> None:
    points, colors, truth = _scene()
    a, b = _links(points)
    out = split_by_colour(colors, np.zeros(len(points), np.int64), a, b, min_points=10)
    assert len(np.unique(out)) == 2
    for k in (0, 1):  # each object is (nearly all) one label of its own
        share = np.bincount(out[truth == k]).max() / (truth == k).sum()
        assert share > 0.95
    assert np.bincount(out[truth == 0]).argmax() != np.bincount(out[truth == 1]).argmax()
    # 6-bit colours (a phone's coarse colour) give the same objects
    quantized = np.round(colors * 63) / 63
    assert np.array_equal(split_by_colour(quantized, np.zeros(len(points), np.int64), a, b, min_points=10), out)


def test_shading_and_noise_on_one_colour_are_one_object() -> None:
    points, colors, truth = _scene()
    one = truth == 1
    assert colour_classes(colors[one]) is None  # light and shadow on one surface: one colour
    a, b = _links(points[one])
    out = split_by_colour(colors[one], np.zeros(int(one.sum()), np.int64), a, b, min_points=10)
    assert np.all(out == 0)


def test_pieces_of_one_colour_cut_apart_by_shape_rejoin_after_a_split() -> None:
    """The bowl was cut in two by shape and one half took the can: the can leaves, the two bowl
    halves join (one colour, touching), and the can stays its own."""
    points, colors, truth = _scene()
    labels = np.where((truth == 1) & (points[:, 0] > 0.18), 1, 0)
    a, b = _links(points)
    out = split_by_colour(colors, labels, a, b, min_points=10)
    bowl, can = out[truth == 1], out[truth == 0]
    assert np.bincount(bowl).max() / len(bowl) > 0.95
    assert np.bincount(can).max() / len(can) > 0.95
    assert np.bincount(bowl).argmax() != np.bincount(can).argmax()


def test_a_piece_smaller_than_min_points_is_not_an_object() -> None:
    """A few odd-coloured points (mixed cells at a contact) do not make an object."""
    points, colors, truth = _scene()
    one = np.flatnonzero(truth == 1)
    colors = colors.copy()
    colors[one[:4]] = (0.1, 0.1, 0.9)
    a, b = _links(points[one])
    out = split_by_colour(colors[one], np.zeros(len(one), np.int64), a, b, min_points=10)
    assert np.all(out == 0)


def _can(centre: tuple[float, float], radius: float, height: float, spacing: float, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """Points and outward normals sampled on a standing cylinder's side and top, about ``spacing`` apart."""
    rng = np.random.default_rng(seed)
    side, top = int(2 * np.pi * radius * height / spacing**2), int(np.pi * radius**2 / spacing**2)
    angle = rng.uniform(0, 2 * np.pi, side)
    ring = np.c_[np.cos(angle), np.sin(angle)]
    r = radius * np.sqrt(rng.uniform(0, 1, top))
    disc = rng.uniform(0, 2 * np.pi, top)
    points = np.vstack([np.c_[centre + radius * ring, rng.uniform(0, height, side)],
                        np.c_[centre + np.c_[r * np.cos(disc), r * np.sin(disc)], np.full(top, height)]])
    normals = np.vstack([np.c_[ring, np.zeros(side)], np.tile((0.0, 0.0, 1.0), (top, 1))])
    return points, normals


def test_a_white_can_against_a_black_one_is_two_objects_given_normals() -> None:
    """One hue, two brightnesses: points facing alike differ threefold, so two materials."""
    white, wn = _can((0.0, 0.0), 0.04, 0.1, 0.006, 1)
    black, bn = _can((0.081, 0.0), 0.035, 0.2, 0.006, 2)
    points, normals = np.vstack([white, black]), np.vstack([wn, bn])
    colors = np.vstack([_shaded(white, (0.85, 0.85, 0.8), 3), _shaded(black, (0.3, 0.3, 0.33), 4)])
    truth = np.r_[np.zeros(len(white), np.int64), np.ones(len(black), np.int64)]
    a, b = _links(points)
    assert np.all(split_by_colour(colors, np.zeros(len(points), np.int64), a, b, min_points=10) == 0)  # hue alone: one
    out = split_by_colour(colors, np.zeros(len(points), np.int64), a, b, min_points=10, normals=normals)
    assert len(np.unique(out)) == 2
    for k in (0, 1):
        assert np.bincount(out[truth == k]).max() / (truth == k).sum() > 0.95
    assert np.bincount(out[truth == 0]).argmax() != np.bincount(out[truth == 1]).argmax()


def test_a_lit_top_and_shaded_sides_of_one_box_are_one_object() -> None:
    """A grey box lit from above: its top three times as bright as its sides, but no two of its
    points that face the same way differ: one object."""
    points = _box_surface((0.0, 0.0, 0.0), (0.12, 0.08, 0.1), 0.006, 5)
    normals = np.zeros_like(points)
    normals[np.isclose(points[:, 2], 0.1), 2] = 1.0
    for axis, lo, hi in ((0, 0.0, 0.12), (1, 0.0, 0.08)):
        normals[np.isclose(points[:, axis], lo), :] = -np.eye(3)[axis]
        normals[np.isclose(points[:, axis], hi), :] = np.eye(3)[axis]
    light = np.where(normals[:, 2] > 0.5, 0.95, 0.3)
    colors = np.clip(np.asarray((0.6, 0.6, 0.6)) * light[:, None] + np.random.default_rng(6).normal(0, 0.01, points.shape), 0, 1)
    assert brightness_classes(colors, normals) is None
    a, b = _links(points)
    assert np.all(split_by_colour(colors, np.zeros(len(points), np.int64), a, b, min_points=10, normals=normals) == 0)


def _box_normals(points: np.ndarray, lo: tuple[float, float, float], hi: tuple[float, float, float]) -> np.ndarray:
    """Outward normals of points on a box's faces (its top and four sides)."""
    normals = np.zeros_like(points)
    normals[np.isclose(points[:, 2], hi[2]), 2] = 1.0
    for axis in (0, 1):
        normals[np.isclose(points[:, axis], lo[axis]), :] = -np.eye(3)[axis]
        normals[np.isclose(points[:, axis], hi[axis]), :] = np.eye(3)[axis]
    return normals


def test_in_a_view_a_print_on_one_surface_stays_and_a_folded_contact_splits() -> None:
    """Pixels show a print's edge as sharply as an object's: a box printed half red, half green is
    one object in a view (its colour border crosses flat faces), while a red box against a lower
    green one splits (their border is the concave step where they meet)."""
    lo, hi = (0.0, 0.0, 0.0), (0.2, 0.1, 0.1)
    box = _box_surface(lo, hi, 0.006, 7)
    normals = _box_normals(box, lo, hi)
    printed = np.where((box[:, 0] < 0.1)[:, None], (0.75, 0.18, 0.13), (0.2, 0.65, 0.3))
    a, b = _links(box)
    zero = np.zeros(len(box), np.int64)
    assert len(np.unique(split_by_colour(printed, zero, a, b, 10))) == 2  # colour alone: two
    assert np.all(split_by_colour(printed, zero, a, b, 10, normals, view_points=box) == 0)

    low_lo, low_hi = (0.1, 0.0, 0.0), (0.2, 0.1, 0.05)
    tall, low = _box_surface(lo, (0.1, 0.1, 0.1), 0.006, 8), _box_surface(low_lo, low_hi, 0.006, 9)
    tall, low = tall[tall[:, 0] < 0.1 - 1e-9], low[low[:, 0] > 0.1 + 1e-9]  # their touching faces are hidden
    points = np.vstack([tall, low])
    normals = np.vstack([_box_normals(tall, lo, (0.1, 0.1, 0.1)), _box_normals(low, low_lo, low_hi)])
    step = np.c_[np.full(300, 0.1), np.random.default_rng(10).uniform([0.0, 0.05], [0.1, 0.1], (300, 2))]
    points = np.vstack([points, step])  # the tall box's side above the low one, facing +x
    normals = np.vstack([normals, np.tile((1.0, 0.0, 0.0), (300, 1))])
    colors = np.vstack([np.tile((0.75, 0.18, 0.13), (len(tall), 1)), np.tile((0.2, 0.65, 0.3), (len(low), 1)),
                        np.tile((0.75, 0.18, 0.13), (300, 1))])
    truth = np.r_[np.zeros(len(tall), np.int64), np.ones(len(low), np.int64), np.zeros(300, np.int64)]
    a, b = _links(points)
    out = split_by_colour(colors, np.zeros(len(points), np.int64), a, b, 10, normals, view_points=points)
    assert len(np.unique(out)) == 2
    assert np.bincount(out[truth == 0]).argmax() != np.bincount(out[truth == 1]).argmax()


def test_every_cluster_s_first_split_is_shared_with_a_helper_and_the_labels_are_the_same(monkeypatch: pytest.MonkeyPatch) -> None:
    import realsim.perception.colour_split as colour_split

    points, colors, _ = _scene()
    shifted = [points + [0.6 * k, 0.0, 0.0] for k in range(4)]  # four clusters of two touching colours each
    pts, cols = np.vstack(shifted), np.vstack([colors] * 4)
    labels = np.repeat(np.arange(4), len(points))
    a, b = _links(pts)
    alone = split_by_colour(cols, labels, a, b, min_points=10)
    monkeypatch.setenv("REALSIM_WORKERS", "2")
    shared: list[int] = []
    fork_map = colour_split.fork_map
    monkeypatch.setattr(colour_split, "fork_map", lambda fn, n, least: shared.append(n) or fork_map(fn, n, least=least))
    out = split_by_colour(cols, labels, a, b, min_points=10)
    assert shared == [4] and 4 >= colour_split.SHARED_CLUSTERS and np.array_equal(out, alone)
    assert len(np.unique(out)) == 8
