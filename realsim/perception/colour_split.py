"""Colour: two touching objects a sparse cloud cannot tell apart by shape, told apart by colour.

In a cloud whose points lie about as far apart as a small object is wide, a point's normal spans
the object, and the fold where two touching objects meet is not seen; in a finer cloud the contact
cut (:mod:`realsim.perception.contact_cut`) misses contacts that show no fold (flush faces, a
small object pressed into a large one's side). The colours still differ:
a cluster whose points fall into two colour populations, each far apart compared with its own
spread, and each (mostly) one connected piece, is two objects. A print on one object is
rarely one such connected population in each colour of its own; a colour gradient (shading)
is one population, not two. Pieces cut apart by shape whose colours cannot be told apart and
which touch are then one object again (only pieces a colour split left, never two clusters
the shape alone separated).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from realsim.perception.supervoxels import link_components

__all__ = ["colour_classes", "split_by_colour"]

QUANTUM = 1.0 / 64  # a colour difference of one 6-bit level (a phone's coarse colour) is no edge
SEPARATION = 6.0  # two populations whose means are this many robust spreads apart are two colours
COHERENT = 0.6  # the largest connected piece of a colour holds at least this share of it


def colour_classes(colors: np.ndarray, separation: float = SEPARATION) -> np.ndarray | None:
    """Class (0/1) of each colour when they form two populations ``separation`` robust spreads
    apart along the line joining their means (each spread at least one 6-bit level); else None.
    Two-means from a split of the principal colour axis at its mean (deterministic)."""
    c = _unshaded(np.asarray(colors, dtype=np.float64))
    if len(c) < 4:
        return None
    centred = c - c.mean(axis=0)
    axis = np.linalg.eigh(centred.T @ centred)[1][:, -1]
    cls = (centred @ axis > 0).astype(np.int64)
    for _ in range(10):
        if cls.min() == cls.max():
            return None
        means = np.stack([c[cls == 0].mean(axis=0), c[cls == 1].mean(axis=0)])
        new = (((c - means[1]) ** 2).sum(axis=1) < ((c - means[0]) ** 2).sum(axis=1)).astype(np.int64)
        if np.array_equal(new, cls):
            break
        cls = new
    if cls.min() == cls.max():
        return None
    means = np.stack([c[cls == 0].mean(axis=0), c[cls == 1].mean(axis=0)])
    d = means[1] - means[0]
    gap = float(np.linalg.norm(d))
    if gap == 0.0:
        return None
    t = c @ (d / gap)
    spread = max(QUANTUM, *(1.4826 * float(np.median(np.abs(t[cls == i] - np.median(t[cls == i])))) for i in (0, 1)))
    return cls if gap >= separation * spread else None


def _unshaded(colors: np.ndarray) -> np.ndarray:
    """Colours with shading taken out: each scaled to the median brightness (sum of channels) of
    them all, so that light and shadow on one surface are one colour (a dark colour's
    brightness counts as at least three 6-bit levels)."""
    brightness = np.maximum(colors.sum(axis=1), 3 * QUANTUM)
    out: np.ndarray = colors * (np.median(brightness) / brightness)[:, None]
    return out


def _members(labels: np.ndarray, parent: dict[int, int], find: Callable[[int], int], root: int) -> np.ndarray:
    """Mask of the points whose cluster's union-find root is ``root``."""
    return np.isin(labels, [k for k in parent if find(k) == root])


def _distinct(c1: np.ndarray, c2: np.ndarray, separation: float = SEPARATION) -> bool:
    """Whether two sets of (unshaded) colours are two colours: their medians ``separation``
    robust spreads apart along the line joining them (a few mixed cells at a contact do not
    move a median)."""
    m1, m2 = np.median(c1, axis=0), np.median(c2, axis=0)
    gap = float(np.linalg.norm(m2 - m1))
    if gap == 0.0:
        return False
    axis = (m2 - m1) / gap
    spread = max(QUANTUM, *(1.4826 * float(np.median(np.abs((c - m) @ axis))) for c, m in ((c1, m1), (c2, m2))))
    return gap >= separation * spread


def _split_once(colors: np.ndarray, idx: np.ndarray, a: np.ndarray, b: np.ndarray, min_points: int) -> np.ndarray | None:
    """The points of ``idx`` (a cluster; ``a``, ``b`` its internal links as positions in ``idx``)
    to give a new label: the largest connected piece of the colour class not holding the
    cluster's largest piece, when both classes are coherent pieces of at least ``min_points``."""
    cls = colour_classes(colors[idx])
    if cls is None:
        return None
    same = cls[a] == cls[b]
    piece = link_components(len(idx), a[same], b[same])
    best = []
    for i in (0, 1):
        mine = piece[cls == i]
        counts = np.bincount(mine)
        top = int(counts.argmax())
        if counts[top] < min_points or counts[top] < COHERENT * len(mine):
            return None
        best.append((int(counts[top]), top))
    minor = min(best)[1]
    return np.flatnonzero(piece == minor)


def split_by_colour(colors: np.ndarray, labels: np.ndarray, a: np.ndarray, b: np.ndarray, min_points: int) -> np.ndarray:
    """Cluster labels (>= 0; -1 none) with every cluster of two colour objects split (again and
    again: three objects in one cluster), then each piece left by a split joined to the touching
    cluster (linked by ``a``, ``b``) it cannot be told from by colour, most links first."""
    out = labels.copy()
    queue = sorted(np.unique(out[out >= 0]).tolist())
    touched: set[int] = set()
    nxt = int(out.max(initial=-1)) + 1
    while queue:
        k = queue.pop()
        idx = np.flatnonzero(out == k)
        if len(idx) < 2 * min_points:
            continue
        pos = np.full(len(out), -1, dtype=np.int64)
        pos[idx] = np.arange(len(idx))
        inside = (pos[a] >= 0) & (pos[b] >= 0)
        new = _split_once(colors, idx, pos[a[inside]], pos[b[inside]], min_points)
        if new is None:
            continue
        out[idx[new]] = nxt
        touched.update((k, nxt))
        queue += [k, nxt]
        nxt += 1
    return _rejoin(colors, out, a, b, touched)


def _rejoin(colors: np.ndarray, labels: np.ndarray, a: np.ndarray, b: np.ndarray, touched: set[int]) -> np.ndarray:
    """Join each cluster of ``touched`` to linked clusters of one colour with it (most links first)."""
    if not touched:
        return labels
    la, lb = labels[a], labels[b]
    cross = (la >= 0) & (lb >= 0) & (la != lb)
    lo, hi = np.minimum(la[cross], lb[cross]), np.maximum(la[cross], lb[cross])
    pairs, counts = np.unique(np.stack([lo, hi], axis=1), axis=0, return_counts=True)
    parent = {int(k): int(k) for k in np.unique(labels[labels >= 0])}

    def find(x: int) -> int:
        while parent[x] != x:
            x = parent[x]
        return x

    unshaded = _unshaded(colors)
    for i in np.argsort(-counts, kind="stable"):
        p, q = int(pairs[i, 0]), int(pairs[i, 1])
        if p not in touched and q not in touched:
            continue
        rp, rq = find(p), find(q)
        if rp != rq and not _distinct(unshaded[_members(labels, parent, find, rp)], unshaded[_members(labels, parent, find, rq)]):
            parent[rq] = rp
    out = labels.copy()
    valid = out >= 0
    out[valid] = [find(int(k)) for k in out[valid]]
    return out
