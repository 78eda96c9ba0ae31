"""Completed neighbours kept apart: foreign points inside a shape, overlapping shapes cut apart."""

from __future__ import annotations

import numpy as np
import trimesh
from scipy.spatial import QhullError

from realsim.completion.hull import trimesh_hull, volume
from realsim.completion.params import CompletionParams
from realsim.completion.stacking import set_shape
from realsim.scene import SceneObject

MIN_PART_VOLUME = 1e-7  # m^3 a clipped part must exceed to be kept


def foreign_fraction(mesh: trimesh.Trimesh, others: np.ndarray) -> float:
    if len(others) == 0:
        return 0.0
    lo, hi = mesh.bounds
    near = others[np.all((others >= lo) & (others <= hi), axis=1)]
    if len(near) == 0:
        return 0.0
    # The shapes are convex: inside means behind every face plane.
    normals, origins = mesh.face_normals, mesh.triangles[:, 0, :]
    inside = np.all(np.einsum("fk,nfk->nf", normals, near[:, None, :] - origins[None, :, :]) <= 0, axis=1)
    return float(inside.sum()) / len(others)


def unique_edges(faces: np.ndarray) -> np.ndarray:
    """``Trimesh.edges_unique`` of a mesh with these ``faces`` (the same rows in the same order): every
    edge once as (lower, higher) vertex index, ordered by the higher index, then the lower (the order
    of trimesh's packed row hashes), without its hashing and caching."""
    edges = np.sort(np.asarray(faces, dtype=np.int64)[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1)
    size = int(edges.max(initial=0)) + 1
    key = np.unique(edges[:, 1] * size + edges[:, 0])
    return np.column_stack([key % size, key // size])


def kept_points(v: np.ndarray, edges: np.ndarray, normal: np.ndarray, offset: float) -> np.ndarray:
    """The corners of the part of a convex body (vertices ``v``, ``edges``) where ``normal . x >= offset``:
    the vertices on that side and where the plane crosses the edges."""
    side = v @ normal - offset
    sa, sb = side[edges[:, 0]], side[edges[:, 1]]
    cross = (sa * sb) < 0
    t = sa[cross] / (sa[cross] - sb[cross])
    return np.vstack([v[side >= 0], v[edges[cross, 0]] + t[:, None] * (v[edges[cross, 1]] - v[edges[cross, 0]])])


def clip_convex(mesh: trimesh.Trimesh, normal: np.ndarray, offset: float) -> trimesh.Trimesh | None:
    """The part of a convex mesh where ``normal . x >= offset`` (a convex hull), or None if too little is left."""
    points = kept_points(np.asarray(mesh.vertices), unique_edges(mesh.faces), normal, offset)
    if len(points) < 4:
        return None
    try:
        out = trimesh_hull(points)
    except QhullError:
        return None
    return out if volume(out) > MIN_PART_VOLUME else None


def separate_neighbours(objects: list[SceneObject], done: dict[int, trimesh.Trimesh], observed: dict[int, np.ndarray],
                        params: CompletionParams, pieces: dict[int, list[trimesh.Trimesh]] | None = None) -> None:
    """Cut apart completed neighbours that overlap (their hidden backs grown into each other).

    The cut is the vertical plane across the line between the two objects' observed centroids,
    midway between their observed points along it; a pair whose observed points interleave along
    that line, or that are stacked, is left as it is. An object made of convex ``pieces`` has each
    piece cut.
    """
    pieces = pieces if pieces is not None else {}
    for i, a in enumerate(objects):
        for b in objects[i + 1:]:
            if a.resting_on == b.id or b.resting_on == a.id:
                continue
            ma, mb = done[a.id], done[b.id]
            if np.any(ma.bounds[0] > mb.bounds[1]) or np.any(mb.bounds[0] > ma.bounds[1]):
                continue
            d = np.zeros(3)
            d[:2] = observed[b.id][:, :2].mean(axis=0) - observed[a.id][:, :2].mean(axis=0)
            if np.linalg.norm(d) < 1e-6:
                continue
            d /= np.linalg.norm(d)
            if np.max(ma.vertices @ d) <= np.min(mb.vertices @ d):
                continue
            pa, pb = np.percentile(observed[a.id] @ d, 99), np.percentile(observed[b.id] @ d, 1)
            if pa > pb:
                continue
            mid = (pa + pb) / 2
            for obj, normal in ((a, -d), (b, d)):
                cut = clip_convex(done[obj.id], normal, float(normal @ (d * mid)))
                if cut is None:
                    continue
                lo, hi = cut.bounds
                done[obj.id] = cut
                if obj.id in pieces:
                    parts = [c for c in (clip_convex(p, normal, float(normal @ (d * mid))) for p in pieces[obj.id]) if c is not None]
                    pieces[obj.id] = parts
                    set_shape(obj, cut, np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]]), params, parts or None)
                else:
                    set_shape(obj, cut, np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]]), params)
                obj.notes.append(f"cut apart from object {(b if obj is a else a).id}, whose completed shape it overlapped")
