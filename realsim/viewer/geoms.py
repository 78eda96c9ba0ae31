"""Visual geoms of a compiled model as viser scene nodes: one frame per body, geoms under it."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np

from realsim.scene_format import VISUAL_GROUP
from realsim.viewer.frames import to_viser

PLANE_EXTENT = 8.0  # metres: how much of an infinite MuJoCo plane to draw


@dataclass
class BodyNode:
    """A body drawn in the browser: its viser frame handle and MuJoCo body id."""

    body: int
    name: str
    handle: object


def node_name(text: str) -> str:
    """A viser scene-tree name segment for a MuJoCo name (``/`` would nest)."""
    return "".join(c if c.isalnum() or c in "_-" else "_" for c in text) or "unnamed"


def geom_rgba(model: mujoco.MjModel, g: int) -> np.ndarray:
    """The colour MuJoCo draws geom ``g`` with: its rgba, or its material's when unset."""
    rgba = model.geom_rgba[g].copy()
    mat = model.geom_matid[g]
    if mat >= 0 and np.allclose(rgba, [0.5, 0.5, 0.5, 1.0]):
        rgba = model.mat_rgba[mat].copy()
    return rgba


def _rgb255(rgba: np.ndarray) -> tuple[int, int, int]:
    return tuple(int(round(float(c) * 255)) for c in np.clip(rgba[:3], 0, 1))  # type: ignore[return-value]


def _texture_image(model: mujoco.MjModel, spec: mujoco.MjSpec | None, xml_dir: Path, g: int):
    """The PIL image of geom ``g``'s RGB texture file, if it has one (builtin textures: None)."""
    mat = model.geom_matid[g]
    if spec is None or mat < 0:
        return None
    tex = model.mat_texid[mat, mujoco.mjtTextureRole.mjTEXROLE_RGB]
    if tex < 0:
        return None
    source = spec.texture(model.tex(tex).name)
    if source is None or not source.file:
        return None
    path = Path(source.file)
    if not path.is_absolute():
        path = xml_dir / spec.texturedir / path
    if not path.is_file():
        return None
    from PIL import Image

    return Image.open(path).convert("RGB")


def add_geom(server, name: str, model: mujoco.MjModel, g: int, spec: mujoco.MjSpec | None = None, xml_dir: Path = Path(".")) -> bool:
    """Add geom ``g`` as node ``name`` (pose relative to its body); False if its type is not drawn."""
    T = mujoco.mjtGeom
    gtype = model.geom_type[g]
    size = model.geom_size[g]
    rgba = geom_rgba(model, g)
    color = _rgb255(rgba)
    opacity = float(rgba[3]) if rgba[3] < 1 else None
    pos, wxyz = to_viser(model.geom_pos[g], model.geom_quat[g])
    common = dict(position=pos, wxyz=wxyz)
    scene = server.scene
    if gtype == T.mjGEOM_MESH:
        m = model.geom_dataid[g]
        v0, nv = model.mesh_vertadr[m], model.mesh_vertnum[m]
        f0, nf = model.mesh_faceadr[m], model.mesh_facenum[m]
        verts = model.mesh_vert[v0 : v0 + nv].astype(np.float32)
        faces = model.mesh_face[f0 : f0 + nf].astype(np.uint32)
        image = _texture_image(model, spec, xml_dir, g) if model.mesh_texcoordnum[m] > 0 else None
        if image is not None:
            import trimesh

            t0 = model.mesh_texcoordadr[m]
            uv = model.mesh_texcoord[t0 : t0 + model.mesh_texcoordnum[m]].copy()
            uv[:, 1] = 1.0 - uv[:, 1]  # MuJoCo flips v at load; glTF/trimesh use the OBJ convention
            corner = model.mesh_facetexcoord[f0 : f0 + nf].reshape(-1)
            flat = trimesh.Trimesh(vertices=verts[faces.reshape(-1)], faces=np.arange(3 * nf).reshape(-1, 3), process=False)
            flat.visual = trimesh.visual.TextureVisuals(uv=uv[corner], image=image)
            scene.add_mesh_trimesh(name, flat, **common)
        else:
            scene.add_mesh_simple(name, verts, faces, color=color, opacity=opacity, **common)
    elif gtype == T.mjGEOM_BOX:
        scene.add_box(name, color=color, dimensions=tuple(float(2 * s) for s in size[:3]), opacity=opacity, **common)
    elif gtype == T.mjGEOM_PLANE:
        sx = 2 * size[0] if size[0] > 0 else PLANE_EXTENT
        sy = 2 * size[1] if size[1] > 0 else PLANE_EXTENT
        scene.add_box(name, color=color, dimensions=(float(sx), float(sy), 0.002), opacity=opacity, **common)
        scene.add_grid(f"{name}_grid", width=float(sx), height=float(sy), cell_size=0.25, section_size=1.0,
                       position=pos + np.array([0.0, 0.0, 0.0015]), wxyz=wxyz)
    elif gtype == T.mjGEOM_SPHERE:
        scene.add_icosphere(name, radius=float(size[0]), color=color, opacity=opacity, **common)
    elif gtype in (T.mjGEOM_CYLINDER, T.mjGEOM_CAPSULE):
        scene.add_cylinder(name, radius=float(size[0]), height=float(2 * size[1]), color=color, opacity=opacity, **common)
    else:
        return False
    return True


def add_visual_geoms(server, model: mujoco.MjModel, data: mujoco.MjData, spec: mujoco.MjSpec | None = None,
                     xml_dir: Path = Path("."), group: int = VISUAL_GROUP) -> list[BodyNode]:
    """One frame node per body with visual geoms (group ``group``), its geoms as children.

    Returns the moving bodies (world-fixed geoms hang under a static ``/world`` frame).
    """
    nodes: list[BodyNode] = []
    for b in range(model.nbody):
        geoms = [g for g in range(model.body_geomadr[b], model.body_geomadr[b] + model.body_geomnum[b]) if model.geom_group[g] == group]
        if not geoms:
            continue
        name = "world" if b == 0 else node_name(model.body(b).name)
        pos, wxyz = to_viser(data.xpos[b], data.xquat[b])
        handle = server.scene.add_frame(f"/{name}", show_axes=False, position=pos, wxyz=wxyz)
        for g in geoms:
            add_geom(server, f"/{name}/{node_name(model.geom(g).name or f'geom{g}')}", model, g, spec, xml_dir)
        if b != 0 and model.body_weldid[b] != 0:  # moves: its pose is streamed
            nodes.append(BodyNode(body=b, name=model.body(b).name, handle=handle))
    return nodes


def add_support_outlines(server, planes: list[dict]) -> int:
    """Outline each observed support polygon of scene.json (not the floor) just above its surface."""
    count = 0
    for plane in planes:
        poly = np.asarray(plane.get("polygon") or [], dtype=float)
        if plane.get("kind") == "floor" or len(poly) < 3:
            continue
        z = float(plane.get("height", 0.0)) + 0.002
        pts = np.column_stack([poly, np.full(len(poly), z)])
        segments = np.stack([pts, np.roll(pts, -1, axis=0)], axis=1).astype(np.float32)
        server.scene.add_line_segments(f"/supports/plane{plane.get('id', count)}", points=segments, colors=(255, 200, 80), line_width=2.0)
        count += 1
    return count
