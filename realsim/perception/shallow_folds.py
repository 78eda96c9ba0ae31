"""Two segments of a camera view that meet in a shallow fold: pieces of one body.

A body's own concave creases are shallow: a lying drill's grip runs into its motor housing, a
pitcher's spout into its wall, with the surface on either side of the crease turned only a little
(about 25-40 degrees, measured over a window of pixels on each side). Two bodies that touch meet in
a sharp concave V instead: each convex body's flank turns away toward the contact (50-90 degrees),
and a thing standing on another meets it over a depth jump, not along a continuous border. Two
segments whose shared border is mostly continuous in depth and whose surfaces on either side of it
turn less than ``max_angle`` are joined. The turn is measured between the mean normals of each
side's own pixels in a square window around sampled border pixels, so pixel noise and the crease's
own few pixels do not decide it.
"""

from __future__ import annotations

import numpy as np

from realsim.perception.supervoxels import link_components

__all__ = ["fold_angles", "join_shallow_folds"]


def fold_angles(labels: np.ndarray, normals: np.ndarray, a: np.ndarray, b: np.ndarray, grid_shape: tuple[int, int],
                window: int, samples: int) -> dict[tuple[int, int], float]:
    """Per pair of segments (``labels`` >= 0 per pixel, row-major over ``grid_shape``) joined by at
    least one link ``a``-``b`` (pixel indices, depth-continuous neighbours): the median angle (degrees)
    between the two sides' surfaces at up to ``samples`` of their border links, each side's surface the
    mean of its own pixels' ``normals`` within ``window`` pixels of its end of the link."""
    la, lb = labels[a], labels[b]
    cross = (la >= 0) & (lb >= 0) & (la != lb)
    a, b, la, lb = a[cross], b[cross], la[cross], lb[cross]
    swap = la > lb
    a, b = np.where(swap, b, a), np.where(swap, a, b)
    la, lb = np.minimum(la, lb), np.maximum(la, lb)
    h, w = grid_shape
    image = labels.reshape(h, w)
    nrm = np.nan_to_num(normals).reshape(h, w, 3)
    out: dict[tuple[int, int], float] = {}
    keys = la.astype(np.int64) * (int(labels.max()) + 1) + lb
    order = np.argsort(keys, kind="stable")
    starts = np.flatnonzero(np.r_[True, np.diff(keys[order]) != 0])
    for s, e in zip(starts, np.r_[starts[1:], len(order)]):
        links = order[s:e][:: max(1, (e - s) // samples)]
        angles = []
        for i in links:
            sides = []
            for p, lab in ((a[i], la[i]), (b[i], lb[i])):
                r, c = divmod(int(p), w)
                box = (slice(max(r - window, 0), r + window + 1), slice(max(c - window, 0), c + window + 1))
                n = nrm[box][image[box] == lab].sum(axis=0)
                sides.append(n / max(float(np.linalg.norm(n)), 1e-12))
            angles.append(np.degrees(np.arccos(np.clip(float(sides[0] @ sides[1]), -1.0, 1.0))))
        out[(int(la[order[s]]), int(lb[order[s]]))] = float(np.median(angles))
    return out


def join_shallow_folds(labels: np.ndarray, points: np.ndarray, normals: np.ndarray, grid_shape: tuple[int, int],
                       jump: np.ndarray | float, max_angle: float, window: int, min_links: int, continuous_share: float,
                       samples: int = 80) -> np.ndarray:
    """``labels`` (>= 0 segments, -1 none, one per pixel of ``grid_shape``) with every two segments
    joined whose border (image 4-neighbours of the two) holds at least ``min_links`` links no longer
    than ``jump`` (m, or per pixel: a link is as long as its shorter end allows), those being at least
    ``continuous_share`` of the border, and whose surfaces on either side turn less than ``max_angle``
    degrees (:func:`fold_angles`, over ``window`` pixels)."""
    h, w = grid_shape
    idx = np.arange(h * w).reshape(h, w)
    a = np.concatenate([idx[:, :-1].ravel(), idx[:-1].ravel()])
    b = np.concatenate([idx[:, 1:].ravel(), idx[1:].ravel()])
    border = (labels[a] >= 0) & (labels[b] >= 0) & (labels[a] != labels[b])
    a, b = a[border], b[border]
    limit = np.minimum(jump[a], jump[b]) if isinstance(jump, np.ndarray) else jump
    with np.errstate(invalid="ignore"):
        near = np.linalg.norm(points[a] - points[b], axis=1) <= limit
    lo, hi = np.minimum(labels[a], labels[b]), np.maximum(labels[a], labels[b])
    base = int(labels.max(initial=0)) + 1
    keys, inverse = np.unique(lo.astype(np.int64) * base + hi, return_inverse=True)
    total = np.bincount(inverse.ravel(), minlength=len(keys))
    linked = np.bincount(inverse.ravel(), near, minlength=len(keys))
    ok = (linked >= min_links) & (linked >= continuous_share * total)
    if not ok.any():
        return labels
    keep = near & ok[inverse.ravel()]
    angles = fold_angles(labels, normals, a[keep], b[keep], grid_shape, window, samples)
    pairs = np.array([k for k, v in angles.items() if v < max_angle], dtype=np.int64).reshape(-1, 2)
    if len(pairs) == 0:
        return labels
    root = link_components(base, pairs[:, 0], pairs[:, 1])
    return np.where(labels >= 0, root[np.maximum(labels, 0)], labels)
