"""``np.unique(keys, return_inverse=True)`` for integer keys, by one value sort instead of an argsort.

Grid code (TSDF fusion, voxel grids) groups millions of integer cell keys. numpy's unique sorts
them with an argsort, which is several times slower than sorting values (SIMD sort). When the
key range and the sample count fit in 63 bits together, each key is packed with its sample index
(``key << bits | index``) and the packed values are sorted: the low bits then give the order
(ties in index order, as a stable argsort), the high bits the sorted keys. The result is exactly
numpy's.
"""

from __future__ import annotations

import numpy as np


def unique_inverse(keys: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(sorted unique keys, index of each key's entry in them): ``np.unique(keys.ravel(),
    return_inverse=True)``, faster for large integer arrays."""
    flat = np.asarray(keys).ravel()
    n = len(flat)
    if n == 0 or flat.dtype.kind not in "iu":
        uniq, inverse = np.unique(flat, return_inverse=True)
        return uniq, inverse.ravel()
    lo, hi = int(flat.min()), int(flat.max())
    bits = max(1, (n - 1).bit_length())
    if (hi - lo) >= (1 << (63 - bits)):  # key range and index do not fit one int64 together
        uniq, inverse = np.unique(flat, return_inverse=True)
        return uniq, inverse.ravel()
    packed = np.subtract(flat, lo, dtype=np.int64)
    packed <<= bits
    packed |= np.arange(n, dtype=np.int64)
    packed.sort()
    order = packed & ((1 << bits) - 1)
    packed >>= bits  # now the sorted keys, minus lo
    first = np.empty(n, dtype=bool)
    first[0] = True
    np.not_equal(packed[1:], packed[:-1], out=first[1:])
    uniq = (packed[first] + lo).astype(flat.dtype)
    inverse = np.empty(n, dtype=np.intp)
    inverse[order] = np.cumsum(first) - 1
    return uniq, inverse


def _row_keys(cells: np.ndarray) -> np.ndarray | None:
    """One int64 key per row of the (N, D) integer grid ``cells``, equal exactly for equal rows (the
    rows' mixed-radix numbers over their ranges); None when the ranges do not fit an int64 together."""
    lo, hi = cells.min(axis=0).astype(object), cells.max(axis=0).astype(object)
    spans = [int(h) - int(low) + 1 for low, h in zip(lo, hi)]
    if cells.dtype.kind not in "iu" or int(np.prod(np.array(spans, dtype=object))) >= 1 << 62:
        return None
    flat = np.zeros(len(cells), dtype=np.int64)
    for d, span in enumerate(spans):
        flat *= span
        flat += cells[:, d].astype(np.int64) - int(lo[d])
    return flat


def distinct_rows(cells: np.ndarray) -> int:
    """``len(np.unique(cells, axis=0))`` for (N, D) integer grid cells, by one flat key per row
    when the cells' ranges fit an int64 together (numpy's row unique sorts a structured view)."""
    cells = np.asarray(cells)
    if len(cells) == 0:
        return 0
    keys = _row_keys(cells)
    return len(np.unique(cells, axis=0)) if keys is None else len(np.unique(keys))


def first_rows(cells: np.ndarray) -> np.ndarray:
    """The index of each distinct row's first occurrence in the (N, D) integer grid ``cells``, ascending:
    ``np.sort(np.unique(cells, axis=0, return_index=True)[1])``, by one flat key per row when it fits."""
    cells = np.asarray(cells)
    keys = _row_keys(cells) if len(cells) else None
    return np.sort(np.unique(cells if keys is None else keys, axis=0, return_index=True)[1])
