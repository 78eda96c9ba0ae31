"""Object segmentation: the points above the supports, split into objects.

1. Foreground: points above a support (more than ``min_height``) and inside its polygon.
2. Links: image-grid 4-neighbours for an organized cloud, k nearest neighbours otherwise; links
   across depth jumps are cut. Normals come from grid tangents (pointing at the camera) or from
   k-neighbour covariances.
3. Supervoxels: SLIC on position, normal and colour, split into connected parts.
4. LCCP-style merging: adjacent supervoxels whose connection is convex (or flat within a
   tolerance) are joined, flattest first; two regions never join when their common border is
   mostly concave, so a stray convex pair at the contact of two objects cannot merge them.
5. Small pieces join their best neighbour; small isolated clusters are noise. Objects standing
   on other objects are found from what lies right under their base.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy import ndimage, sparse
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from realsim.geometry import inside_convex_polygon
from realsim.scene import SupportPlane

__all__ = ["SegmentParams", "SegmentResult", "filter_by_size", "segment_objects"]


@dataclass(frozen=True)
class SegmentParams:
    """Thresholds of the segmentation (lengths in metres, angles in degrees)."""

    # foreground
    min_height: float = 0.008  # points closer than this above their support belong to it
    max_height: float = 1.0  # points higher than this above every support are background
    polygon_margin: float = 0.02  # points beyond a support polygon by more than this are background
    structure_margin: float = 0.03  # points this close under a higher support's polygon are its furniture
    use_assumed_planes: bool = False  # also segment above supports that were not observed
    # neighbourhoods and normals
    normal_window: int = 5  # grid window (pixels) averaging tangent normals, organized clouds
    normal_neighbors: int = 20  # neighbours of the covariance normals, unorganized clouds
    knn_neighbors: int = 8  # neighbours linked per point, unorganized clouds
    # links between neighbouring points (fragments)
    jump_distance: float = 0.008  # neighbours farther apart than this are across a depth jump
    # supervoxels (SLIC on position, normal and colour)
    supervoxel_pixels: int = 10  # seed spacing in the image grid (organized clouds)
    supervoxel_size: float = 0.02  # seed spacing and position scale (m)
    supervoxel_normal_scale: float = 0.5  # normal distance (1 - cos^2) scale
    supervoxel_color_scale: float = 0.15  # colour distance (RGB in [0, 1]) scale
    supervoxel_iterations: int = 4
    min_fragment_points: int = 8  # smaller supervoxel parts are absorbed by their best neighbour
    # merging supervoxels (LCCP)
    convex_tolerance: float = 40.0  # connections this close to flat count as convex
    orientation_radius: float = 0.06  # unorganized clouds: segment normals point away from the centre of what lies this close
    min_contact_links: int = 6  # fewer links between two fragments are not a contact
    color_edge: float | None = None  # segments whose mean RGB differ more do not join directly (None: off;
    # on textured real objects any useful threshold splits objects, see bench)
    max_concave_fraction: float = 0.5  # regions whose border is more concave than this stay apart
    # objects
    absorb_points: int = 600  # smaller segments touching another segment join it
    min_object_points: int = 200  # smaller isolated clusters are noise (-1)
    stack_min_height: float = 0.015  # an object whose base is this high rests on another one
    # sizes of objects (unorganized clouds): larger clusters are structure (walls, furniture sides),
    # smaller ones and floating ones (resting on nothing) are noise
    min_object_size: float = 0.02  # m, largest extent
    absorb_area: float = 0.005  # m^2: unorganized clouds, smaller segments touching another join it
    min_object_area: float = 0.0015  # m^2: unorganized clouds, smaller isolated clusters are noise
    max_object_size: float = 0.8  # m, largest extent


@dataclass
class SegmentResult:
    """Per-point labels (0 support/background, -1 noise, k > 0 object k) and support relations."""

    labels: np.ndarray
    support_of: dict[int, int] = field(default_factory=dict)
    resting_on: dict[int, int | None] = field(default_factory=dict)


def assign_supports(points: np.ndarray, planes: list[SupportPlane], params: SegmentParams) -> tuple[np.ndarray, np.ndarray]:
    """Per point: index into ``planes`` of the highest support it stands above (within ``min_height``
    .. ``max_height`` and inside the polygon), -1 for none; and the height above that support (NaN for none).

    Points under a higher support (within ``structure_margin`` of its polygon) belong to that
    support's furniture (legs, sides), not to objects on the lower one."""
    n = len(points)
    support = np.full(n, -1, dtype=np.int64)
    height = np.full(n, np.nan)
    z = np.where(np.isfinite(points).all(axis=1), points[:, 2], np.nan)
    order = sorted(range(len(planes)), key=lambda i: planes[i].height)
    for i in order:  # higher supports overwrite lower ones
        plane = planes[i]
        if not plane.observed and not params.use_assumed_planes:
            continue
        with np.errstate(invalid="ignore"):
            h = z - plane.height
            candidate = np.flatnonzero((h > params.min_height) & (h < params.max_height))
        candidate = candidate[inside_convex_polygon(points[candidate, :2], plane.polygon, params.polygon_margin)]
        for upper in planes:  # the space under a higher support is its furniture (legs, sides)
            if upper.observed and upper.height > plane.height + params.min_height:
                under = inside_convex_polygon(points[candidate, :2], upper.polygon, params.structure_margin)
                candidate = candidate[~(under & (z[candidate] < upper.height + params.min_height))]
        support[candidate] = i
        height[candidate] = h[candidate]
    return support, height


# ----------------------------------------------------------------------------------------------
# neighbourhoods and normals


def grid_links(valid: np.ndarray, grid_shape: tuple[int, int]) -> tuple[np.ndarray, np.ndarray]:
    """Point index pairs of 4-neighbours in the image grid where both points are valid."""
    h, w = grid_shape
    idx = np.arange(h * w).reshape(h, w)
    v = valid.reshape(h, w)
    pairs = []
    for a, b, m in ((idx[:, :-1], idx[:, 1:], v[:, :-1] & v[:, 1:]), (idx[:-1], idx[1:], v[:-1] & v[1:])):
        pairs.append(np.stack([a[m], b[m]], axis=1))
    links = np.concatenate(pairs)
    return links[:, 0], links[:, 1]


def knn_links(points: np.ndarray, valid: np.ndarray, k: int) -> tuple[np.ndarray, np.ndarray]:
    """Point index pairs of k nearest neighbours among the valid points (each pair once)."""
    ids = np.flatnonzero(valid)
    if len(ids) < 2:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    k = min(k, len(ids) - 1)
    _, nn = cKDTree(points[ids]).query(points[ids], k=k + 1)
    a = np.repeat(np.arange(len(ids)), k)
    b = nn[:, 1:].ravel()
    keys = np.unique(np.minimum(a, b) * len(ids) + np.maximum(a, b))
    return ids[keys // len(ids)], ids[keys % len(ids)]


def _smallest_eigenvectors(cov: np.ndarray) -> np.ndarray:
    """Unit eigenvectors of the smallest eigenvalue of (M, 3, 3) symmetric matrices."""
    _, vecs = np.linalg.eigh(cov)
    return vecs[:, :, 0]


def grid_normals(points: np.ndarray, valid: np.ndarray, grid_shape: tuple[int, int], window: int,
                 max_step: float) -> np.ndarray:
    """Normals of an organized cloud from image-grid tangents, pointing toward the camera; NaN elsewhere.

    The image axes (u right, v down) and the optical axis form a right-handed frame, so the cross
    product of the grid tangents d/du x d/dv points away from the camera on every visible surface,
    whatever the world frame is. Unit cross products are averaged over a ``window`` of pixels;
    tangents spanning a depth jump (longer than ``2 max_step``) or invalid points are skipped.
    """
    h, w = grid_shape
    normals = np.full(points.shape, np.nan)
    v = valid.reshape(h, w)
    rows, cols = np.flatnonzero(v.any(axis=1)), np.flatnonzero(v.any(axis=0))
    if len(rows) == 0:
        return normals
    r0, r1 = max(rows[0] - 1, 0), min(rows[-1] + 2, h)
    c0, c1 = max(cols[0] - 1, 0), min(cols[-1] + 2, w)
    vc = v[r0:r1, c0:c1]
    p = np.where(vc[..., None], points.reshape(h, w, 3)[r0:r1, c0:c1], np.nan)
    du = np.full_like(p, np.nan)
    dv = np.full_like(p, np.nan)
    du[:, 1:-1] = p[:, 2:] - p[:, :-2]
    dv[1:-1] = p[2:] - p[:-2]
    with np.errstate(invalid="ignore"):
        du[np.linalg.norm(du, axis=2) > 2 * max_step] = np.nan
        dv[np.linalg.norm(dv, axis=2) > 2 * max_step] = np.nan
        c = np.cross(du, dv)
        c /= np.linalg.norm(c, axis=2, keepdims=True)
    c = np.nan_to_num(c)
    s = np.stack([ndimage.uniform_filter(c[..., i], size=window, mode="constant") for i in range(3)], axis=2)
    norm = np.linalg.norm(s, axis=2)
    good = vc & (norm > 1e-6)
    out = np.full((r1 - r0, c1 - c0, 3), np.nan)
    out[good] = -s[good] / norm[good][:, None]
    normals.reshape(h, w, 3)[r0:r1, c0:c1] = out
    return normals


def knn_normals(points: np.ndarray, valid: np.ndarray, k: int) -> np.ndarray:
    """Covariance normals over the k nearest valid neighbours; NaN for invalid points."""
    normals = np.full(points.shape, np.nan)
    ids = np.flatnonzero(valid)
    if len(ids) < 3:
        return normals
    pts = points[ids]
    _, nn = cKDTree(pts).query(pts, k=min(k, len(ids)))
    nb = pts[nn] - pts[nn].mean(axis=1, keepdims=True)
    normals[ids] = _smallest_eigenvectors(np.einsum("mki,mkj->mij", nb, nb))
    return normals


# ----------------------------------------------------------------------------------------------
# supervoxels


def _slic(features: np.ndarray, candidates: np.ndarray, labels: np.ndarray, iterations: int) -> np.ndarray:
    """Local k-means (SLIC): each point picks the nearest of its candidate seeds, seeds move to their means.

    ``features`` (M, F) are pre-scaled so that squared Euclidean distance is the SLIC distance;
    ``candidates`` (M, C) hold seed indices (-1 for none); ``labels`` the initial assignment.
    """
    features = features.astype(np.float32)
    n_seeds = int(candidates.max()) + 1
    cand = np.where(candidates >= 0, candidates, 0)
    rows = np.arange(len(cand))
    for _ in range(iterations):
        count = np.bincount(labels, minlength=n_seeds).astype(np.float32)
        centres = np.stack([np.bincount(labels, features[:, f], minlength=n_seeds) for f in range(features.shape[1])], axis=1)
        centres = (centres / np.maximum(count, 1.0)[:, None]).astype(np.float32)
        dist = np.empty(cand.shape, dtype=np.float32)
        for c in range(cand.shape[1]):
            diff = features - centres[cand[:, c]]
            dist[:, c] = np.einsum("ij,ij->i", diff, diff)
        dist[(candidates < 0) | (count[cand] == 0)] = np.inf
        labels = cand[rows, dist.argmin(axis=1)]
    return labels


def _slic_features(points: np.ndarray, colors: np.ndarray | None, normals: np.ndarray, params: SegmentParams) -> np.ndarray:
    """Features whose squared distances weigh position, colour and normal as the parameters say."""
    n = np.nan_to_num(normals)
    # sign-free normal feature: n n^T flattened (upper triangle), distance ~ 1 - (n.m)^2
    nn = np.stack([n[:, 0] ** 2, n[:, 1] ** 2, n[:, 2] ** 2, *(np.sqrt(2) * n[:, i] * n[:, j] for i, j in ((0, 1), (0, 2), (1, 2)))], axis=1)
    parts = [points / params.supervoxel_size, nn / params.supervoxel_normal_scale]
    if colors is not None:
        parts.append(colors / params.supervoxel_color_scale)
    return np.concatenate(parts, axis=1)


def grid_supervoxels(points: np.ndarray, colors: np.ndarray | None, normals: np.ndarray, ids: np.ndarray,
                     grid_shape: tuple[int, int], params: SegmentParams) -> np.ndarray:
    """SLIC supervoxels of the points ``ids`` of an organized cloud, seeded on an image grid."""
    _, w = grid_shape
    step = params.supervoxel_pixels
    ys, xs = np.divmod(ids, w)
    cy, cx = ys // step, xs // step
    ncx = w // step + 1
    cell = cy * ncx + cx
    occupied, labels = np.unique(cell, return_inverse=True)
    lookup = np.full((cy.max() + 3) * ncx, -1, dtype=np.int64)
    lookup[occupied + ncx] = np.arange(len(occupied))  # shifted by one row so that cy - 1 >= 0
    cand = []
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            ok = (cx + dx >= 0) & (cx + dx < ncx)
            cand.append(np.where(ok, lookup[np.clip((cy + 1 + dy) * ncx + cx + dx, 0, None)], -1))
    feats = _slic_features(points[ids], None if colors is None else colors[ids], normals[ids], params)
    return _slic(feats, np.stack(cand, axis=1), labels, params.supervoxel_iterations)


def cloud_supervoxels(points: np.ndarray, colors: np.ndarray | None, normals: np.ndarray, ids: np.ndarray,
                      params: SegmentParams) -> np.ndarray:
    """SLIC supervoxels of the points ``ids`` of an unorganized cloud, seeded on a voxel grid."""
    pts = points[ids]
    voxel = np.floor(pts / params.supervoxel_size).astype(np.int64)
    _, labels = np.unique(voxel, axis=0, return_inverse=True)
    labels = labels.ravel()
    count = np.bincount(labels)
    seeds = np.stack([np.bincount(labels, pts[:, i]) for i in range(3)], axis=1) / count[:, None]
    k = min(8, len(seeds))
    _, cand = cKDTree(seeds).query(pts, k=k)
    cand = cand.reshape(len(pts), k)
    feats = _slic_features(pts, None if colors is None else colors[ids], normals[ids], params)
    return _slic(feats, cand, labels, params.supervoxel_iterations)


# ----------------------------------------------------------------------------------------------
# graphs over segments


def _components(n: int, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Connected component index of each of ``n`` nodes linked by the pairs (a, b)."""
    graph = sparse.coo_matrix((np.ones(len(a), dtype=np.int8), (a, b)), shape=(n, n))
    return connected_components(graph, directed=False)[1]


def _pair_counts(la: np.ndarray, lb: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Distinct unordered label pairs (i < j) among links between different labels, with link counts."""
    cross = la != lb
    lo, hi = np.minimum(la[cross], lb[cross]), np.maximum(la[cross], lb[cross])
    base = int(hi.max(initial=0)) + 1
    keys, counts = np.unique(lo.astype(np.int64) * base + hi, return_counts=True)
    return keys // base, keys % base, counts


def absorb_small(labels: np.ndarray, a: np.ndarray, b: np.ndarray, min_size: int, passes: int = 3) -> np.ndarray:
    """Give each segment smaller than ``min_size`` to the neighbour it shares most links with.

    ``labels`` are segment indices (>= 0) of the linked points; segments with no neighbour stay.
    """
    labels = labels.copy()
    for _ in range(passes):
        size = np.bincount(labels)
        small = size < min_size
        if not small.any():
            break
        i, j, c = _pair_counts(labels[a], labels[b])
        src = np.concatenate([i, j])
        dst = np.concatenate([j, i])
        cnt = np.concatenate([c, c]).astype(np.float64)
        keep = small[src] & ~small[dst]
        if not keep.any():
            break
        src, dst, cnt = src[keep], dst[keep], cnt[keep]
        order = np.lexsort((-size[dst], -cnt, src))  # best neighbour first: most links, then largest
        src, dst = src[order], dst[order]
        first = np.r_[True, src[1:] != src[:-1]]
        target = np.arange(len(size))
        target[src[first]] = dst[first]
        labels = target[labels]
    return np.unique(labels, return_inverse=True)[1].ravel()


def segment_normals(points: np.ndarray, labels: np.ndarray, n_seg: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Centroid, plane-fit normal (unoriented) and point count of each segment."""
    count = np.bincount(labels, minlength=n_seg).astype(np.float64)
    c = np.stack([np.bincount(labels, points[:, i], minlength=n_seg) for i in range(3)], axis=1) / np.maximum(count, 1)[:, None]
    d = points - c[labels]
    cov = np.empty((n_seg, 3, 3))
    for i in range(3):
        for j in range(i, 3):
            cov[:, i, j] = cov[:, j, i] = np.bincount(labels, d[:, i] * d[:, j], minlength=n_seg) / np.maximum(count, 1)
    return c, _smallest_eigenvectors(cov), count


def convex_connections(centroids: np.ndarray, normals: np.ndarray, i: np.ndarray, j: np.ndarray,
                       tolerance_deg: float) -> np.ndarray:
    """LCCP test: the connection of segments i and j is convex (or flat within the tolerance).

    With outward normals, (n_i - n_j) . (c_i - c_j) > 0 on a convex edge and < 0 on a concave one.
    """
    d = centroids[i] - centroids[j]
    d /= np.maximum(np.linalg.norm(d, axis=1, keepdims=True), 1e-12)
    cos = np.clip((normals[i] * normals[j]).sum(axis=1), -1, 1)
    flat = cos > np.cos(np.radians(tolerance_deg))
    return flat | (((normals[i] - normals[j]) * d).sum(axis=1) > 0)


def merge_regions(n_seg: int, si: np.ndarray, sj: np.ndarray, weight: np.ndarray, convex: np.ndarray,
                  order: np.ndarray, max_concave_fraction: float) -> np.ndarray:
    """Greedy union of segments over convex connections, refusing merges across mostly concave borders.

    Convex connections are taken in ``order`` (most reliable first). Two regions merge through one
    only when the concave share of all links between the two regions (``weight`` summed over their
    segment pairs) is at most ``max_concave_fraction``; a stray convex pair at the contact of two
    objects therefore cannot join them. Returns the region index of each segment.
    """
    parent = np.arange(n_seg)
    adj: list[dict[int, list[float]]] = [dict() for _ in range(n_seg)]
    for i, j, w, c in zip(si.tolist(), sj.tolist(), weight.tolist(), convex.tolist()):
        entry = adj[i].get(j)
        if entry is None:
            entry = adj[i][j] = adj[j][i] = [0.0, 0.0]  # one list shared by both directions
        entry[0 if c else 1] += w

    def find(x: int) -> int:
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for k in order.tolist():
        if not convex[k]:
            continue
        ri, rj = find(int(si[k])), find(int(sj[k]))
        if ri == rj:
            continue
        cv, cc = adj[ri].get(rj, (0.0, 0.0))
        if cc > max_concave_fraction * (cv + cc):
            continue
        if len(adj[ri]) < len(adj[rj]):
            ri, rj = rj, ri
        parent[rj] = ri  # fold rj's borders into ri's
        for nb, entry in adj[rj].items():
            if nb == ri:
                continue
            del adj[nb][rj]
            mine = adj[ri].get(nb)
            if mine is None:
                adj[ri][nb] = adj[nb][ri] = entry
            else:
                mine[0] += entry[0]
                mine[1] += entry[1]
        adj[ri].pop(rj, None)
        adj[rj] = {}
    return np.array([find(x) for x in range(n_seg)])


# ----------------------------------------------------------------------------------------------
# objects


def _outward_from_local_centre(centroids: np.ndarray, normals: np.ndarray, counts: np.ndarray, radius: float) -> np.ndarray:
    """For clouds without a viewpoint: each segment normal points away from the (point-weighted)
    centre of the segments within ``radius``, which lies inside the object the segment bounds."""
    tree = cKDTree(centroids)
    pairs = tree.query_pairs(radius, output_type="ndarray")
    i = np.concatenate([pairs[:, 0], pairs[:, 1], np.arange(len(centroids))])
    j = np.concatenate([pairs[:, 1], pairs[:, 0], np.arange(len(centroids))])
    w = counts[j]
    total = np.bincount(i, w, minlength=len(centroids))
    centre = np.stack([np.bincount(i, w * centroids[j, a], minlength=len(centroids)) for a in range(3)], axis=1) / total[:, None]
    outward = ((centroids - centre) * normals).sum(axis=1)
    return normals * np.where(outward < 0, -1.0, 1.0)[:, None]


def _outward_by_free_space(points: np.ndarray, centroids: np.ndarray, normals: np.ndarray, counts: np.ndarray,
                           radius: float, step: float) -> np.ndarray:
    """For clouds without a viewpoint: a surface was seen from its outside, so the space in front
    of it is empty. Each segment normal points to the side along which fewer points lie in a thin
    cylinder (probes every ``step`` up to ``radius``); ties fall back to the local-centre rule.
    Near-horizontal surfaces face up: scans see tops, and an object stacked on a top fills the
    space above it."""
    tree = cKDTree(points)
    ts = np.arange(2 * step, radius + 1e-9, step)
    score = np.zeros(len(centroids))
    for t in ts:
        ahead = tree.query_ball_point(centroids + t * normals, step, return_length=True)
        behind = tree.query_ball_point(centroids - t * normals, step, return_length=True)
        score += np.asarray(behind, float) - np.asarray(ahead, float)
    fallback = _outward_from_local_centre(centroids, normals, counts, radius)
    sign = np.where(score > 0, 1.0, np.where(score < 0, -1.0, 0.0))
    # near-horizontal surfaces were seen from above (what stands on a top blocks its free space)
    level = np.abs(normals[:, 2]) > 0.7
    sign = np.where(level, np.sign(normals[:, 2]), sign)
    return np.where(sign[:, None] == 0, fallback, normals * sign[:, None])


def _orient(normals: np.ndarray, away: np.ndarray) -> np.ndarray:
    """Flip normals so that they point against ``away`` (vectors pointing away from the viewer)."""
    sign = np.where((normals * away).sum(axis=1) > 0, -1.0, 1.0)
    return normals * sign[:, None]


def support_relations(points: np.ndarray, labels: np.ndarray, support: np.ndarray, height: np.ndarray,
                      planes: list[SupportPlane], params: SegmentParams) -> tuple[dict[int, int], dict[int, int | None]]:
    """Which plane each object ultimately stands on and which object (if any) it rests on.

    An object whose base (2nd height percentile) is more than ``stack_min_height`` above its
    support rests on the lower-based object owning most points right under its bottom points
    (within 1.5 cm in xy, from 5 cm below to 1 cm above the base).
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
    base = np.array([np.percentile(h[m], 2) for m in members])
    tree = cKDTree(pts[:, :2])
    for o in range(1, k + 1):
        m = members[o - 1]
        plane_idx = int(np.bincount(support[obj[m]]).argmax())
        support_of[o] = planes[plane_idx].id
        if base[o - 1] < params.stack_min_height:
            continue
        bottom = m[h[m] < base[o - 1] + 0.01]
        bottom = bottom[:: max(1, len(bottom) // 300)]
        dist, nn = tree.query(pts[bottom, :2], k=16, distance_upper_bound=0.015)
        nn = nn[np.isfinite(dist)]
        base_z = pts[bottom, 2].min()
        nn = nn[(owner[nn] != o) & (pts[nn, 2] < base_z + 0.01) & (pts[nn, 2] > base_z - 0.05)]
        nn = nn[base[owner[nn] - 1] < base[o - 1] - 0.005]  # only on something based lower: no cycles
        if len(nn):
            resting_on[o] = int(np.bincount(owner[nn]).argmax())
    # the plane an object ultimately stands on is that of the bottom of its stack
    for o in range(1, k + 1):
        below = resting_on[o]
        while below is not None:
            support_of[o] = support_of[below]
            below = resting_on[below]
    return support_of, resting_on


def segment_objects(points: np.ndarray, colors: np.ndarray | None, planes: list[SupportPlane],
                    grid_shape: tuple[int, int] | None, params: SegmentParams = SegmentParams(),
                    seed: int = 0) -> SegmentResult:
    """Label each point: 0 support/background, -1 noise, k > 0 object k (ordered by centroid x, then y).

    ``points`` (N, 3) are in the world frame (Z up) in input order, NaN rows allowed; ``colors``
    (N, 3) in [0, 1] or None; ``grid_shape`` (H, W) when the cloud is an organized image grid.
    The method is deterministic (``seed`` is accepted for interface uniformity; nothing is random).
    """
    points = np.asarray(points, dtype=np.float64)
    n = len(points)
    labels = np.zeros(n, dtype=np.int32)
    if colors is not None:
        colors = np.asarray(colors, dtype=np.float64)
        if not np.isfinite(colors).all():
            colors = np.nan_to_num(colors)
    support, height = assign_supports(points, planes, params)
    fg = support >= 0
    if fg.sum() < params.min_object_points:
        return SegmentResult(labels)
    organized = grid_shape is not None and grid_shape[0] * grid_shape[1] == n
    if organized:
        normals = grid_normals(points, fg, grid_shape, params.normal_window, params.jump_distance)
        a, b = grid_links(fg, grid_shape)
    else:
        normals = knn_normals(points, fg, params.normal_neighbors)
        a, b = knn_links(points, fg, params.knn_neighbors)
    keep = np.linalg.norm(points[a] - points[b], axis=1) < params.jump_distance
    a, b = a[keep], b[keep]

    ids = np.flatnonzero(fg & np.isfinite(normals).all(axis=1))
    if organized:
        sv_local = grid_supervoxels(points, colors, normals, ids, grid_shape, params)
    else:
        sv_local = cloud_supervoxels(points, colors, normals, ids, params)
    sv = np.full(n, -1, dtype=np.int64)
    sv[ids] = sv_local
    ok = (sv[a] >= 0) & (sv[b] >= 0)
    a, b = a[ok], b[ok]
    # supervoxels become connected parts; tiny parts join their best neighbour
    local = np.full(n, -1, dtype=np.int64)
    local[ids] = np.arange(len(ids))
    la, lb = local[a], local[b]
    same = sv[a] == sv[b]
    part = _components(len(ids), la[same], lb[same])
    part = absorb_small(part, la, lb, params.min_fragment_points)
    n_seg = int(part.max()) + 1

    cent, nrm, seg_count = segment_normals(points[ids], part, n_seg)
    if organized:
        # pixel normals point toward the camera: their sum gives the outward side of each segment
        away_seg = -np.stack([np.bincount(part, normals[ids, i], minlength=n_seg) for i in range(3)], axis=1)
    else:
        nrm = _outward_by_free_space(points[ids], cent, nrm, seg_count, params.orientation_radius, params.jump_distance)
        away_seg = -nrm
    nrm = _orient(nrm, away_seg)

    si, sj, cnt = _pair_counts(part[la], part[lb])
    contact = cnt >= params.min_contact_links
    si, sj = si[contact], sj[contact]
    convex = convex_connections(cent, nrm, si, sj, params.convex_tolerance)
    if colors is not None and params.color_edge is not None:  # a colour edge counts against joining
        col = np.stack([np.bincount(part, colors[ids, i], minlength=n_seg) for i in range(3)], axis=1) / seg_count[:, None]
        convex &= np.linalg.norm(col[si] - col[sj], axis=1) < params.color_edge
    cos = np.clip((nrm[si] * nrm[sj]).sum(axis=1), -1, 1)
    obj = merge_regions(n_seg, si, sj, cnt[contact], convex, np.argsort(-cos, kind="stable"), params.max_concave_fraction)[part]
    obj = absorb_small(obj, la, lb, params.absorb_points)
    size = np.bincount(obj)
    obj_labels = np.full(n, -1, dtype=np.int64)
    obj_labels[ids] = np.where(size[obj] >= params.min_object_points, obj, -1)
    labels[fg] = -1
    labels[ids] = _ordered(points, obj_labels)[ids]
    support_of, resting_on = support_relations(points, labels, support, height, planes, params)
    return SegmentResult(labels, support_of, resting_on)


def _ordered(points: np.ndarray, raw: np.ndarray) -> np.ndarray:
    """Relabel segments (>= 0) as 1..K by centroid x, then y; -1 stays -1."""
    out = np.full(len(raw), -1, dtype=np.int32)
    valid = raw >= 0
    if not valid.any():
        return out
    uniq, inv = np.unique(raw[valid], return_inverse=True)
    count = np.bincount(inv)
    cx = np.bincount(inv, points[valid, 0]) / count
    cy = np.bincount(inv, points[valid, 1]) / count
    order = np.lexsort((cy, cx))
    rank = np.empty(len(uniq), dtype=np.int32)
    rank[order] = np.arange(1, len(uniq) + 1)
    out[valid] = rank[inv]
    return out


def filter_by_size(points: np.ndarray, result: SegmentResult, planes: list[SupportPlane], params: SegmentParams) -> SegmentResult:
    """Keep the objects a capture can hold: clusters wider or taller than ``max_object_size`` are
    structure (0), ones smaller than ``min_object_size`` or floating above their support with
    nothing under them are noise (-1). The rest are renumbered 1..K in their order."""
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
        base = float(np.percentile(pts[:, 2], 2)) - height_of.get(result.support_of.get(o, -1), float(pts[:, 2].min()))
        if extent > params.max_object_size:
            fate[o] = 0
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
