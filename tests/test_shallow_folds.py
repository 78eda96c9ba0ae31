"""Segments of a view meeting in a shallow fold are one body; a sharp V or a depth jump is two."""

from __future__ import annotations

import numpy as np

from realsim.perception.shallow_folds import fold_angles, join_shallow_folds

H, W = 40, 60
PIXEL = 0.001  # m between neighbouring pixels


def _crease(left_deg: float, right_deg: float, step: float = 0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Points, normals and labels of a surface seen from above with a crease down the middle column:
    the left half slopes ``left_deg`` up toward the crease, the right half ``right_deg`` (positive:
    rising away from the crease); ``step`` (m) lifts the right half (a depth jump)."""
    rows, cols = np.mgrid[0:H, 0:W]
    x = (cols - W / 2 + 0.5) * PIXEL
    slope = np.where(x < 0, -np.tan(np.radians(left_deg)), np.tan(np.radians(right_deg)))
    z = slope * x + np.where(x < 0, 0.0, step)
    points = np.stack([x, rows * PIXEL, z], axis=-1).reshape(-1, 3)
    normals = np.stack([-slope, np.zeros_like(slope), np.ones_like(slope)], axis=-1).reshape(-1, 3)
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    labels = np.where(x < 0, 0, 1).reshape(-1)
    return points, normals, labels


def _join(points: np.ndarray, normals: np.ndarray, labels: np.ndarray) -> np.ndarray:
    return join_shallow_folds(labels, points, normals, (H, W), 0.008, max_angle=40.0, window=6, min_links=6,
                              continuous_share=0.5)


def test_the_fold_angle_is_the_turn_between_the_two_sides() -> None:
    points, normals, labels = _crease(15.0, 15.0)
    a = np.arange(H) * W + W // 2 - 1
    angles = fold_angles(labels, normals, a, a + 1, (H, W), 6, 80)
    assert abs(angles[(0, 1)] - 30.0) < 1e-6


def test_a_shallow_fold_joins_the_two_pieces() -> None:
    points, normals, labels = _crease(12.0, 12.0)  # the sides turn 24 degrees: a body's own crease
    assert len(np.unique(_join(points, normals, labels))) == 1


def test_a_sharp_v_keeps_two_touching_bodies_apart() -> None:
    points, normals, labels = _crease(35.0, 35.0)  # 70 degrees: two convex flanks meeting at a contact
    assert len(np.unique(_join(points, normals, labels))) == 2


def test_a_depth_jump_keeps_them_apart_however_flat() -> None:
    points, normals, labels = _crease(0.0, 0.0, step=0.02)  # a thing in front of another: no continuous border
    assert len(np.unique(_join(points, normals, labels))) == 2


def test_unlabelled_pixels_stay_unlabelled() -> None:
    points, normals, labels = _crease(10.0, 10.0)
    labels[:W] = -1
    out = _join(points, normals, labels)
    assert (out[:W] == -1).all() and len(np.unique(out[W:])) == 1
