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
    as dense blocks of ``block``^3 cells where the surface passes: O(1) look-ups, memory that
    grows with the surface, not with the scene's volume."""

    def __init__(self, cells: np.ndarray, block: int = 16) -> None:
        near = np.array([(a, b, c) for a in (-1, 0, 1) for b in (-1, 0, 1) for c in (-1, 0, 1)])
        cells = np.unique(cells, axis=0)
        blocks = np.unique(cells // block, axis=0)
        blocks = np.unique((blocks[:, None, :] + near[None]).reshape(-1, 3), axis=0)
        self.block, self.lo = block, blocks.min(axis=0)
        blocks -= self.lo
        self.lookup = np.full(tuple(blocks.max(axis=0) + 1), -1, dtype=np.int64)
        self.lookup[blocks[:, 0], blocks[:, 1], blocks[:, 2]] = np.arange(len(blocks))
        self.data = np.zeros((len(blocks), block, block, block), dtype=bool)
        for d in near:
            self.data[self._split(cells + d)] = True

    def _split(self, ijk: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        b = ijk // self.block - self.lo
        local = ijk % self.block
        return self.lookup[b[:, 0], b[:, 1], b[:, 2]], local[:, 0], local[:, 1], local[:, 2]

    def __call__(self, ijk: np.ndarray) -> np.ndarray:
        """Whether each cell (M, 3) is occupied."""
        b = ijk // self.block - self.lo
        inside = np.all((b >= 0) & (b < self.lookup.shape), axis=1)
        hit = np.zeros(len(ijk), dtype=bool)
        if inside.any():
            ids, i, j, k = self._split(ijk[inside])
            known = ids >= 0
            hit[np.flatnonzero(inside)[known]] = self.data[ids[known], i[known], j[known], k[known]]
        return hit


def _escapes(occupied: _Occupancy, origin: np.ndarray, dirs: np.ndarray, cell: float, reach: float) -> np.ndarray:
    """Per origin (grid units): how many rays travel ``reach`` without meeting an occupied cell."""
    steps = np.arange(0.0, reach / cell + 1e-9, 1.0)
    count = np.zeros(len(origin), dtype=np.int64)
    for d in dirs:
        free = np.ones(len(origin), dtype=bool)
        for t in steps:
            live = np.flatnonzero(free)
            if len(live) == 0:
                break
            free[live[occupied(np.floor(origin[live] + t * d).astype(np.int64))]] = False
        count += free
    return count


def visibility_score(points: np.ndarray, centroids: np.ndarray, normals: np.ndarray, cell: float, reach: float,
                     offset: float = 2.5) -> np.ndarray:
    """Rays escaping from ``offset`` cells in front of each patch minus rays escaping from behind
    it: positive when ``normals`` point to the side the patch was seen from (the more open one;
    a thin wall, a cup's, seen from both sides, faces its more open side)."""
    lo = points.min(axis=0) - 2 * cell
    occupied = _Occupancy(np.floor((points - lo) / cell).astype(np.int64))
    base = (centroids - lo) / cell
    dirs = escape_directions()
    ahead = _escapes(occupied, base + offset * normals, dirs, cell, reach)
    behind = _escapes(occupied, base - offset * normals, dirs, cell, reach)
    return (ahead - behind).astype(np.float64)
