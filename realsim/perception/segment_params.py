"""Parameters and result of the object segmentation (:mod:`realsim.perception.segment`)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["SegmentParams", "SegmentResult"]


@dataclass(frozen=True)
class SegmentParams:
    """Thresholds of the segmentation (lengths in metres, angles in degrees)."""

    # foreground
    min_height: float = 0.008  # points closer than this above their support belong to it
    max_height: float = 1.0  # points higher than this above every support are background
    polygon_margin: float = 0.02  # points beyond a support polygon by more than this are background
    structure_margin: float = 0.03  # points this close under a higher support's polygon are its furniture
    structure_reach: float = 0.1  # ... and, under its rectangle, in a column rising this close under its height
    use_assumed_planes: bool = False  # also segment above supports that were not observed
    # neighbourhoods and normals
    normal_window: int = 5  # grid window (pixels) averaging tangent normals, organized clouds
    normal_neighbors: int = 20  # neighbours of the covariance normals, unorganized clouds
    knn_neighbors: int = 8  # neighbours linked per point, unorganized clouds
    # links between neighbouring points (fragments)
    jump_distance: float = 0.008  # neighbours farther apart than this are across a depth jump
    jump_max_angle: float = 45.0  # camera views: ... and than a link on a surface turned this far (degrees)
    # from the camera with its ends' measured depth noise at jump_sigmas (pixels lie farther apart, and noisier,
    # the farther they are: realsim.perception.depth_jumps); normals skip tangents over twice that
    jump_sigmas: float = 2.5  # (2.5 sigma keeps 99 % of a surface's links)
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
    visibility_cell: float = 0.007  # m: clouds this fine orient patches by what each side sees (a third of the
    # smallest object: coarser cells, dilated to close a surface, also close the cracks between objects)
    min_contact_links: int = 6  # fewer links between two fragments are not a contact
    color_edge: float | None = None  # segments whose mean RGB differ more do not join directly (None: off;
    # on textured real objects any useful threshold splits objects, see bench)
    max_concave_fraction: float = 0.5  # regions whose border is more concave than this stay apart
    contact_cut_cell: float = 0.015  # m: clouds this fine re-cut touching clusters at concave folds
    # (realsim.perception.contact_cut), and no coarser than segment_scene.fold_resolution (8 mm by default)
    fold_max_angle: float | None = 40.0  # camera views: touching segments whose surfaces turn less than this (degrees) across
    # a depth-continuous border are one body's pieces (realsim.perception.shallow_folds; None: off)
    fold_window: int = 6  # ... each side's surface the mean normal of its pixels this many pixels around the border
    fold_continuous_share: float = 0.5  # ... when at least this share of the border's pixel links is depth-continuous
    step_max_gap: float | None = 0.012  # camera views: segments meeting at a depth step whose nearer side's rim lies this
    # close (m) to the farther side's surface plane are one body's pieces (realsim.perception.step_joins; None: off)
    step_max_facing: float = 0.6  # ... when the nearer side turns from the camera there (|n . view| under this)
    step_consistent_share: float = 0.9  # ... and is the nearer one on at least this share of the step's links
    # objects
    absorb_points: int = 600  # smaller segments touching another segment join it
    min_view_area: float = 0.0015  # m^2 of surface: camera views, smaller segments are never objects by themselves
    front_share: float = 0.8  # camera views: a segment whose border steps toward the camera this much is an object
    inside_concavity: float = 0.05  # camera views: a segment bending toward its centre more than this (of its radius)
    # is seen from inside: a container's inside, joined to the rim that hides it (realsim.perception.container_inside)
    inside_rim_share: float = 0.1  # camera views: ... when that rim holds this share of its image outline (it runs
    # along the inside's near side; an object merely leaning on a container touches it over a few pixels)
    backdrop_share: float = 0.5  # camera views: a cluster whose border continues the surface behind it on more
    # than this share of its pairs is backdrop, cut out of a wall (realsim.perception.backdrop_patch)
    min_object_points: int = 200  # smaller isolated clusters are noise (-1)
    stack_min_height: float = 0.015  # an object whose base is this high rests on another one
    rest_face_angle: float = 30.0  # camera views: ... held up by it where it meets a face of it turned this close to up
    # (degrees), however little of that one is seen around its foot (realsim.perception.attached_parts)
    base_gap: float | None = None  # m: clouds worked on a grid (its cell): an object's base is its lowest point
    # with another within this above it (None: camera views, the 5th-lowest point; object_relations.base_height)
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
