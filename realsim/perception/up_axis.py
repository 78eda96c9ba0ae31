"""The up axis of an unorganized capture from what rests on its large planes.

Gravity makes supports carry things: a floor, a table or a counter has small bodies standing on
its upper side, touching it and lying wholly above it. A wall has things beside it, rarely
touching it, and the counter that meets it touches it only with an edge: that edge is part of a
large plane itself, so it is no body. The up axis is the plane normal (rounded to an input axis)
that the most points of resting bodies stand on, signed toward them.
"""

from __future__ import annotations

import numpy as np
from scipy import ndimage
from scipy.spatial import cKDTree

from realsim.geometry import ransac_plane
from realsim.perception.planes import refine_plane

MAX_PLANES = 5  # large planes taken out in turn (floor, table top and underside, wall, counter front)
MIN_PLANE_SHARE = 0.04  # a plane holding fewer of the points is a body's face, not a support or wall
TOUCH = 2.0  # a body within this many RANSAC thresholds of a plane touches it
CLEAR = 3.0  # a body rising less than this many thresholds above a plane is the plane's rim
MIN_BODY = 20  # points: smaller residual bits are noise, not bodies
MIN_EVIDENCE = 0.002  # share of the points resting bodies must hold for the vote to decide
MARGIN = 2.0  # the winning signed axis must carry this many times the evidence of any other


def _planes(points: np.ndarray, threshold: float, rng: np.random.Generator) -> tuple[list[tuple[np.ndarray, float, np.ndarray]], np.ndarray]:
    """Large planes taken out one after another (normal, offset, inlier indices) and the mask of
    the points in none of them."""
    rest = np.ones(len(points), dtype=bool)
    planes = []
    for _ in range(MAX_PLANES):
        idx = np.flatnonzero(rest)
        if len(idx) < MIN_PLANE_SHARE * len(points):
            break
        normal, offset, _ = ransac_plane(points[idx], threshold, 300, rng)
        normal, offset, _ = refine_plane(points[idx], normal, offset, threshold)  # a thin top is not fit tilted
        inliers = np.flatnonzero(np.abs(points[idx] @ normal + offset) < threshold)
        if len(inliers) < MIN_PLANE_SHARE * len(points):
            break
        planes.append((normal, offset, idx[inliers]))
        rest[idx[inliers]] = False
    return planes, rest


def _bodies(points: np.ndarray, cell: float) -> list[np.ndarray]:
    """Connected groups (26-neighbour voxels of side ``cell``) of ``points``, as index arrays."""
    if len(points) == 0:
        return []
    ijk = np.floor((points - points.min(axis=0)) / cell).astype(np.int64)
    shape = tuple(ijk.max(axis=0) + 1)
    grid = np.zeros(shape, dtype=bool)
    grid[ijk[:, 0], ijk[:, 1], ijk[:, 2]] = True
    labels, count = ndimage.label(grid, structure=np.ones((3, 3, 3), dtype=bool))
    of_point = labels[ijk[:, 0], ijk[:, 1], ijk[:, 2]] - 1
    order = np.argsort(of_point, kind="stable")
    bounds = np.searchsorted(of_point[order], np.arange(count + 1))
    return [order[bounds[k]:bounds[k + 1]] for k in range(count) if bounds[k + 1] - bounds[k] >= MIN_BODY]


def _base_width(foot: np.ndarray, normal: np.ndarray) -> float:
    """The narrower in-plane extent (5-95th percentile) of a body's base points on a plane."""
    if len(foot) < 3:
        return 0.0
    flat = foot - np.outer((foot - foot.mean(axis=0)) @ normal, normal)
    centred = flat - flat.mean(axis=0)
    _, vecs = np.linalg.eigh(centred.T @ centred)
    lo, hi = np.percentile(centred @ vecs[:, 1], [5, 95])  # vecs[:, 0] ~ the normal (no spread)
    return float(hi - lo)


def resting_up(points: np.ndarray, threshold: float, rng: np.random.Generator) -> str | None:
    """The signed input axis that bodies rest on (``+z`` ...), or None when the points hold too
    little evidence (no bodies apart from the planes, or two axes carrying alike)."""
    planes, rest = _planes(points, threshold, rng)
    if not planes:
        return None
    extent = float(np.max(np.ptp(points, axis=0)))
    cell = max(threshold, extent / 200.0)  # a bounded grid however far outliers lie
    residual = np.flatnonzero(rest)
    trees = [cKDTree(points[inl]) for _, _, inl in planes]
    votes: dict[str, float] = {}
    for body in _bodies(points[residual], cell):
        pts = points[residual[body]]
        for (normal, offset, _), tree in zip(planes, trees):
            s = pts @ normal + offset
            for sign in (1.0, -1.0):
                h = sign * s
                if h.min() < -threshold or h.min() > TOUCH * threshold or h.max() < CLEAR * threshold:
                    continue  # crosses the plane, stands clear of it, or is its rim
                foot = pts[h <= TOUCH * threshold]
                if _base_width(foot, normal) < threshold:
                    continue  # a panel on its edge (a counter meeting a wall), no base to rest on
                if not np.isfinite(tree.query(foot, distance_upper_bound=2 * cell)[0]).any():
                    continue  # touches the plane's extension, not the plane
                axis = int(np.argmax(np.abs(normal)))
                key = ("+" if sign * normal[axis] > 0 else "-") + "xyz"[axis]
                votes[key] = votes.get(key, 0.0) + len(pts)
    if not votes:
        return None
    ranked = sorted(votes.items(), key=lambda kv: -kv[1])
    best, weight = ranked[0]
    runner = ranked[1][1] if len(ranked) > 1 else 0.0
    if weight < max(MIN_EVIDENCE * len(points), MIN_BODY) or weight < MARGIN * runner:
        return None
    return best
