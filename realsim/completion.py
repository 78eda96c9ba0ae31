"""Complete single-view object scans into solids that rest on their support.

A camera sees one side of an object. Each segmented cluster becomes a closed convex shape whose
base lies on what the object stands on: the support plane, or the top of the object under it.
Round footprints become upright cylinders fitted to the visible arc; anything else becomes the
convex hull of the observed points and their projection onto the base (the visible hull
extruded down). The observed points are kept for the visual mesh colour.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh
from scipy.spatial import QhullError

from realsim.scene import Scene, SceneObject


@dataclass(frozen=True)
class CompletionParams:
    """Parameters of shape completion."""

    top_percentile: float = 98.0  # object top from this percentile of point heights (robust to spikes)
    min_height: float = 0.01  # thinnest completed object (m)
    cylinder_max_rms: float = 0.08  # circle fit residual / radius below which a footprint is round
    cylinder_min_arc_deg: float = 100.0  # visible arc a cylinder fit needs
    cylinder_max_radius: float = 0.2
    cylinder_sections: int = 32
    max_foreign_fraction: float = 0.03  # completed shape may contain this share of a neighbour's points
    base_clearance: float = 0.0005  # gap left between the base and what it stands on (m)
    min_points: int = 30


def fit_circle(xy: np.ndarray) -> tuple[np.ndarray, float, float]:
    """Algebraic (Kasa) circle fit: centre, radius and RMS radial residual."""
    a = np.column_stack([2 * xy, np.ones(len(xy))])
    b = (xy**2).sum(axis=1)
    sol, *_ = np.linalg.lstsq(a, b, rcond=None)
    centre = sol[:2]
    radius = float(np.sqrt(max(sol[2] + centre @ centre, 1e-12)))
    rms = float(np.sqrt(np.mean((np.linalg.norm(xy - centre, axis=1) - radius) ** 2)))
    return centre, radius, rms


def _arc_coverage_deg(xy: np.ndarray, centre: np.ndarray, bins: int = 72) -> float:
    angles = np.arctan2(xy[:, 1] - centre[1], xy[:, 0] - centre[0])
    hist, _ = np.histogram(angles, bins=bins, range=(-np.pi, np.pi))
    return float(np.count_nonzero(hist) * 360.0 / bins)


def complete_cylinder(points: np.ndarray, base_z: float, top_z: float, params: CompletionParams) -> tuple[trimesh.Trimesh, np.ndarray] | None:
    """An upright cylinder (world frame) when the footprint is a circular arc, else None."""
    side = points[points[:, 2] < top_z - 0.25 * (top_z - base_z)]
    xy = (side if len(side) >= params.min_points else points)[:, :2]
    centre, radius, rms = fit_circle(xy)
    if radius > params.cylinder_max_radius or rms > params.cylinder_max_rms * radius:
        return None
    if _arc_coverage_deg(xy, centre) < params.cylinder_min_arc_deg:
        return None
    height = top_z - base_z
    mesh = trimesh.creation.cylinder(radius=radius, height=height, sections=params.cylinder_sections)
    mesh.apply_translation([centre[0], centre[1], base_z + height / 2])
    return mesh, np.array([centre[0], centre[1], base_z])


def complete_hull(points: np.ndarray, base_z: float, top_z: float) -> tuple[trimesh.Trimesh, np.ndarray]:
    """The observed points' convex hull extruded down to ``base_z`` (world frame)."""
    kept = points[points[:, 2] <= top_z]
    base = kept.copy()
    base[:, 2] = base_z
    top = kept.copy()
    top[:, 2] = np.maximum(top[:, 2], base_z + 1e-3)
    cloud = np.vstack([top, base])
    try:
        mesh = trimesh.convex.convex_hull(cloud)
    except QhullError:
        lo, hi = cloud.min(axis=0), cloud.max(axis=0)
        hi = np.maximum(hi, lo + 0.005)
        mesh = trimesh.creation.box(bounds=np.vstack([lo, hi]))
    lo, hi = mesh.bounds
    return mesh, np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, base_z])


def _foreign_fraction(mesh: trimesh.Trimesh, others: np.ndarray) -> float:
    if len(others) == 0:
        return 0.0
    lo, hi = mesh.bounds
    near = others[np.all((others >= lo) & (others <= hi), axis=1)]
    if len(near) == 0:
        return 0.0
    # The shapes are convex: inside means behind every face plane.
    normals, origins = mesh.face_normals, mesh.triangles[:, 0, :]
    inside = np.all(np.einsum("fk,nfk->nf", normals, near[:, None, :] - origins[None, :, :]) <= 0, axis=1)
    return float(inside.sum()) / len(others)


def complete_objects(scene: Scene, params: CompletionParams = CompletionParams()) -> Scene:
    """Give every scan object a closed collision/visual shape resting on what it stands on."""
    if scene.labels is None or not scene.objects:
        return scene
    labels = scene.labels
    by_id = {o.id: o for o in scene.objects}
    done: dict[int, trimesh.Trimesh] = {}
    order = _bottom_up(scene.objects)
    for obj in order:
        mask = labels == obj.id
        pts = scene.points[mask]
        if obj.resting_on is not None and obj.resting_on in done:
            base_z = _top_under(done[obj.resting_on], pts)
            done[obj.resting_on] = _flatten_top(by_id[obj.resting_on], done[obj.resting_on], base_z, params)
        else:
            base_z = scene.plane(obj.support_id).height if obj.support_id is not None else float(np.min(pts[:, 2]))
        top_z = max(float(np.percentile(pts[:, 2], params.top_percentile)), base_z + params.min_height)
        others = scene.points[(labels > 0) & ~mask]
        shape = complete_cylinder(pts, base_z, top_z, params)
        if shape is not None and _foreign_fraction(shape[0], others[:: max(1, len(others) // 20000)]) > params.max_foreign_fraction:
            shape = None
        kind = "cylinder" if shape is not None else "hull"
        mesh, base_centre = shape if shape is not None else complete_hull(pts, base_z, top_z)
        done[obj.id] = mesh
        _set_shape(obj, mesh, base_centre, params)
        obj.quat = np.array([1.0, 0.0, 0.0, 0.0])
        if scene.colors is not None:
            obj.color = np.median(scene.colors[mask], axis=0)
        obj.notes.append(f"completed from {len(pts)} observed points as a {kind}")
    return scene


def _set_shape(obj: SceneObject, mesh: trimesh.Trimesh, base_centre: np.ndarray, params: CompletionParams) -> None:
    """Give ``obj`` the world-frame ``mesh`` in its object frame (origin at ``base_centre``)."""
    local = mesh.copy()
    local.apply_translation(-base_centre)
    obj.position = base_centre + np.array([0.0, 0.0, params.base_clearance])
    obj.size = local.extents.copy()
    obj.collision = [local]
    obj.visual = local


def _flatten_top(under: SceneObject, mesh: trimesh.Trimesh, top_z: float, params: CompletionParams) -> trimesh.Trimesh:
    """Cut the top of the convex shape another object stands on flat at ``top_z``.

    The top of a completed scan is a shallow dome of noisy facets; a flat base resting on it
    touches at one point, pivots and sinks (one contact), sliding about a centimetre while the
    scene settles. A shared flat face gives MuJoCo a face-face contact (several points).
    """
    verts = mesh.vertices.copy()
    verts[:, 2] = np.minimum(verts[:, 2], top_z - params.base_clearance)  # the upper object drops onto it
    flat = trimesh.convex.convex_hull(verts)
    _set_shape(under, flat, under.position - np.array([0.0, 0.0, params.base_clearance]), params)
    return flat


def _bottom_up(objects: list[SceneObject]) -> list[SceneObject]:
    """Objects ordered so each comes after the object it rests on."""
    placed: list[SceneObject] = []
    remaining = list(objects)
    while remaining:
        ids = {o.id for o in placed}
        ready = [o for o in remaining if o.resting_on is None or o.resting_on in ids or o.resting_on not in {r.id for r in remaining}]
        if not ready:  # a cycle in resting_on: break it deterministically
            ready = [remaining[0]]
            ready[0].resting_on = None
        placed.extend(ready)
        remaining = [o for o in remaining if o not in ready]
    return placed


def _top_under(under: trimesh.Trimesh, pts: np.ndarray) -> float:
    """Height of the top of the convex shape ``under`` below the footprint of ``pts``.

    The upper surface of a convex solid is the lower envelope of its upward-facing face planes;
    the base is its highest point under the footprint (clamped to the solid's bounds).
    """
    normals = under.face_normals
    up = normals[:, 2] > 1e-6
    n, p0 = normals[up], under.triangles[up, 0, :]
    d = -(n * p0).sum(axis=1)
    xy = pts[:, :2]
    z = -(d[None, :] + xy @ n[:, :2].T) / n[None, :, 2]
    top = z.min(axis=1)
    lo, hi = under.bounds
    return float(np.clip(top.max(), lo[2], hi[2]))
