"""A scanned object's visual mesh takes the depth the camera saw where it saw the object.

A completed shape is a fit (planes, a body of revolution, an extrusion); a real box bulges, a
lid warps, a fit tilts a little. Where the camera saw the object, its visual surface need not
stay with the fit: each vertex that faces the camera and lands on the object's own pixels
slides along its line of sight to the median depth of those pixels. Sliding along the line of
sight keeps the pixel a vertex projects to, so the projected texture is unchanged. The shift is
bounded (a fit more than ``max_shift`` off is left alone: that is not the same surface) and the
collision geometry is never touched.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import trimesh


def follow_seen_depth(mesh: trimesh.Trimesh, to_optical: np.ndarray, optical_depth: np.ndarray, mask: np.ndarray,
                      fx: float, project: Callable[[np.ndarray], np.ndarray], max_shift: float = 0.02, min_share: float = 0.5,
                      facing_cos: float = 0.2) -> tuple[trimesh.Trimesh, int]:
    """``mesh`` with its camera-facing vertices slid along their lines of sight to the seen depth.

    ``to_optical`` maps the mesh's frame to the camera's optical frame (4 x 4); ``optical_depth``
    is the captured optical z per pixel (H x W, NaN where no depth); ``mask`` the object's own
    pixels; ``project`` maps optical points to (u, v) pixels. A vertex moves when its normal
    faces the camera (cosine over ``facing_cos``), at least ``min_share`` of the pixel window
    around it (about half a mesh edge across) belongs to the object, and the median depth there
    is within ``max_shift`` of the vertex's own. Returns the new mesh and how many vertices moved.
    """
    verts = np.asarray(mesh.vertices, float)
    if len(verts) == 0 or not mask.any():
        return mesh, 0
    rot, trans = to_optical[:3, :3], to_optical[:3, 3]
    optical = verts @ rot.T + trans
    normals = np.asarray(mesh.vertex_normals, float) @ rot.T
    dist = np.linalg.norm(optical, axis=1)
    facing = np.einsum("ij,ij->i", normals, -optical) > facing_cos * np.maximum(dist, 1e-9)
    pix = project(optical)
    h, w = mask.shape
    z = optical[:, 2]
    edges = np.asarray(mesh.edges_unique_length, float)
    half_edge = 0.25 * float(np.median(edges)) if len(edges) else 0.01
    scale = np.ones(len(verts))
    for i in np.flatnonzero(facing & (z > 1e-3) & np.all(np.isfinite(pix), axis=1)):
        u, v = pix[i]
        r = int(np.clip(round(half_edge * fx / z[i]), 1, 8))
        ui, vi = int(round(u)), int(round(v))
        if not (0 <= ui < w and 0 <= vi < h):
            continue
        win = (slice(max(0, vi - r), min(h, vi + r + 1)), slice(max(0, ui - r), min(w, ui + r + 1)))
        seen = optical_depth[win][mask[win]]
        seen = seen[np.isfinite(seen)]
        if len(seen) < max(3, min_share * (2 * r + 1) ** 2):
            continue
        depth = float(np.median(seen))
        if abs(depth - z[i]) <= max_shift:
            scale[i] = depth / z[i]
    moved = int(np.count_nonzero(scale != 1.0))
    if moved == 0:
        return mesh, 0
    new_optical = optical * scale[:, None]
    out = trimesh.Trimesh((new_optical - trans) @ rot, np.asarray(mesh.faces), process=False)
    return out, moved
