"""Mirror symmetry: the hidden half of a body seen from one side is its visible half reflected."""

from __future__ import annotations

import numpy as np
from scipy.spatial import ConvexHull, QhullError

from realsim.completion.params import CompletionParams
from realsim.completion.view import DepthView
from realsim.perception.unique_keys import distinct_rows


def mirror_hidden_half(points: np.ndarray, view: DepthView, base_z: float, top_z: float, params: CompletionParams,
                       outline: np.ndarray | None = None) -> np.ndarray | None:
    """The observed points plus the mirror image of their front part behind the occluding contour.

    The contour (the leftmost and rightmost points of each height band of the sides, as the camera
    sees them) is where the line of sight grazes the body; for a body symmetric about the vertical
    plane across the line of sight it lies in that plane, so the front is mirrored about it. Points
    behind the plane (a box top seen whole) stay and bound the result. None when the contour is not
    seen (too few side points), the visible depth is already ``mirror_max_depth_share`` of the width,
    or the top is seen whole and as wide as the body (a box's top face shows its depth; a bottle's
    cap does not). ``outline``: the points to find the contour in (default ``points``; the pixels
    seen edge-on, left out of ``points`` as unreliable surface, are where the contour is).

    A body symmetric about that plane has its two grazing lines abreast. When they are staggered by
    more than ``params.mirror_stagger`` of its width (in the height bands whose both ends the camera
    saw past, ``params.mirror_probe`` out), the body is turned: with ``params.mirror_point`` the seen
    near half is turned half a turn about the vertical axis halfway between them (a line through the
    bands' middles: see :func:`_axis_at`), exact for a centrally symmetric section at any turn (a box,
    an oval or rounded-rectangle bottle set diagonally). With ``params.mirror_turn_alone`` that image
    replaces the reflection, which reaches past a turned body's far side, less its points where the
    camera saw through (an axis a little off, a cap or shoulder that is not symmetric), unless more
    than ``params.mirror_turn_refuted`` of it lies there (the body is not centrally symmetric: the
    reflection stands). Without, the hull of both images is kept unless more than
    ``params.mirror_max_seen_through`` of the turned one lies where the camera saw through.
    """
    d = np.append(points[:, :2].mean(axis=0) - view.camera[:2], 0.0)
    if np.linalg.norm(d) < 1e-6:
        return None
    d /= np.linalg.norm(d)
    lateral = np.array([-d[1], d[0], 0.0])
    s, w = points @ d, points @ lateral
    depth = float(np.percentile(s, 98) - np.percentile(s, 2))
    width = float(np.percentile(w, 98) - np.percentile(w, 2))
    top = points[points[:, 2] >= top_z - 0.1 * (top_z - base_z)]
    if top_z - base_z < params.mirror_min_height_share * width:
        return None  # a low body lying flat: the camera above sees its top, there is little behind it
    if depth >= params.mirror_max_depth_share * width or (_top_face_seen(top, d, depth) and np.ptp(top @ lateral) >= 0.8 * width):
        return None  # a top face as wide as the body (a prism's cross-section) shows its depth
    height = top_z - base_z
    rim = points if outline is None else outline
    side = (rim[:, 2] < top_z - 0.25 * height) & (rim[:, 2] > base_z + 0.05 * height)
    ws, ss = rim @ lateral, rim @ d
    edges = np.linspace(base_z + 0.05 * height, top_z - 0.25 * height, params.mirror_bands + 1)
    contour, middles = [], []
    for lo, hi in zip(edges[:-1], edges[1:]):
        band = side & (rim[:, 2] >= lo) & (rim[:, 2] < hi)
        if band.sum() < 10:
            continue
        wb, sb = ws[band], ss[band]
        left, right = float(np.percentile(wb, 1)), float(np.percentile(wb, 99))
        wb = wb - 0.5 * (left + right)  # from the band's middle
        near_left, near_right = _extreme_depth(-wb, sb), _extreme_depth(wb, sb)
        contour.extend([near_left, near_right])
        if params.mirror_point and _both_sides_clear(rim[band], wb, lateral, view, params.mirror_probe):
            middles.append((0.5 * (near_left + near_right), 0.5 * (left + right), abs(near_left - near_right), 0.5 * (lo + hi)))
    if len(contour) < 4:
        return None
    plane = float(np.median(contour))
    front = points[s < plane]
    if len(front) < 10:
        return None
    reflected = front - 2.0 * (front @ d - plane)[:, None] * d[None, :]
    stagger = float(np.median([m[2] for m in middles])) if len(middles) >= 2 else 0.0
    if stagger <= params.mirror_stagger * width:
        return np.vstack([points, reflected])
    # grazing lines not abreast: turned, so half a turn about their middle
    if not params.mirror_turn_alone:
        axis_s, axis_w = np.median(np.asarray(middles)[:, :2], axis=0)
        axis = np.append(axis_s * d[:2] + axis_w * lateral[:2], 0.0)
        turned = 2.0 * axis - points[s < axis_s] * [1, 1, -1]
        if np.mean(view.seen_through(turned, params.carve_tolerance)) <= params.mirror_max_seen_through:
            return np.vstack([points, reflected, turned])  # else the camera saw through where the turned body would be: it is not symmetric so
        return np.vstack([points, reflected])
    axis_s, axis_w = _axis_at(np.asarray(middles), points[:, 2])
    near = s < axis_s  # the near half onto the far half (a far point seen over the top, turned, would land on the seen front)
    centre = axis_s[near, None] * d[None, :] + axis_w[near, None] * lateral[None, :]
    turned = 2.0 * centre - points[near] * [1, 1, -1]
    through = view.seen_through(turned, params.carve_tolerance)
    if np.mean(through) > params.mirror_turn_refuted:
        return np.vstack([points, reflected])  # the free space refutes the half turn: not centrally symmetric
    return np.vstack([points, turned[~through]])


def _axis_at(middles: np.ndarray, z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The vertical axis between the grazing lines at heights ``z``: a straight line (depth and lateral
    offset linear in height, least squares) through the band ``middles`` (rows: depth, lateral, stagger,
    height), held at its ends above and below them. A body narrowing to one side (a bottle's shoulder
    toward an offset cap) moves its middle with height; one axis for all heights turns its upper half
    onto space the camera saw through."""
    zc = np.clip(z, middles[:, 3].min(), middles[:, 3].max())
    fit = np.polyfit(middles[:, 3], middles[:, :2], 1)
    return np.polyval(fit[:, 0], zc), np.polyval(fit[:, 1], zc)


def mirror_about_crest(points: np.ndarray, view: DepthView, base_z: float, top_z: float, params: CompletionParams) -> np.ndarray | None:
    """The observed points plus the mirror image of the near side of a low body lying flat, reflected
    behind its crest (the vertical plane across the line of sight through its highest line).

    A camera above and in front sees a lying round body (a banana, a bottle on its side) from its near
    foot over the crest down to where its line of sight grazes the far side, above the far side's
    widest line: extruded down from there the body is short by a share of its radius. A body
    symmetric about its crest has the far side of its near side. In each slice across the line of
    sight the crest is the middle of the points within ``mirror_crest_tolerance`` of the slice's
    top (its 98th height percentile); a slice is mirrored only where its surface is seen falling away
    past the crest (a flat
    top seen whole is its own middle, so its front face lands on its far edge; a top rising to its far
    edge is no crest), no farther before the crest than ``mirror_crest_reach`` of the slice's height, and
    no image is kept where the camera saw through. None when no slice qualifies or the body is not low (see
    :func:`mirror_hidden_half`)."""
    d = np.append(points[:, :2].mean(axis=0) - view.camera[:2], 0.0)
    if np.linalg.norm(d) < 1e-6 or len(points) < 30:
        return None
    d /= np.linalg.norm(d)
    lateral = np.array([-d[1], d[0], 0.0])
    s, w = points @ d, points @ lateral
    width = float(np.percentile(w, 98) - np.percentile(w, 2))
    if top_z - base_z >= params.mirror_min_height_share * width:
        return None  # an upright body: mirrored about its occluding contour instead
    step = max(params.mirror_crest_slice, width / 20)
    slot = np.floor((w - w.min()) / step).astype(np.int64)
    tol = params.mirror_crest_tolerance
    images = []
    for k in np.unique(slot):
        sl = slot == k
        if sl.sum() < 10:
            continue
        zs, ss = points[sl, 2], s[sl]
        top = float(np.percentile(zs, 98))
        crest = float(np.median(ss[zs >= top - tol]))
        if not np.any(zs[ss > crest] < top - tol):  # not seen falling away past the crest: a flat top, one rising to its far edge ...
            apex = _curved_crest(ss, zs, top, base_z, tol) if params.mirror_crest_curved else None
            if apex is None:
                continue
            crest = apex  # ... or a small round body seen just over its crest
        near = points[sl][(ss < crest) & (ss >= crest - params.mirror_crest_reach * (top - base_z))]
        images.append(near - 2.0 * (near @ d - crest)[:, None] * d[None, :])
    mirrored = np.vstack(images) if images else np.zeros((0, 3))
    mirrored = mirrored[~view.seen_through(mirrored, params.carve_tolerance, footprint=False)]  # not where the camera saw through
    return np.vstack([points, mirrored]) if len(mirrored) else None


def _curved_crest(s: np.ndarray, z: np.ndarray, top: float, base_z: float, tol: float) -> float | None:
    """Where a slice's upper side (its points within a quarter of its height of its ``top``, at least
    ``tol``) curves over a crest, else None: the vertex of a parabola z(s) fitted to it, turning down
    on both sides, as curved as a round section (its radius of curvature at most the slice's height
    and at least half the slice's seen depth: a flat top with a rounded edge is far deeper than that
    edge's radius) and as smooth (within half ``tol`` RMS: a box's corner is no parabola), seen at
    least ``tol`` before the vertex and up to within ``tol`` of it. A small round body (a marker)
    falls away past its crest by less than the tolerance before its far side turns out of sight
    (r (1 - cos e), e the camera's elevation); a flat top or one rising to its far edge is not curved so."""
    upper = z >= top - max(tol, 0.25 * (top - base_z))
    if np.count_nonzero(upper) < 8 or np.ptp(s[upper]) <= 0:
        return None
    fit = np.polyfit(s[upper], z[upper], 2)
    a, b = float(fit[0]), float(fit[1])
    if a >= 0 or not 0.5 * float(np.ptp(s)) <= -0.5 / a <= top - base_z:
        return None
    if float(np.sqrt(np.mean((np.polyval(fit, s[upper]) - z[upper]) ** 2))) > 0.5 * tol:
        return None
    vertex = -b / (2 * a)
    return vertex if s[upper].min() + tol <= vertex <= s[upper].max() + tol else None


def _both_sides_clear(band: np.ndarray, w: np.ndarray, lateral: np.ndarray, view: DepthView, probe: float) -> bool:
    """Whether the camera saw past both lateral ends of a height band of side points (``w``: their
    lateral offsets from the band's middle): a point ``probe`` beyond each end, at the depth of the
    outermost points, lies in the space it saw through. An end that is not (a nearer neighbour hides
    it) may not be the body's widest."""
    ends = []
    for sign in (-1.0, 1.0):
        outer = band[sign * w >= np.percentile(sign * w, 97)]
        ends.append(outer.mean(axis=0) + sign * probe * lateral)
    return bool(np.all(view.seen_through(np.asarray(ends), 0.0, footprint=False)))


def _extreme_depth(w: np.ndarray, s: np.ndarray, share: float = 0.25) -> float:
    """The depth ``s`` at which a side reaches its largest lateral extent ``w`` (measured from the
    body's middle): the vertex of w^2 fitted as a parabola in s (exact for an elliptic section) to the
    points in the outer ``share`` of the extent. The camera sees the side only up to where its line
    of sight grazes it, so the outermost points all lie in front of the extreme (their median is too
    near the camera by a share of the body's depth); that median when the fit is no cap."""
    outer = w >= (1.0 - share) * np.max(w)
    fallback = float(np.median(s[w >= np.percentile(w, 97)]))
    if np.max(w) <= 0 or outer.sum() < 8 or np.ptp(s[outer]) <= 0:
        return fallback
    c2, c1, _ = np.polyfit(s[outer], w[outer] ** 2, 2)
    vertex = -c1 / (2 * c2) if c2 < 0 else np.nan
    reach = float(np.ptp(s[outer]))
    return float(vertex) if np.isfinite(vertex) and s[outer].min() - reach <= vertex <= s[outer].max() + reach else fallback


def _top_face_seen(top: np.ndarray, d: np.ndarray, depth: float, cell: float = 0.005) -> bool:
    """The top band spans the visible depth and fills its outline (a face seen whole, not a rim arc)."""
    if len(top) < 10 or float(np.ptp(top @ d)) < 0.6 * depth:
        return False
    try:
        area = float(ConvexHull(top[:, :2]).volume)
    except QhullError:
        return False
    cells = distinct_rows(np.floor(top[:, :2] / cell).astype(np.int64))
    return cells * cell * cell >= 0.6 * area
