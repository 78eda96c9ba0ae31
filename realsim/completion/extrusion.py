"""The last resort: the visible hull extruded down to the base, in slabs when the body is not convex.

A banana or a pair of scissors lying flat is far from its convex hull. Cut along its longest
horizontal axis into slabs, each slab's visible hull extruded down is one convex piece; the pieces
are used when together they fill clearly less than the single hull (the body is evidently concave).
"""

from __future__ import annotations

import numpy as np
import trimesh
from scipy.spatial import QhullError

from realsim.completion.hull import fast_hull, trimesh_hull
from realsim.completion.neighbours import clip_convex
from realsim.perception.unique_keys import first_rows


def complete_hull(points: np.ndarray, base_z: float, top_z: float, fast: bool = False,
                  drops: np.ndarray | None = None, floors: np.ndarray | None = None) -> tuple[trimesh.Trimesh, np.ndarray]:
    """The observed points' convex hull extruded down to ``base_z`` (world frame); ``fast``: straight
    from Qhull (collision pieces), else trimesh's triangulation (a surface that gets painted).
    ``drops``: which points may be extruded (the space straight below them was not seen empty; a
    tapered side seen below its top edge stays as seen), all when None or fewer than three.
    ``floors``: per point, the height it is extruded down to (a lying body's underside, see
    :mod:`realsim.completion.underside`), ``base_z`` when None."""
    low = points[:, 2] <= top_z
    kept = points[low]
    chosen = drops[low] if drops is not None and np.count_nonzero(drops[low]) >= 3 else np.ones(len(kept), bool)
    base = kept[chosen]
    base[:, 2] = base_z if floors is None else np.maximum(floors[low][chosen], base_z)
    top = kept.copy()
    top[:, 2] = np.maximum(top[:, 2], base_z + 1e-3)
    cloud = np.vstack([top, base])
    try:
        mesh = fast_hull(cloud) if fast else trimesh_hull(cloud)
    except QhullError:
        lo, hi = cloud.min(axis=0), cloud.max(axis=0)
        hi = np.maximum(hi, lo + 0.005)
        mesh = trimesh.creation.box(bounds=np.vstack([lo, hi]))
    lo, hi = mesh.bounds
    return mesh, np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, base_z])


def complete_slabs(points: np.ndarray, base_z: float, top_z: float, slab: float, max_slabs: int, max_fill: float,
                   whole: trimesh.Trimesh | None = None, min_elongation: float = 2.0,
                   drops: np.ndarray | None = None, floors: np.ndarray | None = None) -> list[trimesh.Trimesh] | None:
    """Convex pieces: the points cut into slabs about ``slab`` long across their principal horizontal
    axis, each slab's hull extruded down (neighbouring slabs share their boundary points). None when
    the object is short or not ``min_elongation`` times longer than wide, or the pieces fill more than ``max_fill`` of the single extruded hull
    (``whole``, when already made). ``drops``, ``floors``: see :func:`complete_hull`."""
    low = points[:, 2] <= top_z
    kept = points[low]
    droppable = drops[low] if drops is not None else np.ones(len(kept), bool)
    floor = floors[low] if floors is not None else np.full(len(kept), base_z)
    if len(kept) < 60:
        return None
    one = first_rows(np.floor(kept / 0.003).astype(np.int64))  # one point per 3 mm cell: the hulls need no more
    kept, droppable, floor = kept[one], droppable[one], floor[one]
    xy = kept[:, :2] - kept[:, :2].mean(axis=0)
    _, _, vt = np.linalg.svd(xy, full_matrices=False)
    s, t = xy @ vt[0], xy @ vt[1]
    lo, hi = float(np.percentile(s, 0.5)), float(np.percentile(s, 99.5))
    if hi - lo < min_elongation * float(np.percentile(t, 99.5) - np.percentile(t, 0.5)):
        return None  # a compact footprint: bends along a length need a long body
    count = int(min(max_slabs, np.floor((hi - lo) / slab)))
    if count < 2:
        return None
    edges = np.linspace(lo, hi, count + 1)
    edges[0], edges[-1] = float(s.min()), float(s.max())
    margin = 0.1 * (edges[1] - edges[0])
    slabs = [(s >= a - margin) & (s <= b + margin) for a, b in zip(edges[:-1], edges[1:])]
    filled = [i for i, inside in enumerate(slabs) if inside.sum() >= 8]
    pieces = []
    for i in filled:
        try:
            pieces.append(complete_hull(kept[slabs[i]], base_z, top_z, fast=True, drops=droppable[slabs[i]], floors=floor[slabs[i]])[0])
        except (QhullError, ValueError):
            continue
    for i, j in zip(filled[:-1], filled[1:]):  # a hidden middle (seen on both sides): bridged between the facing ends
        if j - i < 2:
            continue
        face = ((s >= s[slabs[i]].max() - 2 * margin) & slabs[i]) | ((s <= s[slabs[j]].min() + 2 * margin) & slabs[j])
        try:
            pieces.append(complete_hull(kept[face], base_z, top_z, fast=True, drops=droppable[face], floors=floor[face])[0])
        except (QhullError, ValueError):
            continue
    if len(pieces) < 2:
        return None
    whole = whole if whole is not None else complete_hull(kept, base_z, top_z, drops=droppable, floors=floor)[0]
    if sum(p.volume for p in pieces) > max_fill * whole.volume:
        return None
    return pieces


def complete_bands(points: np.ndarray, base_z: float, top_z: float, bands: int, max_fill: float,
                   whole: trimesh.Trimesh, min_height_share: float = 1.0, drops: np.ndarray | None = None) -> list[trimesh.Trimesh] | None:
    """Convex pieces of an upright body whose profile is not convex (a bottle's shoulder and neck):
    the points cut into ``bands`` height bands (neighbours share their boundary points), each band's
    hull with the points above it that may be extruded (``drops``) carried down through it, the
    lowest one extruded down to ``base_z``. None when the body is lower than
    ``min_height_share`` of its width, or the bands fill more than ``max_fill`` of the single hull ``whole``."""
    kept = points[points[:, 2] <= top_z]
    height = top_z - base_z
    if len(kept) < 60 or height < min_height_share * float(np.max(whole.extents[:2])):
        return None
    droppable = drops[points[:, 2] <= top_z] if drops is not None else np.ones(len(kept), bool)
    edges = np.linspace(base_z, top_z, bands + 1)
    margin = 0.1 * height / bands
    pieces, bounds = [], []
    for i, (a, b) in enumerate(zip(edges[:-1], edges[1:])):
        inside = (kept[:, 2] >= a - margin) & (kept[:, 2] <= b + margin)
        if inside.sum() < 8:
            continue
        above = kept[(kept[:, 2] > b) & droppable]  # what stands above extends down through the band (a box's top face)
        cloud = np.vstack([kept[inside], above * [1, 1, 0] + [0, 0, b], above * [1, 1, 0] + [0, 0, a]])
        try:
            if i == 0:
                pieces.append(complete_hull(cloud, base_z, top_z, fast=True, drops=np.concatenate([droppable[inside], np.ones(2 * len(above), bool)]))[0])
            else:
                pieces.append(fast_hull(cloud))
        except (QhullError, ValueError):
            continue
        bounds.append((a, b))
    if len(pieces) < 2 or _band_volume(pieces, bounds) > max_fill * whole.volume:
        return None
    return pieces


def _band_volume(pieces: list[trimesh.Trimesh], bounds: list[tuple[float, float]]) -> float:
    """Volume of band pieces without the overlaps they share with their neighbours (each cut to its band)."""
    up = np.array([0.0, 0.0, 1.0])
    total = 0.0
    for piece, (a, b) in zip(pieces, bounds):
        low = clip_convex(piece, up, a) if piece.bounds[0][2] < a else piece
        band = clip_convex(low, -up, -b) if low is not None and low.bounds[1][2] > b else low
        total += band.volume if band is not None else 0.0
    return total
