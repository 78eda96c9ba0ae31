"""The inside of a container seen through its opening is a piece of the container.

Looking into a mug, a bowl or a pitcher, a camera sees the outer wall up to the front rim and,
beyond the rim, the inner wall and floor: a surface seen from its concave side, which the rim hides
along their common image border and which meets the outer wall only at the sides of the rim, over
a lip a pixel or two wide. The merge of convex connections cannot join them (the inner surface
curves the other way and the lip holds too few links), yet no other object is shaped so: a segment
whose visible surface bends toward its own centre (seen from inside), hidden by a neighbour it also
touches, is that neighbour's inside.

A wide container seen from above (a bowl) shows the other case: its inside runs up to the rim, and
the rim, flaring out, hides the top of the outer wall below it; the two meet at no pixel. A segment
hidden by an inside along its border, in front of it (nearer the camera than the inside's middle) and
under its opening (in plan, within the hull of the inside) is that container's outer wall: another
object hidden by a container stands behind it or beside it.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import ConvexHull, QhullError

from realsim.geometry import inside_convex_polygon
from realsim.perception.supervoxels import grid_links, link_components

__all__ = ["concavity", "join_insides", "join_outsides"]


def concavity(labels: np.ndarray, points: np.ndarray, normals: np.ndarray) -> np.ndarray:
    """Per segment (``labels`` >= 0), the mean distance its centroid lies ahead of its points along
    their normals (``normals`` pointing toward the camera), over its RMS radius: > 0 for a surface
    seen from its concave side, < 0 from its convex side, 0 for a plane."""
    n = int(labels.max(initial=-1)) + 1
    count = np.maximum(np.bincount(labels, minlength=n), 1)
    cent = np.stack([np.bincount(labels, points[:, i], minlength=n) for i in range(3)], axis=1) / count[:, None]
    d = cent[labels] - points
    ahead = np.bincount(labels, np.nan_to_num((d * normals).sum(axis=1)), minlength=n) / count
    radius = np.sqrt(np.bincount(labels, (d * d).sum(axis=1), minlength=n) / count)
    out: np.ndarray = ahead / np.maximum(radius, 1e-9)
    return out


def join_insides(labels: np.ndarray, grid_shape: tuple[int, int], points: np.ndarray, normals: np.ndarray,
                 depth: np.ndarray, min_jump: float, min_concavity: float, min_share: float) -> np.ndarray:
    """``labels`` (segments >= 0 over a row-major ``grid_shape`` image, < 0 elsewhere) with each
    segment seen from inside (:func:`concavity` over ``min_concavity``) joined to the neighbour whose
    rim holds at least ``min_share`` of its image outline: over the neighbour pairs leaving the
    segment, those where that neighbour's point hides it (more than ``min_jump`` nearer along the
    view, ``depth``) or touches it (within ``min_jump`` in space), provided it both hides and touches
    it somewhere. ``normals`` point toward the camera (NaN where unknown). Segments renumbered 0..K-1, the
    rest unchanged."""
    n = int(labels.max(initial=-1)) + 1
    if n < 2:
        return labels
    inner, outer, hides, touching, outline = _border(labels, grid_shape, points, depth, min_jump)
    rim = (inner >= 0) & (outer >= 0) & (hides | touching)
    keys = inner[rim].astype(np.int64) * n + outer[rim]
    pair, count = np.unique(keys, return_counts=True)
    both = np.isin(pair, keys[hides[rim]]) & np.isin(pair, keys[touching[rim]])
    src, dst = pair // n, pair % n
    seg = labels >= 0
    concave = concavity(labels[seg], points[seg], normals[seg]) > min_concavity
    ok = both & concave[src] & (count >= min_share * outline[src])
    if not ok.any():
        return labels
    return _joined(labels, n, src[ok], dst[ok])


def _border(labels: np.ndarray, grid_shape: tuple[int, int], points: np.ndarray, depth: np.ndarray,
            min_jump: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Every image pair leaving a segment (both ways): the segment (``inner``) and what lies next to
    it (``outer``, < 0 for no segment), whether the outer point hides the inner one (more than
    ``min_jump`` nearer along the view, ``depth``) or touches it (within ``min_jump`` in space); and
    per segment the number of such pairs (its image outline)."""
    a, b = grid_links(np.ones(len(labels), dtype=bool), grid_shape)  # every pair, to anything
    la, lb = labels[a], labels[b]
    border = la != lb
    la, lb, pa, pb = la[border], lb[border], a[border], b[border]
    with np.errstate(invalid="ignore"):
        step = depth[pa] - depth[pb]
        touch = np.linalg.norm(points[pa] - points[pb], axis=1) <= min_jump
    inner = np.concatenate([la, lb])
    outer = np.concatenate([lb, la])
    hides = np.concatenate([step > min_jump, -step > min_jump])  # the outer point is the nearer one
    touching = np.concatenate([touch, touch])
    outline = np.bincount(inner[inner >= 0], minlength=int(labels.max(initial=-1)) + 1)
    return inner, outer, hides, touching, outline


def _joined(labels: np.ndarray, n: int, src: np.ndarray, dst: np.ndarray) -> np.ndarray:
    """``labels`` with the segment pairs ``src``-``dst`` joined, segments renumbered 0..K-1."""
    root = link_components(n, src, dst)
    out = labels.copy()
    out[labels >= 0] = np.unique(root[labels[labels >= 0]], return_inverse=True)[1].ravel()
    return out


def _in_plan_hull(inner: np.ndarray, outer: np.ndarray) -> bool:
    """Whether most of the points ``inner`` (N, 3; world, Z up) lie, in plan, within the convex hull of ``outer``."""
    try:
        hull = ConvexHull(outer[:, :2])
    except (QhullError, ValueError):
        return False
    polygon = outer[hull.vertices, :2]
    return bool(np.count_nonzero(inside_convex_polygon(inner[:, :2], polygon)) > 0.5 * len(inner))


def join_outsides(labels: np.ndarray, grid_shape: tuple[int, int], points: np.ndarray, normals: np.ndarray,
                  depth: np.ndarray, min_jump: float, min_concavity: float, min_share: float) -> np.ndarray:
    """``labels`` (segments >= 0 over a row-major ``grid_shape`` image, < 0 elsewhere) with each
    segment that a container's inside (:func:`concavity` over ``min_concavity``) hides over at least
    ``min_share`` of its image outline (its points more than ``min_jump`` nearer along the view,
    ``depth``) joined to that inside when it lies in front of it (its median depth nearer than the
    inside's) and under its opening (:func:`_in_plan_hull`; ``points`` in the world frame, Z up):
    the container's outer wall below its rim. ``normals`` point toward the camera. Segments
    renumbered 0..K-1, the rest unchanged."""
    n = int(labels.max(initial=-1)) + 1
    if n < 2:
        return labels
    inner, outer, hides, _, outline = _border(labels, grid_shape, points, depth, min_jump)
    hidden = (inner >= 0) & (outer >= 0) & hides
    pair, count = np.unique(inner[hidden].astype(np.int64) * n + outer[hidden], return_counts=True)
    src, dst = pair // n, pair % n
    seg = labels >= 0
    concave = concavity(labels[seg], points[seg], normals[seg]) > min_concavity
    ok = concave[dst] & ~concave[src] & (count >= min_share * outline[src])
    for k in np.flatnonzero(ok):
        wall, inside = labels == src[k], labels == dst[k]
        ok[k] = np.nanmedian(depth[wall]) < np.nanmedian(depth[inside]) and _in_plan_hull(points[wall], points[inside])
    if not ok.any():
        return labels
    return _joined(labels, n, src[ok], dst[ok])
