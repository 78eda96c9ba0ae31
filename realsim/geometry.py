"""Plane geometry shared by layout, arena, robot and the generators: a heading as a quaternion,
and convex polygons in the ground plane (inside, apart)."""

from __future__ import annotations

import numpy as np


def yaw_quat(yaw: float) -> np.ndarray:
    """The (w, x, y, z) quaternion of a rotation by ``yaw`` radians about +Z."""
    return np.array([np.cos(yaw / 2), 0.0, 0.0, np.sin(yaw / 2)])


def inside_convex_polygon(xy: np.ndarray, polygon: np.ndarray, margin: float = 0.0) -> np.ndarray:
    """Mask of points inside a counter-clockwise convex polygon grown by ``margin``.

    One edge at a time, so memory stays O(N) for full-resolution clouds.
    """
    edges = np.roll(polygon, -1, axis=0) - polygon
    lengths = np.linalg.norm(edges, axis=1)
    keep = lengths > 1e-12
    inside = np.ones(len(xy), dtype=bool)
    for e, start, length in zip(edges[keep], polygon[keep], lengths[keep]):
        cross = e[0] * (xy[:, 1] - start[1]) - e[1] * (xy[:, 0] - start[0])
        inside &= cross / length >= -margin
    return inside


def polygons_apart(a: np.ndarray, b: np.ndarray, gap: float) -> bool:
    """True when convex polygons ``a`` and ``b`` are separated by at least ``gap`` (SAT)."""
    for poly in (a, b):
        edges = np.roll(poly, -1, axis=0) - poly
        normals = np.column_stack([edges[:, 1], -edges[:, 0]])
        lengths = np.linalg.norm(normals, axis=1)
        normals = normals[lengths > 1e-12] / lengths[lengths > 1e-12, None]
        pa, pb = a @ normals.T, b @ normals.T
        separated = (pa.min(axis=0) - pb.max(axis=0) >= gap) | (pb.min(axis=0) - pa.max(axis=0) >= gap)
        if np.any(separated):
            return True
    return False
