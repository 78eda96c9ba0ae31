"""The completion stage: every scan object gets a closed shape resting on what it stands on."""

from __future__ import annotations

from typing import cast

import numpy as np
import trimesh

from realsim.completion.balance import brace
from realsim.completion.carving import carve, carve_free_space, carve_pieces
from realsim.completion.containers import complete_open_container, round_rim
from realsim.completion.extrusion import complete_bands, complete_hull, complete_slabs
from realsim.completion.fragments import join_occluded_fragments
from realsim.completion.freespace import free_drops, free_space_tolerance, keep_out_of_free_space
from realsim.completion.handles import handle_pieces
from realsim.completion.hull import fast_hull
from realsim.completion.mirror import mirror_about_crest, mirror_hidden_half
from realsim.completion.neighbours import foreign_fraction, separate_neighbours
from realsim.completion.overlaps import part_overlapping
from realsim.completion.params import CompletionParams
from realsim.completion.parts import merge_container_parts
from realsim.completion.revolution import complete_revolved
from realsim.completion.stacking import bottom_up, flatten_top, seat_on, set_shape, sloping_top, top_under
from realsim.completion.view import DepthView
from realsim.scene import Scene


def complete_objects(scene: Scene, params: CompletionParams = CompletionParams()) -> Scene:
    """Give every scan object a closed collision/visual shape resting on what it stands on."""
    if scene.labels is None or not scene.objects:
        return scene
    labels, points = scene.labels, scene.points
    if points is None:
        return scene
    merge_container_parts(scene, params.cylinder_max_radius, params.containers)
    by_id = {o.id: o for o in scene.objects}
    done: dict[int, trimesh.Trimesh] = {}
    observed: dict[int, np.ndarray] = {}
    hollow: set[int] = set()
    pieces: dict[int, list[trimesh.Trimesh]] = {}
    view = DepthView.of(scene) if params.carve else None
    tolerance = free_space_tolerance(view, params, points, scene.planes) if view is not None else 0.0
    if view is not None and params.join_fragments:  # before anything reads the labels: a fragment is its object's points
        join_occluded_fragments(scene, view, tolerance, params.min_points, params.fragment_max_gap)
    if view is not None and params.denoise_window > 1:  # shapes from the surfaces, not the noise's extremes
        smooth = view.denoised(params.denoise_window)
        points, view = view.moved_to(smooth, points), smooth
    veil = view.veil(params.veil_deg, labels.reshape(view.depth.shape) > 0).ravel() if view is not None else np.zeros(len(labels), bool)
    if view is not None and params.veil_keep:
        edge = view.unveiled(veil.reshape(view.depth.shape), tolerance)
        veil &= ~np.isfinite(edge.depth.ravel())
    order = bottom_up(scene.objects)
    for obj in order:
        mask = labels == obj.id
        pts = points[mask & ~veil] if (mask & ~veil).sum() >= params.min_points else points[mask]
        slope = None
        if obj.resting_on is not None and obj.resting_on in done and obj.resting_on not in hollow:
            base_z = top_under(done[obj.resting_on], pts)
            slope = sloping_top(done[obj.resting_on], pts)
            if slope is None:  # a level top is cut flat (a face-face contact); a sloping one is kept
                done[obj.resting_on] = flatten_top(by_id[obj.resting_on], done[obj.resting_on], base_z, params)
        else:
            base_z = scene.plane(obj.support_id).height if obj.support_id is not None else float(np.min(pts[:, 2]))
        top_z = max(float(np.percentile(pts[:, 2], params.top_percentile)), base_z + params.min_height)
        others = points[(labels > 0) & ~mask]
        revolved = complete_revolved(pts, base_z, top_z, params, view.camera[:2] if view is not None else None)
        if revolved is not None and foreign_fraction(revolved.outer, others[:: max(1, len(others) // 20000)]) > params.max_foreign_fraction:
            revolved = None
        parts: list[trimesh.Trimesh] | None = None
        visual: trimesh.Trimesh | None = None
        if revolved is not None and revolved.straight:
            kind = "cylinder"
            mesh, base_centre = revolved.outer, np.array([revolved.centre[0], revolved.centre[1], base_z])
        elif revolved is not None:
            kind = "solid of revolution of its visible profile"
            mesh, parts, visual = revolved.outer, revolved.pieces, revolved.visual
            base_centre = np.array([revolved.centre[0], revolved.centre[1], base_z])
        else:
            mirrored = mirror_hidden_half(pts, view, base_z, top_z, params, points[mask]) if view is not None else None
            kind = "hull mirrored about its silhouette (the hidden half of a symmetric body)" if mirrored is not None else "hull"
            if mirrored is None and view is not None and params.mirror_crest:
                mirrored = mirror_about_crest(pts, view, base_z, top_z, params)
                kind = "hull mirrored behind its crest (the hidden far side of a body lying flat)" if mirrored is not None else kind
            body = pts if mirrored is None else mirrored
            drops = free_drops(body, base_z, view, tolerance) if view is not None else None
            mesh, base_centre = complete_hull(body, base_z, top_z, drops=drops)
        container = None
        rim = round_rim(pts, base_z, top_z, params.cylinder_max_radius) if params.containers.enabled else None
        if rim is not None:
            within = (np.linalg.norm(points[:, :2] - rim[0], axis=1) < rim[1]) & (points[:, 2] < top_z)
            within &= points[:, 2] > base_z + params.containers.min_wall  # lower: the support seen under a flaring wall
            container = complete_open_container(pts, rim[0], rim[1], base_z, top_z, params.containers,
                                                view.camera[:2] if view is not None else None, points[within & ~mask])
        carved = 0.0
        if container is not None and rim is not None:
            mesh, parts, visual = container.outer, container.pieces, container.visual
            base_centre = np.array([rim[0][0], rim[0][1], base_z])
            hollow.add(obj.id)
            kind = f"open container: revolved profile, hollow with a {1000 * container.wall:.0f} mm wall, cavity floor {1000 * (container.floor_z - base_z):.0f} mm up"
            handle = handle_pieces(pts, rim[0], container.outside, view.camera[:2] if view is not None else None)
            if handle:
                parts, visual = [*parts, *handle], cast(trimesh.Trimesh, trimesh.util.concatenate([visual, *handle]))
                kind = f"{kind}, with the handle it was seen with ({len(handle)} pieces)"
        elif revolved is not None and revolved.straight:
            if view is not None:
                mesh, carved = carve_free_space(mesh, view, base_z, pts[pts[:, 2] <= top_z], params, own=obj.id)
        elif revolved is None:
            seen = pts[pts[:, 2] <= top_z]
            carving = carve(mesh, view, base_z, seen, params, own=obj.id) if view is not None else None
            carved = carving.fraction if carving is not None else 0.0
            if carving is not None and carving.tiles is not None:  # much seen through: the body is not convex
                parts, visual = carving.tiles, carving.hull  # one closed surface to paint
                kind = f"{kind}, {len(parts)} convex tiles of what the camera's free space leaves"
            elif (parts := complete_slabs(body, base_z, top_z, params.slab, params.max_slabs, params.slab_max_fill, mesh, drops=drops)) is not None:
                kind = f"{kind} in {len(parts)} slabs (not convex)"
                if view is not None:
                    parts, carved = carve_pieces(parts, view, base_z, params, own=obj.id)
            elif (parts := complete_bands(body, base_z, top_z, params.bands, params.bands_max_fill, mesh, drops=drops)) is not None:
                kind = f"{kind} in {len(parts)} height bands (its profile is not convex)"
            elif carving is not None:
                mesh = carving.hull
        elif view is not None and parts is not None:
            parts, carved = carve_pieces(parts, view, base_z, params, own=obj.id)
            if carved >= params.carve_min_fraction:  # the revolved surface no longer matches: paint the carved hull
                visual = fast_hull(np.vstack([p.vertices for p in parts]))
        if carved >= params.carve_min_fraction and container is None:
            kind = f"{kind} carved by the camera's free space ({100 * carved:.0f} % of its volume)"
        if parts is not None and container is None:
            mesh = fast_hull(np.vstack([p.vertices for p in parts]))
        if slope is not None and obj.resting_on is not None and container is None:
            seated = seat_on(slope, float(done[obj.resting_on].bounds[0][2]), base_z, [mesh, *(parts or [])], params.base_clearance)
            if seated:
                mesh, parts = seated[0], seated[1:] or None
                visual = mesh if parts is None else visual
                base_centre = np.array([base_centre[0], base_centre[1], mesh.bounds[0][2]])
                kind = f"{kind}, seated along the sloping top it lies on"
        done[obj.id] = mesh
        observed[obj.id] = pts
        if parts is not None:
            pieces[obj.id] = parts
        set_shape(obj, mesh, base_centre, params, parts, visual)
        obj.quat = np.array([1.0, 0.0, 0.0, 0.0])
        if scene.colors is not None:
            obj.color = np.median(scene.colors[mask], axis=0)
        obj.notes.append(f"completed from {len(pts)} observed points as a {kind}")
    solid = [o for o in order if o.id not in hollow]
    separate_neighbours(solid, done, observed, params, pieces)
    part_overlapping(solid, done, observed, params, pieces)
    if view is not None and params.clip_free_space:
        held: dict[int, list[np.ndarray]] = {}  # a supporter keeps what stands on it level (those bases) and what was seen of it
        for o in order:
            if o.resting_on is not None and o.collision:
                low = np.vstack([p.vertices for p in o.collision]) + o.position
                seen = observed[o.resting_on]
                held.setdefault(o.resting_on, [seen[:: max(1, len(seen) // 2000)]]).append(low[low[:, 2] <= low[:, 2].min() + 0.002])
        keep_out_of_free_space(order, view, tolerance, params, {k: np.vstack(v) for k, v in held.items()},
                               {k: v[:: max(1, len(v) // 2000)] for k, v in observed.items()})
    for obj in order:
        if obj.resting_on is None and params.balance_margin > 0:
            brace(obj, params.balance_margin)
    return scene
