"""The files of the objects' meshes (collision STL, visual OBJ) and their textured visuals, made by a
forked helper (:class:`realsim.forkmap.Ahead`), perhaps begun before the compose stage.

Right after completion the objects' shapes are final: :func:`begin` starts a helper on them there,
and it works while the ``objects`` stage names them. Compose takes that work only when everything it
read is still the same (the objects' meshes and poses, the photo, the appearance parameters), byte
for byte; else the helper is stopped and the work is made again, so the output never depends on it.
"""

from __future__ import annotations

import numpy as np
import trimesh

from realsim.assets.hulls import capped
from realsim.composition.appearance import AppearanceParams, CaptureImage, capture_image, textured_visual
from realsim.forkmap import Ahead, can_fork
from realsim.scene import Scene

Prepared = tuple[tuple[np.ndarray, np.ndarray, np.ndarray, bytes] | None, list[bytes]]
_begun: list[tuple[int, list[bytes], AppearanceParams, Ahead[Prepared]]] = []  # at most one


def mesh_bytes(mesh: trimesh.Trimesh, file_type: str) -> bytes:
    """Deterministic bytes of a mesh file: binary STL, or OBJ with texture coordinates if any."""
    if file_type == "stl":
        return trimesh.exchange.stl.export_stl(mesh)
    return obj_bytes(mesh)


def obj_bytes(mesh: trimesh.Trimesh) -> bytes:
    """A minimal OBJ (v, vt, f), formatted in one pass per block: far faster than trimesh's exporter."""
    def rows(fmt: str, values: np.ndarray) -> str:  # one C-level % for the whole array (savetxt formats row by row)
        return (fmt * len(values)) % tuple(values.ravel().tolist())

    verts = np.asarray(mesh.vertices, dtype=np.float64)
    uv = getattr(mesh.visual, "uv", None)
    faces = np.asarray(mesh.faces, dtype=np.int64) + 1
    parts = [rows("v %.6f %.6f %.6f\n", verts)]
    if uv is not None and len(uv) == len(mesh.vertices):
        parts.append(rows("vt %.6f %.6f\n", np.asarray(uv, dtype=np.float64)))
        parts.append(rows("f %d/%d %d/%d %d/%d\n", np.repeat(faces, 2, axis=1)))
    else:
        parts.append(rows("f %d %d %d\n", faces))
    return "".join(parts).encode()


def collision_file(hull: trimesh.Trimesh) -> bytes:
    """The STL file of a collision hull: at most 64 vertices (scan pieces can have more)."""
    return mesh_bytes(capped(hull), "stl")


def _start(scene: Scene, image: CaptureImage | None, appearance: AppearanceParams) -> Ahead[Prepared]:
    objects = list(scene.objects)

    def work(k: int) -> Prepared:
        obj = objects[k]
        return textured_visual(obj, image, appearance) if image is not None else None, [
            b"" if h.metadata.get("mujoco_primitive") is not None else collision_file(h) for h in obj.collision]
    return Ahead(work, len(objects))


def _inputs(scene: Scene, image: CaptureImage | None) -> list[bytes]:
    """Everything the work reads, as bytes: the photo and, per object, its id, source, pose and meshes."""
    out = [] if image is None else [np.ascontiguousarray(a).tobytes() for a in (image.rgb, image.labels, image.world, image.world_to_optical)]
    if image is not None:
        out.append(repr(image.intrinsics).encode())
    for obj in scene.objects:
        out.append(f"{obj.id}|{obj.source_file}|{obj.visual is None}|{len(obj.collision)}".encode())
        out += [np.asarray(v, float).tobytes() for v in (obj.position, obj.quat)]
        meshes = ([obj.visual] if obj.visual is not None else []) + list(obj.collision)
        for mesh in meshes:
            out += [np.asarray(mesh.vertices).tobytes(), np.asarray(mesh.faces).tobytes(), np.asarray(mesh.face_normals).tobytes(),
                    repr(mesh.metadata.get("mujoco_primitive")).encode()]
    return out


def begin(scene: Scene, appearance: AppearanceParams = AppearanceParams()) -> None:
    """Start the work on ``scene``'s objects as they are now (no helper to be had: nothing)."""
    stop()
    if not can_fork() or not scene.objects:
        return
    image = capture_image(scene) if appearance.enabled else None
    _begun.append((id(scene), _inputs(scene, image), appearance, _start(scene, image, appearance)))


def stop() -> None:
    """Stop work begun and not taken."""
    while _begun:
        _begun.pop()[3].stop()


def object_meshes(scene: Scene, image: CaptureImage | None, appearance: AppearanceParams) -> Ahead[Prepared]:
    """Per object (in order), its textured visual (:func:`textured_visual`; None without ``image``) and
    its collision files (empty for a primitive): the work begun by :func:`begin` when everything it
    read is the same, else started now."""
    if _begun:
        key, inputs, begun_with, ahead = _begun.pop()
        if key == id(scene) and begun_with == appearance and inputs == _inputs(scene, image):
            return ahead
        ahead.stop()
    return _start(scene, image, appearance)
