"""Convex hulls as closed, outward-wound meshes, straight from Qhull (no mesh repair passes)."""

from __future__ import annotations

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError
from trimesh import triangles, util
from trimesh.constants import tol
from trimesh.convex import QHULL_DEFAULT


def volume(mesh: trimesh.Trimesh) -> float:
    """``mesh.volume`` as trimesh computes it (the surface integral of its mass properties: the same
    operations in the same order) without the centre of mass and inertia computed alongside."""
    tri = np.asarray(mesh.vertices).view(np.ndarray)[mesh.faces]
    edge = tri[:, 1:, :] - tri[:, :2, :]
    cross_x = edge[:, 0, 1] * edge[:, 1, 2] - edge[:, 0, 2] * edge[:, 1, 1]
    return float(np.sum(cross_x * (tri[:, 0, 0] + tri[:, 1, 0] + tri[:, 2, 0])) / 6.0)


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
    return hull if volume(hull) > 1e-9 else None


def within_convex(mesh: trimesh.Trimesh, points: np.ndarray, margin: float) -> np.ndarray:
    """Mask of the ``points`` inside the convex ``mesh`` or within ``margin`` outside one of its faces."""
    planes = np.einsum("fk,fk->f", mesh.face_normals, mesh.triangles[:, 0, :])
    return np.asarray(np.all(points @ mesh.face_normals.T - planes[None, :] <= margin, axis=1))


def extreme_points(points: np.ndarray, margin: float = 1e-9) -> np.ndarray:
    """The ``points`` within ``margin`` of their convex hull's boundary: the only ones that can hold
    the maximum of ``n . x`` for any direction ``n`` (or, as their perspective images, of any line
    through the image); all of them when the hull is flat or there are few."""
    points = np.asarray(points, dtype=np.float64)
    if len(points) <= 16:
        return points
    try:
        eq = ConvexHull(points).equations
    except QhullError:
        return points
    return np.asarray(points[(points @ eq[:, :-1].T + eq[:, -1]).max(axis=1) > -margin])


def trimesh_hull(points: np.ndarray) -> trimesh.Trimesh:
    """``trimesh.convex.convex_hull(points)`` (the same vertices, faces and normals), built without
    its merge and repair passes when they would change nothing: no two vertices within trimesh's
    merge tolerance, every edge shared by two faces in opposite directions, a positive volume.
    Anything else goes to trimesh itself (those passes cost more than the hull)."""
    points = np.asarray(points, dtype=np.float64)
    try:
        hull = ConvexHull(points, qhull_options=str(QHULL_DEFAULT))
    except QhullError:
        return _by_trimesh(points)
    vid = np.sort(hull.vertices)
    index = np.zeros(len(hull.points), dtype=np.int64)
    index[vid] = np.arange(len(vid))
    faces = index[hull.simplices].copy()
    vertices = hull.points[vid].copy()
    crosses = _cross(vertices[faces])
    normals, valid = util.unitize(crosses, check_valid=True)
    faces, crosses = faces[valid], crosses[valid]
    area = triangles.area(crosses=crosses)  # type: ignore[no-untyped-call]
    centre = vertices[faces].mean(axis=1)
    if area.sum() <= 0:
        return _by_trimesh(points)
    backwards = util.diagonal_dot(normals, centre - np.average(centre, weights=area, axis=0)) < 0.0
    faces[backwards] = np.fliplr(faces[backwards])
    normals[backwards] *= -1.0
    rounded = (vertices * 10 ** util.decimal_to_digits(tol.merge)).round().astype(np.int64)
    order = np.lexsort(rounded.T)
    repeated = np.any(np.all(rounded[order[1:]] == rounded[order[:-1]], axis=1))
    edges = faces[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2)
    directed = np.sort(edges[:, 0] * len(vertices) + edges[:, 1])
    reverse = np.sort(edges[:, 1] * len(vertices) + edges[:, 0])
    volume = float(np.einsum("fk,fk->", vertices[faces[:, 0]], np.where(backwards[:, None], -crosses, crosses))) / 6.0
    if repeated or np.any(directed[1:] == directed[:-1]) or not np.array_equal(directed, reverse) or volume <= 1e-15:
        return _by_trimesh(points)  # every directed edge once and its reverse too: closed and consistently wound
    mesh = trimesh.Trimesh(vertices=vertices, faces=faces, process=False, validate=False)
    if _normals_match(vertices, faces, normals):  # what the constructor's ``face_normals`` check does, cheaper
        mesh._cache["face_normals"] = normals
    return mesh


def _cross(tri: np.ndarray) -> np.ndarray:
    """``trimesh.triangles.cross(tri)`` (numpy's cross product of the two edges: the same products and
    differences, so the same bits) without ``np.cross``'s per-call overhead."""
    edge = tri[:, 1:, :] - tri[:, :2, :]
    a, b = edge[:, 0], edge[:, 1]
    return np.column_stack([a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1], a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2],
                            a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]])


def triangles_and_areas(mesh: trimesh.Trimesh) -> tuple[np.ndarray, np.ndarray]:
    """``mesh.triangles`` and ``mesh.area_faces`` (the same operations, so the same bits) without
    trimesh's cache: a piece made once and sampled once pays no cache bookkeeping."""
    tri = np.asarray(mesh.vertices).view(np.ndarray)[np.asarray(mesh.faces).view(np.ndarray)]
    return tri, np.sqrt((_cross(tri) ** 2).sum(axis=1)) / 2.0


def _normals_match(vertices: np.ndarray, faces: np.ndarray, normals: np.ndarray) -> bool:
    """Whether ``Trimesh(face_normals=normals)`` keeps them: finite, not all zero, and the first 20 within
    ``np.allclose`` of the normals of those triangles (its setter's checks, for finite values)."""
    if len(normals) == 0 or normals.shape != faces.shape:
        return False
    ptp = np.ptp(normals)
    if not np.isfinite(ptp) or ptp < tol.merge:
        return False
    check, valid = util.unitize(_cross(vertices[faces[:20]]), check_valid=True)
    compare = np.zeros((len(valid), 3))
    compare[valid] = check
    return bool(np.all(np.abs(compare - normals[:20]) <= 1e-8 + 1e-5 * np.abs(normals[:20])))


def _by_trimesh(points: np.ndarray) -> trimesh.Trimesh:
    """trimesh's hull, or Qhull's own triangles when trimesh's repair left it open (it drops a sliver
    triangle of near-collinear corners, e.g. where a cut plane passes by a vertex): a piece is closed."""
    hull: trimesh.Trimesh = trimesh.convex.convex_hull(points)
    if hull.is_watertight:
        return hull
    try:
        closed = fast_hull(np.asarray(hull.vertices))  # its merged corners, every Qhull triangle kept
    except (QhullError, ValueError):
        return hull
    return closed if closed.is_watertight and volume(closed) > 0 else hull


MeshArrays = tuple[np.ndarray, np.ndarray, np.ndarray]


def mesh_arrays(mesh: trimesh.Trimesh) -> MeshArrays:
    """What :func:`from_arrays` rebuilds ``mesh`` from (vertices, faces, face normals): to send a mesh
    between processes without trimesh's cache."""
    return np.asarray(mesh.vertices).view(np.ndarray), np.asarray(mesh.faces).view(np.ndarray), np.asarray(mesh.face_normals).view(np.ndarray)


def from_arrays(arrays: MeshArrays) -> trimesh.Trimesh:
    """The mesh of :func:`mesh_arrays`: the same vertices, faces and face normals, nothing processed."""
    vertices, faces, normals = arrays
    return trimesh.Trimesh(vertices=vertices, faces=faces, face_normals=normals, process=False, validate=False)
