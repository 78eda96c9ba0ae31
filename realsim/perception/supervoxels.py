"""Neighbourhoods, normals and supervoxels of the points the segmentation works on.

Links are image-grid 4-neighbours for an organized cloud and k nearest neighbours otherwise;
normals come from grid tangents (pointing at the camera) or from k-neighbour covariances;
supervoxels are SLIC on position, normal and colour.
"""

from __future__ import annotations

import numpy as np
from scipy import ndimage, sparse
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from realsim.perception.segment_params import SegmentParams
from realsim.rowsplit import split_rows

__all__ = ["cloud_supervoxels", "grid_links", "grid_normals", "grid_supervoxels", "knn_links", "link_components", "knn_normals", "smallest_eigenvectors"]


# ----------------------------------------------------------------------------------------------
# neighbourhoods and normals


def grid_links(valid: np.ndarray, grid_shape: tuple[int, int]) -> tuple[np.ndarray, np.ndarray]:
    """Point index pairs of 4-neighbours in the image grid where both points are valid."""
    h, w = grid_shape
    idx = np.arange(h * w).reshape(h, w)
    v = valid.reshape(h, w)
    pairs = []
    for a, b, m in ((idx[:, :-1], idx[:, 1:], v[:, :-1] & v[:, 1:]), (idx[:-1], idx[1:], v[:-1] & v[1:])):
        pairs.append(np.stack([a[m], b[m]], axis=1))
    links = np.concatenate(pairs)
    return links[:, 0], links[:, 1]


def knn_links(points: np.ndarray, valid: np.ndarray, k: int) -> tuple[np.ndarray, np.ndarray]:
    """Point index pairs of k nearest neighbours among the valid points (each pair once)."""
    ids = np.flatnonzero(valid)
    if len(ids) < 2:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    k = min(k, len(ids) - 1)
    _, nn = cKDTree(points[ids]).query(points[ids], k=k + 1)
    a = np.repeat(np.arange(len(ids)), k)
    b = nn[:, 1:].ravel()
    keys = np.unique(np.minimum(a, b) * len(ids) + np.maximum(a, b))
    return ids[keys // len(ids)], ids[keys % len(ids)]


def link_components(n: int, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Connected component index of each of ``n`` nodes linked by the pairs (a, b)."""
    graph = sparse.coo_matrix((np.ones(len(a), dtype=np.int8), (a, b)), shape=(n, n))
    out: np.ndarray = connected_components(graph, directed=False)[1]
    return out


def smallest_eigenvectors(cov: np.ndarray) -> np.ndarray:
    """Unit eigenvectors of the smallest eigenvalue of (M, 3, 3) symmetric matrices."""
    _, vecs = np.linalg.eigh(cov)
    return vecs[:, :, 0]


def grid_normals(points: np.ndarray, valid: np.ndarray, grid_shape: tuple[int, int], window: int,
                 max_step: float | np.ndarray) -> np.ndarray:
    """Normals of an organized cloud from image-grid tangents, pointing toward the camera; NaN elsewhere.

    The image axes (u right, v down) and the optical axis form a right-handed frame, so the cross
    product of the grid tangents d/du x d/dv points away from the camera on every visible surface,
    whatever the world frame is. Unit cross products are averaged over a ``window`` of pixels;
    tangents spanning a depth jump (longer than ``2 max_step``, one length or one per pixel) or invalid
    points are skipped.
    """
    h, w = grid_shape
    normals = np.full(points.shape, np.nan)
    v = valid.reshape(h, w)
    rows, cols = np.flatnonzero(v.any(axis=1)), np.flatnonzero(v.any(axis=0))
    if len(rows) == 0:
        return normals
    r0, r1 = max(rows[0] - 1, 0), min(rows[-1] + 2, h)
    c0, c1 = max(cols[0] - 1, 0), min(cols[-1] + 2, w)
    vc = v[r0:r1, c0:c1]
    p = np.where(vc[..., None], points.reshape(h, w, 3)[r0:r1, c0:c1], np.nan)
    du = np.full_like(p, np.nan)
    dv = np.full_like(p, np.nan)
    du[:, 1:-1] = p[:, 2:] - p[:, :-2]
    dv[1:-1] = p[2:] - p[:-2]
    step = np.broadcast_to(np.asarray(max_step, dtype=np.float64), (h * w,)).reshape(h, w)[r0:r1, c0:c1]
    with np.errstate(invalid="ignore"):
        du[np.linalg.norm(du, axis=2) > 2 * step] = np.nan
        dv[np.linalg.norm(dv, axis=2) > 2 * step] = np.nan
        c = np.cross(du, dv)
        c /= np.linalg.norm(c, axis=2, keepdims=True)
    c = np.nan_to_num(c)
    s = np.stack([ndimage.uniform_filter(c[..., i], size=window, mode="constant") for i in range(3)], axis=2)
    norm = np.linalg.norm(s, axis=2)
    good = vc & (norm > 1e-6)
    out = np.full((r1 - r0, c1 - c0, 3), np.nan)
    out[good] = -s[good] / norm[good][:, None]
    normals.reshape(h, w, 3)[r0:r1, c0:c1] = out
    return normals


def knn_normals(points: np.ndarray, valid: np.ndarray, k: int) -> np.ndarray:
    """Covariance normals over the k nearest valid neighbours; NaN for invalid points."""
    normals = np.full(points.shape, np.nan)
    ids = np.flatnonzero(valid)
    if len(ids) < 3:
        return normals
    pts = points[ids]
    _, nn = cKDTree(pts).query(pts, k=min(k, len(ids)))
    nb = pts[nn] - pts[nn].mean(axis=1, keepdims=True)
    normals[ids] = smallest_eigenvectors(np.einsum("mki,mkj->mij", nb, nb))
    return normals


# ----------------------------------------------------------------------------------------------
# supervoxels


def _slic(features: np.ndarray, candidates: np.ndarray, labels: np.ndarray, iterations: int) -> np.ndarray:
    """Local k-means (SLIC): each point picks the nearest of its candidate seeds, seeds move to their means.

    ``features`` (M, F) are pre-scaled so that squared Euclidean distance is the SLIC distance;
    ``candidates`` (M, C) hold seed indices (-1 for none); ``labels`` the initial assignment.
    """
    features = features.astype(np.float32)
    n_seeds = int(candidates.max()) + 1
    cand = np.where(candidates >= 0, candidates, 0)
    for _ in range(iterations):
        count = np.bincount(labels, minlength=n_seeds).astype(np.float32)
        centres = np.stack([np.bincount(labels, features[:, f], minlength=n_seeds) for f in range(features.shape[1])], axis=1)
        centres = (centres / np.maximum(count, 1.0)[:, None]).astype(np.float32)
        labels = split_rows(lambda rows: _nearest_seeds(features[rows], candidates[rows], cand[rows], centres, count), len(cand))
    return labels


def _nearest_seeds(features: np.ndarray, candidates: np.ndarray, cand: np.ndarray, centres: np.ndarray, count: np.ndarray) -> np.ndarray:
    """Per point (row) the nearest of its candidate seeds that hold points (one SLIC assignment);
    ``cand`` is ``candidates`` with -1 read as seed 0 (masked out)."""
    dist = np.empty(cand.shape, dtype=np.float32)
    for c in range(cand.shape[1]):
        diff = features - centres[cand[:, c]]
        dist[:, c] = np.einsum("ij,ij->i", diff, diff)
    dist[(candidates < 0) | (count[cand] == 0)] = np.inf
    return np.asarray(cand[np.arange(len(cand)), dist.argmin(axis=1)])


def _slic_features(points: np.ndarray, colors: np.ndarray | None, normals: np.ndarray, params: SegmentParams) -> np.ndarray:
    """Features whose squared distances weigh position, colour and normal as the parameters say."""
    n = np.nan_to_num(normals)
    # sign-free normal feature: n n^T flattened (upper triangle), distance ~ 1 - (n.m)^2
    nn = np.stack([n[:, 0] ** 2, n[:, 1] ** 2, n[:, 2] ** 2, *(np.sqrt(2) * n[:, i] * n[:, j] for i, j in ((0, 1), (0, 2), (1, 2)))], axis=1)
    parts = [points / params.supervoxel_size, nn / params.supervoxel_normal_scale]
    if colors is not None:
        parts.append(colors / params.supervoxel_color_scale)
    return np.concatenate(parts, axis=1)


def grid_supervoxels(points: np.ndarray, colors: np.ndarray | None, normals: np.ndarray, ids: np.ndarray,
                     grid_shape: tuple[int, int], params: SegmentParams) -> np.ndarray:
    """SLIC supervoxels of the points ``ids`` of an organized cloud, seeded on an image grid."""
    _, w = grid_shape
    step = params.supervoxel_pixels
    ys, xs = np.divmod(ids, w)
    cy, cx = ys // step, xs // step
    ncx = w // step + 1
    cell = cy * ncx + cx
    occupied, labels = np.unique(cell, return_inverse=True)
    lookup = np.full((cy.max() + 3) * ncx, -1, dtype=np.int64)
    lookup[occupied + ncx] = np.arange(len(occupied))  # shifted by one row so that cy - 1 >= 0
    cand = []
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            ok = (cx + dx >= 0) & (cx + dx < ncx)
            cand.append(np.where(ok, lookup[np.clip((cy + 1 + dy) * ncx + cx + dx, 0, None)], -1))
    feats = _slic_features(points[ids], None if colors is None else colors[ids], normals[ids], params)
    return _slic(feats, np.stack(cand, axis=1), labels, params.supervoxel_iterations)


def cloud_supervoxels(points: np.ndarray, colors: np.ndarray | None, normals: np.ndarray, ids: np.ndarray,
                      params: SegmentParams) -> np.ndarray:
    """SLIC supervoxels of the points ``ids`` of an unorganized cloud, seeded on a voxel grid."""
    pts = points[ids]
    voxel = np.floor(pts / params.supervoxel_size).astype(np.int64)
    _, labels = np.unique(voxel, axis=0, return_inverse=True)
    labels = labels.ravel()
    count = np.bincount(labels)
    seeds = np.stack([np.bincount(labels, pts[:, i]) for i in range(3)], axis=1) / count[:, None]
    k = min(8, len(seeds))
    _, cand = cKDTree(seeds).query(pts, k=k)
    cand = cand.reshape(len(pts), k)
    feats = _slic_features(pts, None if colors is None else colors[ids], normals[ids], params)
    return _slic(feats, cand, labels, params.supervoxel_iterations)
