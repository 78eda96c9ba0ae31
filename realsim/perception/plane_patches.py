"""One surface per plane: the connected patches of a plane's inliers that lie on one plane.

A plane fitted through two separate surfaces (RANSAC's slab through two table tops at different
heights, tilted between them) has its inliers in disconnected patches, and each patch refitted
alone lies far from the others' plane. Such a plane is no surface: the largest patch is, with
every patch lying on its refitted plane (a floor cut in two by a table's shadow stays whole).
Inliers that split into no large separate patches are left as they are.
"""

from __future__ import annotations

import numpy as np
from scipy import ndimage

from realsim.geometry import fit_plane
from realsim.perception.plane_refit import refine_plane

__all__ = ["connected_groups", "one_surface", "surface_of"]


def connected_groups(points: np.ndarray, cell: float, least: int = 1) -> list[np.ndarray]:
    """Connected groups (26-neighbour voxels of side ``cell``) of ``points`` holding at least
    ``least`` points, as index arrays (in order of their lowest voxel)."""
    if len(points) == 0:
        return []
    ijk = np.floor((points - points.min(axis=0)) / cell).astype(np.int64)
    shape = tuple(ijk.max(axis=0) + 1)
    grid = np.zeros(shape, dtype=bool)
    grid[ijk[:, 0], ijk[:, 1], ijk[:, 2]] = True
    labels, count = ndimage.label(grid, structure=np.ones((3, 3, 3), dtype=bool))
    of_point = labels[ijk[:, 0], ijk[:, 1], ijk[:, 2]] - 1
    order = np.argsort(of_point, kind="stable")
    bounds = np.searchsorted(of_point[order], np.arange(count + 1))
    return [order[bounds[k]:bounds[k + 1]] for k in range(count) if bounds[k + 1] - bounds[k] >= least]


def _coplanar(points: np.ndarray, normal: np.ndarray, d: float, threshold: float) -> bool:
    """Whether most of ``points`` (their median) lie within ``threshold`` of the plane."""
    return bool(np.median(np.abs(points @ normal + d)) < threshold)


def one_surface(points: np.ndarray, normal: np.ndarray, d: float, inliers: np.ndarray, cell: float, threshold: float,
                least: int) -> tuple[np.ndarray, float, np.ndarray]:
    """A plane (normal, d) with its ``inliers`` (indices into ``points``) made one surface.

    When the inliers hold two or more connected patches (voxels of side ``cell``) of ``least``
    points and one of them does not lie on the largest patch's own least-squares plane (median
    distance ``threshold``), the plane is refitted on the largest patch and the patches lying on
    it, refined on every point of ``points`` in its band (``refine_plane``), and its inliers
    are gathered again (every point within ``threshold``).
    Otherwise the plane and inliers are returned unchanged.
    """
    groups = connected_groups(points[inliers], cell)
    big = [g for g in groups if len(g) >= least]
    if len(big) < 2:
        return normal, d, inliers
    largest = max(big, key=len)
    own_normal, own_d = fit_plane(points[inliers[largest]])
    if all(_coplanar(points[inliers[g]], own_normal, own_d, threshold) for g in big):
        return normal, d, inliers
    keep = np.concatenate([g for g in groups if _coplanar(points[inliers[g]], own_normal, own_d, threshold)])
    new_normal, new_d = fit_plane(points[inliers[keep]])
    if new_normal @ normal < 0:
        new_normal, new_d = -new_normal, -new_d
    # the patches were cut from the surface by the slab's band, unevenly: refit on the surface's band
    new_normal, new_d, _ = refine_plane(points, new_normal, new_d, threshold)
    return new_normal, new_d, np.flatnonzero(np.abs(points @ new_normal + new_d) < threshold)


def surface_of(plane: tuple[np.ndarray, float, np.ndarray], cell: float, threshold: float,
               least: int) -> tuple[np.ndarray, float, np.ndarray]:
    """A plane proposal (normal, d, inlier points) made one surface (:func:`one_surface` on its
    own inliers): what a capture may be levelled on."""
    normal, d, points = plane
    normal, d, keep = one_surface(points, normal, d, np.arange(len(points)), cell, threshold, least)
    return normal, d, points[keep]
