"""Volumes of a closed convex mesh cut by many planes at once, without a hull per plane.

The part of a convex body where ``n . x >= offset`` is bounded by its faces clipped to that side and
by the cap the plane cuts. Its volume is the sum over the clipped faces of the cones they span from a
point on the plane (the cap, lying in the plane, spans none): closed form per face, for every plane
in one pass. It is the volume of the hull of :func:`realsim.completion.neighbours.kept_points` (that
part's corners), to rounding, when the mesh is closed, consistently wound and convex (within a bound
returned alongside when it is convex only to rounding).
"""

from __future__ import annotations

import numpy as np
import trimesh


def convexity_excess(vertices: np.ndarray, faces: np.ndarray, normals: np.ndarray) -> float | None:
    """How far (m) a vertex lies beyond a face's plane at most (0 for a convex mesh), or None when the
    mesh is not closed (each directed edge once, its reverse too) and wound outward (a positive volume)."""
    if len(faces) < 4 or not np.all(np.isfinite(normals)):
        return None
    edges = faces[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2).astype(np.int64)
    n = len(vertices)
    directed, reverse = np.sort(edges[:, 0] * n + edges[:, 1]), np.sort(edges[:, 1] * n + edges[:, 0])
    if np.any(directed[1:] == directed[:-1]) or not np.array_equal(directed, reverse):
        return None
    if np.sum(np.linalg.det(vertices[faces])) <= 0:
        return None
    planes = np.einsum("fk,fk->f", normals, vertices[faces[:, 0]])
    return max(0.0, float(np.max(vertices @ normals.T - planes)))


def _cones(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    """Six times the signed volumes of the tetrahedra (origin, a, b, c), row by row."""
    return np.asarray(np.einsum("ik,ik->i", a, np.cross(b, c)))


def clipped_volumes(mesh: trimesh.Trimesh, normals: np.ndarray, offsets: np.ndarray) -> tuple[np.ndarray, float] | None:
    """Per plane ``normals[j] . x = offsets[j]`` (unit normals), the volume of the part of ``mesh`` where
    ``normals[j] . x >= offsets[j]``, and how much the hull of that part's corners may exceed it (a mesh
    convex only to rounding: twice its largest convexity excess times its area); None when the mesh is
    not closed and wound outward."""
    v, f = np.asarray(mesh.vertices, dtype=np.float64), np.asarray(mesh.faces, dtype=np.int64)
    excess = convexity_excess(v, f, np.asarray(mesh.face_normals, dtype=np.float64))
    if excess is None:
        return None
    centre = v.mean(axis=0)  # about the body, so the closed forms do not cancel large numbers
    v, offsets = v - centre, offsets - normals @ centre
    tri = v[f]  # (F, 3, 3)
    det = _cones(tri[:, 0], tri[:, 1], tri[:, 2])  # a whole face's cone from the origin: det(a, b, c)
    moment = np.cross(tri[:, 0], tri[:, 1]) + np.cross(tri[:, 1], tri[:, 2]) + np.cross(tri[:, 2], tri[:, 0])
    origin = normals * offsets[:, None]  # a point on each plane: its cones are the volume (the cap spans none)
    side = v @ normals.T - offsets  # (V, P)
    s = side[f]  # (F, 3, P)
    kept = s >= 0
    count = kept.sum(axis=1)  # (F, P)
    whole = np.where(count == 3, det[:, None] - moment @ origin.T, 0.0)  # det(a - p, b - p, c - p) for faces kept whole
    face, plane = np.nonzero((count == 1) | (count == 2))
    if len(face):
        k = kept[face, :, plane]  # (M, 3)
        lone = np.where(count[face, plane] == 1, np.argmax(k, axis=1), np.argmin(k, axis=1))  # the vertex alone on its side
        idx = (lone[:, None] + np.arange(3)[None, :]) % 3  # (lone, next, last): the face's own cyclic order
        p = tri[face[:, None], idx] - origin[plane][:, None, :]
        d = s[face[:, None], idx, plane[:, None]]
        t_next = d[:, 0] / (d[:, 0] - d[:, 1])
        t_last = d[:, 0] / (d[:, 0] - d[:, 2])
        to_next = p[:, 0] + t_next[:, None] * (p[:, 1] - p[:, 0])
        to_last = p[:, 0] + t_last[:, None] * (p[:, 2] - p[:, 0])
        one = count[face, plane] == 1
        part = np.where(one, _cones(p[:, 0], to_next, to_last),
                        _cones(to_next, p[:, 1], p[:, 2]) + _cones(to_next, p[:, 2], to_last))
        np.add.at(whole, (face, plane), part)
    area = float(np.sum(np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1))) / 2.0
    return np.asarray(whole.sum(axis=0) / 6.0), 2.0 * excess * area
