"""plane_patches: a plane through two separate surfaces becomes the larger surface; one surface cut
in two (a floor in a table's shadow) stays whole. Ground truth: generated flat tops with noise."""

from __future__ import annotations

import numpy as np

from realsim.geometry import ransac_plane
from realsim.perception.plane_patches import connected_groups, one_surface


def _top(rng: np.random.Generator, centre: tuple[float, float], size: tuple[float, float], height: float,
         spacing: float = 0.01, noise: float = 0.002) -> np.ndarray:
    """A horizontal rectangle of points ``spacing`` apart at ``height`` with Gaussian noise."""
    xs = np.arange(-size[0] / 2, size[0] / 2, spacing) + centre[0]
    ys = np.arange(-size[1] / 2, size[1] / 2, spacing) + centre[1]
    xy = np.stack(np.meshgrid(xs, ys), axis=-1).reshape(-1, 2)
    return np.column_stack([xy, np.full(len(xy), height)]) + rng.normal(0, noise, (len(xy), 3))


def _tilt_deg(normal: np.ndarray) -> float:
    return float(np.degrees(np.arccos(abs(normal[2]) / np.linalg.norm(normal))))


def test_connected_groups_splits_far_apart_points() -> None:
    rng = np.random.default_rng(0)
    a, b = _top(rng, (0, 0), (0.3, 0.3), 0.7), _top(rng, (1.0, 0), (0.2, 0.2), 0.7)
    groups = connected_groups(np.vstack([a, b]), 0.02)
    assert sorted(len(g) for g in groups) == sorted([len(a), len(b)])
    big = connected_groups(np.vstack([a, b]), 0.02, least=len(a))
    assert [len(g) for g in big] == [len(a)] and set(big[0].tolist()) == set(range(len(a)))


def test_slab_through_two_tables_becomes_the_larger_top() -> None:
    """Two tops 13 cm apart in height, 2 m apart: the plane through both (tilted 3.7 deg) is
    refitted on the larger one, level within 0.3 deg and at its height within 3 mm."""
    rng = np.random.default_rng(1)
    desk = _top(rng, (0.0, 0.0), (1.2, 0.8), 0.75)
    side = _top(rng, (2.0, 0.0), (0.6, 0.5), 0.62)
    points = np.vstack([desk, side])
    slab_normal = np.array([0.13, 0.0, 2.0]) / np.linalg.norm([0.13, 0.0, 2.0])  # through both tops' middles
    slab_d = -float(slab_normal @ np.array([0.0, 0.0, 0.75]))
    slab = np.flatnonzero(np.abs(points @ slab_normal + slab_d) < 0.01)
    assert (slab < len(desk)).any() and (slab >= len(desk)).any()  # the slab holds points of both tops
    normal, d, inliers = one_surface(points, slab_normal, slab_d, slab, 0.02, 0.01, 100)
    assert _tilt_deg(normal) < 0.3
    assert abs(-d / normal[2] - 0.75) < 0.003
    assert (inliers < len(desk)).mean() == 1.0 and len(inliers) >= 0.95 * len(desk)


def test_one_surface_cut_in_two_is_left_whole() -> None:
    """A floor seen on both sides of a table's shadow: two patches on one plane, kept as RANSAC gave them."""
    rng = np.random.default_rng(2)
    points = np.vstack([_top(rng, (-0.8, 0.0), (0.8, 1.5), 0.0), _top(rng, (0.8, 0.0), (0.8, 1.5), 0.0)])
    normal, d, inliers = ransac_plane(points, 0.01, 300, np.random.default_rng(0))
    out_normal, out_d, out_inliers = one_surface(points, normal, d, inliers, 0.02, 0.01, 100)
    assert np.array_equal(out_normal, normal) and out_d == d and np.array_equal(out_inliers, inliers)


def test_ransac_through_two_tops_is_refitted_on_one() -> None:
    """Seeded RANSAC with a band (4 cm) wide enough to hold a desk and a side table 6 cm lower in
    one level slab: after one_surface its inliers lie on one top only, level within 0.3 deg."""
    rng = np.random.default_rng(3)
    tops = [_top(rng, (0.0, 0.0), (1.1, 0.75), 0.74), _top(rng, (1.4, 0.0), (0.55, 0.5), 0.68)]
    points = np.vstack(tops)
    for seed in range(3):
        normal, d, inliers = ransac_plane(points, 0.04, 300, np.random.default_rng(seed))
        assert np.ptp(points[inliers, 2]) > 0.05  # RANSAC's plane holds both tops
        normal, d, inliers = one_surface(points, normal, d, inliers, 0.02, 0.04, 100)
        assert np.ptp(points[inliers, 2]) < 0.03 and len(inliers) >= 0.95 * len(tops[0])
        assert _tilt_deg(normal) < 0.3 and abs(-d / normal[2] - 0.74) < 0.003


def test_surface_of_keeps_the_larger_top_of_a_slab_proposal() -> None:
    """A proposal (normal, d, inlier points) through two tops keeps only points of the larger top;
    refitted on the full points (as detect_planes does next) it is level at the top's height."""
    from realsim.perception.plane_patches import surface_of
    from realsim.perception.plane_refit import refine_plane

    rng = np.random.default_rng(4)
    desk, side = _top(rng, (0.0, 0.0), (1.2, 0.8), 0.75), _top(rng, (2.0, 0.0), (0.6, 0.5), 0.62)
    points = np.vstack([desk, side])
    normal = np.array([0.13, 0.0, 2.0]) / np.linalg.norm([0.13, 0.0, 2.0])
    d = -float(normal @ np.array([0.0, 0.0, 0.75]))
    slab = points[np.abs(points @ normal + d) < 0.01]
    out_normal, out_d, kept = surface_of((normal, d, slab), 0.02, 0.01, 100)
    assert np.all(np.abs(kept[:, 2] - 0.75) < 0.01) and len(kept) < len(slab)
    level, offset, _ = refine_plane(points, out_normal, out_d, 0.006)
    assert _tilt_deg(level) < 0.3 and abs(-offset / level[2] - 0.75) < 0.003
    slab_level, _, _ = refine_plane(points, normal, d, 0.006)  # without it, the slab stays tilted
    assert _tilt_deg(slab_level) > 1.0
