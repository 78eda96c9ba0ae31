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


def _escapes(occupied: np.ndarray, shape: np.ndarray, origin: np.ndarray, dirs: np.ndarray, cell: float,
             reach: float) -> np.ndarray:
    """Per origin (grid units): how many rays leave the grid or travel ``reach`` without meeting
    an occupied cell (``occupied``: sorted flat indices of the cells in a grid of ``shape``)."""
    steps = np.arange(0.0, reach / cell + 1e-9, 1.0)
    count = np.zeros(len(origin), dtype=np.int64)
    for d in dirs:
        free = np.ones(len(origin), dtype=bool)
        for t in steps:
            live = np.flatnonzero(free)
            if len(live) == 0:
                break
            ijk = np.floor(origin[live] + t * d).astype(np.int64)
            inside = np.all((ijk >= 0) & (ijk < shape), axis=1)
            key = (ijk[:, 0] * shape[1] + ijk[:, 1]) * shape[2] + ijk[:, 2]
            pos = np.minimum(np.searchsorted(occupied, key), len(occupied) - 1)
            free[live[inside & (occupied[pos] == key)]] = False
        count += free
    return count


def visibility_score(points: np.ndarray, centroids: np.ndarray, normals: np.ndarray, cell: float, reach: float,
                     offset: float = 2.5) -> np.ndarray:
    """Rays escaping from ``offset`` cells in front of each patch minus rays escaping from behind
    it: positive when ``normals`` point to the side the patch was seen from (the more open one;
    a thin wall, a cup's, seen from both sides, faces its more open side)."""
    lo = points.min(axis=0) - 2 * cell
    ijk = np.unique(np.floor((points - lo) / cell).astype(np.int64), axis=0)
    shape = ijk.max(axis=0) + 3
    near = np.array([(a, b, c) for a in (-1, 0, 1) for b in (-1, 0, 1) for c in (-1, 0, 1)])
    cells = (ijk[:, None, :] + near[None]).reshape(-1, 3)  # dilated by one cell: a sampled surface is closed
    occupied = np.unique((cells[:, 0] * shape[1] + cells[:, 1]) * shape[2] + cells[:, 2])
    base = (centroids - lo) / cell
    dirs = escape_directions()
    ahead = _escapes(occupied, shape, base + offset * normals, dirs, cell, reach)
    behind = _escapes(occupied, shape, base - offset * normals, dirs, cell, reach)
    return (ahead - behind).astype(np.float64)
