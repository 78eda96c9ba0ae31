"""How far apart two neighbouring pixels of a camera view may lie and still be on one surface.

Neighbouring pixels on one surface lie one pixel footprint apart plus the depth noise; both grow
with the distance (a Kinect pixel spans 1.7 mm at 1 m and 5 mm at 3 m, its depth noise grows
with the square of the distance). A fixed jump length that parts two objects at 1 m therefore
cuts every link of an object at 3 m into noise. A link crosses a depth jump when it is several
times longer than the links around it: each pixel's typical link is the median of its own four
(one of them across an edge leaves the median on the surface), and the median of those over a
small window (a corner's or a thin part's pixels, with two links across edges, are a minority
there: no edge raises the length it is measured against).
"""

from __future__ import annotations

import numpy as np
from scipy import ndimage

__all__ = ["link_lengths", "pixel_jumps"]


def link_lengths(points: np.ndarray, grid_shape: tuple[int, int]) -> np.ndarray:
    """(H, W, 4) distance from each pixel to its right, left, lower and upper neighbour (NaN where
    either is missing or off the image)."""
    h, w = grid_shape
    p = np.asarray(points, dtype=np.float64).reshape(h, w, 3)
    out = np.full((h, w, 4), np.nan)
    across = np.linalg.norm(np.diff(p, axis=1), axis=2)
    down = np.linalg.norm(np.diff(p, axis=0), axis=2)
    out[:, :-1, 0], out[:, 1:, 1] = across, across
    out[:-1, :, 2], out[1:, :, 3] = down, down
    return out


def pixel_jumps(points: np.ndarray, grid_shape: tuple[int, int], least: float, factor: float, window: int) -> np.ndarray:
    """(H*W,) per pixel, the link length beyond which a link from it crosses a depth jump: ``factor``
    times its typical link (the median of its four, then over ``window`` pixels), never under
    ``least``; ``least`` where no link is measured (missing pixels count as no length: the window's
    median falls, never rises, next to them)."""
    lengths = link_lengths(points, grid_shape)
    known = np.isfinite(lengths).any(axis=2)
    with np.errstate(invalid="ignore"):
        typical = np.where(known, np.nanmedian(np.where(known[..., None], lengths, 0.0), axis=2), 0.0)
    local = ndimage.median_filter(typical, size=window, mode="constant")
    out: np.ndarray = np.maximum(least, factor * np.where(known, local, 0.0)).ravel()
    return out
