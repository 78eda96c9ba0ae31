"""How faithful a set of convex hulls is to the scanned solid (distances, IoU)."""

from __future__ import annotations

import manifold3d as mf
import numpy as np
import trimesh
from scipy.spatial import ConvexHull, cKDTree


def sample_surface(mesh: trimesh.Trimesh, n: int, seed: int = 0) -> np.ndarray:
    """``n`` area-uniform points on the surface, deterministic."""
    rng = np.random.default_rng(seed)
    area = mesh.area_faces
    idx = rng.choice(len(area), size=n, p=area / area.sum())
    tri = mesh.triangles[idx]
    r = rng.random((n, 2))
    flip = r.sum(axis=1) > 1
    r[flip] = 1 - r[flip]
    return tri[:, 0] + r[:, :1] * (tri[:, 1] - tri[:, 0]) + r[:, 1:] * (tri[:, 2] - tri[:, 0])


def union_surface_samples(hulls: list[trimesh.Trimesh], n: int, seed: int = 0, eps: float = 2e-4) -> np.ndarray:
    """Points on the boundary of the union of hulls (samples inside another hull dropped)."""
    areas = np.array([h.area for h in hulls])
    counts = np.maximum(1, np.round(n * areas / areas.sum()).astype(int))
    eqs = [ConvexHull(h.vertices).equations for h in hulls]
    out = []
    for i, (h, k) in enumerate(zip(hulls, counts)):
        p = sample_surface(h, int(k), seed + i)
        keep = np.ones(len(p), bool)
        for j, e in enumerate(eqs):
            if j == i:
                continue
            inside = (p @ e[:, :3].T + e[:, 3] < eps).all(axis=1)  # inside or on a shared cut face
            keep &= ~inside
        out.append(p[keep])
    return np.concatenate(out) if out else np.zeros((0, 3))


def surface_distances(hulls: list[trimesh.Trimesh], solid: trimesh.Trimesh, n: int = 20000, dense: int = 200000, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """(hull-union surface -> scan surface, scan surface -> hull-union surface) distances (m)."""
    scan_dense = sample_surface(solid, dense, seed)
    hull_dense = union_surface_samples(hulls, dense, seed + 1)
    scan_q = sample_surface(solid, n, seed + 2)
    hull_q = union_surface_samples(hulls, n, seed + 3)
    d_h2s = cKDTree(scan_dense).query(hull_q)[0]
    d_s2h = cKDTree(hull_dense).query(scan_q)[0]
    return d_h2s, d_s2h


def _man(m: trimesh.Trimesh) -> mf.Manifold:
    return mf.Manifold(mf.Mesh(vert_properties=np.asarray(m.vertices, np.float32), tri_verts=np.asarray(m.faces, np.uint32)))


def hull_union_manifold(hulls: list[trimesh.Trimesh]) -> mf.Manifold:
    return mf.Manifold.batch_boolean([mf.Manifold.hull_points(np.asarray(h.vertices, np.float64)) for h in hulls], mf.OpType.Add)


def volume_iou(hulls: list[trimesh.Trimesh], solid: trimesh.Trimesh) -> float:
    """Exact volume IoU of the hull union and the solid (manifold booleans)."""
    a = hull_union_manifold(hulls)
    b = _man(solid)
    inter = (a ^ b).volume()
    union = (a + b).volume()
    return float(inter / union) if union > 0 else 0.0


SELF_CHECK_SPACING = 0.0009  # m between the dense surface samples distances are measured against


def dense_count(mesh: trimesh.Trimesh) -> int:
    """How many surface samples put them ``SELF_CHECK_SPACING`` apart (a nearest-sample distance
    overstates the true one by about half the spacing, so the count follows the area)."""
    return int(np.clip(mesh.area / SELF_CHECK_SPACING**2, 60000, 200000))


def parts_fidelity(hulls: list[trimesh.Trimesh], solid: trimesh.Trimesh, n: int = 6000) -> tuple[float, float]:
    """(p95 two-way surface distance, volume IoU) of a decomposition: the self-check."""
    a, b = surface_distances(hulls, solid, n=n, dense=dense_count(solid), seed=11)
    return float(max(np.percentile(a, 95), np.percentile(b, 95))), volume_iou(hulls, solid)
