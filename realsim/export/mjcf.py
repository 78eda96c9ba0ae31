"""Export a scene folder as self-contained MJCF: the whole scene, or one MJCF per object.

Both are built with ``mujoco.MjSpec``: the scene spec is loaded, pruned (for one object) and
its file references are rewritten to a flat ``assets/`` folder next to the written XML, so the
result compiles from any working directory and after being moved or copied elsewhere.
"""

from __future__ import annotations

import json
import shutil
from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np

from realsim.destination import atomic_folder, check_destination
from realsim.errors import InputError
from realsim.scene_format import ASSET_DIR, KEYFRAME, ROBOT_PREFIX, free_joint_bodies, scene_xml, verify_compiles


@dataclass(frozen=True)
class ObjectExport:
    """One object written by :func:`export_objects`."""

    body: str
    xml: Path  # relative to the export folder
    mass: float
    settled_pos: list[float]
    settled_quat_wxyz: list[float]


def load_spec(folder: Path) -> tuple[mujoco.MjSpec, Path]:
    """The scene spec of an output folder and the folder its XML lives in."""
    xml = scene_xml(folder)
    try:
        spec = mujoco.MjSpec.from_file(str(xml))
    except Exception as exc:  # a corrupt or foreign XML is a user error
        raise InputError(f"{xml}: MuJoCo cannot load it ({str(exc).splitlines()[0]})") from None
    return spec, xml.parent


def _resolve(base: Path, subdir: str, file: str) -> Path:
    path = Path(file)
    if path.is_absolute():
        return path
    return (base / subdir / path) if subdir else (base / path)


class _AssetFolder:
    """``dest_dir/assets``: each source file copied once, flat, by base name (a numeric suffix
    resolves a clash between different files of the same name)."""

    def __init__(self, dest_dir: Path) -> None:
        self.folder = dest_dir / ASSET_DIR
        self.folder.mkdir(parents=True, exist_ok=True)
        self.written: dict[Path, str] = {}

    def place(self, source: Path) -> str:
        """The name ``source`` has in the folder (copied there on first use)."""
        if not source.is_file():
            raise InputError(f"{source}: an asset the scene refers to is missing; re-run `realsim convert`")
        source = source.resolve()
        if source not in self.written:
            name, k = source.name, 1
            while name in self.written.values():
                name, k = f"{source.stem}_{k}{source.suffix}", k + 1
            shutil.copyfile(source, self.folder / name)
            self.written[source] = name
        return self.written[source]


def relocate_assets(spec: mujoco.MjSpec, src_dir: Path, dest_dir: Path) -> list[str]:
    """Copy every file the spec refers to into ``dest_dir/assets`` (see :class:`_AssetFolder`) and
    point the spec there. Returns the names written."""
    folder = _AssetFolder(dest_dir)
    place = folder.place
    for mesh in spec.meshes:
        if mesh.file:
            mesh.file = place(_resolve(src_dir, spec.meshdir, mesh.file))
    for skin in spec.skins:
        if skin.file:
            skin.file = place(_resolve(src_dir, spec.meshdir, skin.file))
    for tex in spec.textures:
        if tex.file:
            tex.file = place(_resolve(src_dir, spec.texturedir, tex.file))
        faces = list(tex.cubefiles)
        if any(faces):
            tex.cubefiles = [place(_resolve(src_dir, spec.texturedir, f)) if f else "" for f in faces]
    for hfield in spec.hfields:
        if hfield.file:
            hfield.file = place(_resolve(src_dir, spec.meshdir, hfield.file))
    spec.meshdir = ASSET_DIR
    spec.texturedir = ASSET_DIR
    return sorted(folder.written.values())


FILE_ATTRIBUTES = ("file", "fileright", "fileleft", "fileup", "filedown", "filefront", "fileback")


def _relocated_xml(xml: Path, src_dir: Path, dest_dir: Path) -> str:
    """The text of ``xml`` with every asset file copied to ``dest_dir/assets`` (flat, by base name)
    and referenced there; everything else is left exactly as written."""
    import xml.etree.ElementTree as ET

    root = ET.parse(xml).getroot()
    compiler = root.find("compiler")
    if compiler is None:
        compiler = ET.SubElement(root, "compiler")
    meshdir, texturedir = compiler.get("meshdir", ""), compiler.get("texturedir", "")
    if root.find(".//include") is not None:
        raise InputError(f"{xml}: scenes with <include> are not exported; convert the scene again")
    assets = _AssetFolder(dest_dir)
    for element in root.iter():
        subdir = texturedir if element.tag == "texture" else meshdir
        for attr in FILE_ATTRIBUTES:
            if value := element.get(attr):
                element.set(attr, assets.place(_resolve(src_dir, subdir, value)))
    compiler.set("meshdir", ASSET_DIR)
    compiler.set("texturedir", ASSET_DIR)
    return ET.tostring(root, encoding="unicode")


def export_mjcf(source: Path, dest: Path | str, *, force: bool = False) -> Path:
    """Write the whole scene of ``source`` as a self-contained MJCF folder at ``dest``.

    The folder holds ``scene.xml``, ``assets/`` (meshes and textures, relative paths) and the
    source's ``scene.json``; it is written atomically and compiled before it is moved in place.
    """
    dest = check_destination(dest, inputs=[source], force=force)
    _, src_dir = load_spec(source)  # a scene MuJoCo can load
    with atomic_folder(dest, force=force, kind="export-mjcf") as tmp:
        # the source XML with its file references rewritten, not a spec round trip: MjSpec.to_xml of a
        # loaded scene writes each mesh's recentring offset into its geom again, so the copy would drift
        (tmp / "scene.xml").write_text(_relocated_xml(scene_xml(source), src_dir, tmp))
        if (src_dir / "scene.json").is_file():
            shutil.copyfile(src_dir / "scene.json", tmp / "scene.json")
        verify_compiles(tmp / "scene.xml")
    return Path(dest)


def object_bodies(model: mujoco.MjModel, robot_prefix: str = ROBOT_PREFIX) -> list[str]:
    """Names of the scene's movable objects: free bodies that are not part of the robot."""
    return [name for name, _, _ in free_joint_bodies(model) if not name.startswith(robot_prefix)]


def _prune_to_body(spec: mujoco.MjSpec, keep: str) -> mujoco.MjsBody:
    """Delete everything from ``spec`` except body ``keep`` and the assets its geoms use."""
    for group in (spec.keys, spec.actuators, spec.sensors, spec.tendons, spec.equalities, spec.excludes, spec.pairs,
                  spec.texts, spec.numerics, spec.tuples):
        for element in list(group):
            spec.delete(element)
    spec.nkey = 0  # else compiling (to_xml) re-creates the deleted keyframes from <size nkey>
    world = spec.worldbody
    for element in [b for b in world.bodies if b.name != keep] + list(world.geoms) + list(world.sites) + list(world.cameras) + list(world.lights):
        spec.delete(element)
    for frame in list(world.frames):
        spec.delete(frame)
    body = spec.body(keep)
    used_meshes = {g.meshname for g in body.find_all(mujoco.mjtObj.mjOBJ_GEOM) if g.meshname}
    used_materials = {g.material for g in body.find_all(mujoco.mjtObj.mjOBJ_GEOM) if g.material}
    for mesh in list(spec.meshes):
        if mesh.name not in used_meshes:
            spec.delete(mesh)
    for mat in list(spec.materials):
        if mat.name not in used_materials:
            spec.delete(mat)
    used_textures = {t for m in spec.materials for t in m.textures if t}
    for tex in list(spec.textures):
        if tex.name not in used_textures:
            spec.delete(tex)
    for hfield in list(spec.hfields):
        spec.delete(hfield)
    used_classes = {e.classname.name for e in body.find_all(mujoco.mjtObj.mjOBJ_GEOM)} | {body.classname.name}
    for default in _defaults(spec):
        if default.name not in used_classes and default.name != "main":
            try:
                spec.delete(default)
            except Exception:  # a parent of a used class
                pass
    return body


def _defaults(spec: mujoco.MjSpec) -> list[mujoco.MjsDefault]:
    """Every named default class (children before parents, so they can be deleted in order)."""
    out = []
    for text in spec.to_xml().split("<default class=\"")[1:]:
        name = text.split("\"", 1)[0]
        found = spec.find_default(name)
        if found is not None:
            out.append(found)
    return out[::-1]


def export_objects(source: Path, dest: Path | str, robot_prefix: str = ROBOT_PREFIX, *, force: bool = False) -> list[ObjectExport]:
    """Write one MJCF per object to ``dest/<body>/<body>.xml`` with its own ``assets/``.

    Each file holds the object's free body (convex collision hulls in group 3, the visual mesh
    and its material in group 2, the explicit inertia) at the origin, ready for
    ``MjSpec.attach`` into another scene; ``dest/objects.json`` lists the files with each
    object's settled pose in the source scene (keyframe ``initial``). Element names are the
    scene's (unique per object: ``obj<k>_<label>...``); pass ``prefix`` to ``attach`` to add
    several copies.
    """
    dest = check_destination(dest, inputs=[source], force=force)
    spec, src_dir = load_spec(source)
    model = spec.compile()
    data = mujoco.MjData(model)
    if model.nkey:
        key = next((k for k in range(model.nkey) if model.key(k).name == KEYFRAME), 0)
        mujoco.mj_resetDataKeyframe(model, data, key)
    mujoco.mj_kinematics(model, data)
    names = object_bodies(model, robot_prefix)
    if not names:
        raise InputError(f"{source}: the scene has no free-floating objects to export")
    written: list[ObjectExport] = []
    with atomic_folder(dest, force=force, kind="export-objects") as tmp:
        for name in names:
            child = mujoco.MjSpec.from_file(str(scene_xml(source)))
            body = _prune_to_body(child, name)
            body.pos = [0.0, 0.0, 0.0]
            body.quat = [1.0, 0.0, 0.0, 0.0]
            child.modelname = name
            child.option = mujoco.MjSpec().option  # the host scene's options win on attach
            child.nconmax = child.njmax = -1  # so do its sizes (the scene's capacity is for the whole scene)
            folder = tmp / name
            relocate_assets(child, src_dir, folder)
            xml = folder / f"{name}.xml"
            xml.write_text(child.to_xml())
            verify_compiles(xml)
            b = model.body(name).id
            written.append(ObjectExport(body=name, xml=Path(name) / f"{name}.xml", mass=float(model.body_mass[b]),
                                        settled_pos=np.round(data.xpos[b], 6).tolist(),
                                        settled_quat_wxyz=np.round(data.xquat[b], 6).tolist()))
        index = {
            "format": "realsim-objects/1",
            "source": str(scene_xml(source).resolve()),
            "objects": [{"body": o.body, "xml": str(o.xml), "mass": o.mass, "settled_pos": o.settled_pos,
                         "settled_quat_wxyz": o.settled_quat_wxyz} for o in written],
        }
        (tmp / "objects.json").write_text(json.dumps(index, indent=2) + "\n")
    return written
