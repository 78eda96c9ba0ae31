"""Contacts between objects, cut where the surface folds inward (for clouds seen from around).

Clusters that touch form a group; each group is bisected again and again by a normalized cut
(the Fiedler vector of its point graph) while the best cut runs along a concave fold. Each link
between neighbouring points weighs 1 when the surface bends outward (or is flat) there, and
less the more it folds inward (the LCCP criterion on point normals oriented like the patch
they lie in): two objects pressed together meet in a concave crease all along their contact,
so the cheapest cut follows it, whichever clusters the first segmentation made of them. A cut
is kept only when the links it crosses are mostly concave and both sides are object-sized, so
a convex object is never cut.
Objects that touch over a small patch (a mug's side against a bowl's rim) show little fold but
a narrow neck between two large sides, which the cut also takes. A body's own narrow part (a
lying drill's grip, a bottle's neck) is narrow too, but it stays as wide past the cut as at it;
two bodies in contact both widen beyond their contact. So a cut without a clear fold is kept
only when each side's cross section a little beyond it is wider than the cut's.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import sparse
from scipy.sparse.csgraph import connected_components
from scipy.sparse.linalg import ArpackNoConvergence, LinearOperator, eigsh, splu
from scipy.spatial import cKDTree

from realsim.geometry import inside_convex_polygon, polygon_and_rectangle
from realsim.perception.object_relations import base_height

__all__ = ["CutParams", "concave_link_weights", "cut_contacts", "section_ratio", "supported"]

EIGEN_TOL = 1e-6  # relative accuracy of the Fiedler vector
LINK_FLOOR = EIGEN_TOL  # a link lighter than this holds nothing the eigen solver can tell from no link


@dataclass(frozen=True)
class CutParams:
    """When a group of touching points is cut in two (angles in degrees, lengths in metres)."""

    fold_angle: float = 25.0  # a fold this sharp weighs a link exp(-1)
    max_cut_weight: float = 0.35  # the links a kept cut crosses weigh at most this on average
    neck_ratio: float = 1.0  # or they are this few per square root of the smaller side's points (a narrow
    # contact: its length is small beside that side's size, whatever the density)
    max_mixed_weight: float = 0.5  # or they are mostly folded (the mean weight at most this, as a border more
    # concave than convex keeps regions apart) and their weight, the unfolded rest, is that narrow
    max_ncut: float = 0.2  # and its normalized-cut value is at most this
    min_section_ratio: float = 1.3  # a cut kept without a clear fold: each side's cross section beyond it is
    # this many times the cut's (a contact between bodies; a neck leads into a part as wide as itself)
    min_size: float = 0.02  # m: each side's largest extent is at least this
    min_points: int = 5  # and it holds at least this many points
    stand_height: float = 0.015  # m: a side whose base is higher above its support does not stand on it
    rest_fraction: float = 0.35  # ... and rests on the other only if they meet in its lowest part of its height
    rest_face_angle: float = 30.0  # ... over it seen from above, or on a face of it turned this close to up (degrees)
    max_depth: int = 4  # bisections per group
    intact_share: float = 0.8  # a first cluster with this share of its points in one final part stays as it was
    confirm_share: float = 0.97  # ... and with this share it keeps the rest of its points too


def concave_link_weights(points: np.ndarray, normals: np.ndarray, a: np.ndarray, b: np.ndarray,
                         fold_angle: float, smooth: int = 8) -> np.ndarray:
    """Weight of each link (a, b) in [0, 1], low where the surface folds inward.

    Two tests, multiplied: LCCP on the outward normals ((n_a - n_b) . (p_a - p_b) < 0 on a concave
    connection, weighing exp(-(angle / fold_angle)^2)), and a one-sided one that needs only one
    end's orientation: where either end sees the other in front of its tangent plane (elevation
    sin e), the link weighs exp(-(sin e / sin fold_angle)^2). Positions are averaged over each
    point's ``smooth`` nearest neighbours first, so sensor noise does not look like a fold; at a
    contact where a thin wall's side is ambiguous, the other object's face still sees it in front."""
    d = points[a] - points[b]
    cos = np.clip((normals[a] * normals[b]).sum(axis=1), -1.0, 1.0)
    angle = np.degrees(np.arccos(cos))
    concave = ((normals[a] - normals[b]) * d).sum(axis=1) < 0
    lccp = np.where(concave, np.exp(-((angle / fold_angle) ** 2)), 1.0)
    k = min(smooth + 1, len(points))
    centre = points[cKDTree(points).query(points, k=k)[1].reshape(len(points), k)].mean(axis=1)
    d = centre[b] - centre[a]
    d /= np.maximum(np.linalg.norm(d, axis=1, keepdims=True), 1e-12)
    elevation = np.maximum((normals[a] * d).sum(axis=1), -(normals[b] * d).sum(axis=1))
    one_sided = np.exp(-((np.maximum(elevation, 0.0) / np.sin(np.radians(fold_angle))) ** 2))
    return lccp * one_sided


def _extent(points: np.ndarray) -> float:
    return float(np.max(points.max(axis=0) - points.min(axis=0))) if len(points) else 0.0


def supported(points: np.ndarray, height: np.ndarray, side: np.ndarray, contact: np.ndarray, params: CutParams,
              up: np.ndarray | None = None) -> bool:
    """Whether the points ``side`` can be an object of their own: they stand on the support, or
    they rest on the rest: the points where they meet it (``contact``) lie in their lowest part
    (a handle meets its body at both ends, a stacked can at its bottom) and that lowest part lies
    over the rest seen from above (a stacked can's foot is on its base's top; a handle's lower end
    hangs beside its body, over nothing) or, given each point's upward normal component ``up``,
    the rest's face where they meet it faces up (within ``rest_face_angle``: a face holding a body
    from below, however little of the rest is seen around it; a handle meets a wall)."""
    h = height[side]
    if base_height(h) <= params.stand_height:
        return True
    meet = height[side & contact]
    low = h.min()
    lowest = h <= low + params.rest_fraction * (h.max() - low)
    if not len(meet) or float(np.median(meet)) > low + params.rest_fraction * (h.max() - low):
        return False
    if up is not None and _faces_up(up[~side & contact], params.rest_face_angle):
        return True
    under = points[~side, :2]
    try:
        hull = polygon_and_rectangle(under)[0]
    except ValueError:  # the rest is a line seen from above: nothing to rest on
        return False
    return bool(inside_convex_polygon(points[side][lowest, :2], hull).mean() >= 0.5)


def _faces_up(up: np.ndarray, max_angle: float) -> bool:
    """Whether the median of the upward normal components ``up`` (NaN: unknown) lies within ``max_angle`` (deg) of up."""
    up = up[np.isfinite(up)]
    return bool(len(up)) and float(np.median(up)) >= np.cos(np.radians(max_angle))


def _width(points: np.ndarray, axis: np.ndarray) -> float:
    """Width of points across ``axis``: the geometric mean of their two spreads in the plane normal to it."""
    if len(points) < 3:
        return 0.0
    q = points - points.mean(axis=0)
    q -= np.outer(q @ axis, axis)
    s = np.linalg.svd(q, compute_uv=False)[:2] / np.sqrt(len(q))
    return float(np.sqrt(s[0] * s[1]))


def section_ratio(points: np.ndarray, side: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    """How much wider than the cut the narrower side is just beyond it.

    (a, b) are the links the cut crosses. The cut runs across the mean direction of those links;
    its width is that of their end points across it. Each side's width is that of its points in
    a slab one to two cut widths (at least one link length) beyond the cut's centre. A contact
    between two bodies gives both sides well over 1 (each body widens past the contact patch);
    a body's own neck about 1 (the narrow part goes on as wide as the cut)."""
    near, far = np.where(side[a], a, b), np.where(side[a], b, a)
    step = points[far] - points[near]
    axis = step.sum(axis=0)
    norm = float(np.linalg.norm(axis))
    if norm == 0.0:
        return 0.0
    axis /= norm
    ends = points[np.r_[near, far]]
    cut = _width(ends, axis)
    link = float(np.median(np.linalg.norm(step, axis=1)))
    start = max(cut, link)
    along = (points - ends.mean(axis=0)) @ axis
    ratios = []
    for own, sign in ((side, -1.0), (~side, 1.0)):
        beyond = sign * along
        slab = own & (beyond > start) & (beyond <= 2 * start + link)
        ratios.append(_width(points[slab], axis) / max(cut, 1e-12))
    return min(ratios)


def _loose_nodes(n: int, a: np.ndarray, b: np.ndarray, w: np.ndarray, min_points: int) -> np.ndarray:
    """Nodes (bool) held to the rest only by links weighing less than the eigen solver resolves
    (``LINK_FLOOR``), in pieces too small to be a side: a point whose every link folds right
    back (a thin wall's far side between two near ones) is a component of its own to the
    Laplacian, and its indicator, not the cut, becomes the Fiedler vector."""
    held = w >= LINK_FLOOR
    _, comp = connected_components(sparse.coo_matrix((np.ones(int(held.sum())), (a[held], b[held])), shape=(n, n)),
                                   directed=False)
    return np.asarray(np.bincount(comp)[comp] < min_points, dtype=bool)


def _graph(n: int, a: np.ndarray, b: np.ndarray, w: np.ndarray) -> sparse.csr_matrix:
    """The symmetric weighted adjacency of links (a, b)."""
    return sparse.coo_matrix((np.r_[w, w], (np.r_[a, b], np.r_[b, a])), shape=(n, n)).tocsr()


def _fiedler(n: int, a: np.ndarray, b: np.ndarray, w: np.ndarray) -> np.ndarray | None:
    """The Fiedler vector of the normalized cut (second eigenvector of I - D^-1/2 W D^-1/2, scaled
    by D^-1/2) of a connected graph, or None when the solver does not converge."""
    graph = _graph(n, a, b, w)
    degree = np.asarray(graph.sum(axis=1)).ravel()
    scale = 1.0 / np.sqrt(np.maximum(degree, 1e-12))
    laplacian = (sparse.identity(n) - sparse.diags(scale) @ graph @ sparse.diags(scale)).tocsc()
    shift = -1e-3
    try:  # the two smallest eigenvectors (shift-invert: a near cut has an eigenvalue close to 0,
        # where plain Lanczos converges slowly); the second is the Fiedler direction
        lu = splu((laplacian - shift * sparse.identity(n)).tocsc(), permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                  options={"SymmetricMode": True})  # symmetric positive definite: a symmetric ordering, no pivoting
        inverse = LinearOperator((n, n), matvec=lu.solve, dtype=np.float64)
        vals, vecs = eigsh(laplacian, k=2, sigma=shift, which="LM", OPinv=inverse, v0=np.sqrt(degree), tol=EIGEN_TOL,
                           maxiter=5000)
    except (ArpackNoConvergence, RuntimeError):
        return None
    return np.asarray(vecs[:, int(np.argmax(vals))] * scale, dtype=np.float64)


def _best_cut(n: int, a: np.ndarray, b: np.ndarray, w: np.ndarray, points: np.ndarray, height: np.ndarray,
              params: CutParams) -> np.ndarray | None:
    """The side (bool per node) of the best acceptable normalized cut of a connected graph, or None.

    Candidate cuts split the nodes in the order of the Fiedler vector, computed without the
    loose nodes (:func:`_loose_nodes`); each of those takes the value of the nearest other point."""
    if n < 2 * params.min_points:
        return None
    loose = _loose_nodes(n, a, b, w, params.min_points)
    core = np.flatnonzero(~loose)
    if len(core) < 2 * params.min_points:
        return None
    index = np.full(n, -1, dtype=np.int64)
    index[core] = np.arange(len(core))
    inner = (index[a] >= 0) & (index[b] >= 0)
    core_value = _fiedler(len(core), index[a[inner]], index[b[inner]], w[inner])
    if core_value is None:
        return None
    value = np.empty(n)
    value[core] = core_value
    if loose.any():
        value[loose] = core_value[cKDTree(points[core]).query(points[loose])[1]]
    degree = np.asarray(_graph(n, a, b, w).sum(axis=1)).ravel()
    order = np.argsort(value, kind="stable")
    rank = np.empty(n, dtype=np.int64)
    rank[order] = np.arange(n)
    lo, hi = np.minimum(rank[a], rank[b]), np.maximum(rank[a], rank[b])
    # a link crosses the cut "first t + 1 nodes | rest" for lo <= t < hi
    diff = np.zeros(n + 1)
    np.add.at(diff, lo, w)
    np.add.at(diff, hi, -w)
    cut = np.cumsum(diff)[: n - 1]
    links = np.cumsum(np.bincount(lo, minlength=n + 1) - np.bincount(hi, minlength=n + 1))[: n - 1]
    vol = np.cumsum(degree[order])[: n - 1]
    total = degree.sum()
    ncut = cut / np.maximum(vol, 1e-12) + cut / np.maximum(total - vol, 1e-12)
    sizes = np.arange(1, n)
    folded = cut <= params.max_cut_weight * np.maximum(links, 1)
    width = params.neck_ratio * np.sqrt(np.minimum(sizes, n - sizes))
    # a narrow neck, or a contact folded along most of it whose unfolded (convex) rest is that narrow
    necked = (links <= width) | ((cut <= params.max_mixed_weight * links) & (cut <= width))
    ok = (sizes >= params.min_points) & (n - sizes >= params.min_points) & (folded | necked) & (ncut <= params.max_ncut)
    for t in np.flatnonzero(ok)[np.argsort(ncut[ok], kind="stable")][:8]:
        side = rank <= t
        if _extent(points[side]) < params.min_size or _extent(points[~side]) < params.min_size:
            continue
        crossing = (lo <= t) & (hi > t)
        if not folded[t] and section_ratio(points, side, a[crossing], b[crossing]) < params.min_section_ratio:
            continue  # no clear fold, and one side goes on as narrow as the cut: a body's own neck
        contact = np.zeros(n, dtype=bool)
        contact[a[crossing]] = contact[b[crossing]] = True
        if supported(points, height, side, contact, params) and supported(points, height, ~side, contact, params):
            return side
    return None


def cut_contacts(points: np.ndarray, normals: np.ndarray, height: np.ndarray, labels: np.ndarray, a: np.ndarray,
                 b: np.ndarray, params: CutParams = CutParams()) -> np.ndarray:
    """Cluster labels (>= 0; -1 none) re-cut at concave contacts.

    ``points`` (N, 3) and outward ``normals`` of the segmented points, ``height`` their height above
    their support (m), ``labels`` their clusters,
    (a, b) the links between neighbouring points. Touching clusters are grouped, then each group
    is bisected while an acceptable concave cut exists (see the module doc); what no cut
    separated keeps the clusters it had (:func:`_keep_intact`)."""
    valid = labels >= 0
    keep = valid[a] & valid[b]
    a, b = a[keep], b[keep]
    w = concave_link_weights(points, normals, a, b, params.fold_angle)
    n = len(points)
    _, group = connected_components(sparse.coo_matrix((np.ones(len(a)), (a, b)), shape=(n, n)), directed=False)
    parts: list[np.ndarray] = []
    stack = [(np.flatnonzero(valid & (group == g)), 0) for g in np.unique(group[valid])]
    while stack:
        members, depth = stack.pop()
        local = np.full(n, -1, dtype=np.int64)
        local[members] = np.arange(len(members))
        inside = (local[a] >= 0) & (local[b] >= 0)
        side = None
        if depth < params.max_depth:
            side = _best_cut(len(members), local[a[inside]], local[b[inside]], w[inside], points[members],
                             height[members], params)
        if side is None:
            parts.append(members)
            continue
        for part in (members[side], members[~side]):
            sub = np.full(n, -1, dtype=np.int64)
            sub[part] = np.arange(len(part))
            links = (sub[a] >= 0) & (sub[b] >= 0)
            _, comp = connected_components(sparse.coo_matrix((np.ones(int(links.sum())), (sub[a[links]], sub[b[links]])),
                                                             shape=(len(part), len(part))), directed=False)
            for c in np.unique(comp):
                stack.append((part[comp == c], depth + 1))
    return _keep_intact(labels, parts, params.intact_share, params.confirm_share)


def _keep_intact(labels: np.ndarray, parts: list[np.ndarray], share: float, confirm: float) -> np.ndarray:
    """Labels of the final parts. A cluster of the first segmentation with at least ``share`` of
    its points in one part is kept there as it was (touching objects no cut separated stay apart);
    the rest of that part, pieces of clusters a cut went through, joins its largest kept cluster,
    or becomes a new object when none is kept. A cluster with at least ``confirm`` of its points
    in one part keeps all of them."""
    size = np.bincount(labels[labels >= 0])
    out = np.full(len(labels), -1, dtype=np.int64)
    next_label = int(len(size))
    sure: list[int] = []
    for members in parts:
        own, count = np.unique(labels[members], return_counts=True)
        kept = own[count >= share * size[own]]
        if len(kept) == 0:
            out[members] = next_label
            next_label += 1
            continue
        out[members] = kept[np.argmax(size[kept])]
        whole = np.isin(labels[members], kept)
        out[members[whole]] = labels[members[whole]]
        sure.extend(own[count >= confirm * size[own]].tolist())
    # a cluster the cuts confirm but for a sliver keeps that sliver too: along a boundary it
    # found, the patch-level segmentation is surer than single points
    confirmed = np.isin(labels, sure)
    out[confirmed] = labels[confirmed]
    return out

