"""The capture's appearance on the visual layer: textures projected from the capture's own image.

An organized cloud is a photo with depth. Every visual mesh built from it (scanned objects, the
top of each observed support, the backdrop) is textured by projecting its vertices into that
photo with the fitted intrinsics (:mod:`realsim.perception.intrinsics`): the UV of a vertex is the pixel it
is seen at. A layer's texture is the photo cropped to where its vertices land, with the pixels
that do not belong to the layer (other objects, the table behind, nothing) filled with the
nearest pixel that does; so the unseen side of an object takes the colour of the seen side in
front of it and a table region hidden under an object takes the table colour around it. Meshes
are subdivided to a few centimetres so the per-vertex projection stays perspective-correct.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import trimesh
from scipy.ndimage import distance_transform_edt
from scipy.spatial.transform import Rotation

from realsim.composition.atlas import face_colour_atlas, png_bytes
from realsim.composition.surface_follow import follow_seen_depth
from realsim.geometry import inside_convex_polygon
from realsim.perception.capture_camera import capture_intrinsics
from realsim.perception.intrinsics import Intrinsics
from realsim.scene import Scene, SceneObject, SupportPlane


@dataclass(frozen=True)
class AppearanceParams:
    """How the captured photo becomes textures."""

    enabled: bool = True
    object_edge: float = 0.04  # object visual meshes subdivided to this edge (m)
    support_cell: float = 0.03  # grid cell of a support's textured top (m)
    support_tolerance: float = 0.012  # a pixel within this of a support plane, inside its polygon, is the support (m)
    top_lift: float = 0.0005  # the textured top sits this far above the collision top (m)
    follow_surface: bool = True  # the textured top follows the captured surface's height (else flat on the fitted plane)
    follow_objects: bool = True  # a scanned object's visual surface takes the seen depth where the camera saw it
    object_follow_max: float = 0.02  # ... by at most this much along the line of sight (m); the collision shape stays the fit
    margin_px: int = 2


@dataclass(frozen=True)
class CaptureImage:
    """The capture as a photo: colours, per-pixel labels and world points on the grid, and its camera."""

    rgb: np.ndarray  # (H, W, 3) uint8
    labels: np.ndarray  # (H, W) int: 0 support/background, -1 noise, k object k
    world: np.ndarray  # (H, W, 3) world points, NaN where no depth
    intrinsics: Intrinsics
    world_to_optical: np.ndarray  # (4, 4)

    @property
    def valid(self) -> np.ndarray:
        return np.all(np.isfinite(self.world), axis=2)

    @cached_property
    def optical_depth(self) -> np.ndarray:
        """(H, W) the captured depth along the camera's axis (optical z), NaN where no depth."""
        return np.asarray(self.world, float) @ self.world_to_optical[2, :3] + self.world_to_optical[2, 3]

    def pixels(self, world_points: np.ndarray) -> np.ndarray:
        """(N, 2) pixel coordinates (u, v) of world points."""
        p = np.asarray(world_points, float) @ self.world_to_optical[:3, :3].T + self.world_to_optical[:3, 3]
        return self.intrinsics.project(p)


def capture_image(scene: Scene) -> CaptureImage | None:
    """The capture as a photo, or None (not an organized camera view with colours)."""
    intr = capture_intrinsics(scene)
    if intr is None or scene.colors is None or scene.labels is None:
        return None
    h, w = scene.grid_shape
    rgb = (np.clip(np.nan_to_num(scene.colors), 0, 1) * 255 + 0.5).astype(np.uint8).reshape(h, w, 3)
    return CaptureImage(rgb, scene.labels.reshape(h, w), scene.points.reshape(h, w, 3), intr,
                        np.linalg.inv(np.asarray(scene.capture.input_to_world, float)))


def projected_texture(image: CaptureImage, mask: np.ndarray, pix: np.ndarray, margin: int = 2) -> tuple[bytes, np.ndarray] | None:
    """The photo crop where ``pix`` (vertex pixels) land, non-``mask`` pixels filled from the nearest
    ``mask`` pixel, and the vertices' UVs in it (OpenGL convention: v up). None if ``mask`` is empty."""
    if not mask.any():
        return None
    h, w = mask.shape
    rows, cols = np.nonzero(mask)
    finite = np.all(np.isfinite(pix), axis=1)
    u = np.clip(pix[finite, 0], 0, w - 1) if finite.any() else cols.astype(float)
    v = np.clip(pix[finite, 1], 0, h - 1) if finite.any() else rows.astype(float)
    u0 = int(max(0, np.floor(min(u.min(), cols.min())) - margin))
    u1 = int(min(w, np.ceil(max(u.max(), cols.max())) + margin + 1))
    v0 = int(max(0, np.floor(min(v.min(), rows.min())) - margin))
    v1 = int(min(h, np.ceil(max(v.max(), rows.max())) + margin + 1))
    crop_mask = mask[v0:v1, u0:u1]
    crop = image.rgb[v0:v1, u0:u1]
    if not crop_mask.all():
        _, (ri, ci) = distance_transform_edt(~crop_mask, return_indices=True)
        crop = crop[ri, ci]
    ch, cw = crop.shape[:2]
    pu = np.where(finite, pix[:, 0], u0 + cw / 2)
    pv = np.where(finite, pix[:, 1], v0 + ch / 2)
    uv = np.column_stack([(np.clip(pu, u0, u1 - 1) - u0 + 0.5) / cw, 1.0 - (np.clip(pv, v0, v1 - 1) - v0 + 0.5) / ch])
    return png_bytes(np.ascontiguousarray(crop)), uv


def _object_to_world(obj: SceneObject) -> tuple[np.ndarray, np.ndarray]:
    rot = Rotation.from_quat(np.roll(np.asarray(obj.quat, float), -1)).as_matrix()
    return rot, np.asarray(obj.position, float)


def subdivided(mesh: trimesh.Trimesh, edge: float) -> trimesh.Trimesh:
    """``mesh`` with no edge longer than ``edge`` (plain geometry, no visuals)."""
    verts, faces = trimesh.remesh.subdivide_to_size(np.asarray(mesh.vertices), np.asarray(mesh.faces), max_edge=edge, max_iter=6)
    return trimesh.Trimesh(verts, faces, process=False)


def textured_visual(obj: SceneObject, image: CaptureImage, params: AppearanceParams) -> tuple[np.ndarray, np.ndarray, np.ndarray, bytes] | None:
    """A scanned object's visual mesh with UVs into its own crop of the photo, as arrays (vertices, faces,
    UVs; see :func:`textured_mesh`) and that crop's PNG; None: nothing to texture."""
    if obj.visual is None or obj.source_file is not None:
        return None
    mesh = subdivided(obj.visual, params.object_edge)
    rot, pos = _object_to_world(obj)
    mask = image.labels == obj.id
    if params.follow_objects:
        to_world = np.eye(4)
        to_world[:3, :3], to_world[:3, 3] = rot, pos
        mesh, _ = follow_seen_depth(mesh, image.world_to_optical @ to_world, image.optical_depth, mask,
                                    image.intrinsics.fx, image.intrinsics.project, params.object_follow_max)
    pix = image.pixels(np.asarray(mesh.vertices) @ rot.T + pos)
    result = projected_texture(image, mask, pix, params.margin_px)
    if result is None:
        return None
    png, uv = result
    return np.asarray(mesh.vertices).view(np.ndarray), np.asarray(mesh.faces).view(np.ndarray), uv, png


def textured_mesh(vertices: np.ndarray, faces: np.ndarray, uv: np.ndarray) -> trimesh.Trimesh:
    """A visual mesh with texture coordinates (nothing processed)."""
    mesh = trimesh.Trimesh(vertices, faces, process=False)
    mesh.visual = trimesh.visual.TextureVisuals(uv=uv)
    return mesh


def support_mask(image: CaptureImage, plane: SupportPlane, tolerance: float) -> np.ndarray:
    """Pixels of the photo that show ``plane``: not an object, within ``tolerance`` of it, inside its polygon."""
    world = image.world
    near = image.valid & (image.labels <= 0) & (np.abs(np.nan_to_num(world[..., 2], nan=1e9) - plane.height) < tolerance)
    idx = np.flatnonzero(near)
    inside = inside_convex_polygon(world.reshape(-1, 3)[idx, :2], np.asarray(plane.polygon, float))
    out = np.zeros(near.size, bool)
    out[idx[inside]] = True
    return out.reshape(near.shape)


def support_top(plane: SupportPlane, cell: float, lift: float) -> trimesh.Trimesh:
    """A flat grid over the support's oriented rectangle, ``lift`` above it (world frame)."""
    nx = max(1, int(np.ceil(plane.rect_size[0] / cell)))
    ny = max(1, int(np.ceil(plane.rect_size[1] / cell)))
    gx, gy = np.meshgrid(np.linspace(-0.5, 0.5, nx + 1) * plane.rect_size[0], np.linspace(-0.5, 0.5, ny + 1) * plane.rect_size[1])
    c, s = np.cos(plane.rect_yaw), np.sin(plane.rect_yaw)
    x = plane.rect_center[0] + c * gx - s * gy
    y = plane.rect_center[1] + s * gx + c * gy
    verts = np.column_stack([x.ravel(), y.ravel(), np.full(x.size, plane.height + lift)])
    idx = np.arange((nx + 1) * (ny + 1)).reshape(ny + 1, nx + 1)
    a, b, cc, d = idx[:-1, :-1].ravel(), idx[:-1, 1:].ravel(), idx[1:, 1:].ravel(), idx[1:, :-1].ravel()
    faces = np.vstack([np.column_stack([a, b, cc]), np.column_stack([a, cc, d])])
    return trimesh.Trimesh(verts, faces, process=False)


def follow_captured_surface(top: trimesh.Trimesh, plane: SupportPlane, image: CaptureImage, mask: np.ndarray, lift: float,
                            min_pixels: int = 10) -> trimesh.Trimesh:
    """``top`` (a grid over the support, see :func:`support_top`) with every vertex at the height the
    camera saw the support around it: the median height of the ``mask`` pixels nearer that vertex than
    any other (a sensor's slow depth distortions and a sagging top show; the pixel noise does not),
    plus ``lift``. A vertex with fewer than ``min_pixels`` takes the height of the nearest one with
    enough (under the objects, beyond the view); none with enough: ``top`` unchanged. Visual only:
    the collision top stays the fitted plane."""
    from scipy.spatial import cKDTree

    verts = np.asarray(top.vertices, float)
    seen = image.world[mask]
    if len(seen) < min_pixels or len(verts) == 0:
        return top
    _, node = cKDTree(verts[:, :2]).query(seen[:, :2])
    order = np.lexsort((seen[:, 2], node))
    node_sorted, z_sorted = node[order], seen[order, 2]
    ids, start, count = np.unique(node_sorted, return_index=True, return_counts=True)
    enough = count >= min_pixels
    if not enough.any():
        return top
    ids, median = ids[enough], z_sorted[start[enough] + count[enough] // 2]
    _, nearest = cKDTree(verts[ids, :2]).query(verts[:, :2])
    out = verts.copy()
    out[:, 2] = median[nearest] + lift
    return trimesh.Trimesh(out, np.asarray(top.faces), process=False)


def top_view_texture(plane: SupportPlane, top: trimesh.Trimesh, xy: np.ndarray, rgb: np.ndarray, texel: float = 0.005,
                     max_side: int = 1024) -> tuple[bytes, np.ndarray]:
    """The support seen from above: a texture over its oriented rectangle in which every texel takes
    the colour of the nearest captured support point (``xy``, ``rgb`` 0-1; what objects hid is
    filled from around them), and the UVs of ``top``'s vertices in it."""
    from scipy.spatial import cKDTree

    size = np.asarray(plane.rect_size, float)
    w, h = (int(np.clip(np.ceil(v / texel), 2, max_side)) for v in size)
    c, s = np.cos(plane.rect_yaw), np.sin(plane.rect_yaw)
    u = (np.arange(w) + 0.5) / w - 0.5
    v = 0.5 - (np.arange(h) + 0.5) / h  # image rows run from the far (+y) edge down
    gx, gy = np.meshgrid(u * size[0], v * size[1])
    world = np.column_stack([plane.rect_center[0] + c * gx.ravel() - s * gy.ravel(), plane.rect_center[1] + s * gx.ravel() + c * gy.ravel()])
    _, nearest = cKDTree(xy, balanced_tree=False, compact_nodes=False).query(world)  # built in half the time (sliding midpoint)
    image = (np.clip(rgb[nearest], 0.0, 1.0) * 255 + 0.5).astype(np.uint8).reshape(h, w, 3)
    local = (np.asarray(top.vertices)[:, :2] - plane.rect_center) @ np.array([[c, -s], [s, c]])
    uv = np.clip(local / size + 0.5, 0.0, 1.0)  # OpenGL: v up, the far edge at the top of the image
    return png_bytes(image), uv


def colour_object_from_points(obj: SceneObject, points: np.ndarray, colors: np.ndarray, labels: np.ndarray,
                              params: AppearanceParams, neighbours: int = 4) -> bool:
    """Colour a scanned object's visual mesh from its captured points (an unorganized capture has
    no photo to project): each face takes the mean colour of the nearest points, so the unseen
    side continues the seen side next to it."""
    from scipy.spatial import cKDTree

    if obj.visual is None or obj.source_file is not None:
        return False
    mine = (labels == obj.id) & np.all(np.isfinite(points), axis=1) & np.all(np.isfinite(colors), axis=1)
    if mine.sum() < neighbours:
        return False
    mesh = subdivided(obj.visual, params.object_edge)
    rot, pos = _object_to_world(obj)
    centres = np.asarray(mesh.triangles_center) @ rot.T + pos
    _, near = cKDTree(points[mine]).query(centres, k=neighbours)
    rgb = np.clip(colors[mine], 0.0, 1.0)[near].mean(axis=1)
    obj.visual, obj.texture_png = face_colour_atlas(np.asarray(mesh.vertices), np.asarray(mesh.faces), rgb)
    return True
