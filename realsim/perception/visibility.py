"""Which side of a surface patch a scanner saw, for clouds without a viewpoint.

A surface is seen from its outside, so from a point just outside it some rays reach open space
over the scene, while from a point just inside a closed object every ray upward or sideways
meets the object's own surface. Rays march over an occupancy grid of the points (dilated by one
cell so that a sampled surface is closed); between two objects pressed together, the side
facing the other object still sees out through the opening of the crack, the inside does not.
"""

from __future__ import annotations

import numpy as np

__all__ = ["OccupancyGrid", "escape_directions", "visibility_score"]


def escape_directions(azimuths: int = 8, elevations: tuple[float, ...] = (0.0, 30.0, 60.0)) -> np.ndarray:
    """Unit ray directions over the upper hemisphere (horizontal included) and the zenith."""
    dirs = [np.array([0.0, 0.0, 1.0])]
    for e in np.radians(elevations):
        for a in np.linspace(0.0, 2 * np.pi, azimuths, endpoint=False):
            dirs.append(np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)]))
    return np.array(dirs)


class _Occupancy:
    """Occupied cells of a sparse grid, dilated by one cell (a sampled surface is closed), stored
    as dense blocks of 16^3 cells where the surface passes: O(1) look-ups by bit shifts, memory
    that grows with the surface, not with the scene's volume."""

    SHIFT = 4  # blocks of 2^4 = 16 cells a side

    def __init__(self, cells: np.ndarray) -> None:
        near = np.array([(a, b, c) for a in (-1, 0, 1) for b in (-1, 0, 1) for c in (-1, 0, 1)])
        # repeated cells only write their neighbours again: no need to make them distinct
        blocks = _unique_rows(cells >> self.SHIFT)
        blocks = _unique_rows((blocks[:, None, :] + near[None]).reshape(-1, 3))
        # one empty block margin all round: a look-up clipped into it finds nothing
        self.lo = blocks.min(axis=0) - 1
        blocks -= self.lo
        self.top = blocks.max(axis=0) + 1
        self.empty = len(blocks)  # the id of an all-free block, for cells in no stored block
        self.lookup = np.full(tuple(self.top + 1), self.empty, dtype=np.int64)
        self.lookup[blocks[:, 0], blocks[:, 1], blocks[:, 2]] = np.arange(len(blocks))
        self.data = np.zeros((len(blocks) + 1) << (3 * self.SHIFT), dtype=bool)
        # a cell whose neighbours all lie in its own block finds them at fixed offsets in ``data``
        local = cells & ((1 << self.SHIFT) - 1)
        inner = np.all((local >= 1) & (local < (1 << self.SHIFT) - 1), axis=1)
        inner_flat, border = self.flat(cells[inner]), cells[~inner]
        for d in near:
            self.data[inner_flat + ((int(d[0]) << (2 * self.SHIFT)) + (int(d[1]) << self.SHIFT) + int(d[2]))] = True
            self.data[self.flat(border + d)] = True
        # stored blocks the dilation left free read as the empty block: rays skip them whole
        per = 1 << (3 * self.SHIFT)
        used = np.r_[self.data[:-per].reshape(-1, per).any(axis=1), False]
        self.lookup = np.where(used, np.arange(len(used)), self.empty)[self.lookup]

    def flat(self, ijk: np.ndarray) -> np.ndarray:
        """Index of each cell (M, 3) into ``data``; cells in no stored block index the empty block."""
        s, m = self.SHIFT, (1 << self.SHIFT) - 1
        b = np.clip((ijk >> s) - self.lo, 0, self.top)
        ids = self.lookup[b[:, 0], b[:, 1], b[:, 2]]
        return (ids << (3 * s)) | ((ijk[:, 0] & m) << (2 * s)) | ((ijk[:, 1] & m) << s) | (ijk[:, 2] & m)


_DENSE_ROWS = 1 << 25  # distinct rows are marked in a dense grid up to this many cells (32 MB)


def _unique_rows(ijk: np.ndarray) -> np.ndarray:
    """The distinct rows of integer triples (each within 2^20 of the smallest), sorted: marked in
    a dense grid over their bounds where that is small (block indices), else by a key sort."""
    if len(ijk) == 0:
        return ijk
    lo = ijk.min(axis=0)
    d = ijk - lo
    span = d.max(axis=0) + 1
    if int(np.prod(span)) <= _DENSE_ROWS:
        mark = np.zeros(tuple(span), dtype=bool)
        mark[d[:, 0], d[:, 1], d[:, 2]] = True
        return np.argwhere(mark).astype(ijk.dtype, copy=False) + lo
    key = np.unique((d[:, 0] << 42) | (d[:, 1] << 21) | d[:, 2])
    return np.stack([key >> 42, (key >> 21) & 0x1FFFFF, key & 0x1FFFFF], axis=1) + lo


def _block_table(occupied: _Occupancy, origin: np.ndarray, reach_cells: float) -> tuple[np.ndarray, np.ndarray, int]:
    """The block look-up, padded to hold every block a ray from ``origin`` can reach within
    ``reach_cells``, flattened: (table, strides, key offset); a block's id is
    ``table[(ijk >> SHIFT) @ strides + offset]``, with no clipping."""
    margin = int(np.ceil((reach_cells + 2) / (1 << occupied.SHIFT))) + 1
    blocks = np.floor(origin).astype(np.int64) >> occupied.SHIFT
    lo = np.minimum(blocks.min(axis=0, initial=0), occupied.lo) - margin
    hi = np.maximum(blocks.max(axis=0, initial=0), occupied.lo + occupied.top) + margin
    shape = hi - lo + 1
    table = np.full(tuple(shape), occupied.empty, dtype=np.int64)
    at = occupied.lo - lo
    top = occupied.top + 1
    table[at[0]:at[0] + top[0], at[1]:at[1] + top[1], at[2]:at[2] + top[2]] = occupied.lookup
    strides = np.array([shape[1] * shape[2], shape[2], 1])
    return table.ravel(), strides, int(-(lo * strides).sum())


def _escapes(occupied: _Occupancy, origin: np.ndarray, dirs: np.ndarray, cell: float, reach: float,
             table: tuple[np.ndarray, np.ndarray, int] | None = None) -> np.ndarray:
    """Per origin (grid units): how many rays travel ``reach`` without meeting an occupied cell.

    Each ray is sampled at every whole cell length along it; a sample in an empty block jumps to
    the first sample beyond that block (a line leaves a box once), so the samples tested, and the
    counts, are those of a march through every cell. Coordinates are kept as one array per axis
    (an axis the direction does not move along keeps its cell): the rays still free are taken out
    by one index per step. ``table``: :func:`_block_table` of these origins or of a set holding them."""
    last = float(np.floor(reach / cell + 1e-9))
    s, size = occupied.SHIFT, 1 << occupied.SHIFT
    m = size - 1
    flat_table, strides, offset = table if table is not None else _block_table(occupied, origin, last)
    # 32-bit indices where every key and cell fits them (half the memory traffic of 64-bit)
    small = len(flat_table) + abs(offset) < 2**31 and len(occupied.data) < 2**31 and np.abs(origin).max(initial=0) + last < 2**30
    itype = np.int32 if small else np.int64
    flat_table = flat_table.astype(itype, copy=False)
    count = np.zeros(len(origin), dtype=np.int64)
    for d in dirs:
        axes = np.flatnonzero(d)
        live, t = np.arange(len(origin)), np.zeros(len(origin))
        start = {int(a): np.ascontiguousarray(origin[:, a]) for a in axes}
        fixed = {a: np.floor(origin[:, a]).astype(itype) for a in range(3) if a not in start}
        while len(live):  # only the rays still free are marched on
            ijk = []
            for a in range(3):
                if a in fixed:
                    ijk.append(fixed[a])
                    continue
                x = t * d[a]
                x += start[a]
                ijk.append(np.floor(x, out=x).astype(itype))
            block = [c >> s for c in ijk]
            key = block[0] * itype(strides[0])
            key += block[1] * itype(strides[1])
            key += block[2] * itype(strides[2])
            key += itype(offset)
            ids = flat_table[key]
            flat = ids << (3 * s)
            flat |= (ijk[0] & m) << (2 * s)
            flat |= (ijk[1] & m) << s
            flat |= ijk[2] & m
            nxt = t + 1.0
            skip = np.flatnonzero(ids == occupied.empty)
            if len(skip):
                leave = np.full(len(skip), np.inf)
                for axis in axes:  # the first whole step past the block's far face
                    corner = (block[axis][skip] << s).astype(np.int64)
                    if d[axis] > 0:
                        step = np.ceil((corner + size - start[axis][skip]) / d[axis])
                    else:
                        step = np.floor((corner - start[axis][skip]) / d[axis]) + 1.0
                    leave = np.minimum(leave, step)
                nxt[skip] = np.maximum(leave, nxt[skip])
            free = ~occupied.data[flat]
            out = free & (nxt > last)
            count[live[out]] += 1
            keep = np.flatnonzero(free & ~out)
            live, t = live[keep], nxt[keep]
            start = {a: c[keep] for a, c in start.items()}
            fixed = {a: c[keep] for a, c in fixed.items()}
    return count


class OccupancyGrid:
    """The cells (side ``cell``, m) of a point set, dilated by one: built once, cast into many times."""

    def __init__(self, points: np.ndarray, cell: float) -> None:
        self.cell = cell
        self.lo = points.min(axis=0) - 2 * cell
        self.occupied = _Occupancy(np.floor((points - self.lo) / cell).astype(np.int64))


def visibility_score(points: np.ndarray | OccupancyGrid, centroids: np.ndarray, normals: np.ndarray, cell: float, reach: float,
                     offset: float = 2.5, group: float = 0.0, settle: int = 0) -> np.ndarray:
    """Rays escaping from ``offset`` cells in front of each patch minus rays escaping from behind
    it: positive when ``normals`` point to the side the patch was seen from (the more open one;
    a thin wall, a cup's, seen from both sides, faces its more open side). With ``group`` (m),
    patches in one cube of that side whose normals share an octant share one score, that of their
    mean (two sides of a thin wall keep theirs). ``points`` may be an :class:`OccupancyGrid` of
    side ``cell`` built before (one grid for several calls). With ``settle`` > 0 the score is
    clipped to [-settle, settle], and a patch casts no more rays once the directions left cannot
    move it across that bound (the clipped scores are those of casting every ray)."""
    inverse = None
    if group > 0 and len(centroids):
        centroids, normals, inverse = _grouped(centroids, normals, group)
    grid = points if isinstance(points, OccupancyGrid) else OccupancyGrid(points, cell)
    if grid.cell != cell:
        raise ValueError(f"occupancy grid of {grid.cell} m cells scored at {cell} m")
    occupied = grid.occupied
    base = (centroids - grid.lo) / cell
    dirs = escape_directions()
    if settle > 0:
        score = _settled_score(occupied, base + offset * normals, base - offset * normals, dirs, cell, reach, settle)
    else:
        ahead = _escapes(occupied, base + offset * normals, dirs, cell, reach)
        behind = _escapes(occupied, base - offset * normals, dirs, cell, reach)
        score = (ahead - behind).astype(np.float64)
    return score if inverse is None else score[inverse]


def _settled_score(occupied: _Occupancy, ahead: np.ndarray, behind: np.ndarray, dirs: np.ndarray, cell: float,
                   reach: float, settle: int) -> np.ndarray:
    """Escapes from ``ahead`` minus escapes from ``behind``, clipped to [-settle, settle], one
    direction at a time for the origins whose clipped score the directions left can still change."""
    table = _block_table(occupied, np.vstack([ahead, behind]), float(np.floor(reach / cell + 1e-9)))
    score = np.zeros(len(ahead), dtype=np.int64)
    open_ = np.arange(len(ahead))
    for k, d in enumerate(dirs):
        if not len(open_):
            break
        counts = _escapes(occupied, np.vstack([ahead[open_], behind[open_]]), d[None], cell, reach, table)
        score[open_] += counts[: len(open_)] - counts[len(open_):]
        left, now = len(dirs) - 1 - k, score[open_]
        open_ = open_[(now - left < settle) & (now + left > -settle)]
    return np.clip(score, -settle, settle).astype(np.float64)


def _grouped(centroids: np.ndarray, normals: np.ndarray, size: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Mean position and unit mean normal of the patches in each cube of side ``size`` and normal
    octant, and the group of each patch."""
    cube = np.floor((centroids - centroids.min(axis=0)) / size).astype(np.int64)
    octant = (normals > 0).astype(np.int64) @ np.array([1, 2, 4])
    span = cube.max(axis=0) + 1
    key = ((cube[:, 0] * span[1] + cube[:, 1]) * span[2] + cube[:, 2]) * 8 + octant
    _, inverse, count = np.unique(key, return_inverse=True, return_counts=True)
    inverse = inverse.ravel()

    def mean(v: np.ndarray) -> np.ndarray:
        return np.stack([np.bincount(inverse, v[:, i], minlength=len(count)) for i in range(3)], axis=1) / count[:, None]

    n = mean(normals)
    return mean(centroids), n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-12), inverse
