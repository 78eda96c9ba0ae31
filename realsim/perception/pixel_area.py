"""The surface area each pixel of an organized view covers (m^2), from the grid itself.

A pixel of a depth camera covers more of a surface the farther and the more slanted it is; a
segment's pixel count is therefore no size (600 pixels are 22 cm^2 at 1 m and 88 cm^2 at 2 m with
a Kinect). Neighbouring pixels on one surface lie one footprint apart, so the lengths of a pixel's
links to its right and lower neighbours (its left and upper ones at a border) measure the patch it
covers; links across a depth jump measure no surface and are skipped. Summed over a segment, the
areas give its visible surface in square metres, whatever the sensor and its distance.
"""

from __future__ import annotations

import numpy as np

__all__ = ["pixel_areas"]


def _steps(p: np.ndarray, axis: int, max_step: float) -> np.ndarray:
    """Per pixel, the length of its link to the next pixel along ``axis`` (the previous one where that
    is missing or across a jump); NaN where neither is on its surface."""
    d = np.linalg.norm(np.diff(p, axis=axis), axis=2)
    d = np.where(d <= max_step, d, np.nan)  # NaN (invalid pixels) compares False: skipped too
    pad = [(0, 0), (0, 0)]
    pad[axis] = (0, 1)
    forward = np.pad(d, pad, constant_values=np.nan)
    pad[axis] = (1, 0)
    backward = np.pad(d, pad, constant_values=np.nan)
    return np.where(np.isfinite(forward), forward, backward)


def pixel_areas(points: np.ndarray, grid_shape: tuple[int, int], max_step: float) -> np.ndarray:
    """(H*W,) surface area (m^2) each pixel of an organized cloud (row-major ``grid_shape``, NaN rows
    for missing pixels) covers: the product of its link lengths along both image axes, links longer
    than ``max_step`` (depth jumps) skipped. Pixels with no surface link either way (isolated or
    invalid) get the median area of the others, 0 when there are none."""
    h, w = grid_shape
    p = np.asarray(points, dtype=np.float64).reshape(h, w, 3)
    area = (_steps(p, 1, max_step) * _steps(p, 0, max_step)).ravel()
    known = np.isfinite(area)
    fill = float(np.median(area[known])) if known.any() else 0.0
    return np.where(known, area, fill)
