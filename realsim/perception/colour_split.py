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

Two colours of one hue (a white mug against a black bottle) differ only in brightness, and so
do the lit and the shaded faces of one box. Light depends on which way a surface faces; a
material's brightness does not: two brightness populations are two objects only where points
of both that face the same way still differ that much.

In a camera view the pixels are fine enough to show a print's edge as sharply as an object's,
but also to show where a surface folds or breaks: there, a split is kept only where its
border is a fold or a depth break along most of it (two objects meet so; a print lies on one
smooth surface).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable

import numpy as np

from realsim.forkmap import fork_map
from realsim.perception.contact_cut import CutParams, concave_link_weights
from realsim.perception.supervoxels import link_components

__all__ = ["brightness_classes", "colour_classes", "split_by_colour"]

QUANTUM = 1.0 / 64  # a colour difference of one 6-bit level (a phone's coarse colour) is no edge
SEPARATION = 6.0  # two populations whose means are this many robust spreads apart are two colours
COHERENT = 0.6  # the largest connected piece of a colour holds at least this share of it
SHARED_CLUSTERS = 4  # fewer clusters to try: their first splits are made here (a fork costs about one cluster's try)
BRIGHTNESS_RATIO = 2.0  # two shades of one hue are two materials only when one is this much brighter
MAX_SMOOTH_BORDER = 0.5  # in a view, a split's border links weigh at most this on average (mostly folded)
SHARED_FACING = 0.3  # ... among points of both facing the same ways, at least this share of each
_STEPS = np.array([d for d in itertools.product((-1, 0, 1), repeat=3) if any(d)], dtype=np.float64)
_FACINGS = _STEPS / np.linalg.norm(_STEPS, axis=1, keepdims=True)  # 26 directions a surface can face


def colour_classes(colors: np.ndarray, separation: float = SEPARATION) -> np.ndarray | None:
    """Class (0/1) of each colour when they form two populations ``separation`` robust spreads
    apart along the line joining their means (each spread at least one 6-bit level); else None.
    Two-means from a split of the principal colour axis at its mean (deterministic)."""
    c = _unshaded(np.asarray(colors, dtype=np.float64))
    cls = _two_means(c)
    return cls if cls is not None and _apart(c, cls, separation, QUANTUM) else None


def brightness_classes(colors: np.ndarray, normals: np.ndarray) -> np.ndarray | None:
    """Class (0/1) of each colour when their brightness forms two populations that do not overlap
    (the darker one's 90th percentile below the brighter one's 10th), and points of the two that
    face the same way differ by ``BRIGHTNESS_RATIO`` (:func:`_brighter_facing_alike`); else None.
    ``normals``: the points' outward normals."""
    t = _log_brightness(np.asarray(colors, dtype=np.float64))
    cls = _two_means(t[:, None])
    if cls is None:
        return None
    lo, hi = (0, 1) if np.median(t[cls == 0]) < np.median(t[cls == 1]) else (1, 0)
    if np.percentile(t[cls == lo], 90) >= np.percentile(t[cls == hi], 10):
        return None
    ok = _brighter_facing_alike(t[cls == lo], normals[cls == lo], t[cls == hi], normals[cls == hi])
    return cls if ok else None


def _two_means(values: np.ndarray) -> np.ndarray | None:
    """Two-means classes (0/1) of ``values`` (N, D), from a split of their principal axis at the
    mean (deterministic); None for fewer than 4 values or one class."""
    if len(values) < 4:
        return None
    centred = values - values.mean(axis=0)
    axis = np.linalg.eigh(centred.T @ centred)[1][:, -1]
    cls = (centred @ axis > 0).astype(np.int64)
    for _ in range(10):
        if cls.min() == cls.max():
            return None
        means = np.stack([values[cls == 0].mean(axis=0), values[cls == 1].mean(axis=0)])
        new = (((values - means[1]) ** 2).sum(axis=1) < ((values - means[0]) ** 2).sum(axis=1)).astype(np.int64)
        if np.array_equal(new, cls):
            break
        cls = new
    return None if cls.min() == cls.max() else cls


def _apart(values: np.ndarray, cls: np.ndarray, separation: float, quantum: float) -> bool:
    """Whether the two classes' means are ``separation`` robust spreads (each at least ``quantum``)
    apart along the line joining them."""
    means = np.stack([values[cls == 0].mean(axis=0), values[cls == 1].mean(axis=0)])
    d = means[1] - means[0]
    gap = float(np.linalg.norm(d))
    if gap == 0.0:
        return False
    t = values @ (d / gap)
    spread = max(quantum, *(1.4826 * float(np.median(np.abs(t[cls == i] - np.median(t[cls == i])))) for i in (0, 1)))
    return gap >= separation * spread


def _log_brightness(colors: np.ndarray) -> np.ndarray:
    """Log of each colour's brightness (sum of channels, at least three 6-bit levels)."""
    out: np.ndarray = np.log(np.maximum(colors.sum(axis=1), 3 * QUANTUM))
    return out


def _brighter_facing_alike(dark: np.ndarray, dark_normals: np.ndarray, bright: np.ndarray, bright_normals: np.ndarray) -> bool:
    """Whether log brightnesses ``bright`` exceed ``dark`` by ``BRIGHTNESS_RATIO`` among points
    that face the same ways: points of each are binned by the nearest of 26 directions to their
    normal, and the facings where both sides' points differ that much hold at least
    ``SHARED_FACING`` of each side (a lit top and a shaded side face different ways)."""
    if len(dark) == 0 or len(bright) == 0:
        return False
    bins_d = np.argmax(dark_normals @ _FACINGS.T, axis=1)
    bins_b = np.argmax(bright_normals @ _FACINGS.T, axis=1)
    share_d = np.bincount(bins_d, minlength=len(_FACINGS)) / len(dark)
    share_b = np.bincount(bins_b, minlength=len(_FACINGS)) / len(bright)
    held_d = held_b = 0.0
    for k in np.flatnonzero((share_d > 0) & (share_b > 0)):
        if np.median(bright[bins_b == k]) - np.median(dark[bins_d == k]) >= np.log(BRIGHTNESS_RATIO):
            held_d, held_b = held_d + share_d[k], held_b + share_b[k]
    return min(held_d, held_b) >= SHARED_FACING


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


def _split_once(colors: np.ndarray, normals: np.ndarray | None, idx: np.ndarray, a: np.ndarray, b: np.ndarray,
                min_points: int, points: np.ndarray | None) -> np.ndarray | None:
    """The points of ``idx`` (a cluster; ``a``, ``b`` its internal links as positions in ``idx``)
    to give a new label: the largest connected piece of the colour (else, given ``normals``, the
    brightness) class not holding the cluster's largest piece, when both classes are coherent
    pieces of at least ``min_points`` (and, given ``points``, the piece's border folds)."""
    cls = colour_classes(colors[idx])
    if cls is None and normals is not None:
        cls = brightness_classes(colors[idx], normals[idx])
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
    if points is not None and normals is not None and not _folded_border(points[idx], normals[idx], piece == minor, a, b):
        return None
    return np.flatnonzero(piece == minor)


def _split_cluster(colors: np.ndarray, normals: np.ndarray | None, labels: np.ndarray, k: int, a: np.ndarray, b: np.ndarray,
                   min_points: int, points: np.ndarray | None) -> np.ndarray | None:
    """The points (indices into ``labels``) of cluster ``k`` to give a new label (:func:`_split_once`
    over its internal links among ``a``, ``b``), or None (no split, or too small to hold two objects)."""
    idx = np.flatnonzero(labels == k)
    if len(idx) < 2 * min_points:
        return None
    pos = np.full(len(labels), -1, dtype=np.int64)
    pos[idx] = np.arange(len(idx))
    inside = (pos[a] >= 0) & (pos[b] >= 0)
    new = _split_once(colors, normals, idx, pos[a[inside]], pos[b[inside]], min_points, points)
    return None if new is None else idx[new]


def _folded_border(points: np.ndarray, normals: np.ndarray, side: np.ndarray, a: np.ndarray, b: np.ndarray) -> bool:
    """Whether the links (a, b) across the border of ``side`` fold inward (LCCP, see
    :func:`realsim.perception.contact_cut.concave_link_weights`) along most of it."""
    across = side[a] != side[b]
    if not across.any():
        return False
    smooth = concave_link_weights(points, normals, a[across], b[across], CutParams().fold_angle)
    return bool(smooth.mean() <= MAX_SMOOTH_BORDER)


def split_by_colour(colors: np.ndarray, labels: np.ndarray, a: np.ndarray, b: np.ndarray, min_points: int,
                    normals: np.ndarray | None = None, view_points: np.ndarray | None = None) -> np.ndarray:
    """Cluster labels (>= 0; -1 none) with every cluster of two colour objects split (again and
    again: three objects in one cluster), then each piece left by a split joined to the touching
    cluster (linked by ``a``, ``b``) it cannot be told from by colour, most links first.
    Given the points' outward ``normals``, two brightnesses of one hue count as two colours
    where they differ among points facing alike; given a camera view's ``view_points`` (with
    ``normals``), a split is kept only where its border folds (:func:`_folded_border`)."""
    out = labels.copy()
    queue = sorted(np.unique(out[out >= 0]).tolist())
    # a cluster's points are its own until it is taken from the queue: every first split is made
    # up front, shared with a forked helper; only the pieces a split left are tried again in turn
    initial = list(queue)
    first = dict(zip(initial, fork_map(lambda i: _split_cluster(colors, normals, labels, initial[i], a, b, min_points, view_points),
                                       len(initial), least=SHARED_CLUSTERS)))
    touched: set[int] = set()
    nxt = int(out.max(initial=-1)) + 1
    while queue:
        k = queue.pop()
        new = first.pop(k) if k in first else _split_cluster(colors, normals, out, k, a, b, min_points, view_points)
        if new is None:
            continue
        out[new] = nxt
        touched.update((k, nxt))
        queue += [k, nxt]
        nxt += 1
    return _rejoin(colors, normals, out, a, b, touched)


def _rejoin(colors: np.ndarray, normals: np.ndarray | None, labels: np.ndarray, a: np.ndarray, b: np.ndarray,
            touched: set[int]) -> np.ndarray:
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

    unshaded, logb = _unshaded(colors), _log_brightness(colors)
    for i in np.argsort(-counts, kind="stable"):
        p, q = int(pairs[i, 0]), int(pairs[i, 1])
        if p not in touched and q not in touched:
            continue
        rp, rq = find(p), find(q)
        if rp == rq:
            continue
        mp, mq = _members(labels, parent, find, rp), _members(labels, parent, find, rq)
        if _distinct(unshaded[mp], unshaded[mq]):
            continue
        if normals is not None:
            dark, bright = (mp, mq) if np.median(logb[mp]) < np.median(logb[mq]) else (mq, mp)
            if _brighter_facing_alike(logb[dark], normals[dark], logb[bright], normals[bright]):
                continue
        parent[rq] = rp
    out = labels.copy()
    valid = out >= 0
    out[valid] = [find(int(k)) for k in out[valid]]
    return out
