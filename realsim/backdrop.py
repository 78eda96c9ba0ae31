"""The backdrop: everything the camera saw that is neither an object nor a support, as one mesh.

The organized grid is triangulated directly (pixel neighbours become triangles), subsampled
to a stride that keeps the face count within a budget. A triangle is cut where the surface it
would span is seen edge-on (its normal nearly perpendicular to the view ray): that is a depth
discontinuity (the gap between a chair and the wall behind it), not a surface. UVs are the
pixels themselves, so the texture is the photo. The mesh is visual only (group 2, no contacts).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh

from realsim.appearance import CaptureImage, projected_texture


@dataclass(frozen=True)
class BackdropParams:
    """How the backdrop is triangulated."""

    enabled: bool = True
    max_faces: int = 80000  # face budget: the grid stride grows until it fits
    grazing_deg: float = 85.0  # triangles seen more edge-on than this are depth discontinuities


@dataclass
class Backdrop:
    """The backdrop mesh (world frame, UVs into ``texture_png``) and how it was made."""

    mesh: trimesh.Trimesh
    texture_png: bytes
    stride: int
    pixels: int


def grid_triangles(image: CaptureImage, mask: np.ndarray, stride: int, grazing_deg: float) -> tuple[np.ndarray, np.ndarray]:
    """(node pixel indices (K,) into the flattened grid, faces (F, 3) into them) of ``mask`` at ``stride``."""
    h, w = mask.shape
    rows, cols = np.arange(0, h, stride), np.arange(0, w, stride)
    node = (rows[:, None] * w + cols[None, :])  # (R, C) flat pixel index of each grid node
    ok = mask.ravel()[node]
    a, b = node[:-1, :-1], node[:-1, 1:]
    c, d = node[1:, :-1], node[1:, 1:]
    oa, ob, oc, od = ok[:-1, :-1], ok[:-1, 1:], ok[1:, :-1], ok[1:, 1:]
    tris = np.vstack([np.column_stack([a[m], c[m], b[m]]) for m in [oa & oc & ob]] +
                     [np.column_stack([b[m], c[m], d[m]]) for m in [ob & oc & od]])
    if len(tris) == 0:
        return np.zeros(0, int), np.zeros((0, 3), int)
    world = image.world.reshape(-1, 3)
    p = world[tris]  # (F, 3, 3)
    normal = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    camera = np.linalg.inv(image.world_to_optical)[:3, 3]
    ray = p.mean(axis=1) - camera
    cos = np.abs(np.einsum("fk,fk->f", normal, ray)) / np.maximum(np.linalg.norm(normal, axis=1) * np.linalg.norm(ray, axis=1), 1e-12)
    tris = tris[cos >= np.cos(np.radians(grazing_deg))]
    used, inverse = np.unique(tris, return_inverse=True)
    return used, inverse.reshape(-1, 3)


def build_backdrop(image: CaptureImage, exclude: np.ndarray, params: BackdropParams = BackdropParams()) -> Backdrop | None:
    """The backdrop of the photo's valid pixels outside ``exclude`` (objects, supports), or None."""
    mask = image.valid & ~exclude
    n = int(mask.sum())
    if not params.enabled or n < 16:
        return None
    stride = max(1, int(np.ceil(np.sqrt(2.0 * n / max(params.max_faces, 2)))))
    used, faces = grid_triangles(image, mask, stride, params.grazing_deg)
    if len(faces) == 0:
        return None
    h, w = mask.shape
    vr, vc = np.divmod(used, w)
    result = projected_texture(image, mask, np.column_stack([vc, vr]).astype(float), margin=0)
    if result is None:
        return None
    png, uv = result
    mesh = trimesh.Trimesh(image.world.reshape(-1, 3)[used], faces, process=False)
    mesh.visual = trimesh.visual.TextureVisuals(uv=uv)
    return Backdrop(mesh, png, stride, n)
