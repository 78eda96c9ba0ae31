"""Objects on objects: the order to complete them in, the base under an upper object, flat tops,
and the object frame of a completed shape."""

from __future__ import annotations

from typing import cast

import numpy as np
import trimesh

from realsim.completion.hull import trimesh_hull
from realsim.completion.params import CompletionParams
from realsim.geometry import inside_convex_polygon, polygon_and_rectangle
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
    flat: trimesh.Trimesh = trimesh_hull(verts)
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


def _tops(under: trimesh.Trimesh, xy: np.ndarray) -> np.ndarray:
    """Height of the top of the convex shape ``under`` at each ``xy``: the lower envelope of its
    upward-facing face planes (clamped to the solid's bounds)."""
    normals = under.face_normals
    up = normals[:, 2] > 1e-6
    n, p0 = normals[up], under.triangles[up, 0, :]
    d = -(n * p0).sum(axis=1)
    z = -(d[None, :] + xy @ n[:, :2].T) / n[None, :, 2]
    lo, hi = under.bounds
    return np.asarray(np.clip(z.min(axis=1), lo[2], hi[2]))


def top_under(under: trimesh.Trimesh, pts: np.ndarray) -> float:
    """Height of the top of the convex shape ``under`` below the footprint of ``pts``: its highest
    point there."""
    return float(_tops(under, pts[:, :2]).max())


def rest_inside(pieces: list[trimesh.Trimesh], pts: np.ndarray, tolerance: float) -> float | None:
    """Height of what an object seen as ``pts`` rests on inside a hollow body made of convex
    ``pieces``: the highest top of a piece under one of its points that lies below that point (within
    ``tolerance``: the cavity floor, an inner wall's slope, the rim it lies across), never a wall's
    foot under a point inside it; None when no piece lies under any point."""
    best: float | None = None
    for piece in pieces:
        inside = inside_convex_polygon(pts[:, :2], polygon_and_rectangle(np.asarray(piece.vertices)[:, :2])[0])
        if not inside.any():
            continue
        tops = _tops(piece, pts[inside, :2])
        below = tops[tops <= pts[inside, 2] + tolerance]
        if len(below):
            best = max(best if best is not None else -np.inf, float(below.max()))
    return best


def sloping_top(under: trimesh.Trimesh, pts: np.ndarray, min_slope: float = 0.02, max_residual: float = 0.001) -> np.ndarray | None:
    """The plane ``z = a x + b y + c`` (as ``[a, b, c]``) fitted to the top of ``under`` below the
    footprint of ``pts`` when that top slopes (by ``min_slope`` or more) and is one plane there (RMS
    residual within ``max_residual``: not a hull's top rolling off at an edge); else None."""
    top = _tops(under, pts[:, :2])
    design = np.column_stack([pts[:, :2], np.ones(len(pts))])
    plane = np.linalg.lstsq(design, top, rcond=None)[0]
    if np.hypot(plane[0], plane[1]) < min_slope or np.sqrt(np.mean((design @ plane - top) ** 2)) > max_residual:
        return None
    return np.asarray(plane)


def seat_on(plane: np.ndarray, floor: float, base_z: float, meshes: list[trimesh.Trimesh], clearance: float) -> list[trimesh.Trimesh]:
    """``meshes`` (convex, world frame, flat base at ``base_z``) carried down onto the sloping top
    ``plane`` (see :func:`sloping_top`) of what they lie on, not below ``floor``. A body lying on a
    tilted book lies along it; a flat base at the top's highest point would touch it on one edge,
    tip and slide."""
    out = []
    for mesh in meshes:
        v = np.asarray(mesh.vertices)
        base = v[v[:, 2] <= base_z + 1e-4].copy()
        if len(base) < 3:
            out.append(mesh)
            continue
        seat = np.column_stack([base[:, :2], np.ones(len(base))]) @ plane - clearance
        base[:, 2] = np.minimum(base[:, 2], np.maximum(seat, floor))
        out.append(trimesh_hull(np.vstack([v, base])))
    return out
