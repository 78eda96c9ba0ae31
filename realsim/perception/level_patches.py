"""Level heights: every height of a levelled capture where upward-facing surface piles up.

A table top is an upward-facing, horizontal surface: its points' local normals (PCA over their
neighbours) stand within a few degrees of up, and in a levelled capture they all lie at one
height. Every peak of the histogram of those points' heights is a horizontal plane to propose,
however many there are: a third table that the global RANSAC rounds never reached (they were
spent on walls and table sides) is proposed like the first.
"""

from __future__ import annotations

import numpy as np
import open3d as o3d

__all__ = ["horizontal_mask", "level_heights"]


def horizontal_mask(points: np.ndarray, radius: float, max_tilt_deg: float) -> np.ndarray:
    """Mask of ``points`` whose local surface (PCA over the neighbours within ``radius``, at most
    30) is within ``max_tilt_deg`` of horizontal (the z axis is up)."""
    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(np.ascontiguousarray(points, dtype=np.float64)))
    cloud.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=radius, max_nn=30))
    return np.asarray(np.abs(np.asarray(cloud.normals)[:, 2]) >= np.cos(np.radians(max_tilt_deg)))


def level_heights(points: np.ndarray, radius: float, max_tilt_deg: float, bin_size: float, least: int) -> list[float]:
    """Heights (ascending) of the local maxima of the histogram (bins of ``bin_size``) of the level
    points' (:func:`horizontal_mask`) heights holding at least ``least`` of them, each the median
    height of the level points in its bin and the two beside it."""
    if len(points) < 3:
        return []
    z = points[horizontal_mask(points, radius, max_tilt_deg), 2]
    if len(z) == 0:
        return []
    lo = float(z.min())
    bins = np.floor((z - lo) / bin_size).astype(np.int64)
    counts = np.bincount(bins)
    padded = np.concatenate([[0], counts, [0]])
    peaks = np.flatnonzero((counts >= least) & (counts >= padded[:-2]) & (counts > padded[2:]))
    return [float(np.median(z[np.abs(bins - k) <= 1])) for k in peaks]
