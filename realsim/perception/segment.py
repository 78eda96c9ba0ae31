"""Object segmentation: the points above the supports, split into objects.

1. Foreground: points above a support (more than ``min_height``) and inside its polygon.
2. Links: image-grid 4-neighbours for an organized cloud, k nearest neighbours otherwise; links
   across depth jumps are cut. Normals come from grid tangents (pointing at the camera) or from
   k-neighbour covariances.
3. Supervoxels: SLIC on position, normal and colour, split into connected parts.
4. LCCP-style merging: adjacent supervoxels whose connection is convex (or flat within a
   tolerance) are joined, flattest first; two regions never join when their common border is
   mostly concave, so a stray convex pair at the contact of two objects cannot merge them.
5. Small pieces join their best neighbour; small isolated clusters are noise. In a camera view a
   segment covering an object's surface area (:mod:`realsim.perception.pixel_area`) that lies in
   front of its neighbours (:mod:`realsim.perception.in_front`) stays; a container's inside seen
   past its rim joins the rim (:mod:`realsim.perception.container_inside`), and a cluster whose
   outline continues the surface behind it is backdrop (:mod:`realsim.perception.backdrop_patch`).
   Objects standing on other objects are found from what lies right under their base.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from realsim.beside import Beside
from realsim.geometry import inside_convex_polygon
from realsim.perception.attached_parts import join_attached_parts
from realsim.perception.backdrop_patch import continues_backdrop
from realsim.perception.colour_split import split_by_colour
from realsim.perception.contact_cut import CutParams, cut_contacts
from realsim.perception.container_floor import claim_enclosed_floors
from realsim.perception.container_inside import join_insides, join_outsides
from realsim.perception.footprints import merge_shared_footprints
from realsim.perception.in_front import in_front
from realsim.perception.object_relations import base_height, filter_by_size, support_relations
from realsim.perception.occlusion_bridge import occluded_pairs, view_axis
from realsim.perception.pixel_area import pixel_areas
from realsim.perception.plane_patches import connected_groups
from realsim.perception.segment_params import SegmentParams, SegmentResult
from realsim.perception.shallow_folds import join_shallow_folds
from realsim.perception.stack_split import split_resting
from realsim.perception.step_joins import join_hidden_steps
from realsim.perception.supervoxels import cloud_supervoxels, grid_links, grid_normals, grid_supervoxels, knn_links, knn_normals, smallest_eigenvectors
from realsim.perception.supervoxels import link_components as _components
from realsim.perception.visibility import OccupancyGrid, visibility_score
from realsim.scene import SupportPlane

__all__ = ["SegmentParams", "SegmentResult", "assign_supports", "filter_by_size", "segment_objects"]


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
                below = z[candidate] < upper.height + params.min_height
                under |= below & _rising_under_rectangle(points[candidate], upper, params)
                candidate = candidate[~(under & below)]
        support[candidate] = i
        height[candidate] = h[candidate]
    return support, height


def _rising_under_rectangle(points: np.ndarray, upper: SupportPlane, params: SegmentParams) -> np.ndarray:
    """Mask of ``points`` below ``upper`` in a connected group (cells of ``structure_margin``) of
    them that rises to within ``structure_reach`` under its height inside its rectangle (its top's
    seen extent, grown by ``structure_margin``): the legs and apron under a part of the top that
    objects on it hid (its seen polygon has that corner cut off), whole, not things on the floor."""
    below = np.flatnonzero(points[:, 2] < upper.height)
    local = upper.rect_local(points[below, :2])
    rising = np.all(np.abs(local) <= np.asarray(upper.rect_size) / 2 + params.structure_margin, axis=1)
    rising &= points[below, 2] >= upper.height - params.structure_reach
    out = np.zeros(len(points), dtype=bool)
    if not rising.any():
        return out
    for group in connected_groups(points[below], params.structure_margin):
        if rising[group].any():
            out[below[group]] = True
    return out


# ----------------------------------------------------------------------------------------------
# graphs over segments


def _pair_counts(la: np.ndarray, lb: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Distinct unordered label pairs (i < j) among links between different labels, with link counts."""
    cross = la != lb
    lo, hi = np.minimum(la[cross], lb[cross]), np.maximum(la[cross], lb[cross])
    base = int(hi.max(initial=0)) + 1
    keys, counts = np.unique(lo.astype(np.int64) * base + hi, return_counts=True)
    return keys // base, keys % base, counts


def absorb_small(labels: np.ndarray, a: np.ndarray, b: np.ndarray, min_size: int, passes: int = 3,
                 among_small: bool = False, whole: np.ndarray | None = None) -> np.ndarray:
    """Give each segment smaller than ``min_size`` to the neighbour it shares most links with.

    ``labels`` are segment indices (>= 0) of the linked points; segments with no neighbour stay.
    With ``among_small``, small segments whose neighbours are all small then gather, each in its
    best larger neighbour, where together they reach ``min_size`` (an object seen small is all
    pieces, none of which is an object by itself); smaller gatherings stay as they were. Segments
    holding a point marked in ``whole`` are objects whatever their size: never absorbed.
    """
    out = _absorb(labels, a, b, min_size, passes, False, whole)
    if among_small:
        gathered = _absorb(out, a, b, min_size, passes, True, whole)
        enough = np.bincount(gathered)[gathered] >= min_size
        out = np.where(enough, gathered, out + int(gathered.max(initial=0)) + 1)
    return np.unique(out, return_inverse=True)[1].ravel()


def _absorb(labels: np.ndarray, a: np.ndarray, b: np.ndarray, min_size: int, passes: int,
            among_small: bool, whole: np.ndarray | None) -> np.ndarray:
    """:func:`absorb_small`'s passes; ``among_small``: a small segment with no large neighbour
    joins its best larger (small) one."""
    labels = labels.copy()
    for _ in range(passes):
        size = np.bincount(labels)
        small = size < min_size
        if whole is not None:
            small &= np.bincount(labels, weights=whole, minlength=len(size)) == 0
        if not small.any():
            break
        i, j, c = _pair_counts(labels[a], labels[b])
        src = np.concatenate([i, j])
        dst = np.concatenate([j, i])
        cnt = np.concatenate([c, c]).astype(np.float64)
        keep = small[src] & ~small[dst]
        if among_small:
            has_large = np.zeros(len(size), dtype=bool)
            has_large[src[keep]] = True
            larger = (size[dst] > size[src]) | ((size[dst] == size[src]) & (dst > src))
            keep |= small[src] & small[dst] & ~has_large[src] & larger
        if not keep.any():
            break
        src, dst, cnt = src[keep], dst[keep], cnt[keep]
        order = np.lexsort((-size[dst], -cnt, src))  # best neighbour first: most links, then largest
        src, dst = src[order], dst[order]
        first = np.r_[True, src[1:] != src[:-1]]
        target = np.arange(len(size))
        target[src[first]] = dst[first]
        labels = target[labels]
    return labels


def segment_normals(points: np.ndarray, labels: np.ndarray, n_seg: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Centroid, plane-fit normal (unoriented) and point count of each segment."""
    count = np.bincount(labels, minlength=n_seg).astype(np.float64)
    c = np.stack([np.bincount(labels, points[:, i], minlength=n_seg) for i in range(3)], axis=1) / np.maximum(count, 1)[:, None]
    d = points - c[labels]
    cov = np.empty((n_seg, 3, 3))
    for i in range(3):
        for j in range(i, 3):
            cov[:, i, j] = cov[:, j, i] = np.bincount(labels, d[:, i] * d[:, j], minlength=n_seg) / np.maximum(count, 1)
    return c, smallest_eigenvectors(cov), count


def convex_connections(centroids: np.ndarray, normals: np.ndarray, i: np.ndarray, j: np.ndarray,
                       tolerance_deg: float) -> np.ndarray:
    """LCCP test: the connection of segments i and j is convex (or flat within the tolerance).

    With outward normals, (n_i - n_j) . (c_i - c_j) > 0 on a convex edge and < 0 on a concave one.
    """
    d = centroids[i] - centroids[j]
    d /= np.maximum(np.linalg.norm(d, axis=1, keepdims=True), 1e-12)
    cos = np.clip((normals[i] * normals[j]).sum(axis=1), -1, 1)
    flat = cos > np.cos(np.radians(tolerance_deg))
    out: np.ndarray = flat | (((normals[i] - normals[j]) * d).sum(axis=1) > 0)
    return out


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
                           radius: float, step: float, grid: OccupancyGrid | None, tree: cKDTree | None = None) -> np.ndarray:
    """For clouds without a viewpoint: a surface was seen from its outside, so the space in front
    of it is empty. Each segment normal points to the side along which fewer points lie in a thin
    cylinder (probes every ``step`` up to ``radius``); ties fall back to the local-centre rule.
    With a ``grid`` (the cloud's occupancy at its resolution, fine enough), patches are oriented by what each side
    sees (:mod:`realsim.perception.visibility`) where that decides: at a contact between two
    objects the free space in front of a side is the other object's. Near-horizontal surfaces
    face up: scans see tops, and an object stacked on a top fills the space above it. ``tree``: one of ``points``."""
    tree = tree if tree is not None else cKDTree(points)
    ts = np.arange(2 * step, radius + 1e-9, step)
    score = np.zeros(len(centroids))
    for t in ts:
        ahead = tree.query_ball_point(centroids + t * normals, step, return_length=True)
        behind = tree.query_ball_point(centroids - t * normals, step, return_length=True)
        score += np.asarray(behind, float) - np.asarray(ahead, float)
    fallback = _outward_from_local_centre(centroids, normals, counts, radius)
    sign = np.where(score > 0, 1.0, np.where(score < 0, -1.0, 0.0))
    if grid is not None:
        seen = visibility_score(grid, centroids, normals, grid.cell, 5 * radius, settle=2)  # only |seen| >= 2 decides
        sign = np.where(np.abs(seen) >= 2, np.sign(seen), sign)
    # near-horizontal surfaces were seen from above (what stands on a top blocks its free space)
    level = np.abs(normals[:, 2]) > 0.7
    sign = np.where(level, np.sign(normals[:, 2]), sign)
    return np.where(sign[:, None] == 0, fallback, normals * sign[:, None])


def _point_outward(points: np.ndarray, normals: np.ndarray, working: float, params: SegmentParams,
                   grid: OccupancyGrid | None) -> np.ndarray | None:
    """Each point's normal on its outward side for a cloud whose ``working`` resolution is at most
    ``contact_cut_cell`` (else None): what the point itself sees where that decides (a cloud
    with a ``grid``, :mod:`realsim.perception.visibility`), else the side it was given (its patch's)."""
    if working > params.contact_cut_cell:
        return None
    if grid is None:
        return normals
    # neighbours two cells apart that face one way see alike: one ray cast for them
    seen = visibility_score(grid, points, normals, grid.cell, 5 * params.orientation_radius, group=2 * grid.cell,
                            settle=2)  # only seen <= -2 decides
    return normals * np.where(seen <= -2, -1.0, 1.0)[:, None]


def _spacing(points: np.ndarray, tree: cKDTree | None = None) -> float:
    """Median distance from a point to its nearest neighbour (on a deterministic subset); ``tree``: one of ``points``."""
    if len(points) < 2:
        return float("inf")
    sample = points[:: max(1, len(points) // 5000)]
    return float(np.median((tree if tree is not None else cKDTree(points)).query(sample, k=2)[0][:, 1]))


def _with_known(normals: np.ndarray | None, known: np.ndarray | None, ids: np.ndarray) -> np.ndarray | None:
    """``normals`` (of the points ``ids``) turned to the outward side ``known`` gives (a mesh's
    winding) where it decides (finite, not square to them): the direction stays the estimate at the
    working resolution, the side is the capture's own rather than guessed from free space."""
    if normals is None or known is None:
        return normals
    side = np.nan_to_num((normals * known[ids]).sum(axis=1))
    return normals * np.where(side < 0, -1.0, 1.0)[:, None]


def _orient(normals: np.ndarray, away: np.ndarray) -> np.ndarray:
    """Flip normals so that they point against ``away`` (vectors pointing away from the viewer)."""
    sign = np.where((normals * away).sum(axis=1) > 0, -1.0, 1.0)
    return normals * sign[:, None]


def segment_objects(points: np.ndarray, colors: np.ndarray | None, planes: list[SupportPlane],
                    grid_shape: tuple[int, int] | None, params: SegmentParams = SegmentParams(),
                    seed: int = 0, resolution: float | None = None, context: np.ndarray | None = None,
                    known_normals: np.ndarray | None = None, jump_limits: np.ndarray | None = None) -> SegmentResult:
    """Label each point: 0 support/background, -1 noise, k > 0 object k (ordered by centroid x, then y).

    ``points`` (N, 3) are in the world frame (Z up) in input order, NaN rows allowed; ``colors``
    (N, 3) in [0, 1] or None; ``grid_shape`` (H, W) when the cloud is an organized image grid;
    ``resolution`` (m) the working resolution of an unorganized cloud (None: its measured spacing);
    ``context`` (M, 3) points that are not segmented but block the view (walls left out before);
    ``known_normals`` (N, 3) outward normals the capture knows (a mesh's faces, not necessarily unit;
    NaN or zero rows where unknown): they decide the outward side of an unorganized cloud's
    estimated point normals; ``jump_limits`` (N,) a camera view's per-pixel length beyond which a link
    from the pixel crosses a depth jump (:func:`realsim.perception.depth_jumps.pixel_jumps`; None:
    ``params.jump_distance`` everywhere).
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
    measured = Beside(lambda: _measured_normals(points, grid_shape, params)) if organized else None  # read at the end, made beside
    grid: OccupancyGrid | None = None  # unorganized clouds fine enough: their occupancy, for visibility
    working = float("inf")
    if organized:
        assert grid_shape is not None
        normals = grid_normals(points, fg, grid_shape, params.normal_window,
                               params.jump_distance if jump_limits is None else jump_limits)
        a, b = grid_links(fg, grid_shape)
    else:
        normals = knn_normals(points, fg, params.normal_neighbors)
        a, b = knn_links(points, fg, params.knn_neighbors)
    limit = np.minimum(jump_limits[a], jump_limits[b]) if organized and jump_limits is not None else params.jump_distance
    keep = np.linalg.norm(points[a] - points[b], axis=1) < limit
    axis = view_axis(points, a[~keep], b[~keep], normals, params.jump_distance) if organized else None
    a, b = a[keep], b[keep]

    ids = np.flatnonzero(fg & np.isfinite(normals).all(axis=1))
    if organized:
        assert grid_shape is not None
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
        tree = cKDTree(points[ids]) if len(ids) >= 2 else None  # one tree for the spacing and the free-space probes
        cell = _spacing(points[ids], tree)  # voxel centres lie closer than their voxels: a finer, still closed grid
        working = resolution if resolution is not None else cell
        if working <= params.visibility_cell:  # fine enough to see which side of a patch is open
            grid = OccupancyGrid(points[ids] if context is None else np.vstack([points[ids], context]), cell)
        nrm = _outward_by_free_space(points[ids], cent, nrm, seg_count, params.orientation_radius, params.jump_distance, grid, tree)
        if known_normals is not None:  # the capture's own outward side (a mesh's faces), summed over each segment
            known = np.nan_to_num(known_normals[ids])
            nrm = _with_known(nrm, np.stack([np.bincount(part, known[:, i], minlength=n_seg) for i in range(3)], axis=1),
                              np.arange(n_seg))
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
    if organized and grid_shape is not None:  # a small object in front of its neighbours is no piece of them
        obj = _absorb_view(points, normals, ids, obj, local, grid_links(fg, grid_shape), la, lb, grid_shape, axis, params)
    else:
        obj = absorb_small(obj, la, lb, params.absorb_points)
    size = np.bincount(obj)
    obj_labels = np.full(n, -1, dtype=np.int64)
    obj_labels[ids] = np.where(size[obj] >= params.min_object_points, obj, -1)
    if axis is not None and grid_shape is not None:  # pieces of one object parted by a nearer one
        obj_labels = _bridge_occlusions(points, obj_labels, normals, grid_shape, axis, params)
        if params.fold_max_angle is not None:  # pieces of one body that meet in a shallow fold (before colour tells bodies apart)
            obj_labels = join_shallow_folds(obj_labels, points, normals, grid_shape,
                                            params.jump_distance if jump_limits is None else jump_limits, params.fold_max_angle,
                                            params.fold_window, params.min_contact_links, params.fold_continuous_share)
        if params.step_max_gap is not None:  # a body's nearer piece hiding the foot of its farther piece
            obj_labels = join_hidden_steps(obj_labels, points, normals, grid_shape, axis,
                                           params.jump_distance if jump_limits is None else jump_limits, params.step_max_gap,
                                           params.step_max_facing, params.min_contact_links, params.step_consistent_share)
        if colors is not None:  # touching objects of two colours that meet in a fold
            obj_labels[ids] = split_by_colour(colors[ids], obj_labels[ids], la, lb, params.min_object_points, normals[ids],
                                              view_points=points[ids])
            # a container's outer wall that a touching object held until the colours parted them
            obj_labels = join_outsides(obj_labels, grid_shape, points, normals, points @ axis, params.jump_distance,
                                       params.inside_concavity, params.inside_rim_share)
    if not organized:  # a cloud seen from around: contacts cut at their concave fold, whole footprints seen
        patch_normals = _with_known(_orient(normals[ids], -nrm[part]), known_normals, ids)
        assert patch_normals is not None  # given normals, _with_known returns normals
        point_normals = _with_known(_point_outward(points[ids], patch_normals, working, params, grid), known_normals, ids)
        if point_normals is not None:  # a coarse cloud's point normals span whole small objects: no cut
            cut = CutParams(min_size=params.min_object_size, min_points=params.min_object_points,
                            stand_height=params.stack_min_height)
            obj_labels[ids] = cut_contacts(points[ids], point_normals, height[ids], obj_labels[ids], la, lb, cut)
        if colors is not None:  # where no fold is seen (or cut), the colours tell touching objects apart
            obj_labels[ids] = split_by_colour(colors[ids], obj_labels[ids], la, lb, params.min_object_points,
                                              patch_normals if point_normals is None else point_normals)
        obj_labels[ids] = split_resting(points[ids], patch_normals if point_normals is None else point_normals,
                                        obj_labels[ids], la, lb, working, params.min_object_points, params.min_object_size)
        obj_labels[ids] = _join_footprints(points[ids], obj_labels[ids], support[ids], height[ids], params, working)
    labels[fg] = -1
    labels[ids] = _ordered(points, obj_labels)[ids]
    support_of, resting_on = support_relations(points, labels, support, height, planes, params)
    if not organized:  # a cloud: a handle or a piece of wall resting on its body away from its own foot is the body's
        joined = join_attached_parts(points, labels, height, resting_on, params.stack_min_height, 2 * params.jump_distance,
                                     params.jump_distance, links=(a, b), base_gap=params.base_gap)
        if not np.array_equal(joined, labels):
            labels = _renumbered(points, joined)
            support_of, resting_on = support_relations(points, labels, support, height, planes, params)
        joined = _join_footprints_on_objects(points, labels, resting_on, height, working)
        if not np.array_equal(joined, labels):  # two clusters resting on one object in one place: one object
            labels = _renumbered(points, joined)
            support_of, resting_on = support_relations(points, labels, support, height, planes, params)
    if axis is not None and grid_shape is not None:  # a view: a patch cut out of the surface behind is backdrop
        assert measured is not None
        kept = _drop_backdrop_patches(points, labels, grid_shape, axis, planes, params, measured.result())
        if kept is not labels:  # a patch was dropped: the relations of what is left
            labels = kept
            support_of, resting_on = support_relations(points, labels, support, height, planes, params)
        joined = join_attached_parts(points, labels, height, resting_on, params.stack_min_height, 2 * params.jump_distance,
                                     params.jump_distance, axis, grid_shape, normals=normals,
                                     rest_face_angle=params.rest_face_angle)
        if not np.array_equal(joined, labels):  # a handle or a container's inside is its body's
            labels = _renumbered(points, joined)
            support_of, resting_on = support_relations(points, labels, support, height, planes, params)
        claimed = claim_enclosed_floors(labels, points, _on_supports(points, labels, planes, params), grid_shape)
        if not np.array_equal(claimed, labels):  # a container's floor, seen through its opening
            labels = claimed
            support_of, resting_on = support_relations(points, labels, support, height, planes, params)
    return SegmentResult(labels, support_of, resting_on)


def _renumbered(points: np.ndarray, joined: np.ndarray) -> np.ndarray:
    """Labels after objects were joined (``joined``: 0 support, -1 noise, k objects, some numbers gone), renumbered 1..K."""
    labels = _ordered(points, np.where(joined > 0, joined, -1)).astype(np.int32)
    labels[joined == 0] = 0
    return labels


def _on_supports(points: np.ndarray, labels: np.ndarray, planes: list[SupportPlane], params: SegmentParams) -> np.ndarray:
    """Mask of the unlabelled points within ``min_height`` of an observed support's top, inside its polygon."""
    out = np.zeros(len(points), dtype=bool)
    for plane in planes:
        if plane.observed:
            with np.errstate(invalid="ignore"):
                near = np.flatnonzero((labels == 0) & (np.abs(points[:, 2] - plane.height) <= params.min_height))
            out[near[inside_convex_polygon(points[near, :2], plane.polygon, params.polygon_margin)]] = True
    return out


def _measured_normals(points: np.ndarray, grid_shape: tuple[int, int], params: SegmentParams) -> np.ndarray:
    """Normals of every measured pixel of a camera view (:func:`grid_normals` over the finite points)."""
    return grid_normals(points, np.isfinite(points).all(axis=1), grid_shape, params.normal_window, params.jump_distance)


def _drop_backdrop_patches(points: np.ndarray, labels: np.ndarray, grid_shape: tuple[int, int], axis: np.ndarray,
                           planes: list[SupportPlane], params: SegmentParams, normals: np.ndarray) -> np.ndarray:
    """A camera view's ``labels`` with the clusters that mostly continue into unlabelled pixels
    (:func:`continues_backdrop`, over the ``normals`` of every measured pixel, :func:`_measured_normals`)
    made 0 and the rest renumbered. Pixels on a support's top (within ``min_height`` of it, inside its
    polygon) are no backdrop: an object's own foot lies there."""
    valid = np.isfinite(points).all(axis=1)
    a, b = grid_links(valid, grid_shape)
    behind = labels.copy()
    behind[_on_supports(points, labels, planes, params)] = -1
    patch = continues_backdrop(behind, a, b, points @ axis, normals, params.jump_distance, params.convex_tolerance,
                               params.backdrop_share)
    if not patch.any():
        return labels
    out = np.where(patch[np.maximum(labels, 0)] & (labels > 0), 0, labels).astype(labels.dtype)
    obj = out > 0
    out[obj] = _ordered(points, np.where(obj, out, -1))[obj]
    return out


def _absorb_view(points: np.ndarray, normals: np.ndarray, ids: np.ndarray, obj: np.ndarray, local: np.ndarray,
                 pairs: tuple[np.ndarray, np.ndarray], la: np.ndarray, lb: np.ndarray, grid_shape: tuple[int, int], axis: np.ndarray | None,
                 params: SegmentParams) -> np.ndarray:
    """A camera view's small segments (``obj`` over ``ids``, linked by ``la``-``lb``) joined to their
    neighbours, except those covering an object's surface area (``min_view_area``, m^2) that lie in
    front of their neighbours (:func:`in_front`, over the image ``pairs``); a container's inside seen
    through its rim then joins the rim (:func:`join_insides`), and the outer wall under a rim joins the
    inside (:func:`join_outsides`). The pieces the supervoxels leave are
    counted in pixels, as the supervoxels are seeded."""
    whole = None
    if axis is not None:
        pa, pb = local[pairs[0]], local[pairs[1]]
        both = (pa >= 0) & (pb >= 0)
        front = in_front(obj, pa[both], pb[both], points[ids] @ axis, normals[ids], params.jump_distance,
                         params.convex_tolerance, params.front_share)
        front &= np.bincount(obj, weights=pixel_areas(points, grid_shape, params.jump_distance)[ids]) >= params.min_view_area
        whole = front[obj]
    obj = absorb_small(obj, la, lb, params.absorb_points, among_small=True, whole=whole)
    if axis is None:
        return obj
    full = np.full(len(points), -1, dtype=np.int64)
    full[ids] = obj
    full = join_insides(full, grid_shape, points, normals, points @ axis, params.jump_distance, params.inside_concavity,
                        params.inside_rim_share)
    full = join_outsides(full, grid_shape, points, normals, points @ axis, params.jump_distance, params.inside_concavity,
                         params.inside_rim_share)
    out: np.ndarray = full[ids]
    return out


def _bridge_occlusions(points: np.ndarray, labels: np.ndarray, normals: np.ndarray, grid_shape: tuple[int, int],
                       axis: np.ndarray, params: SegmentParams) -> np.ndarray:
    """Join the segments (``labels`` >= 0) that one nearer object parts in a camera view. Over the image
    lines where only nearer pixels lie between them, the hidden connection of the surfaces seen at the
    two ends mostly (all but ``max_concave_fraction``) curves away (:func:`convex_connections` without a
    flat tolerance; two objects side by side behind the occluder meet at a concave one), and on at least
    ``min_contact_links`` lines it also runs along both (within ``convex_tolerance`` of their tangent
    planes; not into the view, as from an object to one behind it): one surface passing behind."""
    pair, ends, end_normals = occluded_pairs(points, labels + 1, normals, grid_shape, axis, params.jump_distance)
    if len(pair) == 0:
        return labels
    k = np.arange(len(pair))
    convex = convex_connections(ends.reshape(-1, 3), end_normals.reshape(-1, 3), 2 * k, 2 * k + 1, 0.0)  # curving away, not flat
    chord = ends[:, 1] - ends[:, 0]
    chord /= np.maximum(np.linalg.norm(chord, axis=1, keepdims=True), 1e-12)
    with np.errstate(invalid="ignore"):  # the hidden stretch runs along the surface seen at both ends, not into the view
        along = np.all(np.abs((end_normals * chord[:, None]).sum(axis=2)) < np.sin(np.radians(params.convex_tolerance)), axis=1)
    keys, inverse, lines = np.unique(np.sort(pair, axis=1) - 1, axis=0, return_inverse=True, return_counts=True)
    mostly_convex = lines - np.bincount(inverse.ravel(), convex, minlength=len(keys)) <= params.max_concave_fraction * lines
    keys = keys[mostly_convex & (np.bincount(inverse.ravel(), convex & along, minlength=len(keys)) >= params.min_contact_links)]
    if len(keys) == 0:
        return labels
    root = _components(int(labels.max()) + 1, keys[:, 0], keys[:, 1])
    return np.where(labels >= 0, root[np.maximum(labels, 0)], labels)


def _join_footprints(points: np.ndarray, labels: np.ndarray, support: np.ndarray, height: np.ndarray,
                     params: SegmentParams, cell: float) -> np.ndarray:
    """:func:`merge_shared_footprints` (on a grid of ``cell``, m) of the clusters whose base is on their support."""
    if not (labels >= 0).any():
        return labels
    standing = np.zeros(int(labels.max()) + 1, dtype=bool)
    for k in np.unique(labels[labels >= 0]):
        standing[k] = base_height(height[labels == k], params.base_gap) < params.stack_min_height
    return merge_shared_footprints(points[:, :2], labels, support, standing, cell, height=height)


def _join_footprints_on_objects(points: np.ndarray, labels: np.ndarray, resting_on: dict[int, int | None],
                                height: np.ndarray, cell: float) -> np.ndarray:
    """:func:`merge_shared_footprints` (on a grid of ``cell``, m) of the objects (labels >= 1) resting
    on one object, that object their home: two things on a box cannot stand in the same place
    either (a pitcher's handle, cut from it at a crease, stands on the box the pitcher stands on)."""
    home = np.full(len(labels), -1, dtype=np.int64)
    for o, under in resting_on.items():
        if under is not None:
            home[labels == o] = under
    homes = list(resting_on.values())
    if not any(u is not None and homes.count(u) > 1 for u in homes):
        return labels
    standing = np.zeros(int(labels.max()) + 1, dtype=bool)
    standing[[o for o, under in resting_on.items() if under is not None]] = True
    on = home >= 0
    merged = merge_shared_footprints(points[:, :2], np.where(on, labels, -1), home, standing, cell, height=height)
    return np.where(on, merged, labels)


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
