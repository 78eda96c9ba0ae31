"""A fragment seen beyond an occluder is the hidden continuation of the object on its other side.

A banana lying behind a bottle is seen as two ends; segmentation keeps the larger one as the object
and leaves the other, too small to be an object on its own, as noise. Such a fragment belongs to an
object when the image line from the fragment to the object's nearest pixel crosses only another
object seen nearer than both ends (the camera could not see the middle: it is hidden, not empty),
both stand on the same support, and the gap between them in the world is short. Completion then
sees one body with its middle hidden (see :func:`realsim.completion.extrusion.complete_slabs`).
"""

from __future__ import annotations

import numpy as np
from scipy.ndimage import label as connected
from scipy.spatial import cKDTree

from realsim.completion.view import DepthView
from realsim.scene import Scene, SceneObject

EDGE_PIXELS = 2  # pixels at each end of the line that may be silhouette (mixed depths) rather than the occluder
ABOVE_SUPPORT = 0.005  # m: a fragment's points stand at least this far above the support (not the table's own noise)


def _occluded_between(view: DepthView, a: tuple[int, int], b: tuple[int, int], ids: tuple[int, int], tolerance: float) -> bool:
    """Whether every pixel strictly between pixels ``a`` and ``b`` (row, col) shows an object other than
    ``ids`` nearer the camera than both ends by more than ``tolerance``; at least two such pixels."""
    if view.labels is None:
        return False
    steps = int(np.ceil(np.hypot(b[0] - a[0], b[1] - a[1])))
    if steps < 3:
        return False
    t = np.linspace(0.0, 1.0, steps + 1)[1:-1]
    rows = np.rint(a[0] + t * (b[0] - a[0])).astype(int)
    cols = np.rint(a[1] + t * (b[1] - a[1])).astype(int)
    lab, depth = view.labels[rows, cols], view.depth[rows, cols]
    ends = min(float(view.depth[a]), float(view.depth[b]))
    with np.errstate(invalid="ignore"):
        hidden = (lab > 0) & ~np.isin(lab, ids) & (depth < ends - tolerance)
    first, last = np.argmax(hidden), len(hidden) - 1 - np.argmax(hidden[::-1])  # silhouette pixels (mixed depths) at each end aside
    return bool(hidden.any() and first <= EDGE_PIXELS and last >= len(hidden) - 1 - EDGE_PIXELS and hidden[first:last + 1].all()
                and last - first >= 1)


def _owner(scene: Scene, view: DepthView, frag: np.ndarray, pts: np.ndarray, tolerance: float, max_gap: float,
           pixels: dict[int, tuple[np.ndarray, cKDTree]]) -> SceneObject | None:
    """The object whose hidden continuation the fragment (pixel indices ``frag``, world points ``pts``)
    is, or None: the nearest in the world among those it is seen beside across an occluder only.
    ``pixels``: each object's pixel indices and a tree of their (row, col)."""
    w = view.depth.shape[1]
    fr, fc = np.divmod(frag, w)
    world = scene.points
    assert world is not None
    best, best_gap = None, max_gap
    for obj in scene.objects:
        if obj.support_id is None or obj.id not in pixels:
            continue
        if np.percentile(pts[:, 2], 10) < scene.plane(obj.support_id).height + ABOVE_SUPPORT:
            continue
        mine, tree = pixels[obj.id]
        dist, near = tree.query(np.column_stack([fr, fc]))
        k = int(np.argmin(dist))
        r, c = divmod(int(mine[near[k]]), w)
        gap = float(np.linalg.norm(world[frag[k]] - world[mine[near[k]]]))
        if gap < best_gap and _occluded_between(view, (int(fr[k]), int(fc[k])), (r, c), (obj.id, -1), tolerance):
            best, best_gap = obj, gap
    return best


def join_occluded_fragments(scene: Scene, view: DepthView, tolerance: float, min_points: int = 30, max_gap: float = 0.1) -> list[tuple[int, int]]:
    """Give every noise fragment (a connected set of at least ``min_points`` pixels labelled -1) that
    is the hidden continuation of an object (see :func:`_owner`; ends at most ``max_gap`` apart in the
    world) that object's id in ``scene.labels`` (shared with ``view.labels``); the (object id, pixel
    count) pairs joined."""
    if scene.labels is None or scene.points is None or view.labels is None or not scene.objects:
        return []
    parts, count = connected(view.labels == -1, structure=np.ones((3, 3), bool))
    if count == 0:
        return []
    sizes = np.bincount(parts.ravel())
    large = [k for k in np.flatnonzero(sizes >= min_points) if k > 0]
    if not large:
        return []
    flat = view.labels.ravel()
    w = view.depth.shape[1]
    pixels = {}
    for obj in scene.objects:
        mine = np.flatnonzero(flat == obj.id)
        if len(mine):
            pixels[obj.id] = (mine, cKDTree(np.column_stack(np.divmod(mine, w))))
    joined: list[tuple[int, int]] = []
    for k in large:
        frag = np.flatnonzero(parts.ravel() == k)
        pts = scene.points[frag]
        ok = np.all(np.isfinite(pts), axis=1)
        if ok.sum() < min_points:
            continue
        owner = _owner(scene, view, frag[ok], pts[ok], tolerance, max_gap, pixels)
        if owner is None:
            continue
        scene.labels[frag[ok]] = owner.id
        owner.point_count += int(ok.sum())
        owner.notes.append(f"joined with {int(ok.sum())} points seen beyond an occluder (its hidden continuation)")
        joined.append((owner.id, int(ok.sum())))
    return joined
