"""The backdrop: everything the camera saw that is neither an object nor a support, as one mesh.

An organized grid is triangulated directly (pixel neighbours become triangles), subsampled
to a stride that keeps the face count within a budget. A triangle is cut where the surface it
would span is seen edge-on (its normal nearly perpendicular to the view ray): that is a depth
discontinuity (the gap between a chair and the wall behind it), not a surface. UVs are the
pixels themselves, so the texture is the photo. An unorganized capture (a cloud, a mesh's
samples, a fused RGB-D sequence) is thinned to the face budget and meshed by ball pivoting, each
face coloured from its points through a small texture atlas. The mesh is visual only (group 2,
no contacts).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh

from realsim.composition.appearance import CaptureImage, projected_texture
from realsim.composition.atlas import face_colour_atlas


@dataclass(frozen=True)
class BackdropParams:
    """How the backdrop is triangulated."""

    enabled: bool = True
    max_faces: int = 80000  # face budget: the grid stride grows until it fits
    cloud_max_faces: int = 40000  # face budget of an unorganized capture's backdrop (the voxel grows until it fits)
    cloud_min_voxel: float = 0.01  # m: an unorganized capture's backdrop is never finer (it is context, not an object)
    grazing_deg: float = 85.0  # triangles seen more edge-on than this are depth discontinuities


@dataclass
class Backdrop:
    """The backdrop mesh (world frame, UVs into ``texture_png``) and how it was made."""

    mesh: trimesh.Trimesh
    texture_png: bytes
    stride: int  # grid stride (0: an unorganized capture)
    pixels: int  # captured pixels or points it shows


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


def build_cloud_backdrop(points: np.ndarray, colors: np.ndarray, keep: np.ndarray, spacing: float, viewpoint: np.ndarray,
                         params: BackdropParams = BackdropParams()) -> Backdrop | None:
    """The backdrop of an unorganized capture: the ``keep`` points (world frame, colours 0-1) thinned
    on a voxel grid until the face budget holds, meshed by ball pivoting with normals facing
    ``viewpoint`` (where a viewer stands), each face its points' colour. None when too little is left."""
    import open3d as o3d

    ok = keep & np.all(np.isfinite(points), axis=1) & np.all(np.isfinite(colors), axis=1)
    if not params.enabled or ok.sum() < 100:
        return None
    kept = points[ok]
    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(kept))
    cloud.colors = o3d.utility.Vector3dVector(np.clip(colors[ok], 0.0, 1.0))
    voxel = max(float(spacing) if np.isfinite(spacing) else 0.0, params.cloud_min_voxel)
    lower = kept.min(axis=0)  # Open3D's grid starts half a voxel below the cloud's minimum
    sample = kept[::SAMPLE_STRIDE]
    while True:  # the voxel grows until ball pivoting (about two faces a point) fits the face budget
        if not sample_fills(sample, lower, voxel, params.cloud_max_faces / 2):
            thin = cloud.voxel_down_sample(voxel)
            if 2 * len(thin.points) <= params.cloud_max_faces:
                break
        voxel *= 1.25
    if len(thin.points) < 50:
        return None
    thin.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=3 * voxel, max_nn=30))
    thin.orient_normals_towards_camera_location(np.asarray(viewpoint, float))
    surface = o3d.geometry.TriangleMesh.create_from_point_cloud_ball_pivoting(thin, o3d.utility.DoubleVector([1.5 * voxel, 3.0 * voxel]))
    faces = np.asarray(surface.triangles)
    if len(faces) == 0:
        return None
    rgb = np.asarray(surface.vertex_colors)[faces].mean(axis=1)
    mesh, png = face_colour_atlas(np.asarray(surface.vertices), faces, rgb)
    return Backdrop(mesh, png, 0, int(ok.sum()))


SAMPLE_STRIDE = 8  # every 8th point: a cheap lower bound on the voxels the whole cloud fills


def sample_fills(sample: np.ndarray, lower: np.ndarray, voxel: float, count: float) -> bool:
    """True when ``sample`` (every ``SAMPLE_STRIDE``-th point of a cloud) alone fills more than
    ``count`` voxels of Open3D's down-sampling grid (origin ``lower - voxel / 2``), so the whole
    cloud does too: that voxel need not be tried (a margin of 1 % covers rounding at cell borders)."""
    cells = np.floor((sample - (lower - voxel * 0.5)) / voxel).astype(np.int64)
    if len(cells) <= count:
        return False
    span = cells.max(axis=0) + 1
    flat = (cells[:, 0] * span[1] + cells[:, 1]) * span[2] + cells[:, 2]
    return len(np.unique(flat)) > 1.01 * count + 10
