"""Complete single-view object scans into solids that rest on their support.

A camera sees one side of an object. Each segmented cluster becomes a closed convex shape whose
base lies on what the object stands on: the support plane, or the top of the object under it.
Round footprints become upright cylinders fitted to the visible arc; anything else becomes the
convex hull of the observed points and their projection onto the base (the visible hull
extruded down). The observed points are kept for the visual mesh colour.

For a camera view the line of sight to every observed pixel is empty space: a completed shape
is voxelized and every voxel the camera saw through (it projects to a pixel whose captured depth
lies farther away) is carved off, so no completed object covers a pixel where the camera saw
something behind it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError

from realsim.appearance import capture_intrinsics
from realsim.containers import ContainerParams, OpenContainer, complete_open_container, round_rim
from realsim.intrinsics import Intrinsics
from realsim.scene import Scene, SceneObject

OTHER_SURFACE_TOLERANCE = 0.001  # m: in front of another surface by more than this is free space


@dataclass(frozen=True)
class DepthView:
    """What the capture camera saw: per-pixel depth (m along the optical axis, NaN = nothing)."""

    intrinsics: Intrinsics
    world_to_optical: np.ndarray  # (4, 4), optical units
    scale: float  # optical units per metre
    depth: np.ndarray  # (H, W)
    labels: np.ndarray | None = None  # (H, W) object id per pixel (0 support/background), if known

    @classmethod
    def of(cls, scene: Scene) -> "DepthView | None":
        intr = capture_intrinsics(scene)
        if intr is None:
            return None
        w2o = np.linalg.inv(np.asarray(scene.capture.input_to_world, float))
        scale = float(np.cbrt(abs(np.linalg.det(w2o[:3, :3]))))
        z = (scene.points @ w2o[2, :3] + w2o[2, 3]) / scale
        labels = scene.labels.reshape(intr.height, intr.width) if scene.labels is not None else None
        return cls(intr, w2o, scale, z.reshape(intr.height, intr.width), labels)

    def veil(self, tolerance_deg: float = 80.0, where: np.ndarray | None = None) -> np.ndarray:
        """(H, W) mask of veil pixels: mixed depths at silhouettes, seen almost edge-on (a surface whose
        normal, from the grid neighbours, is within ``90 - tolerance_deg`` degrees of perpendicular to the
        ray). Only pixels in ``where`` (default all) are tested."""
        h, w = self.depth.shape
        idx = np.flatnonzero(where.ravel() if where is not None else np.ones(h * w, bool))
        v, u = np.divmod(idx, w)
        inner = (u > 0) & (u < w - 1) & (v > 0) & (v < h - 1)
        idx, v, u = idx[inner], v[inner], u[inner]

        def point(k: np.ndarray) -> np.ndarray:
            kv, ku = np.divmod(k, w)
            z = self.depth.ravel()[k]
            return np.column_stack([(ku - self.intrinsics.cx) / self.intrinsics.fx * z, (kv - self.intrinsics.cy) / self.intrinsics.fy * z, z])

        du = point(idx + 1) - point(idx - 1)
        dv = point(idx + w) - point(idx - w)
        p = point(idx)
        n = np.cross(du, dv)
        with np.errstate(invalid="ignore", divide="ignore"):
            cos = np.abs((n * p).sum(-1)) / (np.linalg.norm(n, axis=-1) * np.linalg.norm(p, axis=-1))
        out = np.zeros(h * w, bool)
        out[idx] = np.nan_to_num(cos, nan=1.0) < np.cos(np.radians(tolerance_deg))
        return out.reshape(h, w)

    def seen_through(self, points: np.ndarray, tolerance: float, own: int | None = None) -> np.ndarray:
        """Mask of world points the camera saw through: nearer than the captured depth at their pixel
        by more than ``tolerance`` where the pixel shows object ``own`` (its own noisy surface), by
        more than a millimetre where it shows anything else (nothing of ``own`` can be in front of that)."""
        opt = points @ self.world_to_optical[:3, :3].T + self.world_to_optical[:3, 3]
        pix = np.rint(self.intrinsics.project(opt)).astype(np.int64, copy=False) if len(points) else np.zeros((0, 2), np.int64)
        h, w = self.depth.shape
        inside = (opt[:, 2] > 0) & (pix[:, 0] >= 0) & (pix[:, 0] < w) & (pix[:, 1] >= 0) & (pix[:, 1] < h)
        seen = np.full(len(points), np.nan)
        seen[inside] = self.depth[pix[inside, 1], pix[inside, 0]]
        tol = np.full(len(points), tolerance)
        if own is not None and self.labels is not None:
            other = np.ones(len(points), bool)
            other[inside] = self.labels[pix[inside, 1], pix[inside, 0]] != own
            tol[other] = OTHER_SURFACE_TOLERANCE
        with np.errstate(invalid="ignore"):
            return opt[:, 2] / self.scale < seen - tol


def _columns(mesh: trimesh.Trimesh, step: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Vertical voxel columns inside the convex ``mesh``: xy centres (M, 2) and their z range.

    A convex solid is the intersection of its face half-spaces ``n.x <= d``: per column, faces
    facing up bound it from above, faces facing down from below, vertical faces cut the footprint.
    """
    lo, hi = mesh.bounds
    gx, gy = (np.arange(a + step / 2, b, step) for a, b in zip(lo[:2], hi[:2]))
    xy = np.stack(np.meshgrid(gx, gy, indexing="ij"), axis=-1).reshape(-1, 2)
    n = mesh.face_normals
    d = np.einsum("fk,fk->f", n, mesh.triangles[:, 0, :])
    rhs = d[None, :] - xy @ n[:, :2].T  # (M, F): n_z z <= rhs
    up, down, side = n[:, 2] > 1e-6, n[:, 2] < -1e-6, np.abs(n[:, 2]) <= 1e-6
    z_top = np.min(rhs[:, up] / n[up, 2], axis=1) if up.any() else np.full(len(xy), hi[2])
    z_bot = np.max(rhs[:, down] / n[down, 2], axis=1) if down.any() else np.full(len(xy), lo[2])
    ok = (z_top > z_bot) & (np.all(rhs[:, side] >= -1e-9, axis=1) if side.any() else True)
    return xy[ok], np.maximum(z_bot[ok], lo[2]), np.minimum(z_top[ok], hi[2])


def carve_free_space(mesh: trimesh.Trimesh, view: DepthView, base_z: float, observed: np.ndarray,
                     params: CompletionParams, own: int | None = None) -> tuple[trimesh.Trimesh, float]:
    """The convex ``mesh`` without the space the camera saw through (the hull of the voxels left and
    the ``observed`` surface points), and the share of voxels carved; ``mesh`` itself when less than
    ``carve_min_fraction`` is free."""
    lo, hi = mesh.bounds
    step = float(np.clip(np.max(hi - lo) / params.carve_voxels, 0.002, 0.005))
    xy, z_bot, z_top = _columns(mesh, step)
    if len(xy) == 0:
        return mesh, 0.0
    counts = np.maximum(np.ceil((z_top - z_bot) / step).astype(np.int64), 1)
    col = np.repeat(np.arange(len(xy)), counts)
    k = np.arange(len(col)) - np.repeat(np.cumsum(counts) - counts, counts)
    cells = np.column_stack([xy[col], np.minimum(z_bot[col] + (k + 0.5) * step, z_top[col])])
    free = view.seen_through(cells, params.carve_tolerance, own)
    fraction = float(free.mean())
    if fraction < params.carve_min_fraction or fraction > 0.9:
        return mesh, fraction
    kept_col, kept_z = col[~free], cells[~free, 2]
    extremes = []  # the lowest and highest kept voxel of each column bound the hull
    for pick in (np.minimum, np.maximum):
        z = np.full(len(xy), np.nan)
        if pick is np.minimum:
            z[:] = np.inf
            np.minimum.at(z, kept_col, kept_z)
        else:
            z[:] = -np.inf
            np.maximum.at(z, kept_col, kept_z)
        good = np.isfinite(z)
        extremes.append(np.column_stack([xy[good], z[good]]))
    kept = np.vstack([*extremes, observed])
    kept[kept[:, 2] < base_z + step, 2] = base_z
    try:
        carved = trimesh.convex.convex_hull(kept)
    except QhullError:
        return mesh, fraction
    return carved, fraction


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
    carve: bool = True  # carve completed shapes by the camera's free space (camera views only)
    carve_tolerance: float = 0.005  # a voxel this much nearer than the captured depth at its pixel is free space (m)
    carve_voxels: int = 40  # voxels along an object's largest extent (clamped to 2-5 mm)
    carve_min_fraction: float = 0.01  # carve only when at least this share of the voxels is free space
    containers: ContainerParams = ContainerParams()  # open round containers completed hollow
    mirror_max_depth_share: float = 0.6  # visible depth below this share of the width: the back half is missing
    veil_deg: float = 80.0  # object pixels seen more edge-on than this are silhouette veils (mixed depths), not surface
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


def mirror_hidden_half(points: np.ndarray, view: DepthView, base_z: float, top_z: float, params: CompletionParams) -> np.ndarray | None:
    """The observed points plus their mirror image behind the silhouette, when the camera evidently saw
    only the front half of a body: its visible depth (along the horizontal view direction) is short
    of its width and its top is not seen whole (a box whose top face is seen has its depth already)."""
    camera = np.linalg.inv(view.world_to_optical)[:3, 3]
    d = np.append(points[:, :2].mean(axis=0) - camera[:2], 0.0)
    if np.linalg.norm(d) < 1e-6:
        return None
    d /= np.linalg.norm(d)
    lateral = np.array([-d[1], d[0], 0.0])
    s, w = points @ d, points @ lateral
    depth = float(np.percentile(s, 98) - np.percentile(s, 2))
    width = float(np.percentile(w, 98) - np.percentile(w, 2))
    if depth >= params.mirror_max_depth_share * width or _top_face_seen(points[points[:, 2] >= top_z - 0.1 * (top_z - base_z)], d, depth):
        return None
    plane = float(np.percentile(s, 98))
    return np.vstack([points, points - 2.0 * (s - plane)[:, None] * d[None, :]])


def _top_face_seen(top: np.ndarray, d: np.ndarray, depth: float, cell: float = 0.005) -> bool:
    """The top band spans the visible depth and fills its outline (a face seen whole, not a rim arc)."""
    if len(top) < 10 or float(np.ptp(top @ d)) < 0.6 * depth:
        return False
    try:
        area = float(ConvexHull(top[:, :2]).volume)
    except QhullError:
        return False
    cells = len(np.unique(np.floor(top[:, :2] / cell).astype(np.int64), axis=0))
    return cells * cell * cell >= 0.6 * area


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
    observed: dict[int, np.ndarray] = {}
    hollow: set[int] = set()
    view = DepthView.of(scene) if params.carve else None
    veil = view.veil(params.veil_deg, labels.reshape(view.depth.shape) > 0).ravel() if view is not None else np.zeros(len(labels), bool)
    order = _bottom_up(scene.objects)
    for obj in order:
        mask = labels == obj.id
        pts = scene.points[mask & ~veil] if (mask & ~veil).sum() >= params.min_points else scene.points[mask]
        if obj.resting_on is not None and obj.resting_on in done and obj.resting_on not in hollow:
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
        mirrored = mirror_hidden_half(pts, view, base_z, top_z, params) if shape is None and view is not None else None
        if mirrored is not None:
            kind = "hull mirrored about its silhouette (the hidden half of a symmetric body)"
        mesh, base_centre = shape if shape is not None else complete_hull(pts if mirrored is None else mirrored, base_z, top_z)
        container = None
        rim = round_rim(pts, base_z, top_z, params.cylinder_max_radius) if params.containers.enabled else None
        if rim is not None:
            container = complete_open_container(pts, rim[0], rim[1], base_z, top_z, params.containers)
        if container is not None:
            mesh = container.outer
            base_centre = np.array([rim[0][0], rim[0][1], base_z])
            hollow.add(obj.id)
            kind = f"open container: revolved profile, hollow with a {1000 * container.wall:.0f} mm wall, cavity floor {1000 * (container.floor_z - base_z):.0f} mm up"
        elif view is not None:
            mesh, carved = carve_free_space(mesh, view, base_z, pts[pts[:, 2] <= top_z], params, own=obj.id)
            if carved >= params.carve_min_fraction:
                kind = f"{kind} carved by the camera's free space ({100 * carved:.0f} % of its volume)"
        done[obj.id] = mesh
        observed[obj.id] = pts
        _set_shape(obj, mesh, base_centre, params, container)
        obj.quat = np.array([1.0, 0.0, 0.0, 0.0])
        if scene.colors is not None:
            obj.color = np.median(scene.colors[mask], axis=0)
        obj.notes.append(f"completed from {len(pts)} observed points as a {kind}")
    _separate_neighbours([o for o in order if o.id not in hollow], done, observed, params)
    return scene


def clip_convex(mesh: trimesh.Trimesh, normal: np.ndarray, offset: float) -> trimesh.Trimesh | None:
    """The part of a convex mesh where ``normal . x >= offset`` (a convex hull), or None if too little is left."""
    v = np.asarray(mesh.vertices)
    side = v @ normal - offset
    edges = mesh.edges_unique
    sa, sb = side[edges[:, 0]], side[edges[:, 1]]
    cross = (sa * sb) < 0
    t = sa[cross] / (sa[cross] - sb[cross])
    points = np.vstack([v[side >= 0], v[edges[cross, 0]] + t[:, None] * (v[edges[cross, 1]] - v[edges[cross, 0]])])
    if len(points) < 4:
        return None
    try:
        out = trimesh.convex.convex_hull(points)
    except QhullError:
        return None
    return out if out.volume > 1e-7 else None


def _separate_neighbours(objects: list[SceneObject], done: dict[int, trimesh.Trimesh], observed: dict[int, np.ndarray],
                         params: CompletionParams) -> None:
    """Cut apart completed neighbours that overlap (their hidden backs grown into each other).

    The cut is the vertical plane across the line between the two objects' observed centroids,
    midway between their observed points along it; a pair whose observed points interleave along
    that line, or that are stacked, is left as it is.
    """
    for i, a in enumerate(objects):
        for b in objects[i + 1:]:
            if a.resting_on == b.id or b.resting_on == a.id:
                continue
            ma, mb = done[a.id], done[b.id]
            if np.any(ma.bounds[0] > mb.bounds[1]) or np.any(mb.bounds[0] > ma.bounds[1]):
                continue
            d = np.zeros(3)
            d[:2] = observed[b.id][:, :2].mean(axis=0) - observed[a.id][:, :2].mean(axis=0)
            if np.linalg.norm(d) < 1e-6:
                continue
            d /= np.linalg.norm(d)
            if np.max(ma.vertices @ d) <= np.min(mb.vertices @ d):
                continue
            pa, pb = np.percentile(observed[a.id] @ d, 99), np.percentile(observed[b.id] @ d, 1)
            if pa > pb:
                continue
            mid = (pa + pb) / 2
            for obj, normal in ((a, -d), (b, d)):
                cut = clip_convex(done[obj.id], normal, float(normal @ (d * mid)))
                if cut is None:
                    continue
                lo, hi = cut.bounds
                done[obj.id] = cut
                _set_shape(obj, cut, np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]]), params)
                obj.notes.append(f"cut apart from object {(b if obj is a else a).id}, whose completed shape it overlapped")


def _set_shape(obj: SceneObject, mesh: trimesh.Trimesh, base_centre: np.ndarray, params: CompletionParams,
               container: OpenContainer | None = None) -> None:
    """Give ``obj`` the world-frame ``mesh`` (or ``container``'s pieces and visual) in its object
    frame (origin at ``base_centre``)."""
    local = mesh.copy()
    local.apply_translation(-base_centre)
    obj.position = base_centre + np.array([0.0, 0.0, params.base_clearance])
    obj.size = local.extents.copy()
    if container is None:
        obj.collision = [local]
        obj.visual = local
        return
    obj.collision = [p.copy().apply_translation(-base_centre) for p in container.pieces]
    obj.visual = container.visual.copy().apply_translation(-base_centre)


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
