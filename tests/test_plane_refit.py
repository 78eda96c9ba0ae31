"""refine_plane's shortlist gives the masks and planes of testing every point; the convex
polygon test keeps its formula's exact values."""

from __future__ import annotations

import numpy as np
import pytest

from realsim.geometry import fit_plane, inside_convex_polygon, polygon_and_rectangle
from realsim.perception.plane_refit import _SHORTLIST_BANDS, _NearPlane, level_unless_resolved, refine_plane


def _plain_refine(points: np.ndarray, normal: np.ndarray, d: float, band: float, passes: int = 3,
                  max_passes: int = 12) -> tuple[np.ndarray, float, np.ndarray]:
    """The refit testing every point on every pass (the definition)."""
    mask = np.zeros(len(points), dtype=bool)
    for i in range(max_passes):
        width = band * (0.6 ** min(i, passes - 1))
        new_mask = np.abs(points @ normal + d) < width
        if new_mask.sum() < 3:
            break
        if i >= passes and np.array_equal(new_mask, mask):
            break
        mask = new_mask
        new_normal, new_d = fit_plane(points[mask])
        if new_normal @ normal < 0:
            new_normal, new_d = -new_normal, -new_d
        normal, d = new_normal, new_d
    return normal, d, mask


def _scene(seed: int, tilt: float) -> np.ndarray:
    """A noisy tilted table top with boxes on it and scattered clutter."""
    rng = np.random.default_rng(seed)
    top = rng.uniform(-1.0, 1.0, (20_000, 2))
    z = 0.7 + tilt * top[:, 0] + rng.normal(0.0, 0.002, len(top))
    boxes = rng.uniform([-0.5, -0.5, 0.7], [0.5, 0.5, 0.9], (5_000, 3))
    clutter = rng.uniform(-1.5, 1.5, (5_000, 3))
    return np.vstack([np.c_[top, z], boxes, clutter])


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("start_tilt_deg", [0.0, 0.5, 3.0])  # 3 degrees: the shortlist cannot hold, every point is tested
def test_shortlist_refit_equals_testing_every_point(seed: int, start_tilt_deg: float) -> None:
    points = _scene(seed, tilt=0.01)
    t = np.radians(start_tilt_deg)
    normal = np.array([np.sin(t), 0.0, np.cos(t)])
    d = -0.7
    n1, d1, m1 = refine_plane(points, normal, d, 0.006)
    n0, d0, m0 = _plain_refine(points, normal, d, 0.006)
    assert np.array_equal(m1, m0) and m0.sum() > 300
    assert np.array_equal(n1, n0) and d1 == d0
    near = _NearPlane(points, normal, d, _SHORTLIST_BANDS * 0.006)
    assert near.holds(n0, d0, 0.006 * 0.36) == (start_tilt_deg < 1.0)  # the refit plane: shortlist held or not


def test_convex_polygon_test_keeps_its_formula() -> None:
    rng = np.random.default_rng(3)
    polygon = polygon_and_rectangle(rng.normal(size=(200, 2)))[0]
    xy = rng.uniform(-4.0, 4.0, (50_000, 2))
    xy[::97] = polygon[rng.integers(0, len(polygon), len(xy[::97]))]  # points on the vertices: ties at the edges
    for margin in (0.0, 0.05, -0.02):
        edges = np.roll(polygon, -1, axis=0) - polygon
        expected = np.ones(len(xy), dtype=bool)
        for e, start in zip(edges, polygon):
            expected &= (e[0] * (xy[:, 1] - start[1]) - e[1] * (xy[:, 0] - start[0])) / np.linalg.norm(e) >= -margin
        got = inside_convex_polygon(xy, polygon, margin)
        assert np.array_equal(got, expected)
        assert 0 < got.sum() < len(xy)


def _ring_top(tilt_deg: float, low_side_mm: float, seed: int = 0) -> np.ndarray:
    """A 0.5 m square top seen only along its border (a far table in a sweep), tilted ``tilt_deg``
    about y, one side's points ``low_side_mm`` low (a grazing view's layer), 1 mm noise."""
    rng = np.random.default_rng(seed)
    t = rng.uniform(-0.25, 0.25, 2000)
    side = rng.integers(0, 4, 2000)
    x = np.where(side == 0, -0.25, np.where(side == 1, 0.25, t))
    y = np.where(side == 2, -0.25, np.where(side == 3, 0.25, t))
    x, y = x + rng.uniform(0, 0.03, 2000) * np.sign(-x), y + rng.uniform(0, 0.03, 2000) * np.sign(-y)
    z = 0.8 + np.tan(np.radians(tilt_deg)) * x - 0.001 * low_side_mm * (side == 0) + rng.normal(0, 0.001, 2000)
    return np.stack([x, y, z], axis=1)


def test_a_top_tilted_within_the_resolution_takes_gravity() -> None:
    """A level top whose seen border lies a few mm low on one side fits tilted (0.3-1 deg); at an
    8 mm resolution that lean is within what the capture resolves across 0.5 m: it takes up."""
    up = np.array([0.0, 0.0, 1.0])
    top = _ring_top(0.0, 4.0)
    normal = fit_plane(top)[0]
    assert np.degrees(np.arccos(normal[2])) > 0.3
    assert level_unless_resolved(top, normal, up, 0.008) is up
    assert level_unless_resolved(top, normal, up, 0.001) is normal  # a 1 mm capture resolves it: its own fit


def test_a_truly_tilted_top_keeps_its_tilt() -> None:
    """A top tilted 3 deg leans by more than an 8 mm capture can err across it: its fit stays."""
    top = _ring_top(3.0, 4.0)
    normal = fit_plane(top)[0]
    assert level_unless_resolved(top, normal, np.array([0.0, 0.0, 1.0]), 0.008) is normal
