"""The ``segment`` stage: objects from the scan, as SceneObjects with ids, supports and labels."""

from __future__ import annotations

import dataclasses

import numpy as np
from scipy import ndimage
from scipy.spatial import cKDTree

from realsim.geometry import inside_convex_polygon, polygon_and_rectangle
from realsim.perception.capture_camera import capture_intrinsics, optical_depth
from realsim.perception.depth_jumps import pixel_jumps
from realsim.perception.footprints import filled_footprint
from realsim.perception.resolution import working_resolution
from realsim.perception.segment import SegmentParams, SegmentResult, assign_supports, filter_by_size, segment_objects
from realsim.perception.stack_split import give_resting_base
from realsim.scene import Scene, SceneObject
from realsim.scene_format import safe_name

__all__ = ["SegmentParams", "segment_scene"]


def _label_for(scene: Scene, mask: np.ndarray) -> str:
    """The name capture.yaml gives the annotated object most of the cluster's points belong to."""
    names = scene.capture.config.labels
    if not names or scene.annotations is None:
        return "object"
    annotated = scene.annotations[mask]
    ids = annotated[annotated >= 20] // 10
    if len(ids) < 0.5 * mask.sum():
        return "object"
    majority = int(np.bincount(ids.astype(np.int64)).argmax())
    label = names.get(majority, names.get(str(majority)))
    return str(label) if label else "object"


def at_resolution(params: SegmentParams, resolution: float) -> SegmentParams:
    """The parameters for an unorganized cloud worked at ``resolution`` (m): link and supervoxel
    lengths grow with the spacing, the point counts of the defaults (tuned on Kinect views, about
    1.5 mm apart) become the same areas counted in cells of this size, and object sizes are areas.
    The base of an object standing on its support shows on the grid up to one cell above the
    foreground's lower bound (a cell's centre averages what lies in it), so only a base higher
    than that rests on something else; the base is a cluster's lowest cell with another within a
    cell above it (a sparse object has few cells near its base: no count of them is its base)."""
    kinect_cell = 0.0015**2

    def count(points: int, floor: int) -> int:
        return max(floor, int(round(points * kinect_cell / resolution**2)))

    return dataclasses.replace(
        params,
        jump_distance=max(params.jump_distance, 2.5 * resolution),
        supervoxel_size=max(params.supervoxel_size, 4.0 * resolution),
        min_fragment_points=count(params.min_fragment_points, 3),
        min_contact_links=min(params.min_contact_links, count(params.min_contact_links * 4, 2)),
        absorb_points=max(6, int(round(params.absorb_area / resolution**2))),
        min_object_points=max(5, int(round(params.min_object_area / resolution**2))),
        stack_min_height=max(params.stack_min_height, params.min_height + resolution),
        base_gap=resolution,
        contact_cut_cell=min(params.contact_cut_cell, fold_resolution(params)),
    )


def fold_resolution(params: SegmentParams) -> float:
    """The coarsest cell (m) at which a concave fold between two touching objects can be seen: a
    point's normal is fitted over its ``normal_neighbors`` nearest cells, a disc of radius
    ``cell * sqrt(k / pi)``; wider than the smallest object (``min_object_size``), it spans whole
    objects and their contact alike (coarser clouds tell touching objects apart by colour)."""
    return float(params.min_object_size / np.sqrt(params.normal_neighbors / np.pi))


MIN_OBJECT_HEIGHT = 0.002  # m: the lowest an object's point can be above its support (noiseless meshes)


def _noise(scene: Scene, params: SegmentParams) -> float:
    """The capture's depth noise (m): robust spread of the points on its largest observed support."""
    observed = [p for p in scene.planes if p.observed]
    if not observed or scene.points is None:
        return 0.0
    plane = max(observed, key=lambda p: p.inlier_count)
    pts = scene.points[::max(1, len(scene.points) // 200_000)]
    with np.errstate(invalid="ignore"):
        near = np.abs(pts[:, 2] - plane.height) < params.min_height
    near &= inside_convex_polygon(np.nan_to_num(pts[:, :2]), plane.polygon, 0.0)
    r = pts[near, 2] - plane.height
    if len(r) < 20:
        return 0.0
    return float(1.4826 * np.median(np.abs(r - np.median(r))))


def _segment_unorganized(scene: Scene, params: SegmentParams) -> tuple[np.ndarray, SegmentResult]:
    """Segment the points above the supports on a voxel grid at the capture's working resolution,
    then give every input point its voxel's label: the cost depends on the scene, not on how
    densely it was sampled."""
    resolution = working_resolution(scene.capture.point_spacing if scene.capture.point_spacing is not None else float("nan"))
    support, height = assign_supports(scene.points, scene.planes, params)
    fg = np.flatnonzero(support >= 0)
    tall = _in_tall_columns(scene.points[fg], support[fg], height[fg], params)
    walls, fg = fg[tall], fg[~tall]
    labels = np.zeros(len(scene.points), dtype=np.int32)
    if len(fg) == 0:
        return labels, SegmentResult(labels)
    cells = np.floor(scene.points[fg] / resolution).astype(np.int64)
    cells -= cells.min(axis=0)
    span = cells.max(axis=0) + 1
    keys = (cells[:, 0] * span[1] + cells[:, 1]) * span[2] + cells[:, 2]
    _, inverse, counts = np.unique(keys, return_inverse=True, return_counts=True)
    inverse = inverse.ravel()

    def mean(values: np.ndarray) -> np.ndarray:
        return np.stack([np.bincount(inverse, values[:, i], minlength=len(counts)) for i in range(3)], axis=1) / counts[:, None]

    centres = mean(scene.points[fg])
    colors = None if scene.colors is None else mean(np.nan_to_num(np.asarray(scene.colors, dtype=np.float64)[fg]))
    normals = None if scene.normals is None else mean(scene.normals[fg])  # a voxel's outward side: its faces' resultant
    context = scene.points[walls][:: max(1, int(round((resolution / (scene.capture.point_spacing or resolution)) ** 2)))]
    noise = _noise(scene, params)
    working = at_resolution(params, resolution)
    if resolution < 2 * noise:  # neighbours' offsets are mostly noise: a fold cannot be told at one cell
        working = dataclasses.replace(working, contact_cut_cell=0.0)
    if (scene.capture.surface_detail or 0.0) > working.contact_cut_cell:  # a surface smoothed wider than the
        working = dataclasses.replace(working, contact_cut_cell=0.0)  # fold resolution rounds the creases it would cut
    result = segment_objects(centres, colors, scene.planes, None, working, seed=scene.seed,
                             resolution=resolution, context=context, known_normals=normals)
    result = filter_by_size(centres, result, scene.planes, working, max_sheet=max(params.min_object_size / 2, 6 * noise))
    labels[fg] = result.labels[inverse]
    labels[fg] = give_resting_base(scene.points[fg], labels[fg], result.resting_on, max(2 * noise, MIN_OBJECT_HEIGHT),
                                   working.jump_distance, resolution)
    _extend_to_base(scene, labels, support, height, centres, result.labels, params, noise,
                    at_resolution(params, resolution).jump_distance, resolution)
    return labels, result


def _in_tall_columns(points: np.ndarray, support: np.ndarray, height: np.ndarray, params: SegmentParams) -> np.ndarray:
    """Points in a vertical column (``min_object_size`` across) whose points rise higher above
    their support than any object is tall: a wall or a cabinet side, structure before it costs
    the segmentation anything."""
    cell = params.min_object_size
    ij = np.floor(points[:, :2] / cell).astype(np.int64)
    ij -= ij.min(axis=0, initial=0)
    key = (support.astype(np.int64) * (ij[:, 0].max(initial=0) + 1) + ij[:, 0]) * (ij[:, 1].max(initial=0) + 1) + ij[:, 1]
    _, col = np.unique(key, return_inverse=True)
    col = col.ravel()
    top = np.full(col.max(initial=-1) + 1, -np.inf)
    low = np.full(len(top), np.inf)
    np.maximum.at(top, col, height)
    np.minimum.at(low, col, height)
    return (top - low)[col] > params.max_object_size


def _extend_to_base(scene: Scene, labels: np.ndarray, support: np.ndarray, above: np.ndarray, centres: np.ndarray,
                    centre_labels: np.ndarray, params: SegmentParams, noise: float, reach: float, cell: float) -> None:
    """Give the points between the support's noise and ``min_height`` to the object whose foot
    they are, once the objects are found (the objects are never joined through it): above 4 sigma
    of the noise (never under 2 mm), to the object within ``reach``; between 1 and 4 sigma, only
    under the outline of that object's foot (the convex hull of its points less than a cell over
    ``min_height`` above their support, ``above``; grown by the noise): the support under an
    object's foot is hidden, so what rises there is the object's foot, not the support's noise; an
    overhang (a handle, a spout, a lying drill's body) leaves the support under it in view
    (the cells of side ``cell`` it occupies would take the support's noise up to a cell around it). Inside
    the footprint's holes (cells its outline encloses: a bowl's or a mug's inner floor) nothing
    of the support is seen at all, so every point there down to 4 sigma under it is the object's."""
    low, sure = max(noise, MIN_OBJECT_HEIGHT), max(4 * noise, MIN_OBJECT_HEIGHT)
    obj = centre_labels > 0
    if low >= params.min_height or not obj.any():
        return
    foot_labels, foot = centre_labels[obj], np.floor(centres[obj][:, :2] / cell).astype(np.int64)
    hole_labels, holes = _footprint_holes(foot_labels, foot)
    cand = np.flatnonzero(support < 0)
    cand = cand[_near_cells(scene.points[cand, :2], np.vstack([foot, holes]), cell, reach)]
    lower, height_c = assign_supports(scene.points[cand], scene.planes, dataclasses.replace(params, min_height=-sure))
    band, height = cand[lower >= 0], height_c[lower >= 0]  # height: per band point from here on
    mine = np.floor(scene.points[band, :2] / cell).astype(np.int64)
    lo = np.min([foot.min(axis=0), mine.min(axis=0, initial=0)], axis=0) if len(band) else foot.min(axis=0)
    span = np.max([foot.max(axis=0), mine.max(axis=0, initial=0)], axis=0) - lo + 1

    def key(lab: np.ndarray | int, ij: np.ndarray) -> np.ndarray:
        return (np.asarray(lab, dtype=np.int64) * span[0] + (ij[:, 0] - lo[0])) * span[1] + (ij[:, 1] - lo[1])

    # under an object's outline: that object's, however far from its seen points (a bowl's floor)
    hole_keys = key(0, holes)
    order = np.argsort(hole_keys, kind="stable")
    hole_keys, hole_labels = hole_keys[order], hole_labels[order]
    at = np.minimum(np.searchsorted(hole_keys, key(0, mine)), max(len(hole_keys) - 1, 0))
    hidden = hole_keys[at] == key(0, mine) if len(hole_keys) else np.zeros(len(band), dtype=bool)
    labels[band[hidden]] = hole_labels[at[hidden]]
    rest = ~hidden & (height > low)
    band, mine, height = band[rest], mine[rest], height[rest]
    if len(band) == 0:
        return
    dist, nn = cKDTree(centres[obj]).query(scene.points[band], distance_upper_bound=reach)
    near = np.isfinite(dist)
    band, mine, height, owner = band[near], mine[near], height[near], foot_labels[nn[near]]
    with np.errstate(invalid="ignore"):
        footing = np.where((labels > 0) & ~(above < params.min_height + cell), 0, labels)
    keep = (height > sure) | _under_outline(scene.points[band, :2], owner, scene.points[:, :2], footing, noise)
    labels[band[keep]] = owner[keep]


def _under_outline(xy: np.ndarray, owner: np.ndarray, all_xy: np.ndarray, labels: np.ndarray, margin: float) -> np.ndarray:
    """Mask of the points ``xy`` inside the xy convex hull (grown by ``margin``) of the points of
    ``all_xy`` labelled as their ``owner``."""
    out = np.zeros(len(xy), dtype=bool)
    for k in np.unique(owner):
        mine = owner == k
        try:
            polygon = polygon_and_rectangle(all_xy[labels == k])[0]
        except ValueError:  # a degenerate object (collinear points): no outline to be under
            continue
        out[mine] = inside_convex_polygon(xy[mine], polygon, margin)
    return out


def _near_cells(xy: np.ndarray, cells: np.ndarray, cell: float, reach: float) -> np.ndarray:
    """Mask of the points ``xy`` whose xy cell (side ``cell``) is one of ``cells`` or lies within
    ``reach`` of one: a superset of the points within ``reach`` of anything in those cells, found
    on a small dense grid instead of testing every support point against every support polygon."""
    if len(cells) == 0 or len(xy) == 0:
        return np.zeros(len(xy), dtype=bool)
    r = int(np.ceil(reach / cell)) + 1
    lo = cells.min(axis=0) - r
    grid = np.zeros(tuple(cells.max(axis=0) - lo + r + 1), dtype=bool)
    grid[cells[:, 0] - lo[0], cells[:, 1] - lo[1]] = True
    grid = ndimage.binary_dilation(grid, structure=np.ones((2 * r + 1, 2 * r + 1), dtype=bool))
    with np.errstate(invalid="ignore"):
        ij = np.floor(np.nan_to_num(xy, nan=np.inf) / cell)
    inside = np.all((ij >= lo) & (ij < lo + grid.shape), axis=1)
    out = np.zeros(len(xy), dtype=bool)
    at = ij[inside].astype(np.int64) - lo
    out[inside] = grid[at[:, 0], at[:, 1]]
    return out


def _footprint_holes(labels: np.ndarray, cells: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The xy cells each object's occupied ``cells`` enclose (as label, cell pairs): openings its
    outline closes around, wider than the one- or two-cell gaps sampling leaves in a surface (a
    box top seen from above has those, and the support under it is no floor of the box's)."""
    out_l, out_c = [np.zeros(0, np.int64)], [np.zeros((0, 2), np.int64)]
    for k in np.unique(labels):
        closed, filled, lo = filled_footprint(cells[labels == k])
        holes = np.argwhere(filled & ~closed)
        out_l.append(np.full(len(holes), k, dtype=np.int64))
        out_c.append(holes + lo)
    return np.concatenate(out_l), np.concatenate(out_c)


def _jump_limits(scene: Scene, params: SegmentParams) -> np.ndarray | None:
    """A camera view's per-pixel depth-jump lengths from its own camera (focal length and measured
    depth noise, :mod:`realsim.perception.depth_jumps`); None for other organized grids."""
    intr = capture_intrinsics(scene)
    if intr is None or scene.grid_shape is None:
        return None
    depth = optical_depth(scene).reshape(scene.grid_shape)
    return pixel_jumps(depth, float(np.sqrt(intr.fx * intr.fy)), params.jump_distance, params.jump_max_angle,
                       params.jump_sigmas)


def segment_scene(scene: Scene, params: SegmentParams = SegmentParams()) -> Scene:
    """Label every input point (0 support, -1 noise, k object) and create one SceneObject per k.

    Organized camera views are segmented on their image grid; unorganized clouds (sampled
    meshes, fused sequences, scans of any density) on voxels at their working resolution."""
    if scene.points is None:
        return scene
    if scene.grid_shape is not None and scene.grid_shape[0] * scene.grid_shape[1] == len(scene.points):
        result = segment_objects(scene.points, scene.colors, scene.planes, scene.grid_shape, params, seed=scene.seed,
                                 jump_limits=_jump_limits(scene, params))
        # a wall in view is structure; small or floating clusters stay (a single view hides bases)
        result = filter_by_size(scene.points, result, scene.planes, params, structure_only=True)
        scene.labels = result.labels.astype(np.int32)
    else:
        scene.labels, result = _segment_unorganized(scene, params)
    if not (scene.labels > 0).any():
        scene.warn("no objects found above the supports: the scene converts with an empty table; check the capture "
                   "(objects at least 2 cm tall, in view) or --set segment.min_height=...")
    counts = np.bincount(scene.labels[scene.labels > 0], minlength=int(scene.labels.max(initial=0)) + 1)
    scene.objects = []
    for k in range(1, len(counts)):
        if counts[k] == 0:
            continue
        label = _label_for(scene, scene.labels == k)
        scene.objects.append(
            SceneObject(
                id=k,
                name=f"obj{k}_{safe_name(label)}",
                label=label,
                position=np.zeros(3),
                quat=np.array([1.0, 0.0, 0.0, 0.0]),
                size=np.zeros(3),
                support_id=result.support_of.get(k),
                resting_on=result.resting_on.get(k),
                point_count=int(counts[k]),
            )
        )
    return scene
