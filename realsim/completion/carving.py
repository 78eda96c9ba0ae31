"""Free-space carving: a completed convex shape loses every voxel the camera saw through."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh
from scipy.spatial import QhullError, cKDTree

from realsim.completion.hull import solid_hull, trimesh_hull, volume
from realsim.completion.params import CompletionParams
from realsim.completion.view import DepthView

Voxels = tuple[float, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]  # step, column xy, voxel column, centre, free, ends


def _columns(mesh: trimesh.Trimesh, step: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Vertical voxel columns inside the convex ``mesh``: xy centres (M, 2) and their z range.

    A convex solid is the intersection of its face half-spaces ``n.x <= d``: per column, faces
    facing up bound it from above, faces facing down from below, vertical faces cut the footprint.
    """
    lo, hi = mesh.bounds
    gx, gy = (np.arange(a + step / 2, b, step) for a, b in zip(lo[:2], hi[:2]))
    xy = np.stack(np.meshgrid(gx, gy, indexing="ij"), axis=-1).reshape(-1, 2)
    n = mesh.face_normals
    d = np.einsum("fk,fk->f", n, mesh.triangles[:, 0, :])
    products = (xy @ n[:, :2].T).T  # (F, M), one face's products per row

    def rhs(faces: np.ndarray) -> np.ndarray:  # (faces, M): n_z z <= rhs, made in place in its own copy
        out = products[faces]
        return np.asarray(np.subtract(d[faces][:, None], out, out=out))

    up, down, side = n[:, 2] > 1e-6, n[:, 2] < -1e-6, np.abs(n[:, 2]) <= 1e-6
    z_top = np.min(np.divide(top := rhs(up), n[up, 2][:, None], out=top), axis=0) if up.any() else np.full(len(xy), hi[2])
    z_bot = np.max(np.divide(bot := rhs(down), n[down, 2][:, None], out=bot), axis=0) if down.any() else np.full(len(xy), lo[2])
    ok = (z_top > z_bot) & (np.all(rhs(side) >= -1e-9, axis=0) if side.any() else True)
    return xy[ok], np.maximum(z_bot[ok], lo[2]), np.minimum(z_top[ok], hi[2])


def _voxels(mesh: trimesh.Trimesh, view: DepthView, params: CompletionParams, own: int | None, base_z: float,
            surface_ends: bool = False) -> Voxels:
    """Voxelize the convex ``mesh`` and test every voxel against the free space: the voxel step,
    column xy centres (M, 2), each voxel's column and centre, which voxels are free (seen through;
    with ``carve_over_support`` also above the support at ``base_z`` where the camera saw it: :meth:`DepthView.over_support`),
    and each voxel's (low, high) ends: with ``surface_ends`` a column's first voxel reaches down
    to the mesh's underside there (a round underside stays round, not its lowest voxel centres laid
    on the support; nothing was seen of it), else (and every other voxel) its centre."""
    lo, hi = mesh.bounds
    step = float(np.clip(np.max(hi - lo) / params.carve_voxels, 0.002, 0.005))
    xy, col, cells, ends = _cells(mesh, step, surface_ends)
    free = view.seen_through(cells, params.carve_tolerance, own, footprint=False)
    return step, xy, col, cells, (free | view.over_support(cells, base_z)) if params.carve_over_support else free, ends


def _cells(mesh: trimesh.Trimesh, step: float, surface_ends: bool = False) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Voxel centres inside the convex ``mesh``: column xy centres (M, 2), each voxel's column and
    centre, and its (low, high) ends (N, 2): the centre's height, or with ``surface_ends`` the
    mesh's bottom for its column's first voxel (the top is the seen points', which the hulls take)."""
    xy, z_bot, z_top = _columns(mesh, step)
    if len(xy) == 0:
        return xy, np.zeros(0, np.int64), np.zeros((0, 3)), np.zeros((0, 2))
    counts = np.maximum(np.ceil((z_top - z_bot) / step).astype(np.int64), 1)
    col = np.repeat(np.arange(len(xy)), counts)
    k = np.arange(len(col)) - np.repeat(np.cumsum(counts) - counts, counts)
    z = np.minimum(z_bot[col] + (k + 0.5) * step, z_top[col])
    ends = np.column_stack([z, z])
    if surface_ends:
        ends[:, 0] = np.where(k == 0, z_bot[col], z)
    return xy, col, np.column_stack([xy[col], z]), ends


def voxel_centres(mesh: trimesh.Trimesh, step: float) -> np.ndarray:
    """(N, 3) centres of the ``step`` voxels inside the convex ``mesh``."""
    return _cells(mesh, step)[2]


def _column_extremes(n_columns: int, col: np.ndarray, z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Lowest and highest kept voxel of each column (inf / -inf where none is kept)."""
    z_lo, z_hi = np.full(n_columns, np.inf), np.full(n_columns, -np.inf)
    np.minimum.at(z_lo, col, z)
    np.maximum.at(z_hi, col, z)
    return z_lo, z_hi


@dataclass
class Carving:
    """A convex shape carved by the free space: the share of its voxels seen through, the hull of what
    is left (the shape itself when too little is free), and that as convex tiles (when much is free)."""

    fraction: float
    hull: trimesh.Trimesh
    tiles: list[trimesh.Trimesh] | None = None


def carve(mesh: trimesh.Trimesh, view: DepthView, base_z: float, observed: np.ndarray, params: CompletionParams,
          own: int | None = None, tiles: bool = True, surface_ends: bool = False, outline: np.ndarray | None = None) -> Carving:
    """Voxelize ``mesh`` once: its carved hull (see :func:`carve_free_space`) and, when ``tiles`` and
    the body is evidently not convex (at least ``tile_min_fraction`` is seen through, or the carved
    hull fills ``carve_min_fraction`` of the voxels again with space the camera saw through), its
    tiles (see :func:`carve_to_tiles`; only the voxel columns under the ``outline``, see :func:`under_outline`).
    ``surface_ends``: see :func:`_voxels`."""
    voxels = _voxels(mesh, view, params, own, base_z, surface_ends)
    fraction = float(voxels[4].mean()) if len(voxels[4]) else 0.0
    if fraction < params.carve_min_fraction or fraction > 0.9:
        return Carving(fraction, mesh)
    hull = _carved_hull(mesh, voxels, base_z, observed, not surface_ends)
    many = tiles and (fraction >= params.tile_min_fraction or (params.tile_when_refilled and _refilled(hull, voxels) >= params.carve_min_fraction))
    if many and outline is not None and params.tile_outline_steps > 0:
        step, xy, col, cells, free, ends = voxels
        voxels = (step, xy, col, cells, free | ~under_outline(xy, outline, params.tile_outline_steps * step)[col], ends)
    pieces = _tiles(voxels, base_z, observed, params) if many else None
    return Carving(fraction, hull, pieces)


def under_outline(xy: np.ndarray, outline: np.ndarray, reach: float) -> np.ndarray:
    """Which voxel columns (centres ``xy``, (M, 2)) have a point of the body's ``outline`` (its seen and
    completed points, (N, 2+)) within ``reach`` horizontally. A body lying on its support seen from
    above reaches no farther than its outline from above: a column beyond it is space the body hides
    from the camera (behind a thin blade, inside a loop, between a handle and a barrel), not body."""
    if not len(xy) or not len(outline):
        return np.zeros(len(xy), bool)
    distance, _ = cKDTree(np.asarray(outline)[:, :2]).query(xy, distance_upper_bound=reach)
    return np.asarray(np.isfinite(distance))


def _refilled(hull: trimesh.Trimesh, voxels: Voxels) -> float:
    """The share of the seen-through voxels that the carved ``hull`` fills again (only those are tested)."""
    free = voxels[4]
    return float(np.count_nonzero(_inside_convex(hull, voxels[3][free]))) / len(free)


def _inside_convex(mesh: trimesh.Trimesh, points: np.ndarray) -> np.ndarray:
    """Which ``points`` lie inside the convex ``mesh`` (behind every face plane)."""
    n = mesh.face_normals
    d = np.einsum("fk,fk->f", n, mesh.triangles[:, 0, :])
    return np.asarray(np.all(points @ n.T <= d + 1e-9, axis=1))


def _carved_hull(mesh: trimesh.Trimesh, voxels: Voxels, base_z: float, observed: np.ndarray, snap: bool = True) -> trimesh.Trimesh:
    step, xy, col, cells, free, ends = voxels
    z_lo = _column_extremes(len(xy), col[~free], ends[~free, 0])[0]
    z_hi = _column_extremes(len(xy), col[~free], ends[~free, 1])[1]
    good = np.isfinite(z_lo)  # the lowest and highest kept voxel of each column bound the hull
    kept = np.vstack([np.column_stack([xy[good], z_lo[good]]), np.column_stack([xy[good], z_hi[good]]), observed])
    low = kept[:, 2] < base_z + step  # near the base: seen points, and voxel centres (unless ``snap`` is off: surface ends), stand for a body reaching down to it
    low[: 2 * np.count_nonzero(good)] &= snap
    kept[low, 2] = base_z
    try:
        hull: trimesh.Trimesh = trimesh_hull(kept)  # trimesh's triangulation: the painted surface
        return hull
    except QhullError:
        return mesh


def carve_free_space(mesh: trimesh.Trimesh, view: DepthView, base_z: float, observed: np.ndarray,
                     params: CompletionParams, own: int | None = None, surface_ends: bool = False) -> tuple[trimesh.Trimesh, float]:
    """The convex ``mesh`` without the space the camera saw through (the hull of the voxels left and
    the ``observed`` surface points), and the share of voxels carved; ``mesh`` itself when less than
    ``carve_min_fraction`` is free. ``surface_ends``: see :func:`_voxels`."""
    result = carve(mesh, view, base_z, observed, params, own, tiles=False, surface_ends=surface_ends)
    return result.hull, result.fraction


def carve_to_tiles(mesh: trimesh.Trimesh, view: DepthView, base_z: float, observed: np.ndarray,
                   params: CompletionParams, own: int | None = None) -> tuple[list[trimesh.Trimesh] | None, float]:
    """What is left of the convex ``mesh`` after carving the free space, as convex pieces: the kept
    voxels grouped in cubic tiles (at least ``carve_tile`` wide, about ``max_pieces`` of them; each
    tile takes one more voxel layer of its neighbours so the pieces meet), each tile the hull of its
    voxel centres and the ``observed`` points in it. A hull of everything kept would fill the free
    space again wherever the body is not convex (under a pitcher's handle). None (and the share
    carved) when less than ``carve_min_fraction`` is free."""
    voxels = _voxels(mesh, view, params, own, base_z)
    fraction = float(voxels[4].mean()) if len(voxels[4]) else 0.0
    if fraction < params.carve_min_fraction or fraction > 0.9:
        return None, fraction
    return _tiles(voxels, base_z, observed, params), fraction


def _tiles(voxels: Voxels, base_z: float, observed: np.ndarray, params: CompletionParams) -> list[trimesh.Trimesh] | None:
    step, xy, col, cells, free, _ = voxels
    kept, kept_col = cells[~free].copy(), col[~free]
    kept[kept[:, 2] < base_z + step, 2] = base_z  # voxel centres within a step of the base stand on it: separate convex tiles, each round underneath, would rock (a tiled banana rolled 21 mm while settling)
    tile = max(params.carve_tile, float(np.cbrt(np.prod(np.ptp(kept, axis=0) + step) / params.max_pieces)))
    origin = kept.min(axis=0) - step
    shifts = np.array([[i, j, k] for i in (0, 1) for j in (0, 1) for k in (0, 1)], float) * step
    grid = np.vstack([np.floor((kept - shift - origin) / tile) for shift in shifts]).astype(np.int64)
    dims = grid.max(axis=0) + 1
    tiles = np.ravel_multi_index(grid.T, dims)
    index = np.tile(np.arange(len(kept)), len(shifts))
    # a tile's hull needs only the lowest and highest of its voxels in each column
    groups, inverse = np.unique(tiles * len(xy) + kept_col[index], return_inverse=True)
    z_lo, z_hi = np.full(len(groups), np.inf), np.full(len(groups), -np.inf)
    np.minimum.at(z_lo, inverse, kept[index, 2])
    np.maximum.at(z_hi, inverse, kept[index, 2])
    group_tile, group_xy = groups // len(xy), xy[groups % len(xy)]
    starts = np.flatnonzero(np.r_[True, group_tile[1:] != group_tile[:-1]])  # groups are sorted by tile
    obs_grid = np.floor((observed - origin) / tile).astype(np.int64) if len(observed) else np.zeros((0, 3), np.int64)
    obs_inside = np.all((obs_grid >= 0) & (obs_grid < dims), axis=1)
    obs_tiles = np.full(len(observed), -1, np.int64)
    obs_tiles[obs_inside] = np.ravel_multi_index(obs_grid[obs_inside].T, dims)
    pieces = []
    for start, end in zip(starts, np.r_[starts[1:], len(groups)]):
        g = slice(start, end)
        pts = np.vstack([np.column_stack([group_xy[g], z_lo[g]]), np.column_stack([group_xy[g], z_hi[g]]),
                         observed[obs_tiles == group_tile[start]]])
        piece = solid_hull(pts)
        if piece is not None:
            pieces.append(piece)
    return pieces or None


def carve_pieces(pieces: list[trimesh.Trimesh], view: DepthView, base_z: float, params: CompletionParams,
                 own: int | None = None) -> tuple[list[trimesh.Trimesh], float]:
    """Each convex piece of a shape carved by the free space (pieces left empty dropped), and the
    volume share carved; with ``carve_surface_ends`` each keeps its completed underside (see :func:`_voxels`)."""
    out, before, after = [], 0.0, 0.0
    for piece in pieces:
        carved, fraction = carve_free_space(piece, view, base_z, np.zeros((0, 3)), params, own, params.carve_surface_ends)
        before += volume(piece)
        if fraction > 0.9:
            continue  # all but seen through
        out.append(carved)
        after += volume(carved)
    if not out:
        return pieces, 0.0
    return out, max(0.0, 1.0 - after / before) if before > 0 else 0.0
