"""Pieces of one surface parted by a nearer object in an organized view (generated pinhole grid)."""

from __future__ import annotations

import numpy as np

from realsim.perception.occlusion_bridge import occluded_pairs, view_axis
from realsim.perception.supervoxels import grid_links


def _view(bar_depth: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, tuple[int, int]]:
    """A 40 x 60 pinhole view along +z of a wall 1 m away with a vertical bar at ``bar_depth``
    across columns 25-34: labels 1 (wall, left), 2 (bar), 3 (wall, right); normals face the camera."""
    h, w = 40, 60
    v, u = np.mgrid[0:h, 0:w]
    depth = np.where((u >= 25) & (u < 35), bar_depth, 1.0)
    ray = np.stack([(u - w / 2) / 500.0, (v - h / 2) / 500.0, np.ones_like(u, dtype=float)], axis=-1)
    points = (ray * depth[..., None]).reshape(-1, 3)
    labels = np.where(u < 25, 1, np.where(u < 35, 2, 3)).ravel()
    normals = np.tile([0.0, 0.0, -1.0], (h * w, 1))
    return points, labels, normals, (h, w)


def test_view_axis_runs_along_the_rays_away_from_the_camera() -> None:
    points, _, normals, shape = _view(0.8)
    a, b = grid_links(np.ones(len(points), bool), shape)
    axis = view_axis(points, a, b, normals, 0.008)
    assert axis is not None and axis[2] > 0.99


def test_wall_behind_a_nearer_bar_pairs_on_every_row() -> None:
    points, labels, normals, shape = _view(0.8)
    pair, ends, end_normals = occluded_pairs(points, labels, normals, shape, np.array([0.0, 0.0, 1.0]), 0.008)
    assert len(pair) == shape[0] and set(map(tuple, pair)) == {(1, 3)}
    assert np.allclose(ends[:, :, 2], 1.0) and np.allclose(end_normals[:, :, 2], -1.0)


def test_a_farther_object_between_two_does_not_part_one() -> None:
    points, labels, normals, shape = _view(1.2)  # the bar stands behind: the two sides are not one hidden surface
    pair, _, _ = occluded_pairs(points, labels, normals, shape, np.array([0.0, 0.0, 1.0]), 0.008)
    assert len(pair) == 0
