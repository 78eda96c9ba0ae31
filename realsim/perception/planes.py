"""Support planes: level the capture on its dominant support and find every horizontal surface.

Seeded RANSAC proposes planes on a voxel-downsampled copy; each horizontal proposal is
split into connected regions in xy and refitted by least squares on the full-resolution points
near it, which is what brings the height to millimetres.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np
from scipy import ndimage
from scipy.spatial import cKDTree

from realsim.errors import InputError
from realsim.geometry import inside_convex_polygon, polygon_and_rectangle, ransac_plane, rotation_between
from realsim.perception.level_patches import level_heights
from realsim.perception.plane_patches import surface_of
from realsim.perception.plane_refit import level_unless_resolved, refine_plane
from realsim.perception.resolution import PLAUSIBLE_EXTENT, working_resolution
from realsim.perception.up_axis import evidence_points, resting_normal
from realsim.scene import Scene, SupportPlane


@dataclass(frozen=True)
class PlaneParams:
    """Parameters of plane detection and levelling."""

    voxel_size: float = 0.01  # downsampling for RANSAC proposals (m)
    distance_threshold: float = 0.01  # RANSAC inlier distance (m)
    ransac_iterations: int = 1000
    max_planes: int = 8  # proposals examined
    min_plane_points: int = 100  # (downsampled) points for a proposal to count
    min_level_points: int = 50  # (downsampled) points facing up at one height that propose a horizontal plane there
    level_max_tilt_deg: float = 60.0  # dominant support searched within this of the coarse up
    resting_max_tilt_deg: float = 20.0  # ... or within this of the plane bodies rest on, when large planes disagree
    min_support_share: float = 0.04  # of a camera view's planar points: a smaller plane facing the picture's up is a thing's face
    view_max_tilt_deg: float = 75.0  # ... of a camera view's picture up: its seen, upper side (a camera looking down steeply)
    overhead_max_tilt_deg: float = 20.0  # ... else of the camera's backward axis: a camera looking (nearly) straight down
    support_max_tilt_deg: float = 8.0  # a support is horizontal within this after levelling
    refine_threshold: float = 0.006  # full-resolution refit band (m)
    region_cell: float = 0.02  # grid cell for splitting a plane into regions (m)
    min_support_area: float = 0.03  # observed area (occupied grid cells) of a support, m^2
    min_support_width: float = 0.12  # m: a higher surface narrower than this is a ledge (a wall's top), no support
    merge_height_tol: float = 0.02  # regions within this height are one surface (m)
    merge_gap: float = 0.5  # ... when their hulls come this close in xy (m)
    min_support_gap: float = 0.25  # a flat top closer than this above a support is an object (m)
    under_margin: float = 0.05  # a lower plane reaching this close to a support's outline lies under it (m)
    floor_min_gap: float = 0.3  # a support this far below another one is the floor (m)
    floor_min_size: float = 1.5  # a lowest support this large in both directions is the floor (m)
    assumed_support_height: float = 0.75  # height given to the lowest support when no floor is seen
    max_support_height: float = 2.5  # planes higher than this above the floor are ceilings
    max_covered_fraction: float = 0.5  # a surface mostly covered by another just above it is an underside
    covered_band: tuple[float, float] = (0.01, 0.08)  # ... within this height band above it (m)
    max_work_points: int = 500_000  # denser captures are worked on a seeded subset (3x denser: voxels at their resolution first)
    table_heights: tuple[float, float] = (0.4, 1.2)  # plausible table or counter tops above the floor (m)


def _finite(points: np.ndarray) -> np.ndarray:
    return np.asarray(np.isfinite(points).all(axis=1))


def _voxel_keys(points: np.ndarray, voxel: float) -> np.ndarray:
    """One int64 key per point: its cell of a ``voxel`` grid anchored at the points' lower corner,
    so the same surface in other units, moved or reordered, gets the same keys."""
    cells = np.floor((points - points.min(axis=0)) / voxel).astype(np.int64)
    span = cells.max(axis=0) + 1
    return (cells[:, 0] * span[1] + cells[:, 1]) * span[2] + cells[:, 2]


def _mix(keys: np.ndarray) -> np.ndarray:
    """A fixed pseudo-random permutation of int64 keys (splitmix64's finalizer): a seed-free,
    unit-free random order of the cells."""
    z = keys.astype(np.uint64) + np.uint64(0x9E3779B97F4A7C15)
    with np.errstate(over="ignore"):
        z = (z ^ (z >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
        z = (z ^ (z >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
    return z ^ (z >> np.uint64(31))


def voxel_downsample(points: np.ndarray, voxel: float, keyed: bool = False) -> np.ndarray:
    """Centroid of the points in each occupied voxel of a grid anchored at the points' lower
    corner, in sorted-key order, or with ``keyed`` in an order drawn from the cells' keys (a random
    order that units, a shift or the points' order do not change)."""
    keys = _voxel_keys(points, voxel)
    uniq, inverse, counts = np.unique(keys, return_inverse=True, return_counts=True)
    sums = np.zeros((len(counts), 3))
    for axis in range(3):
        sums[:, axis] = np.bincount(inverse.ravel(), weights=points[:, axis], minlength=len(counts))
    centroids = sums / counts[:, None]
    return centroids[np.argsort(_mix(uniq), kind="stable")] if keyed else centroids


def ransac_proposals(points: np.ndarray, params: PlaneParams, seed: int) -> list[tuple[np.ndarray, float, np.ndarray]]:
    """Planes found by repeated seeded RANSAC on a voxel-downsampled copy: (normal, d, inlier
    points) each, largest first. Deterministic: the same input and seed give the same planes.
    The copy is in a key-drawn random order and RANSAC scores on its head, so a few voxels that
    float rounding (other units, a shift) adds or drops change a few scored points, not all."""
    remaining = voxel_downsample(points, params.voxel_size, keyed=True)
    rng = np.random.default_rng(seed)
    proposals = []
    for _ in range(params.max_planes):
        if len(remaining) < params.min_plane_points:
            break
        normal, d, inliers = ransac_plane(remaining, params.distance_threshold, params.ransac_iterations, rng, shuffled=True)
        if len(inliers) < params.min_plane_points:
            break
        proposals.append((normal, d, remaining[inliers]))
        keep = np.ones(len(remaining), dtype=bool)
        keep[inliers] = False
        remaining = remaining[keep]
    return proposals


def _regions(xy: np.ndarray, cell: float, min_area: float) -> list[np.ndarray]:
    """Connected regions of points on an xy grid covering at least ``min_area``; index arrays."""
    lo = xy.min(axis=0)
    ij = np.floor((xy - lo) / cell).astype(np.int64)
    grid = np.zeros(ij.max(axis=0) + 1, dtype=bool)
    grid[ij[:, 0], ij[:, 1]] = True
    grid = ndimage.binary_closing(grid, structure=np.ones((3, 3)), iterations=1, border_value=0) | grid
    labels, count = ndimage.label(grid, structure=np.ones((3, 3)))
    point_labels = labels[ij[:, 0], ij[:, 1]]
    occupied = np.bincount(point_labels, minlength=count + 1)
    cells = np.zeros(count + 1, dtype=np.int64)
    flat = np.unique(ij[:, 0] * (ij[:, 1].max() + 1) + ij[:, 1])
    unique_cells = np.stack([flat // (ij[:, 1].max() + 1), flat % (ij[:, 1].max() + 1)], axis=1)
    np.add.at(cells, labels[unique_cells[:, 0], unique_cells[:, 1]], 1)
    big = [k for k in range(1, count + 1) if cells[k] * cell * cell >= min_area and occupied[k] >= 3]
    return [np.flatnonzero(point_labels == k) for k in big]


def _transform(points: np.ndarray, rotation: np.ndarray, translation: np.ndarray) -> np.ndarray:
    return np.asarray(points @ rotation.T + translation)


def _orient_up(normal: np.ndarray, d: float, viewpoint: np.ndarray | None) -> tuple[np.ndarray, float]:
    """Sign a plane so its normal points up: toward the camera for camera views, else +z."""
    if viewpoint is not None:
        flip = normal @ viewpoint + d < 0
    else:
        flip = normal[2] < 0
    return (-normal, -d) if flip else (normal, d)


def _apply_rigid(scene: Scene, rotation: np.ndarray, translation: np.ndarray) -> None:
    """Apply a rigid motion to the scene's points (and their normals) and compose it into input_to_world."""
    step = np.eye(4)
    step[:3, :3] = rotation
    step[:3, 3] = translation
    if scene.points is not None:
        scene.points = _transform(scene.points, rotation, translation)
    if scene.normals is not None:
        scene.normals = scene.normals @ rotation.T
    scene.capture.input_to_world = step @ scene.capture.input_to_world


def _size(candidate: tuple[np.ndarray, float, np.ndarray]) -> int:
    """A plane proposal's inlier count."""
    return len(candidate[2])


def _has_support(candidates: list[tuple[np.ndarray, float, np.ndarray]], planar: int, params: PlaneParams) -> bool:
    """Whether a candidate holds ``params.min_support_share`` of a view's ``planar`` points (else all are things' faces)."""
    return any(len(c[2]) >= params.min_support_share * planar for c in candidates)


def _resting_direction(work: np.ndarray, big: list[tuple[np.ndarray, float, np.ndarray]], params: PlaneParams,
                       seed: int) -> np.ndarray | None:
    """The normal bodies rest on (:func:`resting_normal`, on :func:`evidence_points` of ``work``) when two
    of the ``big`` proposals are far from parallel, so the size-and-tilt rule could level on a
    wall; else None (one support direction: nothing to decide)."""
    cos_rest = np.cos(np.radians(params.resting_max_tilt_deg))
    if not any(abs(float(a[0] @ b[0])) < cos_rest for i, a in enumerate(big) for b in big[i + 1:]):
        return None
    rng = np.random.default_rng(seed)
    sample, threshold = evidence_points(work, rng)
    return resting_normal(sample, threshold, rng)


def _facing(proposals: list[tuple[np.ndarray, float, np.ndarray]], direction: np.ndarray, resign: bool,
            params: PlaneParams) -> list[tuple[np.ndarray, float, np.ndarray]]:
    """The proposals whose normals lie within ``resting_max_tilt_deg`` of ``direction``; with
    ``resign`` each is first signed toward it (an unorganized cloud has no side to sign it by)."""
    cos_rest = np.cos(np.radians(params.resting_max_tilt_deg))
    signed = [(-n, -d, inl) if resign and n @ direction < 0 else (n, d, inl) for n, d, inl in proposals]
    return [c for c in signed if float(c[0] @ direction) >= cos_rest]


def _support_kind(height: float) -> str:
    if height < 0.1:
        return "floor"
    if height <= 1.1:
        return "table"
    return "shelf"


def _size_hint(points: np.ndarray, units: str) -> str:
    """The capture's size when it is not that of a real scene (then the units are the likelier fault)."""
    extent = float(np.max(np.ptp(points, axis=0))) if len(points) else 0.0
    if PLAUSIBLE_EXTENT[0] <= extent <= PLAUSIBLE_EXTENT[1]:
        return ""
    return f" and --units: read in {units} the capture is {extent:.3g} m across, not a plausible scene ({PLAUSIBLE_EXTENT[0]}-{PLAUSIBLE_EXTENT[1]:.0f} m)"


def detect_planes(scene: Scene, params: PlaneParams = PlaneParams()) -> Scene:
    """Level the scene on its dominant support, find every horizontal support, floor at z = 0.

    1. Seeded RANSAC proposals on a downsampled copy, each signed up (toward the camera for
       camera views). The largest one within ``level_max_tilt_deg`` of the loaded up axis
       (``view_max_tilt_deg`` of the picture's up for camera views), size weighted by cos^2 of the
       tilt, is the dominant support; its normal, refitted on full-resolution points, becomes +Z.
       A camera view looks (nearly) straight down when a plane facing back along its optical axis
       (within ``overhead_max_tilt_deg``) is larger than every one facing up; it is upside down
       when none of ``min_support_share`` of its planar points faces up nor back (the support
       faces the picture's down).
    2. Every horizontal proposal is split into connected xy regions; regions at one height close
       to each other are one support (a table broken up by the objects occluding it), refitted by
       least squares on the full-resolution points in a thin band.
    3. Flat object tops (small planes just above a support) are dropped; the lowest support is the
       floor when another stands well above it or a camera looks down from standing height,
       otherwise it is a table at ``assumed_support_height`` over an assumed floor.
    """
    if scene.points is None:
        return scene
    finite = _finite(scene.points)
    resolution = working_resolution(scene.capture.point_spacing if scene.capture.point_spacing is not None else float("nan"))
    params = at_resolution(params, resolution)
    work = scene.points[finite]
    if len(work) > 3 * params.max_work_points:  # a dense capture is worked at its resolution: bounded cost
        work = voxel_downsample(work, resolution)
    if len(work) > params.max_work_points:  # a least-squares plane on this many points is already exact
        work = work[np.sort(np.random.default_rng(scene.seed).choice(len(work), params.max_work_points, replace=False))]
    proposals = ransac_proposals(work, params, scene.seed)
    viewpoint = scene.capture.input_to_world[:3, 3] if scene.capture.camera_view else None
    max_tilt = params.view_max_tilt_deg if viewpoint is not None else params.level_max_tilt_deg
    cos_level = np.cos(np.radians(max_tilt))
    # Each plane signed up (a camera sees a support's upper side: toward the camera), then the
    # largest near the loaded up, weighted by cos^2 of its tilt. Cameras are held roughly
    # upright, so a wall facing a camera that looks down on a counter faces away from the
    # picture's up and never levels the scene, and a big wall seen at a grazing angle does not
    # win over the table.
    oriented = [(*_orient_up(n, d, viewpoint), inl) for n, d, inl in proposals]
    candidates = [prop for prop in oriented if prop[0][2] >= cos_level]
    planar = sum(len(prop[2]) for prop in proposals)
    weight = lambda c: len(c[2]) * c[0][2] ** 2  # noqa: E731 - size by cos^2 of the tilt from the loaded up
    # Only large planes (min_support_share of the planar points) are supports or walls; a smaller one is a thing's face.
    big = [c for c in (oriented if viewpoint is not None else proposals) if len(c[2]) >= params.min_support_share * planar]
    rest = _resting_direction(work, big, params, scene.seed)
    resting = [] if rest is None else _facing(big, rest, viewpoint is None, params)
    if resting:
        # Bodies stand on the support, never on a wall: whichever way the capture was held (a file
        # turned 40 degrees, a picture upside down), the plane they rest on is searched first.
        candidates, weight = resting, lambda c: len(c[2]) * float(c[0] @ rest) ** 2
    elif viewpoint is not None:
        # A camera looking (nearly) straight down sees the support facing back along its optical
        # axis, tilted past the picture's up: it is larger than any plane facing up (those are
        # things' tops). Failing both, only small faces of things face up: the picture is upside down.
        backward = -scene.capture.input_to_world[:3, 2] / np.linalg.norm(scene.capture.input_to_world[:3, 2])
        cos_overhead = np.cos(np.radians(params.overhead_max_tilt_deg))
        overhead = [prop for prop in oriented if prop[0] @ backward >= cos_overhead and prop[0][2] >= 0.0]
        if max(map(_size, overhead), default=0) > max(map(_size, candidates), default=0):
            candidates, weight = overhead, lambda c: len(c[2]) * float(c[0] @ backward) ** 2
        elif not _has_support(candidates, planar, params):
            candidates = [prop for prop in oriented if -prop[0][2] >= cos_level]
    if not candidates:
        facing = " facing the camera" if viewpoint is not None else ""
        raise InputError(
            f"{scene.capture.environment_file}: no support plane found (no large flat surface{facing} within "
            f"{max_tilt:.0f} deg of the up axis '{scene.capture.up}'); check --up{_size_hint(work, scene.capture.units)}"
        )
    candidates = [surface_of(c, params.region_cell, params.distance_threshold, params.min_plane_points) for c in candidates]
    normal, d, _ = max(candidates, key=weight)
    normal, d, _ = refine_plane(work, normal, d, params.refine_threshold)
    rotation = rotation_between(normal, np.array([0.0, 0.0, 1.0]))
    pts = work @ rotation.T

    cos_support = np.cos(np.radians(params.support_max_tilt_deg))
    up = np.array([0.0, 0.0, 1.0])
    regions: list[tuple[float, np.ndarray]] = []  # (height, downsampled region points)
    for p_normal, _, inliers in proposals:
        p_normal = rotation @ p_normal
        if abs(p_normal[2]) < cos_support:
            continue
        inliers = inliers @ rotation.T
        for region in _regions(inliers[:, :2], params.region_cell, params.min_support_area):
            regions.append((float(np.median(inliers[region, 2])), inliers[region]))
    regions += _unproposed_patches(pts, regions, params)
    # an underside (a table top's, seen by a capture from around) is no support: dropped before it joins a top near it
    regions = [r for r in regions if _covered_from_above(pts, r[0], r[1], params, scene.seed) <= params.max_covered_fraction]
    supports = []
    for group in _merge_regions(regions, params):
        band = _support_points(pts, group, params)
        if band is None:
            continue
        n, dd, mask = refine_plane(band, np.array([0.0, 0.0, 1.0]), -float(np.median(band[:, 2])), params.refine_threshold)
        if n[2] < cos_support:  # a sliver (a table edge in a sparse capture) refits to a tilted plane
            continue
        # a cloud's points lie within its resolution (a camera's depth noise grows with distance instead)
        level = n if viewpoint is not None else level_unless_resolved(band[mask], n, up, resolution)
        if level is not n:  # gravity (the levelled scene's up), through the points' centroid
            n, dd = level, -float(band[mask].mean(axis=0)[2])
        supports.append((height_where_seen(band[mask], n, dd), band[mask], n))
    supports = [sup for sup in supports if _covered_from_above(pts, sup[0], sup[1], params, scene.seed) <= params.max_covered_fraction]
    if not supports:
        raise InputError(f"{scene.capture.environment_file}: no horizontal support surface found in the scan; "
                         "check --up and --units")
    supports.sort(key=lambda r: r[0])
    supports = supports[:1] + [s for s in supports[1:] if _width(s[1][:, :2]) >= params.min_support_width]
    supports = _drop_object_tops(supports, params)
    planes, shift = _place_floor(scene, supports, params)
    _warn_implausible(scene, planes, params)
    offset = _recentre(planes)
    scene.planes = planes
    _apply_rigid(scene, rotation, np.array([offset[0], offset[1], shift]))
    return scene


def height_where_seen(points: np.ndarray, normal: np.ndarray, d: float) -> float:
    """The height of the plane ``normal . x + d = 0`` at the centroid of the ``points`` fitted to it.

    A support is stored level, so one height stands for it; a fit's residual tilt (a far floor
    seen through a camera's growing noise leans 0.1 deg) read 2-3 m away, under the camera at the
    origin, is off by millimetres, while at its own points it is where the surface was seen."""
    centre = points.mean(axis=0)
    return float(-(d + normal[0] * centre[0] + normal[1] * centre[1]) / normal[2])


def _width(xy: np.ndarray) -> float:
    """Width of a surface's points: across the narrower side of their minimal rectangle, between
    the 1st and 99th percentiles (the few points noise scatters past its edges do not widen a ledge)."""
    _, _, size, yaw = polygon_and_rectangle(xy)
    across = yaw + (0.0 if size[0] <= size[1] else np.pi / 2)
    t = xy @ np.array([np.cos(across), np.sin(across)])
    lo, hi = np.percentile(t, [1, 99])
    return float(hi - lo)


def at_resolution(params: PlaneParams, resolution: float) -> PlaneParams:
    """Grid cells at least twice the capture's working resolution, so sparse captures still fill them."""
    return dataclasses.replace(params, voxel_size=max(params.voxel_size, resolution),
                               region_cell=max(params.region_cell, 2.0 * resolution))


def _covered_from_above(pts: np.ndarray, height: float, support_pts: np.ndarray, params: PlaneParams, seed: int) -> float:
    """Fraction of a support's points with another surface right above them (``covered_band``):
    the underside of a table top or of a floor slab, never the surface things stand on."""
    lo, hi = params.covered_band
    above = pts[(pts[:, 2] > height + lo) & (pts[:, 2] < height + hi)]
    if len(above) == 0:
        return 0.0
    rng = np.random.default_rng(seed)
    sample = support_pts[rng.choice(len(support_pts), min(len(support_pts), 3000), replace=False)]
    reach = max(0.01, params.voxel_size)
    lo_xy, hi_xy = sample[:, :2].min(axis=0) - reach, sample[:, :2].max(axis=0) + reach
    above = above[np.all((above[:, :2] >= lo_xy) & (above[:, :2] <= hi_xy), axis=1)]  # only what can lie within reach
    if len(above) == 0:
        return 0.0
    dist, _ = cKDTree(above[:, :2]).query(sample[:, :2], distance_upper_bound=reach)
    return float(np.isfinite(dist).mean())


def _warn_implausible(scene: Scene, planes: list[SupportPlane], params: PlaneParams) -> None:
    """Say when an observed support stands at a height no table or counter has."""
    lo, hi = params.table_heights
    if not any(p.kind == "floor" and p.observed for p in planes):
        return
    for p in planes:
        if p.kind != "floor" and p.observed and not lo <= p.height <= hi:
            scene.warn(f"support {p.id} is {p.height:.2f} m above the floor, outside the {lo}-{hi} m of tables and "
                       "counters: check it (a shelf, a step, or wrong --units)")


def _unproposed_patches(pts: np.ndarray, regions: list[tuple[float, np.ndarray]], params: PlaneParams) -> list[tuple[float, np.ndarray]]:
    """Horizontal planes at every height where the levelled ``pts``' level points pile up
    (:func:`level_heights` on a ``voxel_size`` copy, ``min_level_points`` each), split into
    connected xy regions of ``min_support_area`` like a RANSAC proposal's inliers, (height,
    points) each, that no proposed region already holds: most of their points lie no farther than
    ``region_cell`` from a region's points at their height (``merge_height_tol``)."""
    down = voxel_downsample(pts, params.voxel_size)
    trees = [(h, cKDTree(other[:, :2])) for h, other in regions]
    found = []
    for height in level_heights(down, 3.0 * params.voxel_size, params.support_max_tilt_deg, params.distance_threshold,
                                params.min_level_points):
        band = down[np.abs(down[:, 2] - height) < params.distance_threshold]
        for region in _regions(band[:, :2], params.region_cell, params.min_support_area):
            xy = band[region, :2]
            held = np.zeros(len(xy), dtype=bool)
            for h, tree in trees:
                if abs(h - height) <= params.merge_height_tol:
                    held |= np.isfinite(tree.query(xy, distance_upper_bound=params.region_cell)[0])
            if held.mean() < 0.5:
                found.append((float(np.median(band[region, 2])), band[region]))
    return found


def _merge_regions(regions: list[tuple[float, np.ndarray]], params: PlaneParams) -> list[np.ndarray]:
    """Group regions at one height (within ``merge_height_tol``) lying within ``merge_gap`` in xy."""
    order = sorted(range(len(regions)), key=lambda i: regions[i][0])
    parent = list(range(len(regions)))

    def find(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    trees = [cKDTree(r[1][:, :2]) for r in regions]
    for a_pos, a in enumerate(order):
        for b in order[a_pos + 1 :]:
            if regions[b][0] - regions[a][0] > params.merge_height_tol:
                break
            gap, _ = trees[a].query(regions[b][1][:, :2], k=1, distance_upper_bound=params.merge_gap)
            if np.isfinite(gap).any():
                parent[find(b)] = find(a)
    groups: dict[int, list[np.ndarray]] = {}
    for i in order:
        groups.setdefault(find(i), []).append(regions[i][1])
    return [np.vstack(g) for g in groups.values()]


def _support_points(pts: np.ndarray, group: np.ndarray, params: PlaneParams) -> np.ndarray | None:
    """Full-resolution points in a thin height band over the xy hull of a region group."""
    z = float(np.median(group[:, 2]))
    polygon = polygon_and_rectangle(group[:, :2])[0]
    lo, hi = polygon.min(axis=0), polygon.max(axis=0)
    near = np.flatnonzero(np.abs(pts[:, 2] - z) < params.distance_threshold)  # the height band first: few points
    near = near[np.all((pts[near, :2] >= lo) & (pts[near, :2] <= hi), axis=1)]
    band = pts[near][inside_convex_polygon(pts[near, :2], polygon)]
    cell = params.voxel_size
    observed_area = _occupied_cells(band[:, :2], cell) * cell * cell
    return band if observed_area >= params.min_support_area else None


def _occupied_cells(xy: np.ndarray, cell: float) -> int:
    """Number of distinct ``cell``-sized grid squares holding points (one int64 key per square)."""
    if len(xy) == 0:
        return 0
    ij = np.floor((xy - xy.min(axis=0)) / cell).astype(np.int64)
    span = ij.max(axis=0) + 1
    if int(np.prod(span)) <= 1 << 25:  # a support's cells: marked on a dense grid (at most 32 MB)
        mark = np.zeros(tuple(span), dtype=bool)
        mark[ij[:, 0], ij[:, 1]] = True
        return int(np.count_nonzero(mark))
    return len(np.unique(ij[:, 0] * span[1] + ij[:, 1]))


Support = tuple[float, np.ndarray, np.ndarray]  # height, inlier points, normal


def _drop_object_tops(supports: list[Support], params: PlaneParams) -> list[Support]:
    """Keep real supports only.

    A plane within ``min_support_gap`` above a larger support under it is a flat object top; a
    plane within that gap below the largest support and reaching under its outline (sensor
    noise, a sheet under the table edge) is dropped too. A lower table beside it stays.
    """
    primary_height, primary_pts, _ = max(supports, key=lambda s: len(s[1]))
    primary_polygon = polygon_and_rectangle(primary_pts[:, :2])[0]
    kept: list[tuple[float, np.ndarray, np.ndarray, np.ndarray]] = []
    for height, pts, normal in supports:  # sorted by height
        polygon, *_ = polygon_and_rectangle(pts[:, :2])
        if 0 < primary_height - height < params.min_support_gap and inside_convex_polygon(polygon, primary_polygon, params.under_margin).any():
            continue
        centre = polygon.mean(axis=0, keepdims=True)
        on_top = any(
            height - h < params.min_support_gap and inside_convex_polygon(centre, poly, 0.05)[0]
            for h, _, _, poly in kept
        )
        if not on_top:
            kept.append((height, pts, normal, polygon))
    return [(h, p, n) for h, p, n, _ in kept]


def _place_floor(scene: Scene, supports: list[Support], params: PlaneParams) -> tuple[list[SupportPlane], float]:
    """Decide which support is the floor; return the planes with the floor at z = 0 and the z shift."""
    lowest, lowest_pts, _ = supports[0]
    highest = supports[-1][0]
    lowest_size = polygon_and_rectangle(lowest_pts[:, :2])[2]
    sees_floor = (highest - lowest) >= params.floor_min_gap or bool(np.min(lowest_size) >= params.floor_min_size)
    assumed = scene.capture.config.support_height
    if sees_floor:
        # The floor is one surface however the furniture splits it up in the view.
        floor_parts = [s for s in supports if s[0] - lowest < params.merge_height_tol]
        floor_pts = np.vstack([s[1] for s in floor_parts])
        n, dd, mask = refine_plane(floor_pts, np.array([0.0, 0.0, 1.0]), -float(np.median(floor_pts[:, 2])), params.refine_threshold)
        supports = [(height_where_seen(floor_pts[mask], n, dd), floor_pts, n)] + supports[len(floor_parts):]
        lowest = supports[0][0]
        shift = -lowest
    else:
        shift = float(assumed if assumed is not None else params.assumed_support_height) - lowest
        scene.warn(
            f"no floor in view: the lowest support is taken as a table at "
            f"{shift + lowest:.2f} m (set support_height in capture.yaml to change)"
        )
    planes: list[SupportPlane] = []
    for height, inlier_pts, normal in supports:
        z = height + shift
        if z > params.max_support_height:
            continue
        polygon, center, size, yaw = polygon_and_rectangle(inlier_pts[:, :2])
        planes.append(
            SupportPlane(
                id=len(planes) + 1,
                kind=_support_kind(z),
                normal=normal,
                height=z,
                polygon=polygon,
                rect_center=center,
                rect_size=size,
                rect_yaw=yaw,
                inlier_count=len(inlier_pts),
            )
        )
    if not sees_floor:
        span = max(float(np.max(p.rect_size)) for p in planes) + 2.0
        c = planes[0].rect_center
        square = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], dtype=np.float64) * span / 2 + c
        planes.insert(
            0,
            SupportPlane(0, "floor", np.array([0.0, 0.0, 1.0]), 0.0, square, c.copy(), np.array([span, span]), 0.0, 0, observed=False),
        )
    return planes, shift


def _recentre(planes: list[SupportPlane]) -> np.ndarray:
    """Move the planes so the primary support is centred at the xy origin; return the xy offset."""
    tables = [p for p in planes if p.kind != "floor"]
    primary = max(tables or planes, key=lambda p: (p.observed, p.inlier_count, float(np.prod(p.rect_size))))
    offset = -primary.rect_center
    for p in planes:
        p.polygon = p.polygon + offset
        p.rect_center = p.rect_center + offset
    return offset
