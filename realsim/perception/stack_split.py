"""Objects resting on a flat top, split from the cluster they merged into (clouds seen from around).

A box lying on a table has a flat, level top; an object resting on it stands above that top,
inside its outline seen from above. Where the surface-based segmentation could not see the
crease between them (a sparse cloud, whose normals blur a small object into the box's top),
the cluster holds both. The split is taken only when the top is the cluster's top everywhere
else (nearly all of the cluster higher than the top lies over it, as a resting object does;
a taller neighbour merged beside the box does not) and the part above covers a small share of
the top seen from above: a mug's or bowl's inner bottom is level too, but its walls rise all
around it and enclose it, so neither is split.
"""

from __future__ import annotations

import numpy as np
from scipy import sparse
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from realsim.geometry import inside_convex_polygon, polygon_and_rectangle

__all__ = ["give_resting_base", "split_resting"]

LEVEL_COS = float(np.cos(np.radians(20.0)))  # a normal this close to vertical lies on a level surface
OVER_SHARE = 0.9  # this share of the points above the top lie over it (within one cell of its outline)
MAX_COVER = 0.5  # the outline of what lies above holds at most this share of the top's points
LEVEL_SHARE = 0.5  # a base's top is level around what rests on it: this share of its points there lie in one layer


def _top(z: np.ndarray, level: np.ndarray, cell: float) -> float | None:
    """Height of the most populated upward-facing level layer (one ``cell`` thick) of a cluster, None without one."""
    if level.sum() < 3:
        return None
    bins = np.floor(z[level] / cell).astype(np.int64)
    values, counts = np.unique(bins, return_counts=True)
    best = values[np.argmax(counts)]
    near = level & (np.abs(np.floor(z / cell) - best) <= 1)
    return float(np.median(z[near]))


def _split_one(points: np.ndarray, normals: np.ndarray, a: np.ndarray, b: np.ndarray, cell: float,
               min_points: int, min_size: float) -> np.ndarray | None:
    """A mask of the points of one cluster resting on its flat top, or None."""
    z = points[:, 2]
    level = normals[:, 2] >= LEVEL_COS
    top = _top(z, level, cell)
    if top is None:
        return None
    plane = level & (np.abs(z - top) <= cell)
    if top - z.min() < min_size:
        return None  # a top stands on a body of its own below it (a box), not on a low layer of a lying thing
    if plane.sum() < min_points or np.ptp(points[plane, :2], axis=0).min() < min_size:
        return None
    try:
        outline = polygon_and_rectangle(points[plane, :2])[0]
    except ValueError:
        return None
    above = z > top + cell
    if above.sum() < min_points or inside_convex_polygon(points[above, :2], outline, cell).mean() < OVER_SHARE:
        return None  # something rises beside the top (a taller neighbour merged with the box)
    try:
        footprint = polygon_and_rectangle(points[above, :2])[0]
    except ValueError:
        return None
    if inside_convex_polygon(points[plane, :2], footprint).mean() > MAX_COVER:
        return None  # what rises encloses the level part: walls around an inner bottom, not things on a top
    both = above[a] & above[b]
    n = len(points)
    _, comp = connected_components(sparse.coo_matrix((np.ones(int(both.sum())), (a[both], b[both])), shape=(n, n)),
                                   directed=False)
    resting = np.zeros(n, dtype=bool)
    for c in np.unique(comp[above]):
        part = above & (comp == c)
        if part.sum() < min_points:
            continue
        if np.ptp(points[part], axis=0).max() >= min_size and z[part].max() - top >= min_size:
            resting |= part  # object-sized, and tall enough over the top to stand on it
    rest = ~resting
    if not resting.any() or rest.sum() < min_points:
        return None
    return resting


def split_resting(points: np.ndarray, normals: np.ndarray, labels: np.ndarray, a: np.ndarray, b: np.ndarray,
                  cell: float, min_points: int, min_size: float) -> np.ndarray:
    """Cluster labels (>= 0; -1 none) with objects resting on a cluster's flat top made their own.

    ``points`` (N, 3) world positions (Z up) and outward ``normals`` of the segmented points,
    (a, b) links between neighbours, ``cell`` the working resolution (m); a resting object holds
    at least ``min_points`` points and is ``min_size`` (m) across and tall over the top."""
    out = labels.copy()
    next_label = int(labels.max(initial=-1)) + 1
    for k in np.unique(labels[labels >= 0]):
        members = np.flatnonzero(labels == k)
        local = np.full(len(points), -1, dtype=np.int64)
        local[members] = np.arange(len(members))
        inside = (local[a] >= 0) & (local[b] >= 0)
        resting = _split_one(points[members], normals[members], local[a[inside]], local[b[inside]], cell, min_points,
                             min_size)
        if resting is not None:
            out[members[resting]] = next_label
            next_label += 1
    return out


def give_resting_base(points: np.ndarray, labels: np.ndarray, resting_on: dict[int, int | None], band: float,
                      reach: float, step: float) -> np.ndarray:
    """Labels (per point; objects > 0) with the lowest part of each object resting on another's
    level top taken back from that base.

    Segments straddle the crease where a resting object meets the top it stands on, so a ring of
    its lowest points can end up with the base. A top is the highest surface of what it tops:
    the base's points inside the resting object's outline (grown by ``band``) more than ``band``
    above the base's top are the resting object's when they continue its surface, reached from
    its kept points in steps of at most ``step`` (the working resolution); a relief of the top
    itself (a cap's dome) lies apart from the object's wall. The top is the most populated layer
    (``band`` thick) of the base's points within ``reach`` of the outline, and is used only when
    level: at least ``LEVEL_SHARE`` of those points lie in it (a ridge's slopes have no such layer)."""
    out = labels.copy()
    for a, b in resting_on.items():
        if b is None:
            continue
        mine, base = labels == a, np.flatnonzero(labels == b)
        if mine.sum() < 3 or len(base) < 3:
            continue
        try:
            outline = polygon_and_rectangle(points[mine, :2])[0]
        except ValueError:  # a degenerate object (collinear seen from above): no outline
            continue
        near = base[inside_convex_polygon(points[base, :2], outline, reach)]
        if len(near) < 3:
            continue
        z = points[near, 2]
        values, counts = np.unique(np.floor(z / band).astype(np.int64), return_counts=True)
        layer = np.abs(np.floor(z / band) - values[np.argmax(counts)]) <= 1
        if layer.mean() < LEVEL_SHARE:
            continue
        top = float(np.median(z[layer]))
        cand = near[(z > top + band) & inside_convex_polygon(points[near, :2], outline, band)]
        out[cand[_reached(points[cand], points[mine], step)]] = a
    return out


def _reached(candidates: np.ndarray, start: np.ndarray, step: float) -> np.ndarray:
    """Mask of the ``candidates`` reached from the ``start`` points in steps of at most ``step``
    through other candidates."""
    reached = np.zeros(len(candidates), dtype=bool)
    if len(candidates) == 0:
        return reached
    fresh = cKDTree(start).query(candidates, distance_upper_bound=step)[0] <= step
    while fresh.any():
        reached |= fresh
        rest = np.flatnonzero(~reached)
        if len(rest) == 0:
            break
        fresh = np.zeros(len(candidates), dtype=bool)
        fresh[rest] = cKDTree(candidates[reached]).query(candidates[rest], distance_upper_bound=step)[0] <= step
    return reached
