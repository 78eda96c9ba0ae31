"""Parameters of shape completion."""

from __future__ import annotations

from dataclasses import dataclass

from realsim.completion.containers import ContainerParams


@dataclass(frozen=True)
class CompletionParams:
    """Parameters of shape completion."""

    top_percentile: float = 98.0  # object top from this percentile of point heights (robust to spikes)
    min_height: float = 0.01  # thinnest completed object (m)
    cylinder_max_rms: float = 0.08  # circle fit residual / radius below which a footprint is round
    cylinder_min_arc_deg: float = 100.0  # visible arc a cylinder fit needs
    cylinder_max_radius: float = 0.2
    round_max_outside: float = 0.1  # a round body's points beyond its circle (a handle, a spout) are at most this share
    round_outside_margin: float = 1.2  # beyond: farther from the axis than this many radii (a lip, a flaring rim) ...
    round_outside_gap: float = 0.003  # ... plus this (m; the sensor noise)
    cylinder_sections: int = 32
    revolution_bands: int = 10  # height bands of a revolved profile (one convex frustum each)
    straight_profile_share: float = 0.12  # band radii within this share of the radius: a cylinder (one convex piece)
    revolution_silhouette: bool = True  # a profile that is not straight takes its axis from the silhouette band by band (the near arc's circle is pulled toward the camera)
    revolution_underside: bool = True  # a revolved profile seen turning in below its widest: its unseen underside mirrors the upper side
    revolution_percentile: float = 75.0  # a band's radius: this percentile of its points' distances from the axis
    silhouette_min_share: float = 0.85  # a round body's silhouette is at least this share of its fitted diameter
    max_foreign_fraction: float = 0.03  # completed shape may contain this share of a neighbour's points
    carve: bool = True  # carve completed shapes by the camera's free space (camera views only)
    carve_tolerance: float = 0.005  # a voxel this much nearer than the captured depth at its pixel is free space (m)
    carve_voxels: int = 40  # voxels along an object's largest extent (clamped to 2-5 mm)
    carve_tile: float = 0.02  # much carved shapes are kept as convex cubic tiles at least this wide (m)
    max_pieces: int = 24  # about this many tiles (the bounding box cut in this many cubes)
    tile_min_fraction: float = 0.1  # a shape this much seen through is kept as tiles (a hull would refill the free space)
    tile_outline_steps: float = 1.0  # a lying body's tiles keep only voxel columns within this many voxel steps of its points from above (0: all)
    tile_when_refilled: bool = False  # also tiles when the carved hull fills carve_min_fraction of its voxels again with seen free space
    denoise_window: int = 5  # object pixels' depth: the median of this many pixels square of the same object (camera views)
    clip_free_space: bool = True  # cut every finished piece back out of the space the camera saw through
    free_space_sigmas: float = 4.0  # a piece nearer than the captured depth by this many sensor-noise sigmas is cut back
    free_space_min_tolerance: float = 0.003  # m: the least such tolerance (quantized depth shows no noise)
    carve_over_support: bool = False  # voxels above the support where the camera saw it are free too (fewer seen-free pixels covered; test55 PSNR -0.14 dB, drift 0.16 -> 0.19 mm: off)
    carve_surface_ends: bool = True  # a carved piece of a shape in pieces (a revolved profile, slabs) keeps its completed underside (a round one stays round), not its lowest voxel centres laid on the support (a single hull and tiles keep them on it: test55's hulls' seen feet, separate round tiles rock)
    carve_min_fraction: float = 0.01  # carve only when at least this share of the voxels is free space
    slab: float = 0.025  # a body that is not convex is extruded in slabs about this long (m)
    max_slabs: int = 8
    slab_max_fill: float = 0.8  # slabs are used when they fill less than this share of the single hull
    bands: int = 6  # an upright body whose profile is not convex is its hulls in this many height bands
    bands_max_fill: float = 0.98  # bands are used when they fill less than this share of the single hull
    containers: ContainerParams = ContainerParams()  # open round containers completed hollow
    mirror_max_depth_share: float = 1.5  # mirror about the occluding contour unless the visible depth is this share of the width
    mirror_point: bool = True  # the hidden half is also the seen half turned half a turn about the vertical axis between the grazing lines (centrally symmetric sections at any turn), not only reflected about the plane across the line of sight
    mirror_turn_alone: bool = True  # a turned body's hidden half is its half-turned near half alone, less its points in seen free space (the reflection across the line of sight of a turned body's front reaches past its far side)
    mirror_turn_refuted: float = 0.05  # ... unless more of that image than this share lies where the camera saw through: not centrally symmetric, reflected instead (upright bleach bottles 0.1-1.3 %, a lying pitcher 14 %, a real scene's 17 cm object 28 %)
    mirror_stagger: float = 0.1  # grazing lines farther apart along the line of sight than this share of the width: a turned body
    mirror_max_seen_through: float = 0.01  # a half-turned image with more of its points in seen free space is refuted
    mirror_probe: float = 0.01  # m: a side's grazing line counts when the camera saw past it this far out
    mirror_min_height_share: float = 0.5  # bodies lower than this share of their width are not mirrored
    mirror_crest: bool = True  # a low body lying flat is mirrored behind its crest (its highest line across the line of sight)
    mirror_crest_slice: float = 0.005  # m: the least width of the slices across the line of sight in which the crest is found
    mirror_crest_tolerance: float = 0.003  # m: points this close to a slice's highest are on its crest
    mirror_crest_curved: bool = True  # a slice also has a crest where its upper side is seen curving over one (a marker falls away past it by less than the tolerance)
    mirror_crest_reach: float = 0.75  # the near side mirrored reaches this share of the slice's height before its crest (a round section: half)
    underside: bool = True  # a lying body's underside is its upper side mirrored below its widest level (not extruded straight down)
    underside_max_height_share: float = 0.5  # lying: lower than this share of its longest horizontal extent
    underside_edge: float = 0.002  # m: points this close to a slice's lateral extreme show the level where it is widest
    underside_central: bool = True  # a section turned about its long axis: the side seen widest higher is mirrored about the image of the other's level through the middle height (centrally symmetric sections)
    occluded_continuation: bool = True  # a silhouette edge bordering a nearer object is continued behind it (see completion.occlusion)
    occlusion_gap: float = 0.01  # m: a neighbour this much nearer than an edge pixel occludes it
    occlusion_reach: int = 2  # pixels: an edge pixel this near an occluding pixel borders it
    occlusion_max_share: float = 1.0  # continued at most this share of the body's visible extent along the hidden direction
    occlusion_max_seen_through: float = 0.01  # a continuation whose added hull has more of its volume in seen free space is refuted (as mirror_max_seen_through)
    mirror_bands: int = 8  # height bands in which the occluding contour is found
    veil_deg: float = 80.0  # object pixels seen more edge-on than this are silhouette veils (mixed depths), not surface
    veil_keep: bool = True  # veil pixels continuing the surface beside them (within the free-space tolerance) are kept: the edge
    balance_margin: float = 0.005  # m: a completed base must hold the centre of mass this far inside its polygon
    base_clearance: float = 0.0005  # gap left between the base and what it stands on (m)
    min_points: int = 30
    join_fragments: bool = True  # a noise fragment seen beyond an occluder joins the object on its other side (camera views)
    fragment_max_gap: float = 0.1  # m: the longest hidden middle between a fragment and its object
