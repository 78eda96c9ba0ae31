"""The completion stage: every scan object gets a closed shape resting on what it stands on."""

from __future__ import annotations

import numpy as np
import trimesh

from realsim.completion.balance import brace
from realsim.completion.fragments import join_occluded_fragments
from realsim.completion.freespace import free_space_tolerance, keep_out_of_free_space
from realsim.completion.neighbours import separate_neighbours
from realsim.completion.object_shape import Context, Shape, complete_object
from realsim.completion.overlaps import part_overlapping
from realsim.completion.params import CompletionParams
from realsim.completion.parts import merge_container_parts
from realsim.completion.stacking import bottom_up, flatten_top, rest_inside, seat_on, set_shape, sloping_top, top_under
from realsim.completion.view import DepthView
from realsim.forkmap import fork_map
from realsim.scene import Scene, SceneObject


def stacking_levels(order: list[SceneObject]) -> list[list[SceneObject]]:
    """``order`` (each object after the one it rests on, :func:`bottom_up`) cut into its longest runs
    in which no object rests on another of the same run: each run's shapes can be made together once
    the earlier runs' are done (an object's completion reads only its supporter's finished shape)."""
    levels: list[list[SceneObject]] = []
    ids: set[int] = set()
    for obj in order:
        if not levels or obj.resting_on in ids:
            levels.append([])
            ids = set()
        levels[-1].append(obj)
        ids.add(obj.id)
    return levels


def _place(obj: SceneObject, shape: Shape, slope: np.ndarray | None, floor: float, ctx: Context, done: dict[int, trimesh.Trimesh],
           pts: np.ndarray, hollow: set[int], pieces: dict[int, list[trimesh.Trimesh]]) -> None:
    """Give ``obj`` its completed ``shape`` (seated along the ``slope`` of the top it lies on, not below
    that supporter's bottom ``floor``) and record it in ``done``, ``hollow`` and ``pieces``."""
    params = ctx.params
    mesh, parts, visual, base_centre, kind = shape.mesh, shape.parts, shape.visual, shape.base_centre, shape.kind
    if shape.hollow:
        hollow.add(obj.id)
    if slope is not None and obj.resting_on is not None and not shape.hollow:
        seated = seat_on(slope, floor, shape.base_z, [mesh, *(parts or [])], params.base_clearance)
        if seated:
            mesh, parts = seated[0], seated[1:] or None
            visual = mesh if parts is None else visual
            base_centre = np.array([base_centre[0], base_centre[1], mesh.bounds[0][2]])
            kind = f"{kind}, seated along the sloping top it lies on"
    done[obj.id] = mesh
    if parts is not None:
        pieces[obj.id] = parts
    set_shape(obj, mesh, base_centre, params, parts, visual)
    obj.quat = np.array([1.0, 0.0, 0.0, 0.0])
    if ctx.scene.colors is not None:
        obj.color = np.median(ctx.scene.colors[ctx.labels == obj.id], axis=0)
    obj.notes.append(f"completed from {len(pts)} observed points as a {kind}")


def complete_objects(scene: Scene, params: CompletionParams = CompletionParams()) -> Scene:
    """Give every scan object a closed collision/visual shape resting on what it stands on."""
    if scene.labels is None or not scene.objects:
        return scene
    labels, points = scene.labels, scene.points
    if points is None:
        return scene
    view = DepthView.of(scene) if params.carve else None  # its labels are the scene's: the merge below shows in them
    merge_container_parts(scene, params.cylinder_max_radius, params.containers, view.camera if view is not None else None)
    by_id = {o.id: o for o in scene.objects}
    done: dict[int, trimesh.Trimesh] = {}
    observed: dict[int, np.ndarray] = {}
    hollow: set[int] = set()
    pieces: dict[int, list[trimesh.Trimesh]] = {}
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
    ctx = Context(scene, labels, points, veil, view, tolerance, params)
    for level in stacking_levels(order):
        bases: list[tuple[float, np.ndarray | None, float]] = []  # per object: base height, sloping top, its supporter's bottom
        for obj in level:
            slope, pts, floor = None, ctx.observed(obj), np.nan
            if obj.resting_on is not None and obj.resting_on in done and obj.resting_on not in hollow:
                base_z = top_under(done[obj.resting_on], pts)
                slope = sloping_top(done[obj.resting_on], pts)
                if slope is None:  # a level top is cut flat (a face-face contact); a sloping one is kept
                    done[obj.resting_on] = flatten_top(by_id[obj.resting_on], done[obj.resting_on], base_z, params)
                floor = float(done[obj.resting_on].bounds[0][2])
            else:  # on a support, or on a hollow body: down to what is under it inside (its cavity floor), not through it
                inside = rest_inside(pieces[obj.resting_on], pts, tolerance) if obj.resting_on in hollow else None
                base_z = ctx.floor_under(obj, pts) if inside is None else inside + params.base_clearance
            bases.append((base_z, slope, floor))
            observed[obj.id] = pts
        made = fork_map(lambda k: complete_object(level[k], ctx, bases[k][0]).packed(), len(level))  # shared with a forked helper
        for obj, (_, slope, floor), packed in zip(level, bases, made):
            _place(obj, Shape.unpacked(packed), slope, floor, ctx, done, observed[obj.id], hollow, pieces)
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


def complete_and_begin_meshes(scene: Scene, params: CompletionParams = CompletionParams()) -> Scene:
    """:func:`complete_objects`, then the objects' mesh files for compose begun by a forked helper
    while the next stages run (:func:`realsim.composition.object_meshes.begin`)."""
    from realsim.composition.object_meshes import begin  # here: composition imports completion

    scene = complete_objects(scene, params)
    begin(scene)
    return scene
