"""What each cluster is: where it stands (support relations, stacks) and whether it is an object
at all (structure, noise or a sheet of a wall)."""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from realsim.perception.footprints import enclosed
from realsim.perception.segment_params import SegmentParams, SegmentResult
from realsim.perception.supervoxels import smallest_eigenvectors
from realsim.scene import SupportPlane

__all__ = ["base_height", "filter_by_size", "sheet_thickness", "support_relations"]


def base_height(heights: np.ndarray, gap: float | None = None, lowest: int = 5) -> float:
    """Height of an object's base: its lowest point that is no stray.

    With a ``gap`` (m; clouds worked on a grid, whose clusters hold a point per cell): the lowest
    point with another of the object's points within ``gap`` above it (a point alone more than a
    cell beneath the rest is a stray); a sparse object has few points near its base, so no count
    of them is its base. Without (a camera view): its ``lowest``-th lowest point.
    A percentile would rise with the object's shape (a bottle lying on its side, a round-bottomed
    pitcher have few points near the support) and call objects standing on the support floating."""
    if len(heights) == 0:
        return float("nan")
    if gap is not None:
        h = np.sort(heights)
        joined = np.flatnonzero(np.diff(h) <= gap)
        return float(h[joined[0]] if len(joined) else h[-1])
    k = min(lowest, len(heights)) - 1
    return float(np.partition(heights, k)[k])


def support_relations(points: np.ndarray, labels: np.ndarray, support: np.ndarray, height: np.ndarray,
                      planes: list[SupportPlane], params: SegmentParams) -> tuple[dict[int, int], dict[int, int | None]]:
    """Which plane each object ultimately stands on and which object (if any) it rests on.

    An object whose base (:func:`base_height`) is more than ``stack_min_height`` above its
    support rests on the lower-based object owning most points right under its bottom points
    (those within 1 cm and a ``base_gap`` of its base; the points under them within 1.5 cm or a
    link, ``jump_distance``, in xy, from 5 cm below to 1 cm above the base): on a coarse grid a
    resting object's lowest cells lie a cell apart, so what is under them is as far. With nothing
    there, a cloud's object rests on the one whose walls rise to its base all around its bottom
    (:func:`_on_unseen_top`): a sweep at table height sees a lying box's walls, not its top.
    """
    k = int(labels.max(initial=0))
    support_of: dict[int, int] = {}
    resting_on: dict[int, int | None] = {o: None for o in range(1, k + 1)}
    if k == 0:
        return support_of, resting_on
    obj = np.flatnonzero(labels > 0)
    owner, pts, h = labels[obj], points[obj], height[obj]
    order = np.argsort(owner, kind="stable")
    starts = np.searchsorted(owner[order], np.arange(1, k + 2))
    members = [order[starts[o - 1]:starts[o]] for o in range(1, k + 1)]
    base = np.array([base_height(h[m], params.base_gap) for m in members])
    tree = cKDTree(pts[:, :2])
    for o in range(1, k + 1):
        m = members[o - 1]
        under = support[obj[m]]
        plane_idx = int(np.bincount(under[under >= 0]).argmax())  # a container's claimed floor has no support of its own
        support_of[o] = planes[plane_idx].id
        if base[o - 1] < params.stack_min_height:
            continue
        bottom = m[h[m] < base[o - 1] + 0.01 + (params.base_gap or 0.0)]
        bottom = bottom[:: max(1, len(bottom) // 300)]
        dist, nn = tree.query(pts[bottom, :2], k=16, distance_upper_bound=max(0.015, params.jump_distance))
        nn = nn[np.isfinite(dist)]
        base_z = pts[bottom, 2].min()
        nn = nn[(owner[nn] != o) & (pts[nn, 2] < base_z + 0.01) & (pts[nn, 2] > base_z - 0.05)]
        nn = nn[base[owner[nn] - 1] < base[o - 1] - 0.005]  # only on something based lower: no cycles
        if len(nn):
            resting_on[o] = int(np.bincount(owner[nn]).argmax())
        elif params.base_gap is not None:
            resting_on[o] = _on_unseen_top(pts, members, base, o, bottom, base_z, params.base_gap)
    # the plane an object ultimately stands on is that of the bottom of its stack
    for o in range(1, k + 1):
        below = resting_on[o]
        while below is not None:
            support_of[o] = support_of[below]
            below = resting_on[below]
    return support_of, resting_on


def _on_unseen_top(pts: np.ndarray, members: list[np.ndarray], base: np.ndarray, o: int, bottom: np.ndarray,
                   base_z: float, cell: float) -> int | None:
    """The object (1-based; None for none) based lower than ``o`` whose points top out at ``o``'s
    base (``base_z``, within 1 cm and a ``cell``) and whose filled footprint on that grid
    (:func:`realsim.perception.footprints.enclosed`) holds most of ``o``'s ``bottom`` points: the
    top ``o`` stands on, unseen between the walls seen around it."""
    best, best_share = None, 0.5
    bottom_cells = np.floor(pts[bottom, :2] / cell).astype(np.int64)
    for k, m in enumerate(members, start=1):
        if k == o or len(m) == 0 or base[k - 1] >= base[o - 1] - 0.005:
            continue
        top = float(pts[m, 2].max())
        if not base_z - 0.01 - cell <= top <= base_z + 0.01:
            continue
        share = float(enclosed(bottom_cells, np.floor(pts[m, :2] / cell).astype(np.int64)).mean())
        if share > best_share:
            best, best_share = k, share
    return best


def sheet_thickness(points: np.ndarray) -> tuple[float, float]:
    """Thickness (2nd to 98th percentile along the thinnest principal axis, m) of a cluster and
    the vertical component of that axis."""
    if len(points) < 4:
        return 0.0, 1.0
    d = points - points.mean(axis=0)
    axis = smallest_eigenvectors((d.T @ d)[None])[0]
    t = np.percentile(d @ axis, [2, 98])
    return float(t[1] - t[0]), float(abs(axis[2]))


def _is_sheet(points: np.ndarray, max_thickness: float, rise: float, band: float) -> bool:
    """Whether a cluster is a sheet of structure: no thicker than ``max_thickness`` and either
    upright (a piece of a wall) or level and rising (``rise``, its top above its support) no more
    than that thickness over the support's ``band`` (a patch of the support's own top, lifted by
    an error of its fitted height: a thing with sides rises above the band by its depth)."""
    thickness, vertical = sheet_thickness(points)
    return thickness < max_thickness and (vertical < 0.5 or rise < band + max_thickness)


def filter_by_size(points: np.ndarray, result: SegmentResult, planes: list[SupportPlane], params: SegmentParams,
                   max_sheet: float | None = None, structure_only: bool = False) -> SegmentResult:
    """Keep the objects a capture can hold: clusters wider or taller than ``max_object_size`` are
    structure (0), ones smaller than ``min_object_size`` or floating above their support with
    nothing under them are noise (-1). The rest are renumbered 1..K in their order.

    With ``max_sheet`` (m; for captures that saw objects from around, never a single view), an
    upright sheet no thicker than that (a piece of a wall or a cabinet side), or a level one lying
    within that of the support's ``min_height`` band (a patch of the support's top), is structure
    too: an object standing on a support shows its sides and top, so its points have depth. With
    ``structure_only`` (a single camera view, where bases are hidden) only structure is removed."""
    labels = result.labels
    k = int(labels.max(initial=0))
    if k == 0:
        return result
    height_of = {p.id: p.height for p in planes}
    fate: dict[int, int] = {}  # 1 object, 0 structure, -1 noise
    for o in range(1, k + 1):
        pts = points[labels == o]
        if len(pts) == 0:
            continue
        extent = float(np.max(pts.max(axis=0) - pts.min(axis=0)))
        ground = height_of.get(result.support_of.get(o, -1), float(pts[:, 2].min()))
        base = base_height(pts[:, 2], params.base_gap) - ground
        if extent > params.max_object_size:
            fate[o] = 0
        elif max_sheet is not None and _is_sheet(pts, max_sheet, float(pts[:, 2].max()) - ground, params.min_height):
            fate[o] = 0
        elif structure_only:
            fate[o] = 1
        elif extent < params.min_object_size or (base > params.stack_min_height and result.resting_on.get(o) is None):
            fate[o] = -1
        else:
            fate[o] = 1
    for _ in range(k):  # what rests on structure is structure, on noise is noise
        changed = False
        for o, f in fate.items():
            below = result.resting_on.get(o)
            if f == 1 and below is not None and fate.get(below, -1) != 1:
                fate[o], changed = fate.get(below, -1), True
        if not changed:
            break
    out = labels.copy()
    for o, f in fate.items():
        if f != 1:
            out[labels == o] = f
    keep = [o for o, f in fate.items() if f == 1]
    new_id = {o: i + 1 for i, o in enumerate(keep)}
    lut = np.zeros(k + 1, dtype=np.int32)
    for o, n in new_id.items():
        lut[o] = n
    obj = out > 0
    out[obj] = lut[out[obj]]
    resting = {new_id[o]: new_id.get(r) if r is not None else None for o, r in result.resting_on.items() if o in new_id}
    return SegmentResult(out.astype(np.int32), {new_id[o]: s for o, s in result.support_of.items() if o in new_id}, resting)
