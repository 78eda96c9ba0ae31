"""Meshes the generator builds scenes from: YCB scans, boxes, and a ray caster over the result."""

from __future__ import annotations

import functools

import numpy as np
import trimesh

from realsim.errors import InputError

TESSELLATION = 0.03  # support boxes are split into triangles no longer than this (m)


@functools.lru_cache(maxsize=32)
def load_ycb(path: str) -> trimesh.Trimesh:
    """A YCB scan's geometry (cached per path)."""
    try:
        mesh = trimesh.load(path, force="mesh", process=False)
    except Exception as exc:  # trimesh raises many types
        raise InputError(f"{path}: cannot read the YCB mesh ({exc})") from None
    return trimesh.Trimesh(np.asarray(mesh.vertices), np.asarray(mesh.faces), process=False)


def raycaster(mesh: trimesh.Trimesh):  # noqa: ANN201 - open3d type
    """An Open3D ray-casting scene over ``mesh`` (for views and closest-point labels)."""
    import open3d as o3d

    rc = o3d.t.geometry.RaycastingScene()
    rc.add_triangles(o3d.core.Tensor(np.asarray(mesh.vertices, np.float32)), o3d.core.Tensor(np.asarray(mesh.faces, np.uint32)))
    return rc


def box_mesh(extents: tuple[float, float, float], center: tuple[float, float, float]) -> trimesh.Trimesh:
    """A box split into triangles no longer than :data:`TESSELLATION` (sampled and ray-cast evenly)."""
    box = trimesh.creation.box(extents=extents)
    box.apply_translation(center)
    v, f = trimesh.remesh.subdivide_to_size(box.vertices, box.faces, TESSELLATION)
    return trimesh.Trimesh(v, f, process=False)
