"""Which side of a surface patch a scanner saw, for clouds without a viewpoint.

A surface is seen from its outside, so from a point just outside it some rays reach open space
over the scene, while from a point just inside a closed object every ray upward or sideways
meets the object's own surface. Rays march over an occupancy grid of the points (dilated by one
cell so that a sampled surface is closed); between two objects pressed together, the side
facing the other object still sees out through the opening of the crack, the inside does not.
"""

from __future__ import annotations

import numpy as np

__all__ = ["escape_directions", "visibility_score"]


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
        cells = _unique_rows(cells)
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
        for d in near:
            self.data[self._flat(cells + d)] = True

    def _flat(self, ijk: np.ndarray) -> np.ndarray:
        s, m = self.SHIFT, (1 << self.SHIFT) - 1
        b = np.clip((ijk >> s) - self.lo, 0, self.top)
        ids = self.lookup[b[:, 0], b[:, 1], b[:, 2]]
        return (ids << (3 * s)) | ((ijk[:, 0] & m) << (2 * s)) | ((ijk[:, 1] & m) << s) | (ijk[:, 2] & m)

    def __call__(self, ijk: np.ndarray) -> np.ndarray:
        """Whether each cell (M, 3) is occupied."""
        return self.data[self._flat(ijk)]


def _unique_rows(ijk: np.ndarray) -> np.ndarray:
    """The distinct rows of integer triples (each within 2^20 of the smallest), sorted."""
    if len(ijk) == 0:
        return ijk
    lo = ijk.min(axis=0)
    d = ijk - lo
    key = np.unique((d[:, 0] << 42) | (d[:, 1] << 21) | d[:, 2])
    return np.stack([key >> 42, (key >> 21) & 0x1FFFFF, key & 0x1FFFFF], axis=1) + lo


def _escapes(occupied: _Occupancy, origin: np.ndarray, dirs: np.ndarray, cell: float, reach: float) -> np.ndarray:
    """Per origin (grid units): how many rays travel ``reach`` without meeting an occupied cell."""
    steps = np.arange(0.0, reach / cell + 1e-9, 1.0)
    count = np.zeros(len(origin), dtype=np.int64)
    for d in dirs:
        live, start = np.arange(len(origin)), origin
        for t in steps:  # only the rays still free are marched on
            if len(live) == 0:
                break
            free = ~occupied(np.floor(start + t * d).astype(np.int64))
            live, start = live[free], start[free]
        count[live] += 1
    return count


def visibility_score(points: np.ndarray, centroids: np.ndarray, normals: np.ndarray, cell: float, reach: float,
                     offset: float = 2.5, group: float = 0.0) -> np.ndarray:
    """Rays escaping from ``offset`` cells in front of each patch minus rays escaping from behind
    it: positive when ``normals`` point to the side the patch was seen from (the more open one;
    a thin wall, a cup's, seen from both sides, faces its more open side). With ``group`` (m),
    patches in one cube of that side whose normals share an octant share one score, that of their
    mean (two sides of a thin wall keep theirs)."""
    inverse = None
    if group > 0 and len(centroids):
        centroids, normals, inverse = _grouped(centroids, normals, group)
    lo = points.min(axis=0) - 2 * cell
    occupied = _Occupancy(np.floor((points - lo) / cell).astype(np.int64))
    base = (centroids - lo) / cell
    dirs = escape_directions()
    ahead = _escapes(occupied, base + offset * normals, dirs, cell, reach)
    behind = _escapes(occupied, base - offset * normals, dirs, cell, reach)
    score = (ahead - behind).astype(np.float64)
    return score if inverse is None else score[inverse]


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
