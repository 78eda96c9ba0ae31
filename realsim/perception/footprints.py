"""Footprints: two objects standing on the same support cannot stand in the same place.

A cluster of the 3D segmentation that stands on its support (its base is on it) occupies the
area under it: the cells its points fill seen from above, closed across the gaps sampling leaves
and with the openings they enclose filled (a bowl's, a mug's inside). Not their convex hull: an
object standing in the bay of an L-shaped one (a can beside a lying drill's grip) lies in the
drill's hull but beside its footprint. When most of another standing
cluster lies inside that area, the two are pieces of one object that the surface-based
segmentation cut apart at a concave crease of its own (a bowl's inside from its outside, the
underside of a lying drill from its body). An object stacked on another does not stand on the
support and is never joined this way, nor is one whose points nearly all lie above the other's
top: a bottle standing on a lying box whose cluster took a few points of the box's side down to
the support "stands" by those, but sits on the box, not in it (a bowl's inside lies below its rim).
Two standing clusters that together close around an opening neither closes alone (a large share of
their joint footprint) are the walls of one body cut apart at two of its corners: a lying box whose
top a sweep at table height never saw is four walls around nothing.
"""

from __future__ import annotations

import numpy as np
from scipy import ndimage

__all__ = ["enclosed", "filled_footprint", "merge_shared_footprints"]

RING_SHARE = 0.3  # two clusters whose joint footprint encloses an opening this share of it are one body's walls
OVER_SHARE = 0.9  # a cluster with this share of its points above another's top rests on it
TOP_QUANTILE = 95.0  # a cluster's top: this percentile of its heights (a few stray points rise above a box's top)


def filled_footprint(cells: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The footprint of the occupied xy ``cells`` (K, 2 ints): (closed, filled, origin), boolean
    grids whose cell (0, 0) is ``origin``. ``closed``: the cells closed across the one-cell gaps
    sampling leaves in a surface; ``filled``: with the openings they enclose filled as well."""
    lo = cells.min(axis=0) - 2
    grid = np.zeros(tuple(cells.max(axis=0) - lo + 3), dtype=bool)
    grid[cells[:, 0] - lo[0], cells[:, 1] - lo[1]] = True
    closed = ndimage.binary_closing(grid, structure=np.ones((3, 3), dtype=bool))
    return closed, ndimage.binary_fill_holes(closed), lo


def enclosed(cells: np.ndarray, around: np.ndarray) -> np.ndarray:
    """Mask of the xy ``cells`` (K, 2 ints) inside the filled footprint of the occupied cells ``around``."""
    _, filled, origin = filled_footprint(around)
    return _inside(cells, filled, origin)


def _inside(cells: np.ndarray, grid: np.ndarray, origin: np.ndarray) -> np.ndarray:
    """Mask of the ``cells`` that are set in ``grid`` (cell (0, 0) at ``origin``)."""
    at = cells - origin
    ok = np.all((at >= 0) & (at < grid.shape), axis=1)
    out = np.zeros(len(cells), dtype=bool)
    out[ok] = grid[at[ok, 0], at[ok, 1]]
    return out


def merge_shared_footprints(xy: np.ndarray, labels: np.ndarray, support: np.ndarray, standing: np.ndarray,
                            cell: float, min_share: float = 0.5, height: np.ndarray | None = None) -> np.ndarray:
    """Cluster labels (>= 0; -1 none) with standing clusters that share a footprint joined.

    ``xy`` (N, 2) are the points' horizontal positions (m), ``support`` the support index of each
    point, ``standing`` (per label) whether the cluster stands on its support, ``cell`` (m) the
    grid the points were worked at (about one point per cell of a surface). Two standing
    clusters on the same support join when at least ``min_share`` of one's points lie in the
    other's filled footprint (:func:`filled_footprint`); the larger share first, each pair judged
    on the clusters as found. With ``height`` (per point, m above the support), a cluster with
    ``OVER_SHARE`` of its points above the other's top (:func:`_over_top`) rests on it: not joined."""
    ks = [k for k in np.unique(labels[labels >= 0]).tolist() if standing[k]]
    if len(ks) < 2 or not np.isfinite(cell) or cell <= 0:
        return labels
    members = {k: np.flatnonzero(labels == k) for k in ks}
    home = {k: int(np.bincount(support[m] - support[m].min()).argmax() + support[m].min()) for k, m in members.items()}
    cells = {k: np.floor(xy[m] / cell).astype(np.int64) for k, m in members.items()}
    shares = []
    for a in ks:
        _, filled, origin = filled_footprint(cells[a])
        for b in ks:
            if a != b and home[a] == home[b]:
                share = float(_inside(cells[b], filled, origin).mean())
                if share >= min_share and not (height is not None and _over_top(height[members[b]], height[members[a]])):
                    shares.append((share, a, b))
                elif a < b and _close_a_ring(cells[a], cells[b]):
                    shares.append((0.0, a, b))
    if not shares:
        return labels
    parent = {k: k for k in ks}

    def find(x: int) -> int:
        while parent[x] != x:
            x = parent[x]
        return x

    for _, a, b in sorted(shares, reverse=True):
        ra, rb = find(a), find(b)
        if ra != rb:
            parent[rb] = ra
    out = labels.copy()
    for k in ks:
        out[members[k]] = find(k)
    return out


def _close_a_ring(a: np.ndarray, b: np.ndarray) -> bool:
    """Whether the occupied cells ``a`` and ``b`` together enclose openings (cells their joint
    :func:`filled_footprint` fills and neither fills alone) of at least ``RING_SHARE`` of it."""
    if np.any(a.min(axis=0) > b.max(axis=0) + 2) or np.any(b.min(axis=0) > a.max(axis=0) + 2):
        return False  # more than a closing apart: they touch nowhere
    closed, filled, origin = filled_footprint(np.vstack([a, b]))
    opening = filled & ~closed
    if opening.sum() < RING_SHARE * filled.sum():
        return False
    cells = np.argwhere(opening) + origin
    alone = np.zeros(len(cells), dtype=bool)
    for part in (a, b):
        _, own, own_origin = filled_footprint(part)
        alone |= _inside(cells, own, own_origin)
    return bool((~alone).sum() >= RING_SHARE * filled.sum())


def _over_top(upper: np.ndarray, lower: np.ndarray) -> bool:
    """Whether nearly all (``OVER_SHARE``) of the heights ``upper`` lie above the top of ``lower``
    (its ``TOP_QUANTILE`` percentile): the one cluster sits on the other."""
    with np.errstate(invalid="ignore"):
        return bool(np.mean(upper > np.nanpercentile(lower, TOP_QUANTILE)) >= OVER_SHARE)
