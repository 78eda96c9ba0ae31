"""The up axis of an unorganized capture from what rests on its large planes.

Gravity makes supports carry things: a floor, a table or a counter has small bodies standing on
its upper side, touching it and lying wholly above it. A wall has things beside it, rarely
touching it, and the counter that meets it touches it only with an edge: that edge is part of a
large plane itself, so it is no body. Up is the normal of the plane that the most points of
resting bodies stand on, signed toward them, whatever the file's axes: parallel planes (a floor
and the table top above it) pool their bodies. The file's axes only name it (rounded).
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from realsim.geometry import ransac_plane
from realsim.perception.plane_patches import connected_groups
from realsim.perception.plane_refit import refine_plane

MAX_PLANES = 5  # large planes taken out in turn (floor, table top and underside, wall, counter front)
MIN_PLANE_SHARE = 0.04  # a plane holding fewer of the points is a body's face, not a support or wall
TOUCH = 2.0  # a body within this many RANSAC thresholds of a plane touches it
CLEAR = 3.0  # a body rising less than this many thresholds above a plane is the plane's rim
MIN_BODY = 20  # points: smaller residual bits are noise, not bodies
MIN_EVIDENCE = 0.002  # share of the points resting bodies must hold for the vote to decide
MARGIN = 2.0  # the winning direction must carry this many times the evidence of any other
SAMPLE = 50_000  # points the evidence is gathered on (a seeded subset)
RELATIVE_THRESHOLD = 0.01  # the planes' band as a share of the capture's extent (a table's 5 cm apron is its rim)
OWN_FACE = 0.9  # share of a plane's points inside a body's box that makes it the body's own face
PARALLEL_DEG = 15.0  # planes whose signed normals are this close pool their bodies (floor and table top)


def evidence_points(points: np.ndarray, rng: np.random.Generator) -> tuple[np.ndarray, float]:
    """The finite points (a seeded subset of SAMPLE) the evidence is gathered on, and the plane
    band for them: RELATIVE_THRESHOLD of their extent, in the capture's own units."""
    pts = points[np.isfinite(points).all(axis=1)]
    if len(pts) > SAMPLE:
        pts = pts[rng.choice(len(pts), SAMPLE, replace=False)]
    extent = float(np.max(np.ptp(pts, axis=0))) if len(pts) else 0.0
    return pts, max(extent * RELATIVE_THRESHOLD, 1e-6)


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
        inliers = inliers[_largest_patch(points[idx[inliers]], 2 * threshold)]  # one surface, not a slab through two
        if len(inliers) < MIN_PLANE_SHARE * len(points):
            break
        planes.append((normal, offset, idx[inliers]))
        rest[idx[inliers]] = False
    return planes, rest


def _largest_patch(points: np.ndarray, cell: float) -> np.ndarray:
    """Indices of the largest connected group (26-neighbour voxels of side ``cell``) of ``points``:
    a RANSAC plane through two groups far apart (a wall's ledge and a box's side) is no surface."""
    groups = connected_groups(points, cell)
    return max(groups, key=len) if groups else np.arange(len(points))


def _touches(foot: np.ndarray, tree: cKDTree, cell: float) -> bool:
    """Whether any of a body's points near a plane lies on the plane's points (not its extension)."""
    return len(foot) > 0 and bool(np.isfinite(tree.query(foot, distance_upper_bound=2 * cell)[0]).any())


def _within(plane_pts: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> bool:
    """Whether a plane's points (OWN_FACE of them) lie in a body's box: the plane is one of the
    body's own faces, not a surface the body meets."""
    inside = np.all((plane_pts >= lo) & (plane_pts <= hi), axis=1)
    return bool(inside.mean() >= OWN_FACE)


def _base_width(foot: np.ndarray, normal: np.ndarray) -> float:
    """The narrower in-plane extent (5-95th percentile) of a body's base points on a plane."""
    if len(foot) < 3:
        return 0.0
    flat = foot - np.outer((foot - foot.mean(axis=0)) @ normal, normal)
    centred = flat - flat.mean(axis=0)
    _, vecs = np.linalg.eigh(centred.T @ centred)
    lo, hi = np.percentile(centred @ vecs[:, 1], [5, 95])  # vecs[:, 0] ~ the normal (no spread)
    return float(hi - lo)


def resting_normal(points: np.ndarray, threshold: float, rng: np.random.Generator) -> np.ndarray | None:
    """The unit normal (signed toward the bodies) of the plane that bodies rest on, or None when
    the points hold too little evidence (no bodies apart from the planes, or two directions
    carrying alike)."""
    planes, rest = _planes(points, threshold, rng)
    if not planes:
        return None
    extent = float(np.max(np.ptp(points, axis=0)))
    cell = max(threshold, extent / 200.0)  # a bounded grid however far outliers lie
    residual = np.flatnonzero(rest)
    trees = [cKDTree(points[inl]) for _, _, inl in planes]
    votes = np.zeros((len(planes), 2))  # points of bodies resting on each plane's (+, -) side
    cos_parallel = np.cos(np.radians(PARALLEL_DEG))
    for body in connected_groups(points[residual], cell, MIN_BODY):
        pts = points[residual[body]]
        heights = [pts @ normal + offset for normal, offset, _ in planes]
        lo, hi = pts.min(axis=0) - 2 * cell, pts.max(axis=0) + 2 * cell
        touched = [k for k, (h, tree) in enumerate(zip(heights, trees))
                   if _touches(pts[np.abs(h) <= TOUCH * threshold], tree, cell) and not _within(points[planes[k][2]], lo, hi)]
        for k in touched:
            normal = planes[k][0]
            if any(abs(float(normal @ planes[j][0])) < cos_parallel for j in touched):
                continue  # wedged between two crossing surfaces (a thing against a wall): evidence for neither
            for side, sign in enumerate((1.0, -1.0)):
                h = sign * heights[k]
                if h.min() < -threshold or h.max() < CLEAR * threshold:
                    continue  # crosses the plane, or is its rim
                if _base_width(pts[h <= TOUCH * threshold], normal) < threshold:
                    continue  # a panel on its edge (a counter meeting a wall), no base to rest on
                votes[k, side] += len(pts)
    return _strongest(planes, votes, max(MIN_EVIDENCE * len(points), MIN_BODY))


def _strongest(planes: list[tuple[np.ndarray, float, np.ndarray]], votes: np.ndarray, least: float) -> np.ndarray | None:
    """The signed normal of the most voted plane of the winning direction (parallel planes pooled),
    or None when that direction carries under ``least`` points or under MARGIN times another's."""
    signed = [(sign * normal, float(votes[k, side])) for k, (normal, _, _) in enumerate(planes)
              for side, sign in enumerate((1.0, -1.0)) if votes[k, side] > 0]
    if not signed:
        return None
    cos_parallel = np.cos(np.radians(PARALLEL_DEG))
    pooled = [sum(w for m, w in signed if float(n @ m) >= cos_parallel) for n, _ in signed]
    order = sorted(range(len(signed)), key=lambda i: (-pooled[i], -signed[i][1]))
    best = signed[order[0]][0]
    rivals = [pooled[i] for i in order if float(signed[i][0] @ best) < cos_parallel]
    if pooled[order[0]] < least or pooled[order[0]] < MARGIN * max(rivals, default=0.0):
        return None
    return best


def axis_name(direction: np.ndarray) -> str:
    """The signed input axis (``+z`` ...) nearest ``direction``."""
    axis = int(np.argmax(np.abs(direction)))
    return ("+" if direction[axis] > 0 else "-") + "xyz"[axis]


def resting_up(points: np.ndarray, threshold: float, rng: np.random.Generator) -> str | None:
    """The signed input axis nearest the normal bodies rest on (:func:`resting_normal`), or None."""
    normal = resting_normal(points, threshold, rng)
    return None if normal is None else axis_name(normal)
