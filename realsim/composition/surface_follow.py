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
    todo = np.flatnonzero(facing & (z > 1e-3) & np.all(np.isfinite(pix), axis=1))
    radius = np.clip(np.rint(half_edge * fx / z[todo]), 1, 8).astype(np.int64)
    ui, vi = np.rint(pix[todo, 0]), np.rint(pix[todo, 1])
    on = (ui >= 0) & (ui < w) & (vi >= 0) & (vi < h)
    todo, radius, ui, vi = todo[on], radius[on], ui[on].astype(np.int64), vi[on].astype(np.int64)
    seen_depth = np.pad(np.where(mask & np.isfinite(optical_depth), optical_depth, np.nan), 8, constant_values=np.nan)
    for r in np.unique(radius):
        pick = radius == r
        depth = _window_medians(seen_depth, vi[pick] + 8, ui[pick] + 8, int(r), max(3, min_share * (2 * r + 1) ** 2))
        i = todo[pick]
        ok = np.abs(depth - z[i]) <= max_shift  # NaN (too few pixels) is never ok
        scale[i[ok]] = depth[ok] / z[i[ok]]
    moved = int(np.count_nonzero(scale != 1.0))
    if moved == 0:
        return mesh, 0
    new_optical = optical * scale[:, None]
    out = trimesh.Trimesh((new_optical - trans) @ rot, np.asarray(mesh.faces), process=False)
    return out, moved


def _window_medians(values: np.ndarray, v: np.ndarray, u: np.ndarray, r: int, least: float) -> np.ndarray:
    """Per centre (v, u): the median of the finite ``values`` in its (2r+1) x (2r+1) window, NaN where
    fewer than ``least`` are finite (``values`` padded so every window lies inside)."""
    dv, du = np.meshgrid(np.arange(-r, r + 1), np.arange(-r, r + 1), indexing="ij")
    windows = np.sort(values[v[:, None] + dv.ravel()[None, :], u[:, None] + du.ravel()[None, :]], axis=1)  # NaN last
    count = np.count_nonzero(np.isfinite(windows), axis=1)
    rows = np.arange(len(windows))
    low, high = windows[rows, np.maximum((count - 1) // 2, 0)], windows[rows, np.maximum(count // 2, 0)]
    median = np.where(count % 2 == 1, high, (low + high) / 2)  # np.median's: the middle one, or the mean of the two
    return np.where(count >= least, median, np.nan)
