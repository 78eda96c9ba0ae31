"""The cheapest plane cut of a piece: the least share of its inside lost plus a price per bad sample left.

Every direction's projections of the inside points are one row of ``pt`` (N, n), a transposed view
(no copy): the directions still open are gathered into contiguous rows before their rows are sorted. A ``bound`` (the cost of a cut found otherwise, which this one has
to beat or tie) skips the cuts and directions that cannot reach it; the cuts that can are counted
exactly as without it (the same comparisons, shifted or not), so the search returns what the full
search returns whenever that costs no more than the bound.
"""

from __future__ import annotations

import numpy as np

PRUNE_SLACK = 4  # inside points of slack when skipping cut directions that cannot win (see open_columns)
MISS_WEIGHT = 20.0  # leaving this share of the surface seen through costs as much as losing the whole piece, inverted
SORT_ROWS = 8  # more cuts than this per direction are counted in one sorted array (see kept_by_sorting)


def kept_by_sorting(pt: np.ndarray, cuts: np.ndarray, shift: np.ndarray) -> np.ndarray:
    """Per cut (M, K) how many of the projections ``pt`` (M, n) of its row lie at or below it: the rows
    set apart by ``shift`` (M, ascending, wider apart than any value) in one sorted array."""
    sub = np.sort(pt, axis=1)
    found = np.searchsorted((sub + shift[:, None]).ravel(), (cuts + shift[:, None]).ravel(), side="right")
    return found.reshape(cuts.shape) - pt.shape[1] * np.arange(len(cuts))[:, None]


def _count(below: np.ndarray) -> np.ndarray:
    """How many of each row's entries (along the last axis) of the boolean ``below`` are true: summed as
    bytes into 16 bits when no sum can overflow them (twice as fast as numpy's default 64-bit sum)."""
    small = below.shape[-1] < 2**15
    return np.add.reduce(below.view(np.int8), axis=-1, dtype=np.int16 if small else np.int64)


def _kept(pt: np.ndarray, cuts: np.ndarray, shift: np.ndarray | None) -> np.ndarray:
    """Per cut (M, K) how many projections of its row ``pt`` (M, n) lie at or below it, both moved by
    ``shift`` (M) first when given (the comparison :func:`kept_by_sorting` makes)."""
    if shift is not None and cuts.shape[1] > SORT_ROWS:
        return kept_by_sorting(pt, cuts, shift)
    if shift is not None:
        pt, cuts = pt + shift[:, None], cuts + shift[:, None]
    if cuts.shape[1] == 1:
        return _count(pt <= cuts)[:, None]
    return _count(pt[:, None, :] <= cuts[:, :, None])


def open_columns(pt: np.ndarray, cuts: np.ndarray, first: np.ndarray, best: float, samples: int) -> np.ndarray:
    """The directions (rows of ``pt``, (N, n)) whose cuts ``cuts`` (K, N, ascending) may cost no more
    than ``best``: the lowest (``first``, its cost per direction) or a higher one, which keeps at most
    what the highest keeps and leaves a bad sample more (MISS_WEIGHT / samples). The others cannot hold
    the least cost (PRUNE_SLACK points of slack for rounding), so their counts are not made."""
    n = pt.shape[1]
    slack = PRUNE_SLACK / max(n, 1)
    reach = 1.0 - _count(pt <= cuts[-1][:, None]) / max(n, 1) + MISS_WEIGHT / samples
    return np.flatnonzero((first <= best + slack) | (reach <= best + slack))


def best_cut(inside: np.ndarray, bad: np.ndarray, normals: np.ndarray, samples: int,
             keep: np.ndarray | None = None, bound: float = np.inf) -> tuple[np.ndarray, float, float]:
    """The cut (normal, offset: keep ``n . x <= c``) minimising the share of ``inside`` lost plus
    MISS_WEIGHT times the share of the ``samples`` surface samples left seen through (``bad``), and
    that cost (the cost of no cut when no cut is better). Only cuts leaving few enough bad samples to
    beat the best cut that leaves none are weighed (leaving each costs MISS_WEIGHT / samples); with
    ``bound``, only cuts that may cost no more than it (the answer is exact when one does)."""
    pb = bad @ normals.T
    projections = inside @ normals.T
    pt = projections.T  # (N, n), a view: the open rows are gathered contiguous before sorting
    count = max(pt.shape[1], 1)
    low_pi, high_pi = projections.min(axis=0), projections.max(axis=0)  # along the contiguous rows: the same values
    width = 1e-6 * np.maximum(high_pi - low_pi, 1e-9)
    limit = (keep @ normals.T).max(axis=0)[None, :] if keep is not None and len(keep) else None
    none = MISS_WEIGHT * len(bad) / samples

    def costs(cuts: np.ndarray, columns: np.ndarray | None = None, shift: np.ndarray | None = None) -> np.ndarray:
        """Each cut's cost (cuts (K, N)); only the ``columns`` (default all) are counted, the others cost inf."""
        if columns is None:
            cost, kept = np.empty(cuts.shape), _kept(pt, cuts.T, shift)
            cost[:] = 1.0 - kept.T / count + MISS_WEIGHT * np.arange(len(cuts))[:, None] / samples
        else:
            cost, kept = np.full(cuts.shape, np.inf), _kept(pt[columns], cuts.T[columns], shift)
            cost[:, columns] = 1.0 - kept.T / count + MISS_WEIGHT * np.arange(len(cuts))[:, None] / samples
        return cost if limit is None else np.where(cuts >= limit, cost, np.inf)  # leave every ``keep`` point

    first = costs(pb.min(axis=0)[None, :] - width)
    best = min(float(first.min()), none)
    rows = min(len(pb), int(np.floor(best * samples / MISS_WEIGHT)) + 1)
    if rows > 1:
        low = np.partition(pb, rows - 1, axis=0)[:rows] if rows < len(pb) else pb
        cuts = np.sort(low, axis=0) - width
        shift = None
        if rows > SORT_ROWS:  # the full search counts these rows in one sorted array: the same comparisons
            span = 2.0 * max(float(high_pi.max()), -float(low_pi.min()), float(np.abs(cuts).max())) + 1.0
            shift = span * np.arange(len(pt))
        if bound < best:  # a cut leaving k bad samples costs at least MISS_WEIGHT k / samples
            cuts = cuts[:max(1, min(rows, int(np.floor(bound * samples / MISS_WEIGHT)) + 2))]
        columns = open_columns(pt, cuts, first[0], min(best, bound), samples)
        cost = costs(cuts, columns, None if shift is None else shift[columns])
    else:
        cost = first
    k, j = np.unravel_index(int(np.argmin(cost)), cost.shape)
    if cost[k, j] >= none:
        return normals[0], np.inf, none
    cut = np.sort(pb[:, j])[k] - width[j]
    return normals[j], float(cut), float(cost[k, j])
