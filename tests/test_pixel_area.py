"""Pixel areas of an organized view: the metric surface a segment covers, whatever the distance."""

from __future__ import annotations

import numpy as np

from realsim.perception.pixel_area import pixel_areas


def _view(depth: np.ndarray, f: float = 500.0) -> np.ndarray:
    """Back-project a depth image (optical frame, pinhole with focal ``f`` pixels, centred)."""
    h, w = depth.shape
    v, u = np.mgrid[0:h, 0:w].astype(float)
    x = (u - (w - 1) / 2) / f * depth
    y = (v - (h - 1) / 2) / f * depth
    return np.stack([x, y, depth], axis=-1).reshape(-1, 3)


def _square_area(distance: float, side: float = 0.05, f: float = 500.0) -> float:
    """Area summed over the pixels of a ``side`` square plate seen face-on at ``distance``."""
    h = w = 120
    pts = _view(np.full((h, w), distance), f)
    area = pixel_areas(pts, (h, w), max_step=0.008)
    inside = (np.abs(pts[:, 0]) < side / 2) & (np.abs(pts[:, 1]) < side / 2)
    return float(area[inside].sum())


def test_a_face_on_plate_covers_its_true_area_at_any_distance() -> None:
    near, far = _square_area(0.6), _square_area(1.2)
    assert abs(near - 0.0025) < 0.0025 * 0.08
    assert abs(far - 0.0025) < 0.0025 * 0.15
    # the pixel count is four times smaller at twice the distance; the area is the same
    assert abs(near - far) < 0.0025 * 0.15


def test_a_slanted_surface_covers_more_per_pixel() -> None:
    h, w = 40, 40
    flat = pixel_areas(_view(np.full((h, w), 1.0)), (h, w), 0.008)
    v = np.arange(h, dtype=float)[:, None] * np.ones((1, w))
    slanted = pixel_areas(_view(1.0 + 0.004 * v), (h, w), 0.008)  # depth grows down the image: tilted plane
    assert np.median(slanted) > 1.5 * np.median(flat)


def test_depth_jumps_and_missing_pixels_measure_no_surface() -> None:
    h, w = 30, 30
    depth = np.full((h, w), 1.0)
    depth[:, 15:] = 1.5  # a step far longer than max_step: each side keeps its own footprint
    pts = _view(depth)
    pts[0, :] = np.nan  # a missing pixel
    area = pixel_areas(pts, (h, w), 0.008)
    grid = area.reshape(h, w)
    assert np.allclose(grid[5:, 14], (1.0 / 500) ** 2, rtol=1e-6)  # the near side of the jump
    assert np.allclose(grid[5:, 15], (1.5 / 500) ** 2, rtol=1e-6)  # the far side
    assert np.isfinite(area).all()
