"""One object seen in two pieces because a nearer one stands in front of it (a camera view).

In an organized view, an object partly hidden behind a nearer object (a bowl behind a bottle, a
bottle behind a pitcher's handle) shows as two segments with no pixel links between them: every
image line from one to the other crosses the occluder. They are one object when, on enough image
lines, the occluder's pixels alone lie between them, the occluder is nearer than both ends, and the
hidden surface can continue from one end to the other: the chord between the two ends runs along
the surface seen at each end (within ``max_turn`` of its tangent plane), as a surface passing
behind the occluder does, while a second object farther back or standing apart breaks it.
"""

from __future__ import annotations

import numpy as np

from realsim.perception.supervoxels import smallest_eigenvectors

__all__ = ["occluded_pairs", "view_axis"]


def view_axis(points: np.ndarray, a: np.ndarray, b: np.ndarray, normals: np.ndarray, min_jump: float) -> np.ndarray | None:
    """Unit direction the camera looks along, from the image links ``a``-``b`` of an organized view
    that cross a depth jump (longer than ``min_jump``): two neighbouring pixels lie on nearly one ray,
    so their difference runs along it. Oriented against ``normals`` (which face the camera); None
    without jumps."""
    d = points[b] - points[a]
    length = np.linalg.norm(d, axis=1)
    d = d[np.isfinite(length) & (length > min_jump)]
    if len(d) < 3:
        return None
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    axis: np.ndarray = smallest_eigenvectors((-(d.T @ d))[None])[0]  # the largest eigenvector of the scatter
    facing = np.nansum(normals @ axis)
    return axis if facing <= 0 else -axis


def _runs(labels: np.ndarray, order: np.ndarray, line: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Runs of one label along image lines: pixels ``order`` (line by line, depthless pixels left
    out) with their ``line``; returns each run's label, first and last position in ``order`` and line."""
    lab = labels[order]
    start = np.r_[True, (lab[1:] != lab[:-1]) | (line[1:] != line[:-1])]
    first = np.flatnonzero(start)
    last = np.r_[first[1:] - 1, len(order) - 1]
    return lab[first], first, last, line[first]


def occluded_pairs(points: np.ndarray, labels: np.ndarray, normals: np.ndarray, grid_shape: tuple[int, int],
                   axis: np.ndarray, min_jump: float, reach: int = 2) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Along every image row and column: pairs of different objects (``labels`` > 0 per pixel) met
    one after the other with only nearer pixels between them (every pixel between is more than
    ``min_jump`` nearer along the viewing ``axis`` than both ends; depthless pixels do not count),
    with at most ``reach`` runs between them (the occluder and a sliver of mixed pixels at its
    silhouette; more is a row of objects in front). Returns the two labels (N, 2), end points (N, 2, 3) and the
    normals two pixels in from each end (N, 2, 3), the surface each end shows."""
    h, w = grid_shape
    finite = np.isfinite(points).all(axis=1)
    grid = np.arange(h * w).reshape(h, w)
    depth = np.where(finite, np.nan_to_num(points) @ axis, np.nan)
    out_l, out_p, out_n = [np.zeros((0, 2), np.int64)], [np.zeros((0, 2, 3))], [np.zeros((0, 2, 3))]
    for image in (grid, grid.T):  # rows, then columns
        order = image.ravel()[finite[image.ravel()]]
        if len(order) < 3:
            continue
        line = np.repeat(np.arange(image.shape[0]), finite[image].sum(axis=1))
        lab, first, last, run_line = _runs(labels, order, line)
        deepest = np.maximum.reduceat(depth[order], first)
        for gap in range(2, reach + 2):
            i = np.arange(len(lab) - gap)
            j = i + gap
            ok = (run_line[i] == run_line[j]) & (lab[i] > 0) & (lab[j] > 0) & (lab[i] != lab[j])
            between = np.max([deepest[i + k] for k in range(1, gap)], axis=0)
            ok &= between < np.minimum(depth[order[last[i]]], depth[order[first[j]]]) - min_jump
            i, j = i[ok], j[ok]
            ends = np.stack([order[last[i]], order[first[j]]], axis=1)
            inner = np.stack([order[np.maximum(last[i] - 2, first[i])], order[np.minimum(first[j] + 2, last[j])]], axis=1)
            out_l.append(np.stack([lab[i], lab[j]], axis=1))
            out_p.append(points[ends])
            out_n.append(normals[inner])
    return np.concatenate(out_l), np.concatenate(out_p), np.concatenate(out_n)
