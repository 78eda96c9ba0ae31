"""Geometry shared by perception, layout, arena, robot and the generators: planes fitted to
points (least squares, seeded RANSAC), a heading as a quaternion, and convex polygons in the
ground plane (inside, apart)."""

from __future__ import annotations

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError


def yaw_quat(yaw: float) -> np.ndarray:
    """The (w, x, y, z) quaternion of a rotation by ``yaw`` radians about +Z."""
    return np.array([np.cos(yaw / 2), 0.0, 0.0, np.sin(yaw / 2)])


def inside_convex_polygon(xy: np.ndarray, polygon: np.ndarray, margin: float = 0.0) -> np.ndarray:
    """Mask of points inside a counter-clockwise convex polygon grown by ``margin``.

    One edge at a time into two reused buffers, so memory stays O(N) for full-resolution clouds.
    """
    edges = np.roll(polygon, -1, axis=0) - polygon
    lengths = np.linalg.norm(edges, axis=1)
    keep = lengths > 1e-12
    x, y = np.ascontiguousarray(xy[:, 0]), np.ascontiguousarray(xy[:, 1])
    inside = np.ones(len(xy), dtype=bool)
    cross, other, ok = np.empty(len(xy)), np.empty(len(xy)), np.empty(len(xy), dtype=bool)
    for e, start, length in zip(edges[keep], polygon[keep], lengths[keep]):
        # e0 (y - s1) - e1 (x - s0), over the edge's length: the signed distance
        np.subtract(y, start[1], out=cross)
        cross *= e[0]
        np.subtract(x, start[0], out=other)
        other *= e[1]
        cross -= other
        cross /= length
        inside &= np.greater_equal(cross, -margin, out=ok)
    return inside


def polygons_apart(a: np.ndarray, b: np.ndarray, gap: float) -> bool:
    """True when convex polygons ``a`` and ``b`` are separated by at least ``gap`` (SAT)."""
    for poly in (a, b):
        edges = np.roll(poly, -1, axis=0) - poly
        normals = np.column_stack([edges[:, 1], -edges[:, 0]])
        lengths = np.linalg.norm(normals, axis=1)
        normals = normals[lengths > 1e-12] / lengths[lengths > 1e-12, None]
        pa, pb = a @ normals.T, b @ normals.T
        separated = (pa.min(axis=0) - pb.max(axis=0) >= gap) | (pb.min(axis=0) - pa.max(axis=0) >= gap)
        if np.any(separated):
            return True
    return False


def fit_plane(points: np.ndarray) -> tuple[np.ndarray, float]:
    """Least-squares plane (unit normal with +z component >= 0, offset d of n.x + d = 0)."""
    centroid = points.mean(axis=0)
    centred = points - centroid
    _, vectors = np.linalg.eigh(centred.T @ centred)  # 3x3 scatter matrix: cheap for any N
    normal = vectors[:, 0]
    if normal[2] < 0:
        normal = -normal
    return normal, float(-normal @ centroid)


def ransac_plane(points: np.ndarray, threshold: float, max_iterations: int, rng: np.random.Generator,
                 confidence: float = 0.999, batch: int = 128, score_points: int = 4000,
                 shuffled: bool = False) -> tuple[np.ndarray, float, np.ndarray]:
    """Seeded RANSAC plane: (unit normal, d, inlier indices into ``points``) with most inliers.

    Hypotheses are scored in vectorized batches on a random subset of ``score_points`` points;
    sampling stops once ``confidence`` says a better plane is unlikely (the adaptive RANSAC
    bound), or after ``max_iterations``. The inliers of the winner are taken from all points.
    ``shuffled`` points are already in a random order: the subset is their head.
    """
    full = points
    if len(points) > score_points:
        points = points[:score_points] if shuffled else points[rng.choice(len(points), score_points, replace=False)]
    n = len(points)
    best_count, best_normal, best_d = -1, np.array([0.0, 0.0, 1.0]), 0.0
    done, needed = 0, max_iterations
    while done < min(needed, max_iterations):
        k = min(batch, max_iterations - done)
        idx = rng.integers(0, n, size=(k, 3))
        a, b, c = points[idx[:, 0]], points[idx[:, 1]], points[idx[:, 2]]
        normals = np.cross(b - a, c - a)
        norms = np.linalg.norm(normals, axis=1)
        ok = norms > 1e-12
        if ok.any():
            normals = normals[ok] / norms[ok, None]
            offsets = -np.einsum("ij,ij->i", normals, a[ok])
            counts = (np.abs(points @ normals.T + offsets) < threshold).sum(axis=0)
            j = int(np.argmax(counts))
            if counts[j] > best_count:
                best_count, best_normal, best_d = int(counts[j]), normals[j], float(offsets[j])
        done += k
        ratio = best_count / n
        if 0.0 < ratio < 1.0:
            needed = int(np.ceil(np.log(1.0 - confidence) / np.log(1.0 - ratio**3)))
        elif ratio >= 1.0:
            break
    inliers = np.flatnonzero(np.abs(full @ best_normal + best_d) < threshold)
    return best_normal, best_d, inliers


def rotation_between(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The minimal rotation matrix taking unit vector ``a`` to unit vector ``b``."""
    a = a / np.linalg.norm(a)
    b = b / np.linalg.norm(b)
    v = np.cross(a, b)
    c = float(a @ b)
    if np.linalg.norm(v) < 1e-12:
        if c > 0:
            return np.eye(3)
        axis = np.cross(a, [1.0, 0.0, 0.0])
        if np.linalg.norm(axis) < 1e-6:
            axis = np.cross(a, [0.0, 1.0, 0.0])
        axis /= np.linalg.norm(axis)
        return 2.0 * np.outer(axis, axis) - np.eye(3)
    vx = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    return np.eye(3) + vx + vx @ vx * (1.0 / (1.0 + c))


def polygon_and_rectangle(xy: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """Convex hull (counter-clockwise) and minimal oriented rectangle (centre, size, yaw) of xy."""
    try:
        hull = ConvexHull(xy)
    except (QhullError, ValueError):
        raise ValueError("degenerate region: fewer than three non-collinear points") from None
    polygon = xy[hull.vertices]
    to_rect, extents = trimesh.bounds.oriented_bounds_2D(polygon)
    from_rect = np.linalg.inv(to_rect)
    center = from_rect[:2, 2]
    yaw = float(np.arctan2(from_rect[1, 0], from_rect[0, 0]))
    size = np.asarray(extents, dtype=np.float64)
    # Canonical yaw in (-pi/2, pi/2] so equal rectangles read the same.
    if yaw > np.pi / 2:
        yaw -= np.pi
    elif yaw <= -np.pi / 2:
        yaw += np.pi
    return polygon, center, size, yaw
