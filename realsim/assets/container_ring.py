"""An open container as a floor slab and a ring of wall slabs: its cavity kept with few hulls.

A free decomposition of a thin curved wall takes many hulls, because the hull of a curved patch
fills the chord on its concave side: the whole sagitta s = r (1 - cos a/2) of a patch spanning
angle a at radius r lands on one side. A flat piece between the least-squares planes of the
patch's outer and inner faces (each plane passes midway between its face's bulge and chord)
strays only about s/2 to either side, so each piece can span about 1.4x the angle. The ring about
the cavity axis (the circle through the rim) gets as many sectors as that half-sagitta within
the tolerance needs at the rim radius, and as many height bands as the self-check asks for; the
floor (the nearly horizontal surface at the bottom) is one slab. What is not thin wall or floor
(a handle, a spout, a lump inside) keeps the free decomposition's hulls that hold it.
"""

from __future__ import annotations

import math

import numpy as np
import trimesh

from realsim.assets.fidelity import dense_count, parts_fidelity, surface_distances
from realsim.assets.hulls import make_hull
from realsim.assets.params import AssetParams
from realsim.completion.circles import fit_circle

RIM_BAND = 0.1  # top fraction of the height whose vertices give the rim circle (the cavity axis)
FLOOR_NORMAL = 0.9  # |normal z| at least this, in the bottom FLOOR_HEIGHT of the height: the floor
FLOOR_HEIGHT = 0.25
EXTRA_SECTORS = 3  # sectors tried beyond the curvature estimate
MAX_BANDS = 4
THIN_WALL = 0.25  # a wall thicker than this fraction of the rim radius is not a thin wall
MASK_BANDS = 16  # height bands (and as many sectors) in which the wall's outer radius is measured


def _plane(points: np.ndarray, axis: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(point, unit normal turned towards ``axis``) of the least-squares plane through ``points``."""
    centre = points.mean(axis=0)
    normal = np.linalg.svd(points - centre, full_matrices=False)[2][2]
    return centre, normal if normal @ axis >= 0 else -normal


def _slab(points: np.ndarray, normals: np.ndarray, axis: np.ndarray | None = None) -> np.ndarray:
    """Vertices of the flat piece through a wall patch: the patch's footprint between the
    least-squares planes of its two faces (the surface facing along and against the patch's
    normal, or ``axis`` when given: those planes keep its direction). A plane fitted to a curved
    face passes midway between its bulge and its chord."""
    fixed = axis is not None
    axis = _plane(points, np.ones(3))[1] if axis is None else axis
    facing = normals @ axis > 0
    if facing.sum() < 3 or (~facing).sum() < 3:
        return points
    out = []
    for side in (facing, ~facing):
        centre, normal = (np.median(points[side], axis=0), axis) if fixed else _plane(points[side], axis)
        out.append(points - np.outer((points - centre) @ normal, normal))
    return np.vstack(out)


def _wall_mask(v: np.ndarray, floor: np.ndarray, centre: np.ndarray, radius: float, bands: int, tolerance: float) -> np.ndarray:
    """Thin-wall vertices: not floor, no farther out than the wall's outer radius at their height
    around most of the ring (the median over MASK_BANDS sectors of each sector's largest radius) plus
    ``tolerance``, and no deeper in than ``THIN_WALL`` x the rim ``radius`` below it; the rest (a
    handle, a spout, a lump inside) is left to the free decomposition."""
    d = v[:, :2] - centre
    r = np.linalg.norm(d, axis=1)
    sector = np.floor((np.arctan2(d[:, 1], d[:, 0]) + np.pi) / (2 * np.pi) * MASK_BANDS).astype(int) % MASK_BANDS
    z0, z1 = float(v[~floor, 2].min()), float(v[:, 2].max())
    band = np.clip(np.floor((v[:, 2] - z0) / max(z1 - z0, 1e-9) * bands).astype(int), 0, bands - 1)
    wall = ~floor
    for j in range(bands):
        reach = [r[c].max() for c in (wall & (band == j) & (sector == k) for k in range(MASK_BANDS)) if c.any()]
        if reach:
            outer = float(np.median(reach))
            wall &= ~((band == j) & ((r > outer + tolerance) | (r < outer - THIN_WALL * radius)))
    return wall


def ring_parts(solid: trimesh.Trimesh, centre: np.ndarray, radius: float, sectors: int, bands: int, tolerance: float) -> tuple[list[np.ndarray], np.ndarray]:
    """The floor slab and ``sectors`` x ``bands`` wall slabs of an upright container (vertex sets),
    and the vertices that are neither floor nor wall."""
    v = np.asarray(solid.vertices)
    normals = np.asarray(solid.vertex_normals)
    height = float(v[:, 2].max())
    floor = (np.abs(normals[:, 2]) >= FLOOR_NORMAL) & (v[:, 2] <= FLOOR_HEIGHT * height)
    parts = [_slab(v[floor], normals[floor], np.array([0.0, 0.0, 1.0]))] if floor.sum() >= 4 else []
    wall = _wall_mask(v, floor, centre, radius, MASK_BANDS, tolerance)
    d = v[:, :2] - centre
    sector = np.floor((np.arctan2(d[:, 1], d[:, 0]) + np.pi) / (2 * np.pi) * sectors).astype(int) % sectors
    z0 = float(v[~floor, 2].min())
    band = np.clip(np.floor((v[:, 2] - z0) / max(height - z0, 1e-9) * bands).astype(int), 0, bands - 1)
    for k in range(sectors):
        for j in range(bands):
            cell = wall & (sector == k) & (band == j)
            if cell.sum() >= 4:
                parts.append(_slab(v[cell], normals[cell]))
    return parts, v[~floor & ~wall]


def container_ring(solid: trimesh.Trimesh, params: AssetParams) -> tuple[list[trimesh.Trimesh], np.ndarray, dict] | None:
    """The fewest-hull ring (sectors x bands + floor) whose hulls stay within the tolerance of the
    scan, the vertices it leaves to a free decomposition, and a report; None when no ring within
    ``params.max_hulls`` fits. With nothing left over, the whole self-check must hold."""
    v = np.asarray(solid.vertices)
    top = v[v[:, 2] >= v[:, 2].max() * (1 - RIM_BAND)]
    if len(top) < 3:
        return None
    centre, radius, _ = fit_circle(top[:, :2])
    cos_half = 1.0 - 2.0 * params.target_p95 / max(radius, 1e-9)  # a slab strays s/2: s <= 2 x tolerance
    least = 3 if cos_half <= -1 else max(3, math.ceil(math.pi / math.acos(cos_half)))
    shapes = sorted(((n, m) for n in range(least, least + EXTRA_SECTORS + 1) for m in range(1, MAX_BANDS + 1)
                     if n * m + 1 <= params.max_hulls), key=lambda s: (s[0] * s[1], s[1]))
    for sectors, bands in shapes:
        parts, rest = ring_parts(solid, centre, radius, sectors, bands, params.target_p95)
        hulls = [h for h in (make_hull(p, params.min_hull_thickness, params.max_hull_vertices) for p in parts) if h is not None]
        if not hulls:
            continue
        if len(rest):  # only the ring's own stray from the scan counts until the rest is decomposed
            d95, iou = float(np.percentile(surface_distances(hulls, solid, n=6000, dense=dense_count(solid), seed=11)[0], 95)), 0.0
        else:
            d95, iou = parts_fidelity(hulls, solid)
        if d95 <= params.target_p95:
            report = {"ring": {"sectors": sectors, "bands": bands, "rim_radius": radius, "left_over_vertices": len(rest)},
                      "self_check": {"p95": d95, "iou": iou}}
            return hulls, rest, report
    return None


def ring_with_rest(ring: list[trimesh.Trimesh], rest: np.ndarray, hulls: list[trimesh.Trimesh], solid: trimesh.Trimesh,
                   params: AssetParams) -> tuple[list[trimesh.Trimesh], dict] | None:
    """The ring plus those of a free decomposition's ``hulls`` that hold a left-over vertex (a handle,
    a spout), when that is fewer hulls and passes the self-check's surface distance; else None."""
    near = params.target_p95 / 4
    keep = [h for h in hulls if ((rest @ (eq := h.face_normals).T - (eq * h.triangles[:, 0]).sum(axis=1)).max(axis=1) <= near).any()]
    both = ring + keep
    if len(both) >= len(hulls):
        return None
    d95, iou = parts_fidelity(both, solid)
    return (both, {"p95": d95, "iou": iou}) if d95 <= params.target_p95 else None
