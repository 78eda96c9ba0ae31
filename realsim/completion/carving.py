"""Free-space carving: a completed convex shape loses every voxel the camera saw through."""

from __future__ import annotations

import numpy as np
import trimesh
from scipy.spatial import QhullError

from realsim.completion.params import CompletionParams
from realsim.completion.view import DepthView


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
    rhs = d[None, :] - xy @ n[:, :2].T  # (M, F): n_z z <= rhs
    up, down, side = n[:, 2] > 1e-6, n[:, 2] < -1e-6, np.abs(n[:, 2]) <= 1e-6
    z_top = np.min(rhs[:, up] / n[up, 2], axis=1) if up.any() else np.full(len(xy), hi[2])
    z_bot = np.max(rhs[:, down] / n[down, 2], axis=1) if down.any() else np.full(len(xy), lo[2])
    ok = (z_top > z_bot) & (np.all(rhs[:, side] >= -1e-9, axis=1) if side.any() else True)
    return xy[ok], np.maximum(z_bot[ok], lo[2]), np.minimum(z_top[ok], hi[2])


def carve_free_space(mesh: trimesh.Trimesh, view: DepthView, base_z: float, observed: np.ndarray,
                     params: CompletionParams, own: int | None = None) -> tuple[trimesh.Trimesh, float]:
    """The convex ``mesh`` without the space the camera saw through (the hull of the voxels left and
    the ``observed`` surface points), and the share of voxels carved; ``mesh`` itself when less than
    ``carve_min_fraction`` is free."""
    lo, hi = mesh.bounds
    step = float(np.clip(np.max(hi - lo) / params.carve_voxels, 0.002, 0.005))
    xy, z_bot, z_top = _columns(mesh, step)
    if len(xy) == 0:
        return mesh, 0.0
    counts = np.maximum(np.ceil((z_top - z_bot) / step).astype(np.int64), 1)
    col = np.repeat(np.arange(len(xy)), counts)
    k = np.arange(len(col)) - np.repeat(np.cumsum(counts) - counts, counts)
    cells = np.column_stack([xy[col], np.minimum(z_bot[col] + (k + 0.5) * step, z_top[col])])
    free = view.seen_through(cells, params.carve_tolerance, own)
    fraction = float(free.mean())
    if fraction < params.carve_min_fraction or fraction > 0.9:
        return mesh, fraction
    kept_col, kept_z = col[~free], cells[~free, 2]
    extremes = []  # the lowest and highest kept voxel of each column bound the hull
    for pick in (np.minimum, np.maximum):
        z = np.full(len(xy), np.nan)
        if pick is np.minimum:
            z[:] = np.inf
            np.minimum.at(z, kept_col, kept_z)
        else:
            z[:] = -np.inf
            np.maximum.at(z, kept_col, kept_z)
        good = np.isfinite(z)
        extremes.append(np.column_stack([xy[good], z[good]]))
    kept = np.vstack([*extremes, observed])
    kept[kept[:, 2] < base_z + step, 2] = base_z
    try:
        carved = trimesh.convex.convex_hull(kept)
    except QhullError:
        return mesh, fraction
    return carved, fraction


def carve_pieces(pieces: list[trimesh.Trimesh], view: DepthView, base_z: float, params: CompletionParams,
                 own: int | None = None) -> tuple[list[trimesh.Trimesh], float]:
    """Each convex piece of a shape carved by the free space (pieces left empty dropped), and the
    volume share carved."""
    out, before, after = [], 0.0, 0.0
    for piece in pieces:
        carved, fraction = carve_free_space(piece, view, base_z, np.zeros((0, 3)), params, own)
        before += piece.volume
        if fraction > 0.9:
            continue  # all but seen through
        out.append(carved)
        after += carved.volume
    if not out:
        return pieces, 0.0
    return out, max(0.0, 1.0 - after / before) if before > 0 else 0.0
