"""Hidden extents behind a nearer object: a silhouette edge that borders a nearer object is no edge.

Where an object's image borders background (or anything farther), the camera saw past it: its
silhouette is its true edge. Where it borders, beside it, another object seen nearer, the object may
go on behind that occluder: the visible points there are where the view was cut, not where the body
ends. Each such edge point is continued along the horizontal direction that moves its image under
the occluder, until the camera saw through the continued point or the space below it (free space),
the object's visible extent along that direction is repeated (the visible share of a body cut at an
unknown place is, as likely as not, at least half of it: doubling is the median guess), or it passes
the farthest true side edge the object shows on that side, whichever comes first. A continuation
whose hull reaches into seen free space is refuted (see :func:`seen_through_added`)."""

from __future__ import annotations

import numpy as np

from realsim.completion.carving import voxel_centres
from realsim.completion.extrusion import complete_hull
from realsim.completion.view import DepthView

MARCH_STEP = 0.003  # m: the continuation is tested for free space this often
COLUMN = np.array([0.0, 0.25, 0.5, 0.75])  # and at these shares of its height down to the base (it is extruded down)


def lateral_edges(labels: np.ndarray, depth: np.ndarray, own: int, gap: float, reach: int,
                  stacked: tuple[int, ...] = ()) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The side edges of object ``own`` in the (H, W) ``labels``: its pixels (flat indices) within
    ``reach`` pixels along their row of another object seen nearer than them by more than ``gap`` (m),
    with the side (-1 left, +1 right) that occluder is on; and its pixels as near to the background or
    to anything farther (the camera saw past them: true edges) on a side edge (the pixels ``reach``
    above and below are the object's: not a top or bottom edge running aslant), with their side.
    Objects ``stacked`` on it or under it hide its top or stand below it: they occlude nothing here
    (the hull of its top seen around what stands on it already spans it). An occluder below or
    above hides height or depth, which extrusion to the support and the mirrors complete."""
    h, w = labels.shape
    v, u = np.nonzero(labels == own)
    hidden, seen = np.zeros(len(v)), np.zeros(len(v))
    mine = depth[v, u]
    for du in [k for r in range(1, reach + 1) for k in (-r, r)]:
        uu = u + du
        ok = (uu >= 0) & (uu < w)
        lab, d = labels[v[ok], uu[ok]], depth[v[ok], uu[ok]]
        near, past = np.zeros(len(v), bool), np.zeros(len(v), bool)
        with np.errstate(invalid="ignore"):
            near[ok] = (lab > 0) & (lab != own) & ~np.isin(lab, stacked) & (d < mine[ok] - gap)
            past[ok] = (lab != own) & ((lab <= 0) | ~np.isfinite(d) | (d > mine[ok] + gap))
        hidden += near * np.sign(du)
        seen += past * np.sign(du)
    upright = np.ones(len(v), bool)  # a side edge runs up and down: the pixels above and below are the object's too
    for dv in [k for r in range(1, reach + 1) for k in (-r, r)]:
        vv = v + dv
        ok = (vv >= 0) & (vv < h)
        upright[ok] &= labels[vv[ok], u[ok]] == own
        upright[~ok] = False
    occluded, clear = hidden != 0, (seen != 0) & (hidden == 0) & upright
    flat = v * w + u
    return flat[occluded], np.sign(hidden[occluded]), flat[clear], np.sign(seen[clear])


def _horizontal_steps(view: DepthView, points: np.ndarray, image_steps: np.ndarray) -> np.ndarray:
    """Per world point the unit horizontal direction along which its image moves along ``image_steps``
    (zero where the image does not move horizontally enough to tell)."""
    eps = 1e-3

    def project(p: np.ndarray) -> np.ndarray:
        opt = p @ view.world_to_optical[:3, :3].T + view.world_to_optical[:3, 3]
        return np.asarray(opt[:, :2] / opt[:, 2:3])

    base = project(points)
    jx = (project(points + [eps, 0.0, 0.0]) - base) / eps  # image motion per metre along world x, y
    jy = (project(points + [0.0, eps, 0.0]) - base) / eps
    jac = np.stack([jx, jy], axis=-1)  # (N, 2 image, 2 world)
    det = np.linalg.det(jac)
    out = np.zeros((len(points), 3))
    ok = np.abs(det) > 1e-9
    if ok.any():
        steps = image_steps[ok] * [1.0 / view.intrinsics.fx, 1.0 / view.intrinsics.fy]  # pixels -> normalized image
        sol = np.linalg.solve(jac[ok], steps[..., None])[..., 0]
        norm = np.linalg.norm(sol, axis=1)
        good = norm > 1e-12
        idx = np.flatnonzero(ok)[good]
        out[idx, :2] = sol[good] / norm[good, None]
    return out


def hidden_continuation(view: DepthView, labels: np.ndarray, points: np.ndarray, usable: np.ndarray, own: int,
                        body: np.ndarray, base_z: float, tolerance: float, gap: float, reach: int, max_share: float,
                        stacked: tuple[int, ...] = ()) -> np.ndarray:
    """Points continuing object ``own`` behind the nearer objects it borders in the image (see the module
    doc): each of its usable edge points (``usable``: flat pixel mask of reliable surface points;
    ``points``: one world point per pixel) moved along its hidden direction up to ``max_share`` of
    ``body``'s extent along it (``body``: the points the object is completed from), short of the first
    place the camera saw through (beyond ``tolerance``) at it or below it down to ``base_z``, and not past
    the farthest true side edge on its side. Empty when it borders no nearer object (``stacked``: the
    objects on it or under it, see :func:`lateral_edges`)."""
    pixels, sides, clear, clear_sides = lateral_edges(labels.reshape(view.depth.shape), view.depth, own, gap, reach, stacked)
    keep = usable[pixels] & np.all(np.isfinite(points[pixels]), axis=1)
    pixels, sides = pixels[keep], sides[keep]
    if len(pixels) == 0 or len(body) < 4:
        return np.zeros((0, 3))
    edge = points[pixels]
    direction = _horizontal_steps(view, edge, np.column_stack([sides, np.zeros(len(sides))]))
    moving = np.linalg.norm(direction, axis=1) > 0
    edge, direction, sides = edge[moving], direction[moving], sides[moving]
    if len(edge) == 0:
        return np.zeros((0, 3))
    body = body[:: max(1, len(body) // 2000)]
    along = body @ direction.T  # (B, E): the body's extent along each edge point's direction
    extent = max_share * (np.percentile(along, 98, axis=0) - np.percentile(along, 2, axis=0))
    ok = usable[clear] & np.all(np.isfinite(points[clear]), axis=1)
    for side in (-1.0, 1.0):  # a true edge seen on the same side bounds the body there
        bound = points[clear[ok & (clear_sides == side)]]
        here = sides == side
        if len(bound) and here.any():
            farthest = np.max(bound @ direction[here].T, axis=0)  # per edge point: the farthest true edge along its direction
            extent[here] = np.minimum(extent[here], np.maximum(farthest - np.einsum("ij,ij->i", edge[here], direction[here]), 0.0))
    steps = int(np.ceil(np.max(extent) / MARCH_STEP))
    if steps < 1:
        return np.zeros((0, 3))
    t = np.minimum((np.arange(steps) + 1)[None, :] * MARCH_STEP, extent[:, None])  # (E, S)
    samples = edge[:, None, :] + t[..., None] * direction[:, None, :]
    column = np.repeat(samples[..., None, :], len(COLUMN), axis=-2)  # each sample and the points below it down to the base
    column[..., 2] -= COLUMN * (column[..., 2] - base_z)
    free = np.any(view.seen_through(column.reshape(-1, 3), tolerance, own).reshape(*t.shape, len(COLUMN)), axis=-1)
    first = np.where(free.any(axis=1), np.argmax(free, axis=1), steps)  # steps before the first seen-through sample
    reach_t = np.where(first > 0, t[np.arange(len(t)), np.maximum(first - 1, 0)], 0.0)
    far = reach_t > 0
    ends = edge[far] + reach_t[far, None] * direction[far]
    middles = edge[far] + 0.5 * reach_t[far, None] * direction[far]
    return np.vstack([middles, ends])


def seen_through_added(view: DepthView, body: np.ndarray, hidden: np.ndarray, base_z: float, top_z: float,
                       own: int, tolerance: float) -> float:
    """The share of the volume that the ``hidden`` continuation adds to ``body``'s hull (extruded down to
    ``base_z``) lying where the camera saw through: the hull reaches beyond the shadow there."""
    step = float(np.clip(np.ptp(np.vstack([body, hidden]), axis=0).max() / 40, 0.002, 0.005))
    counts = []
    for cloud in (body, np.vstack([body, hidden])):
        cells = voxel_centres(complete_hull(cloud, base_z, top_z, fast=True)[0], step)
        counts.append((len(cells), int(np.count_nonzero(view.seen_through(cells, tolerance, own, footprint=False)))))
    added = counts[1][0] - counts[0][0]
    return (counts[1][1] - counts[0][1]) / added if added > 0 else 0.0
