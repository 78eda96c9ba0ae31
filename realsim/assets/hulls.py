"""MuJoCo-valid convex hulls: thickened when flat, at most a given number of vertices."""

from __future__ import annotations

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError, cKDTree

from realsim.assets.fidelity import sample_surface


def make_hull(points: np.ndarray, min_thickness: float = 0.0005, max_vertices: int = 64) -> trimesh.Trimesh | None:
    """A MuJoCo-valid convex hull of ``points``: thickened when flat, None when degenerate."""
    pts = np.unique(np.asarray(points, float).round(9), axis=0)
    if len(pts) < 3:
        return None
    c = pts.mean(axis=0)
    _, s, vt = np.linalg.svd(pts - c, full_matrices=False)
    proj = (pts - c) @ vt.T
    thickness = proj[:, 2].max() - proj[:, 2].min() if len(s) == 3 else 0.0
    if len(s) < 3 or thickness < min_thickness:
        if len(s) < 2 or (proj[:, 1].max() - proj[:, 1].min()) < min_thickness:
            return None  # a line or a point
        n = vt[2] if len(vt) == 3 else np.cross(vt[0], vt[1])
        mid = (proj[:, 2].max() + proj[:, 2].min()) / 2
        flat = pts - np.outer(proj[:, 2] - mid, n)
        pts = np.vstack([flat + n * min_thickness / 2, flat - n * min_thickness / 2])
    try:
        hull = ConvexHull(pts)
    except QhullError:
        return None
    verts = pts[hull.vertices]
    if len(verts) > max_vertices:
        verts = _cap_vertices(verts, max_vertices)
        if verts is None:
            return None
    mesh = trimesh.convex.convex_hull(verts)
    if len(mesh.vertices) < 4 or mesh.volume <= 1e-12:
        return None
    return mesh


def _cap_vertices(verts: np.ndarray, max_vertices: int) -> np.ndarray | None:
    """At most ``max_vertices`` of a convex polytope's vertices whose hull stays closest to it:
    start from the extreme points in 12 directions, then add, one at a time, the vertex lying
    farthest outside the current hull (greedy Hausdorff reduction: the base an object stands on
    and every protrusion are kept first)."""
    idx = list(np.unique(np.argmax(verts @ _fibonacci(12).T, axis=0)))
    while len(idx) < max_vertices:
        try:
            eq = ConvexHull(verts[idx]).equations
        except QhullError:
            return None
        outside = (verts @ eq[:, :3].T + eq[:, 3]).max(axis=1)
        outside[idx] = -np.inf
        far = int(np.argmax(outside))
        if outside[far] <= 1e-9:
            break
        idx.append(far)
    try:
        hull = ConvexHull(verts[idx])
    except QhullError:
        return None
    return verts[idx][hull.vertices]


def _fibonacci(n: int) -> np.ndarray:
    i = np.arange(n) + 0.5
    phi = np.arccos(1 - 2 * i / n)
    theta = np.pi * (1 + 5**0.5) * i
    return np.stack([np.cos(theta) * np.sin(phi), np.sin(theta) * np.sin(phi), np.cos(phi)], axis=1)


def hull_p95_distance(hull: trimesh.Trimesh, solid: trimesh.Trimesh, n: int = 4000, dense: int = 60000) -> float:
    """95th percentile distance between a single hull and the solid surface, both ways (m)."""
    tree = cKDTree(sample_surface(solid, dense, 7))
    d_h2s = tree.query(sample_surface(hull, n, 8))[0]
    eq = ConvexHull(hull.vertices).equations
    d_s2h = np.maximum(-(sample_surface(solid, n, 9) @ eq[:, :3].T + eq[:, 3]).max(axis=1), 0.0)
    return float(max(np.percentile(d_h2s, 95), np.percentile(d_s2h, 95)))


def capped(mesh: trimesh.Trimesh, max_vertices: int = 64) -> trimesh.Trimesh:
    """``mesh`` when it has at most ``max_vertices`` vertices, else its convex hull cut down to that
    many (MuJoCo collides a mesh as its convex hull; GPU collision wants few vertices per hull)."""
    if len(mesh.vertices) <= max_vertices:
        return mesh
    hull = make_hull(np.asarray(mesh.vertices), max_vertices=max_vertices)
    return hull if hull is not None else mesh
