"""Parts of one object that a camera view segments apart: a handle, a container's inside.

In a view, a pitcher's handle, a mug's handle or a bowl's inside can come out as clusters of
their own, each "resting on" its body (the body lies under its lowest points) or floating
beside it (nothing under it). A thing that truly rests on another meets it at its own foot,
over the other's top (a can on a box); a part meets its body elsewhere: a handle along its
height, a container's inside around its rim, above its lowest part. Such a cluster is joined
to the body it rests on, or, floating, to the object most of its near points belong to, when
that one is larger, does not rest on it, and is not in front of it (an object whose foot a
nearer one hides floats in a view too, and is no part of what hides it).
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from realsim.perception.contact_cut import CutParams, supported
from realsim.perception.object_relations import base_height
from realsim.perception.supervoxels import grid_links

__all__ = ["join_attached_parts"]


def join_attached_parts(points: np.ndarray, labels: np.ndarray, height: np.ndarray, resting_on: dict[int, int | None],
                        stand_height: float, reach: float, jump: float, view_axis: np.ndarray | None = None,
                        grid_shape: tuple[int, int] | None = None, links: tuple[np.ndarray, np.ndarray] | None = None,
                        base_gap: float | None = None, normals: np.ndarray | None = None,
                        rest_face_angle: float = 30.0) -> np.ndarray:
    """Labels (>= 1 objects) with each object that rests on another (or floats next to it) but
    is not held up by it at its own foot (:func:`realsim.perception.contact_cut.supported`)
    merged into that other one; an object standing on its support stays.

    ``height`` is each point's height above its support (m), ``resting_on`` the object each
    object rests on (None: its support, or nothing), ``stand_height`` (m) the base height up to
    which an object stands on its support, ``reach`` (m) how near two objects' points touch,
    ``view_axis`` the unit direction the camera looks along, ``grid_shape`` the view's image
    (row-major over the points): a floating object whose foot a nearer one hides (more than a
    depth ``jump``, m, nearer just below it in the image) stays as it is. A cloud seen from around
    (no view) gives its neighbour ``links`` instead and the ``base_gap`` of its grid
    (:func:`realsim.perception.object_relations.base_height`); no foot of it is hidden. Given the
    points' ``normals``, an object also rests on another where that one's face under it turns less
    than ``rest_face_angle`` (degrees) from up (:func:`realsim.perception.contact_cut.supported`)."""
    params = CutParams(stand_height=stand_height, rest_face_angle=rest_face_angle)
    root = {o: o for o in resting_on}

    def find(o: int) -> int:
        while root[o] != o:
            o = root[o]
        return o

    out = labels.copy()
    if view_axis is not None and grid_shape is not None:
        links = grid_links(np.isfinite(points).all(axis=1), grid_shape)
    if links is None:
        raise ValueError("join_attached_parts needs a view (view_axis and grid_shape) or the cloud's links")
    with np.errstate(invalid="ignore"):  # lowest first: a base's pieces join before what stands on it is judged
        level = {o: float(np.nanmedian(height[labels == o])) if (labels == o).any() else np.inf for o in resting_on}
    for o in sorted(resting_on, key=lambda k: (level[k], k)):
        mine = out == o
        if not mine.any() or base_height(height[mine], base_gap) <= stand_height:
            continue
        below = resting_on[o]
        floating = below is None
        body = _nearest_object(points, out, mine, reach) if below is None else find(below)
        if body is None or body == o:
            continue
        theirs = out == body
        if floating and (resting_on.get(body) == o or theirs.sum() <= mine.sum()):
            continue
        group = np.flatnonzero(mine | theirs)
        side = mine[group]
        contact = _contact(points, group, side, links, jump, reach)
        if not contact[side].any() or not contact[~side].any():
            continue
        if floating and view_axis is not None and grid_shape is not None and _foot_hidden(height, points @ view_axis, out, o,
                                                                                          grid_shape, jump):
            continue  # its foot is hidden, not missing
        if not supported(points[group], height[group], side, contact, params, None if normals is None else normals[group, 2]):
            out[mine] = body
            root[o] = body
    return out


def _contact(points: np.ndarray, group: np.ndarray, side: np.ndarray, links: tuple[np.ndarray, np.ndarray],
             jump: float, reach: float) -> np.ndarray:
    """Mask over ``group`` of the points where its two ``side``s meet: the ends of neighbouring
    pixel pairs across them whose surfaces touch (no farther apart than a depth ``jump``, m: the
    crease where a body lying on another meets its face); where the image shows no such pair, those
    no farther apart than ``reach`` (m; a thin body's far outline merely passes over the face behind
    it, so it counts only where no crease shows); where none either (a handle's ends hidden behind
    its body), the points within ``reach`` of the other side."""
    local = np.full(len(points), -1, dtype=np.int64)
    local[group] = np.arange(len(group))
    la, lb = local[links[0]], local[links[1]]
    both = (la >= 0) & (lb >= 0)
    la, lb = la[both], lb[both]
    across = side[la] != side[lb]
    length = np.linalg.norm(points[group[la]] - points[group[lb]], axis=1)
    for limit in (jump, reach):
        near = across & (length <= limit)
        if near.any():
            contact = np.zeros(len(group), dtype=bool)
            contact[la[near]] = contact[lb[near]] = True
            return contact
    contact = np.zeros(len(group), dtype=bool)
    for near_side, far in ((side, ~side), (~side, side)):
        dist, _ = cKDTree(points[group[far]]).query(points[group[near_side]], distance_upper_bound=reach)
        contact[np.flatnonzero(near_side)[np.isfinite(dist)]] = True
    return contact


def _foot_hidden(height: np.ndarray, depth: np.ndarray, labels: np.ndarray, o: int, shape: tuple[int, int],
                 jump: float) -> bool:
    """Whether, below ``o``'s lowest pixel in each image column (down: the image direction in which
    heights fall), the next pixel mostly shows something more than a depth ``jump`` nearer (an
    occluder standing in front of its foot) rather than its support or what lies behind it."""
    h, w = shape
    grid = np.nan_to_num(height, nan=np.inf).reshape(h, w)
    fall_rows, fall_cols = _median_fall(grid[:-1], grid[1:]), _median_fall(grid[:, :-1], grid[:, 1:])
    image = labels.reshape(h, w) == o
    d = depth.reshape(h, w)
    if abs(fall_cols) > abs(fall_rows):  # a camera rolled a quarter turn: work on the transposed image
        image, d, fall_rows = image.T, d.T, fall_cols
    if fall_rows < 0:  # heights fall toward the first row: flip so that down is the next row
        image, d = image[::-1], d[::-1]
    cols = np.flatnonzero(image.any(axis=0))
    rows = image.shape[0] - 1 - np.argmax(image[::-1, cols], axis=0)  # lowest pixel of each column
    ok = rows + 1 < image.shape[0]
    cols, rows = cols[ok], rows[ok]
    if len(cols) == 0:
        return False
    below = d[rows + 1, cols]
    with np.errstate(invalid="ignore"):
        return bool(np.mean(below < d[rows, cols] - jump) > 0.5)


def _median_fall(upper: np.ndarray, lower: np.ndarray) -> float:
    """Median of ``upper - lower`` where both are finite (0 where nowhere)."""
    with np.errstate(invalid="ignore"):
        fall = upper - lower
    fall = fall[np.isfinite(fall)]
    return float(np.median(fall)) if len(fall) else 0.0


def _nearest_object(points: np.ndarray, labels: np.ndarray, mine: np.ndarray, reach: float) -> int | None:
    """The other object (label >= 1) owning most points within ``reach`` of the points ``mine``."""
    others = np.flatnonzero((labels > 0) & ~mine)
    if len(others) == 0:
        return None
    dist, _ = cKDTree(points[mine]).query(points[others], distance_upper_bound=reach)
    near = labels[others[np.isfinite(dist)]]
    return int(np.bincount(near).argmax()) if len(near) else None
