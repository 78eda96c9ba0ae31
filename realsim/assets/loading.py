"""Loading object meshes (OBJ+MTL+textures, GLB/glTF, STL, PLY) and naming them."""

from __future__ import annotations

import io
import re
import warnings
from pathlib import Path

import numpy as np
import trimesh

from realsim.errors import InputError

SUPPORTED = {".obj", ".glb", ".gltf", ".stl", ".ply", ".off"}
GENERIC_STEMS = {"textured", "model", "mesh", "nontextured", "scene", "object", "untitled", "textured_simple", "poisson", "google_16k", "google_64k", "meshes"}


def label_from_path(path: Path) -> str:
    """``025_mug/textured.obj`` -> ``mug``; ``cracker_box.glb`` -> ``cracker_box``."""
    path = Path(path)
    stem = path.stem.lower()
    parts = [p for p in path.parent.parts[::-1]]
    name = stem
    if stem in GENERIC_STEMS or re.fullmatch(r"[\d_\-]*", stem):
        for p in parts:  # 025_mug/google_16k/textured.obj -> mug
            if p.lower() not in GENERIC_STEMS and not re.fullmatch(r"[\d_\-]*", p):
                name = p.lower()
                break
    name = re.sub(r"^[\d_\-\s]+", "", name)
    name = re.sub(r"[\s\-]+", "_", name).strip("_")
    return name or "object"


def _gltf_to_z_up() -> np.ndarray:
    # glTF is +Y up: (x, y, z) -> (x, -z, y)
    return np.array([[1, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 1]], dtype=float)


def load_object_mesh(path: Path, label: str | None = None) -> tuple[trimesh.Trimesh, str]:
    """Load one object mesh (all parts concatenated, visuals kept) and its label.

    glTF/GLB (+Y up) is rotated to +Z up. Raises :class:`InputError` when the file is missing,
    unsupported, corrupt or holds no triangles.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError(f"object mesh {path} does not exist; pass an existing OBJ/GLB/glTF/STL/PLY file")
    ext = path.suffix.lower()
    if ext not in SUPPORTED:
        raise InputError(f"object mesh {path}: unsupported format {ext!r}; use one of {', '.join(sorted(SUPPORTED))}")
    if path.stat().st_size == 0:
        raise InputError(f"object mesh {path} is empty (0 bytes); re-export the mesh")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            loaded = trimesh.load(str(path), process=False, maintain_order=True)
    except Exception as exc:  # trimesh raises many types on corrupt input
        raise InputError(f"object mesh {path} could not be read ({type(exc).__name__}: {exc}); check that the file is a valid {ext[1:].upper()}") from exc
    mesh = _to_single_mesh(loaded)
    if mesh is None or len(mesh.faces) == 0 or len(mesh.vertices) < 3:
        raise InputError(f"object mesh {path} holds no triangles; export it as a triangle mesh (not a point cloud or empty scene)")
    if not np.isfinite(mesh.vertices).all():
        raise InputError(f"object mesh {path} has NaN or infinite vertex coordinates; repair or re-export it")
    if ext in (".glb", ".gltf"):
        mesh.apply_transform(_gltf_to_z_up())
    return mesh, (label if label else label_from_path(path))


def _to_single_mesh(loaded) -> trimesh.Trimesh | None:
    if isinstance(loaded, trimesh.Trimesh):
        return loaded
    if isinstance(loaded, trimesh.Scene):
        meshes = []
        for node in loaded.graph.nodes_geometry:
            transform, geom_name = loaded.graph[node]
            geom = loaded.geometry[geom_name]
            if isinstance(geom, trimesh.Trimesh) and len(geom.faces):
                m = geom.copy()
                m.apply_transform(transform)
                meshes.append(m)
        if not meshes:
            return None
        if len(meshes) == 1:
            return meshes[0]
        # keep the textured part's visuals when only one carries a texture; else colours per face
        textured = [m for m in meshes if _texture_image(m) is not None]
        if len(textured) == 1 and len(meshes) > 1:
            others = [m for m in meshes if m is not textured[0]]
            merged = trimesh.util.concatenate([textured[0]] + others)
            return merged
        return trimesh.util.concatenate(meshes)
    return None


def _texture_image(mesh: trimesh.Trimesh):
    vis = getattr(mesh, "visual", None)
    mat = getattr(vis, "material", None)
    if mat is None:
        return None
    img = getattr(mat, "image", None)
    if img is None:
        img = getattr(mat, "baseColorTexture", None)
    return img


def colour_captured(mesh: trimesh.Trimesh) -> bool:
    """Whether the file says what colour the object is: a texture image, vertex or face colours, or
    a material colour it sets (an MTL ``Kd``, a glTF ``baseColorFactor``). A material that names a
    texture file which is not there says nothing: its grey is the loader's default, not the object's."""
    vis = getattr(mesh, "visual", None)
    if getattr(vis, "kind", None) in ("face", "vertex"):
        return True
    if _texture_image(mesh) is not None:
        return True
    mat = getattr(vis, "material", None)
    if isinstance(mat, trimesh.visual.material.PBRMaterial):
        return mat.baseColorFactor is not None
    return mat is not None and any(k.lower() == "kd" for k in (getattr(mat, "kwargs", None) or {}))


def texture_file(path: Path) -> Path | None:
    """The PNG named by an OBJ's MTL ``map_Kd`` when it exists (read as is, no re-encoding)."""
    path = Path(path)
    if path.suffix.lower() != ".obj":
        return None
    try:
        with path.open("r", errors="ignore") as fh:
            head = [line for _, line in zip(range(200), fh)]
    except OSError:
        return None
    for line in head:
        if line.startswith("mtllib"):
            mtl = path.parent / line.split(maxsplit=1)[1].strip()
            if mtl.is_file():
                for mline in mtl.read_text(errors="ignore").splitlines():
                    if mline.strip().startswith("map_Kd"):
                        tex = path.parent / mline.split()[-1]
                        if tex.is_file() and tex.suffix.lower() == ".png":
                            return tex
    return None


def missing_references(path: Path) -> list[str]:
    """Files an OBJ names (its ``mtllib`` and the MTL's texture maps) that do not exist."""
    path = Path(path)
    if path.suffix.lower() != ".obj":
        return []
    missing: list[str] = []
    try:
        with path.open("r", errors="ignore") as fh:
            mtllibs = [line.split(maxsplit=1)[1].strip() for _, line in zip(range(2000), fh)
                       if line.startswith("mtllib") and len(line.split()) > 1]
    except OSError:
        return []
    for name in mtllibs:
        mtl = path.parent / name
        if not mtl.is_file():
            missing.append(name)
            continue
        for mline in mtl.read_text(errors="ignore").splitlines():
            words = mline.split()
            if words and words[0].lower().startswith("map_") and len(words) > 1 and not (mtl.parent / words[-1]).is_file():
                missing.append(words[-1])
    return missing


def visual_appearance(mesh: trimesh.Trimesh, texture_path: Path | None = None) -> tuple[bytes | None, tuple[float, float, float, float], bool]:
    """(PNG bytes of the texture or None, RGBA material colour, has UVs)."""
    vis = mesh.visual
    rgba = (0.7, 0.7, 0.7, 1.0)
    png = None
    has_uv = getattr(vis, "uv", None) is not None and len(vis.uv) == len(mesh.vertices)
    mat = getattr(vis, "material", None)
    if mat is not None:
        color = getattr(mat, "diffuse", None)
        if color is None:
            color = getattr(mat, "baseColorFactor", None)
        if color is not None:
            c = np.asarray(color, dtype=float).ravel()
            if c.max() > 1.0:
                c = c / 255.0
            if len(c) == 3:
                c = np.append(c, 1.0)
            rgba = tuple(float(x) for x in np.clip(c[:4], 0, 1))
    elif getattr(vis, "kind", None) in ("face", "vertex"):
        cols = vis.face_colors if vis.kind == "face" else vis.vertex_colors
        c = np.asarray(cols, dtype=float).mean(axis=0) / 255.0
        rgba = tuple(float(x) for x in c[:4])
    img = _texture_image(mesh)
    if img is not None and has_uv:
        if texture_path is not None:
            png = Path(texture_path).read_bytes()
        else:
            buf = io.BytesIO()
            img.save(buf, format="PNG", compress_level=1)
            png = buf.getvalue()
        # a textured material's diffuse is multiplied with the texture; white keeps the texture as is
        rgba = (1.0, 1.0, 1.0, rgba[3])
    return png, rgba, has_uv
