"""Meshes without a source file as :class:`PreparedObject`: completed scan shapes and primitives.

An object named in a photo with no mesh of its own gets a box or an upright cylinder of its size
table category's typical extents (round categories become cylinders), ordered like the size
Claude saw (the largest table extent goes where the photo's largest extent was).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import trimesh

from realsim.assets import PreparedObject
from realsim.physics.size_table import lookup
from realsim.understanding.shape_label import is_round

DEFAULT_EXTENT = 0.08  # m, a cube for an unknown object with no usable size


def prepared_from_mesh(label: str, mesh: trimesh.Trimesh, source: Path, rgba: tuple[float, float, float, float] = (0.6, 0.6, 0.6, 1.0),
                       warnings: list[str] | None = None) -> PreparedObject:
    """A closed convex/primitive mesh in the object frame (base centre at the origin, Z up)."""
    mesh = mesh.copy()
    volume = float(abs(mesh.volume))
    if mesh.is_volume and volume > 0:
        com = np.asarray(mesh.center_mass, float)
        inertia = np.asarray(mesh.moment_inertia, float) / max(float(mesh.mass), 1e-12)
    else:
        com = mesh.bounds.mean(axis=0)
        e = mesh.extents
        inertia = np.diag([e[1] ** 2 + e[2] ** 2, e[0] ** 2 + e[2] ** 2, e[0] ** 2 + e[1] ** 2]) / 12.0
        volume = volume or float(np.prod(e))
    return PreparedObject(
        label=label, source=source, visual=mesh, texture_png=None, rgba=tuple(float(c) for c in rgba), color=np.asarray(rgba[:3], float),
        hulls=[mesh],
        volume=volume, size=np.asarray(mesh.extents, float), com=com, inertia_unit_mass=inertia, scale_applied=1.0,
        warnings=list(warnings or []), solid=mesh, surface_area=float(mesh.area), convex_hull_volume=float(abs(mesh.convex_hull.volume)),
        solid_method="primitive",
    )


def primitive_extents(label: str, seen_size: tuple[float, float, float] | None) -> tuple[np.ndarray, bool]:
    """(x, y, z extents, round) for a label: table typical extents, ordered like ``seen_size``."""
    m = lookup(label)
    if m is None:
        size = np.clip(np.asarray(seen_size or (DEFAULT_EXTENT,) * 3, float), 0.01, 1.0)
        return size, False
    cat = m.category
    dims = np.sort(np.asarray((list(cat.dims) + [cat.dims[-1]] * 3)[:3], float))[::-1]
    round_ = is_round(cat)
    if round_:
        d = dims
        if abs(d[0] - d[1]) <= abs(d[1] - d[2]):  # wide and flat (bowl, plate): diameter d0, height d2
            return np.array([d[0], d[0], d[2]]), True
        return np.array([d[1], d[1], d[0]]), True  # tall (can, bottle): diameter d1, height d0
    order = np.argsort(-np.asarray(seen_size, float)) if seen_size is not None else np.array([1, 2, 0])
    out = np.empty(3)
    out[order] = dims
    return out, False


def primitive_mesh(extents: np.ndarray, round_: bool) -> trimesh.Trimesh:
    """A box or an upright cylinder with its base centre at the origin."""
    if round_:
        mesh = trimesh.creation.cylinder(radius=float(extents[0]) / 2, height=float(extents[2]), sections=32)
    else:
        mesh = trimesh.creation.box(extents=extents)
    mesh.apply_translation([0.0, 0.0, float(extents[2]) / 2])
    return mesh
