"""Objects on objects: the order to complete them in, the base under an upper object, flat tops,
and the object frame of a completed shape."""

from __future__ import annotations

from typing import cast

import numpy as np
import trimesh

from realsim.completion.params import CompletionParams
from realsim.scene import SceneObject


def set_shape(obj: SceneObject, mesh: trimesh.Trimesh, base_centre: np.ndarray, params: CompletionParams,
              pieces: list[trimesh.Trimesh] | None = None, visual: trimesh.Trimesh | None = None) -> None:
    """Give ``obj`` the world-frame convex ``mesh`` (or convex ``pieces`` and their ``visual``, for a
    shape that is not convex) in its object frame (origin at ``base_centre``)."""
    local = mesh.copy()
    local.apply_translation(-base_centre)
    obj.position = base_centre + np.array([0.0, 0.0, params.base_clearance])
    obj.size = local.extents.copy()
    if pieces is None:
        obj.collision = [local]
        obj.visual = local
        return
    obj.collision = [_moved(p, -base_centre) for p in pieces]
    obj.visual = _moved(visual if visual is not None else cast(trimesh.Trimesh, trimesh.util.concatenate(pieces)), -base_centre)


def _moved(mesh: trimesh.Trimesh, offset: np.ndarray) -> trimesh.Trimesh:
    """A copy of ``mesh`` translated by ``offset``."""
    moved = mesh.copy()
    moved.apply_translation(offset)
    return moved


def flatten_top(under: SceneObject, mesh: trimesh.Trimesh, top_z: float, params: CompletionParams) -> trimesh.Trimesh:
    """Cut the top of the convex shape another object stands on flat at ``top_z``.

    The top of a completed scan is a shallow dome of noisy facets; a flat base resting on it
    touches at one point, pivots and sinks (one contact), sliding about a centimetre while the
    scene settles. A shared flat face gives MuJoCo a face-face contact (several points).
    """
    verts = mesh.vertices.copy()
    verts[:, 2] = np.minimum(verts[:, 2], top_z - params.base_clearance)  # the upper object drops onto it
    flat: trimesh.Trimesh = trimesh.convex.convex_hull(verts)
    set_shape(under, flat, under.position - np.array([0.0, 0.0, params.base_clearance]), params)
    return flat


def bottom_up(objects: list[SceneObject]) -> list[SceneObject]:
    """Objects ordered so each comes after the object it rests on."""
    placed: list[SceneObject] = []
    remaining = list(objects)
    while remaining:
        ids = {o.id for o in placed}
        ready = [o for o in remaining if o.resting_on is None or o.resting_on in ids or o.resting_on not in {r.id for r in remaining}]
        if not ready:  # a cycle in resting_on: break it deterministically
            ready = [remaining[0]]
            ready[0].resting_on = None
        placed.extend(ready)
        remaining = [o for o in remaining if o not in ready]
    return placed


def top_under(under: trimesh.Trimesh, pts: np.ndarray) -> float:
    """Height of the top of the convex shape ``under`` below the footprint of ``pts``.

    The upper surface of a convex solid is the lower envelope of its upward-facing face planes;
    the base is its highest point under the footprint (clamped to the solid's bounds).
    """
    normals = under.face_normals
    up = normals[:, 2] > 1e-6
    n, p0 = normals[up], under.triangles[up, 0, :]
    d = -(n * p0).sum(axis=1)
    xy = pts[:, :2]
    z = -(d[None, :] + xy @ n[:, :2].T) / n[None, :, 2]
    top = z.min(axis=1)
    lo, hi = under.bounds
    return float(np.clip(top.max(), lo[2], hi[2]))
