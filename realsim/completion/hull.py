"""Convex hulls as closed, outward-wound meshes, straight from Qhull (no mesh repair passes)."""

from __future__ import annotations

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError


def fast_hull(points: np.ndarray) -> trimesh.Trimesh:
    """The convex hull of ``points`` (raises scipy's QhullError when it is flat or too small)."""
    hull = ConvexHull(np.asarray(points, float))
    faces = hull.simplices.copy()
    v = hull.points
    normal = np.cross(v[faces[:, 1]] - v[faces[:, 0]], v[faces[:, 2]] - v[faces[:, 0]])
    flip = np.einsum("fk,fk->f", normal, hull.equations[:, :3]) < 0
    faces[flip] = faces[flip][:, ::-1]
    used, faces = np.unique(faces, return_inverse=True)
    return trimesh.Trimesh(v[used], faces.reshape(-1, 3), process=False)


def solid_hull(points: np.ndarray) -> trimesh.Trimesh | None:
    """The convex hull of ``points`` when it encloses a volume, else None (fewer than 4 points,
    flat, or vanishing)."""
    if len(points) < 4:
        return None
    try:
        hull = fast_hull(points)
    except QhullError:
        return None
    return hull if hull.volume > 1e-9 else None
