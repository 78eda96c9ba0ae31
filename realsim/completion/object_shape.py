"""The completed shape of one scan object from what the camera saw of it (see :mod:`realsim.completion.stage`)."""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any, cast

import numpy as np
import trimesh

from realsim.completion.carving import carve, carve_free_space, carve_pieces
from realsim.completion.containers import complete_open_container, round_rim
from realsim.completion.extrusion import complete_bands, complete_hull, complete_slabs
from realsim.completion.freespace import free_drops
from realsim.completion.handles import handle_pieces
from realsim.completion.hull import from_arrays, mesh_arrays, solid_hull
from realsim.completion.mirror import mirror_about_crest, mirror_hidden_half
from realsim.completion.neighbours import foreign_fraction
from realsim.completion.occlusion import hidden_continuation, seen_through_added
from realsim.completion.params import CompletionParams
from realsim.completion.revolution import complete_revolved
from realsim.completion.underside import underside_floors
from realsim.completion.view import DepthView
from realsim.scene import Scene, SceneObject


@dataclass
class Context:
    """What every object's completion reads: the scan (labels and points, denoised), the points under
    the veil of grazing views, the depth view and its free-space tolerance, the parameters."""

    scene: Scene
    labels: np.ndarray
    points: np.ndarray
    veil: np.ndarray
    view: DepthView | None
    tolerance: float
    params: CompletionParams

    def observed(self, obj: SceneObject) -> np.ndarray:
        """The object's points, those under the veil left out when enough remain."""
        mask = self.labels == obj.id
        return np.asarray(self.points[mask & ~self.veil] if (mask & ~self.veil).sum() >= self.params.min_points else self.points[mask])

    def floor_under(self, obj: SceneObject, pts: np.ndarray) -> float:
        """The base height of an object standing on no other object: its support plane, else its lowest point."""
        return self.scene.plane(obj.support_id).height if obj.support_id is not None else float(np.min(pts[:, 2]))


@dataclass
class Shape:
    """A completed shape (world frame): one convex ``mesh``, or convex ``parts`` (their hull in ``mesh``)
    painted as ``visual``; its base centre and height, how it was made, whether it is an open container."""

    mesh: trimesh.Trimesh
    parts: list[trimesh.Trimesh] | None
    visual: trimesh.Trimesh | None
    base_centre: np.ndarray
    base_z: float
    kind: str
    hollow: bool

    def packed(self) -> tuple[Any, ...]:
        """The shape as arrays (to send between processes; see :meth:`unpacked`)."""
        return (mesh_arrays(self.mesh), None if self.parts is None else [mesh_arrays(p) for p in self.parts],
                None if self.visual is None else mesh_arrays(self.visual), self.base_centre, self.base_z, self.kind, self.hollow)

    @staticmethod
    def unpacked(packed: tuple[Any, ...]) -> Shape:
        mesh, parts, visual, base_centre, base_z, kind, hollow = packed
        return Shape(from_arrays(mesh), None if parts is None else [from_arrays(p) for p in parts],
                     None if visual is None else from_arrays(visual), base_centre, base_z, kind, hollow)


def complete_object(obj: SceneObject, ctx: Context, base_z: float) -> Shape:
    """The closed shape of ``obj`` standing at ``base_z``: a cylinder or revolved profile, an open
    container, or its hull (mirrored, carved by the free space, in slabs or bands when not convex)."""
    mask = ctx.labels == obj.id
    pts = ctx.observed(obj)
    top_z = max(float(np.percentile(pts[:, 2], ctx.params.top_percentile)), base_z + ctx.params.min_height)
    others = ctx.points[(ctx.labels > 0) & ~mask]
    revolved = complete_revolved(pts, base_z, top_z, ctx.params, ctx.view.camera[:2] if ctx.view is not None else None)
    if revolved is not None and foreign_fraction(revolved.outer, others[:: max(1, len(others) // 20000)]) > ctx.params.max_foreign_fraction:
        revolved = None
    parts: list[trimesh.Trimesh] | None = None
    visual: trimesh.Trimesh | None = None
    floors: np.ndarray | None = None
    if revolved is not None and revolved.straight:
        kind = "cylinder"
        mesh, base_centre = revolved.outer, np.array([revolved.centre[0], revolved.centre[1], base_z])
    elif revolved is not None:
        kind = "solid of revolution of its visible profile"
        mesh, parts, visual = revolved.outer, revolved.pieces, revolved.visual
        base_centre = np.array([revolved.centre[0], revolved.centre[1], base_z])
    else:
        mirrored = mirror_hidden_half(pts, ctx.view, base_z, top_z, ctx.params, ctx.points[mask]) if ctx.view is not None else None
        kind = "hull mirrored about its silhouette (the hidden half of a symmetric body)" if mirrored is not None else "hull"
        if mirrored is None and ctx.view is not None and ctx.params.mirror_crest:
            mirrored = mirror_about_crest(pts, ctx.view, base_z, top_z, ctx.params)
            kind = "hull mirrored behind its crest (the hidden far side of a body lying flat)" if mirrored is not None else kind
        body = pts if mirrored is None else mirrored
        if ctx.view is not None and ctx.params.occluded_continuation:
            hidden = hidden_continuation(ctx.view, ctx.labels, ctx.points, ~ctx.veil, obj.id, body, base_z, ctx.tolerance,
                                         ctx.params.occlusion_gap, ctx.params.occlusion_reach, ctx.params.occlusion_max_share,
                                         tuple(o.id for o in ctx.scene.objects if o.resting_on == obj.id or o.id == obj.resting_on))
            hidden = hidden[hidden[:, 2] <= top_z]
            if len(hidden) and seen_through_added(ctx.view, body, hidden, base_z, top_z, obj.id, ctx.tolerance) <= ctx.params.occlusion_max_seen_through:
                body = np.vstack([body, hidden])
                kind = f"{kind}, continued behind the nearer objects hiding it"
        drops = free_drops(body, base_z, ctx.view, ctx.tolerance) if ctx.view is not None else None
        floors = (underside_floors(body, base_z, top_z, ctx.params.slab, ctx.params.underside_max_height_share, ctx.params.underside_edge,
                                   ctx.params.underside_central)
                  if ctx.params.underside else None)
        kind = f"{kind}, its underside the mirror of its upper side" if floors is not None else kind
        mesh, base_centre = complete_hull(body, base_z, top_z, drops=drops)
    container = None
    rim = round_rim(pts, base_z, top_z, ctx.params.cylinder_max_radius) if ctx.params.containers.enabled else None
    if rim is not None:
        within = (np.linalg.norm(ctx.points[:, :2] - rim[0], axis=1) < rim[1]) & (ctx.points[:, 2] < top_z)
        within &= ctx.points[:, 2] > base_z + ctx.params.containers.min_wall  # lower: the support seen under a flaring wall
        container = complete_open_container(pts, rim[0], rim[1], base_z, top_z, ctx.params.containers,
                                            ctx.view.camera[:2] if ctx.view is not None else None, ctx.points[within & ~mask],
                                            float(ctx.view.camera[2]) if ctx.view is not None else None)
    carved = 0.0
    if container is not None and rim is not None:
        mesh, parts, visual = container.outer, container.pieces, container.visual
        base_centre = np.array([rim[0][0], rim[0][1], base_z])
        kind = f"open container: revolved profile, hollow with a {1000 * container.wall:.0f} mm wall, cavity floor {1000 * (container.floor_z - base_z):.0f} mm up"
        handle = handle_pieces(pts, rim[0], container.outside, ctx.view.camera[:2] if ctx.view is not None else None)
        if handle:
            parts, visual = [*parts, *handle], cast(trimesh.Trimesh, trimesh.util.concatenate([visual, *handle]))
            kind = f"{kind}, with the handle it was seen with ({len(handle)} pieces)"
    elif revolved is not None and revolved.straight:
        if ctx.view is not None:
            mesh, carved = carve_free_space(mesh, ctx.view, base_z, pts[pts[:, 2] <= top_z], ctx.params, own=obj.id)
    elif revolved is None:
        seen = pts[pts[:, 2] <= top_z]
        carving = carve(mesh, ctx.view, base_z, seen, ctx.params, own=obj.id) if ctx.view is not None else None
        if floors is not None:  # not convex or not: judged on the hull extruded down (the space under a round side says nothing of it)
            mesh, base_centre = complete_hull(body, base_z, top_z, drops=drops, floors=floors)
            tiled = replace(ctx.params, tile_min_fraction=0.0 if carving is not None and carving.tiles is not None else np.inf)
            carving = carve(mesh, ctx.view, base_z, seen, tiled, own=obj.id, outline=body[body[:, 2] <= top_z]) if ctx.view is not None else None
        carved = carving.fraction if carving is not None else 0.0
        if carving is not None and carving.tiles is not None:  # much seen through: the body is not convex
            parts, visual = carving.tiles, carving.hull  # one closed surface to paint
            kind = f"{kind}, {len(parts)} convex tiles of what the camera's free space leaves"
        elif (parts := complete_slabs(body, base_z, top_z, ctx.params.slab, ctx.params.max_slabs, ctx.params.slab_max_fill, mesh, drops=drops, floors=floors)) is not None:
            kind = f"{kind} in {len(parts)} slabs (not convex)"
            if ctx.view is not None:
                parts, carved = carve_pieces(parts, ctx.view, base_z, ctx.params, own=obj.id)
        elif (parts := complete_bands(body, base_z, top_z, ctx.params.bands, ctx.params.bands_max_fill, mesh, drops=drops)) is not None:
            kind = f"{kind} in {len(parts)} height bands (its profile is not convex)"
        elif carving is not None:
            mesh = carving.hull
    elif ctx.view is not None and parts is not None:
        parts, carved = carve_pieces(parts, ctx.view, base_z, ctx.params, own=obj.id)
        if carved >= ctx.params.carve_min_fraction:  # the revolved surface no longer matches: paint the carved hull
            carved_hull = _hull_of(parts)
            visual = carved_hull if carved_hull is not None else visual
    if carved >= ctx.params.carve_min_fraction and container is None:
        kind = f"{kind} carved by the camera's free space ({100 * carved:.0f} % of its volume)"
    if parts is not None and container is None:
        parts = [p for p in parts if solid_hull(np.asarray(p.vertices)) is not None]  # a carved piece may be left flat
        whole = _hull_of(parts)
        if whole is None:  # the carved pieces enclose nothing (flat or none): the shape as completed before carving
            parts, visual, kind = None, None, f"{kind}; its carved pieces enclosed no volume, so it is kept uncarved"
        else:
            mesh = whole
    return Shape(mesh, parts, visual, base_centre, base_z, kind, container is not None)


def _hull_of(parts: list[trimesh.Trimesh]) -> trimesh.Trimesh | None:
    """The convex hull of all ``parts`` when they enclose a volume, else None (none left, or flat)."""
    return solid_hull(np.vstack([p.vertices for p in parts])) if parts else None
