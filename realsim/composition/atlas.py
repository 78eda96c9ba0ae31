"""Images for meshes: deterministic PNG bytes, and flat per-face colours as a texture atlas
(MuJoCo meshes take colour from a texture, not from their vertices)."""

from __future__ import annotations

import io

import numpy as np
import trimesh
from PIL import Image


def png_bytes(rgb: np.ndarray) -> bytes:
    """Deterministic PNG bytes of an (H, W, 3) uint8 image."""
    out = io.BytesIO()
    Image.fromarray(rgb).save(out, format="PNG", compress_level=1)  # fast; photos barely compress anyway
    return out.getvalue()


def face_colour_atlas(vertices: np.ndarray, faces: np.ndarray, rgb: np.ndarray) -> tuple[trimesh.Trimesh, bytes]:
    """A mesh whose faces show flat colours ``rgb`` (F, 3; 0-1): each face gets its own 2x2-texel
    cell of a square texture (2x2, so linear filtering at the cell's centre never mixes
    neighbours); the mesh's vertices are unshared so every corner carries its face's UV."""
    n = len(faces)
    side = int(np.ceil(np.sqrt(n)))
    cells = np.zeros((side * side, 3), np.uint8)
    cells[:n] = (np.clip(rgb, 0.0, 1.0) * 255 + 0.5).astype(np.uint8)
    image = np.repeat(np.repeat(cells.reshape(side, side, 3), 2, axis=0), 2, axis=1)
    row, col = np.divmod(np.arange(n), side)
    uv = np.column_stack([(2 * col + 1) / (2 * side), 1.0 - (2 * row + 1) / (2 * side)])  # OpenGL: v up
    mesh = trimesh.Trimesh(vertices[faces].reshape(-1, 3), np.arange(3 * n).reshape(-1, 3), process=False)
    mesh.visual = trimesh.visual.TextureVisuals(uv=np.repeat(uv, 3, axis=0))
    return mesh, png_bytes(image)


MAX_BAKED_FACES = 40000  # a mesh with more faces keeps one mean colour (the atlas would outgrow the output budget)


def baked_colours(mesh: trimesh.Trimesh) -> tuple[trimesh.Trimesh, bytes] | None:
    """A mesh painted with vertex or face colours that vary (a phone scan, a generated asset) as
    an atlas-textured mesh; None when its colours are uniform (a material colour says it all),
    absent, or on more than :data:`MAX_BAKED_FACES` faces."""
    vis = mesh.visual
    kind = getattr(vis, "kind", None)
    if kind not in ("face", "vertex") or not 0 < len(mesh.faces) <= MAX_BAKED_FACES:
        return None
    cols = np.asarray(vis.face_colors if kind == "face" else vis.vertex_colors, float)[:, :3] / 255.0
    rgb = cols if kind == "face" else cols[mesh.faces].mean(axis=1)
    if float(rgb.std(axis=0).max()) < 0.03:
        return None
    return face_colour_atlas(np.asarray(mesh.vertices), np.asarray(mesh.faces), rgb)


def surface_colour(mesh: trimesh.Trimesh, png: bytes) -> np.ndarray | None:
    """The mean colour (RGB 0-1) a textured mesh shows: its texture sampled at each face's UV
    centroid, weighted by face area; None without per-vertex UVs."""
    uv = getattr(mesh.visual, "uv", None)
    if uv is None or len(uv) != len(mesh.vertices) or len(mesh.faces) == 0:
        return None
    with Image.open(io.BytesIO(png)) as im:
        image = np.asarray(im.convert("RGB"), float) / 255.0
    h, w = image.shape[:2]
    centre = np.asarray(uv, float)[mesh.faces].mean(axis=1) % 1.0  # textures repeat
    shown = image[((1.0 - centre[:, 1]) * (h - 1)).round().astype(int), (centre[:, 0] * (w - 1)).round().astype(int)]
    area = np.asarray(mesh.area_faces)
    return (shown * area[:, None]).sum(axis=0) / max(float(area.sum()), 1e-12)
