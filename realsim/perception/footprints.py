"""Footprints: two objects standing on the same support cannot stand in the same place.

A cluster of the 3D segmentation that stands on its support (its base is on it) occupies the
area under it, the convex hull of its points seen from above. When most of another standing
cluster lies inside that area, the two are pieces of one object that the surface-based
segmentation cut apart at a concave crease of its own (a bowl's inside from its outside, the
underside of a lying drill from its body). An object stacked on another does not stand on the
support and is never joined this way.
"""

from __future__ import annotations

import numpy as np

from realsim.geometry import inside_convex_polygon, polygon_and_rectangle

__all__ = ["merge_shared_footprints"]


def merge_shared_footprints(xy: np.ndarray, labels: np.ndarray, support: np.ndarray, standing: np.ndarray,
                            min_share: float = 0.5) -> np.ndarray:
    """Cluster labels (>= 0; -1 none) with standing clusters that share a footprint joined.

    ``xy`` (N, 2) are the points' horizontal positions (m), ``support`` the support index of each
    point, ``standing`` (per label) whether the cluster stands on its support. Two standing
    clusters on the same support join when at least ``min_share`` of one's points lie inside the
    other's convex hull; the larger share first, each pair judged on the clusters as found."""
    ks = [k for k in np.unique(labels[labels >= 0]).tolist() if standing[k]]
    if len(ks) < 2:
        return labels
    members = {k: np.flatnonzero(labels == k) for k in ks}
    home = {k: int(np.bincount(support[m] - support[m].min()).argmax() + support[m].min()) for k, m in members.items()}
    hulls = {}
    for k, m in members.items():
        if len(m) >= 3 and np.ptp(xy[m], axis=0).min() > 0:
            hulls[k] = polygon_and_rectangle(xy[m])[0]
    shares = []
    for a in hulls:
        for b in ks:
            if a != b and home[a] == home[b]:
                share = float(inside_convex_polygon(xy[members[b]], hulls[a]).mean())
                if share >= min_share:
                    shares.append((share, a, b))
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
