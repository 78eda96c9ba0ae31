"""The last resort: the visible hull extruded down to the base."""

from __future__ import annotations

import numpy as np
import trimesh
from scipy.spatial import QhullError


def complete_hull(points: np.ndarray, base_z: float, top_z: float) -> tuple[trimesh.Trimesh, np.ndarray]:
    """The observed points' convex hull extruded down to ``base_z`` (world frame)."""
    kept = points[points[:, 2] <= top_z]
    base = kept.copy()
    base[:, 2] = base_z
    top = kept.copy()
    top[:, 2] = np.maximum(top[:, 2], base_z + 1e-3)
    cloud = np.vstack([top, base])
    try:
        mesh = trimesh.convex.convex_hull(cloud)
    except QhullError:
        lo, hi = cloud.min(axis=0), cloud.max(axis=0)
        hi = np.maximum(hi, lo + 0.005)
        mesh = trimesh.creation.box(bounds=np.vstack([lo, hi]))
    lo, hi = mesh.bounds
    return mesh, np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, base_z])
