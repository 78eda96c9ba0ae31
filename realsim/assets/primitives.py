"""MuJoCo primitives fitted to a whole object: a box, an upright cylinder or a sphere.

A primitive collides far more cheaply than convex meshes (box-box and box-plane contacts are
analytic, a cylinder is one geom instead of dozens of hulls) and is used when it matches the
scanned solid as well as hulls would: two-way 95th-percentile surface distance within the
tolerance and volume IoU at the target. The primitive travels as a mesh (for fidelity checks
and footprints) whose ``metadata["mujoco_primitive"]`` says what geom to write:
``{"type": "box"|"cylinder"|"sphere", "size": [...], "pos": [...], "quat": [w, x, y, z]}``.
"""

from __future__ import annotations

import numpy as np
import trimesh
from scipy.spatial import ConvexHull

from realsim.assets.fidelity import parts_fidelity

PRIMITIVE_KEY = "mujoco_primitive"


def _tagged(mesh: trimesh.Trimesh, kind: str, size: list[float], pos: np.ndarray, yaw: float = 0.0) -> trimesh.Trimesh:
    mesh.metadata[PRIMITIVE_KEY] = {
        "type": kind,
        "size": [float(v) for v in size],
        "pos": [float(v) for v in pos],
        "quat": [float(np.cos(yaw / 2)), 0.0, 0.0, float(np.sin(yaw / 2))],
    }
    return mesh


def _min_area_rect(xy: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    """(centre, side lengths, yaw) of the smallest rectangle around 2-D points (rotating calipers)."""
    pts = xy[ConvexHull(xy).vertices]
    best = None
    for a, b in zip(pts, np.roll(pts, -1, axis=0)):
        edge = b - a
        yaw = float(np.arctan2(edge[1], edge[0]))
        c, s = np.cos(yaw), np.sin(yaw)
        local = pts @ np.array([[c, -s], [s, c]])
        lo, hi = local.min(axis=0), local.max(axis=0)
        area = float(np.prod(hi - lo))
        if best is None or area < best[0] - 1e-12:
            centre = np.array([[c, -s], [s, c]]) @ ((lo + hi) / 2)
            best = (area, centre, hi - lo, yaw)
    assert best is not None
    return best[1], best[2], best[3]


def box_fit(solid: trimesh.Trimesh) -> trimesh.Trimesh:
    """The upright box of least footprint around the solid."""
    v = np.asarray(solid.vertices)
    centre, sides, yaw = _min_area_rect(v[:, :2])
    z0, z1 = float(v[:, 2].min()), float(v[:, 2].max())
    pos = np.array([centre[0], centre[1], (z0 + z1) / 2])
    transform = trimesh.transformations.rotation_matrix(yaw, [0, 0, 1])
    transform[:3, 3] = pos
    mesh = trimesh.creation.box(extents=[sides[0], sides[1], z1 - z0], transform=transform)
    return _tagged(mesh, "box", [sides[0] / 2, sides[1] / 2, (z1 - z0) / 2], pos, yaw)


def cylinder_fit(solid: trimesh.Trimesh, sections: int = 48) -> trimesh.Trimesh:
    """The upright cylinder through the solid's outline: least-squares circle of its xy hull."""
    v = np.asarray(solid.vertices)
    ring = v[ConvexHull(v[:, :2]).vertices, :2]
    a = np.column_stack([2 * ring, np.ones(len(ring))])
    (cx, cy, k), *_ = np.linalg.lstsq(a, (ring**2).sum(axis=1), rcond=None)
    radius = float(np.sqrt(max(k + cx * cx + cy * cy, 1e-12)))
    z0, z1 = float(v[:, 2].min()), float(v[:, 2].max())
    pos = np.array([cx, cy, (z0 + z1) / 2])
    mesh = trimesh.creation.cylinder(radius=radius, height=z1 - z0, sections=sections,
                                     transform=trimesh.transformations.translation_matrix(pos))
    return _tagged(mesh, "cylinder", [radius, (z1 - z0) / 2], pos)


def sphere_fit(solid: trimesh.Trimesh) -> trimesh.Trimesh:
    """The sphere centred in the solid's bounds with its mean surface radius."""
    v = np.asarray(solid.vertices)
    pos = (v.min(axis=0) + v.max(axis=0)) / 2
    radius = float(np.mean(np.linalg.norm(v - pos, axis=1)))
    mesh = trimesh.creation.icosphere(subdivisions=3, radius=radius)
    mesh.apply_translation(pos)
    return _tagged(mesh, "sphere", [radius], pos)


def fit_primitive(solid: trimesh.Trimesh, tolerance: float, min_iou: float) -> tuple[trimesh.Trimesh | None, dict]:
    """The best-fitting primitive within ``tolerance`` (p95, m) and ``min_iou``, or None; and
    the fidelity of every candidate tried."""
    tried: dict = {}
    best: tuple[float, trimesh.Trimesh] | None = None
    for kind, fit in (("box", box_fit), ("cylinder", cylinder_fit), ("sphere", sphere_fit)):
        try:
            mesh = fit(solid)
        except Exception:  # degenerate outline (a flat or tiny solid)
            continue
        p95, iou = parts_fidelity([mesh], solid)
        tried[kind] = {"p95": p95, "iou": iou}
        if p95 <= tolerance and iou >= min_iou and (best is None or p95 < best[0]):
            best = (p95, mesh)
    return (best[1] if best else None), tried
