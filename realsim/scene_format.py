"""The on-disk contract of a scene folder: file names, geom groups, keyframes, and one reader.

Conversion writes these names; the runtime, the viewer and the exporters read them through
this module, never through the conversion modules.
"""

from __future__ import annotations

import json
import os
import re
import tempfile
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from realsim.errors import InputError

SCENE_XML = "scene.xml"
SCENE_JSON = "scene.json"
LABELS_NPY = "labels.npy"
PREVIEW_PNG = "preview.png"
ASSET_DIR = "assets"
RUNS_DIR = "runs"
SCENE_FORMAT = "realsim-scene/1"  # scene.json's "format"

VISUAL_GROUP = 2  # visual meshes: contype/conaffinity 0 (the Menagerie convention)
COLLISION_GROUP = 3  # collision hulls and primitives
KEYFRAME = "initial"  # everything at rest, robot at home
HOME_KEYFRAME = "home"  # the robot's posture before settling
ROBOT_PREFIX = "panda/"  # the attached Panda's element names


def scene_xml(folder: Path | str) -> Path:
    """The ``scene.xml`` of a realsim output folder (or the file itself); InputError if none."""
    folder = Path(folder)
    xml = folder / SCENE_XML if folder.is_dir() else folder
    if not xml.is_file():
        raise InputError(f"{folder}: no {SCENE_XML} here; pass an output folder of `realsim convert`")
    return xml


def read_scene_record(folder: Path | str) -> dict[str, Any]:
    """The ``scene.json`` of a scene folder as a dict (``{}`` when absent); InputError if unreadable."""
    path = Path(folder) / SCENE_JSON
    if not path.is_file():
        return {}
    try:
        record = json.loads(path.read_text())
    except (OSError, ValueError) as exc:
        raise InputError(f"{path}: not a readable scene record ({exc})") from None
    if not isinstance(record, dict):
        raise InputError(f"{path}: not a scene record (expected a JSON object)")
    return record


def keyframe_id(model: mujoco.MjModel, name: str = KEYFRAME) -> int | None:
    """Id of the keyframe called ``name``, or None when the model has none."""
    key = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, name)
    return None if key < 0 else int(key)


def free_joint_bodies(model: mujoco.MjModel) -> list[tuple[str, int, int]]:
    """(body name, qpos address, dof address) of every free-floating body."""
    out = []
    for j in range(model.njnt):
        if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE:
            body = model.jnt_bodyid[j]
            out.append((model.body(body).name, int(model.jnt_qposadr[j]), int(model.jnt_dofadr[j])))
    return out


def jsonable(value: Any, digits: int = 6) -> Any:
    """``value`` with numpy types, paths and pydantic models made JSON-ready (floats rounded)."""
    if isinstance(value, dict):
        return {str(k): jsonable(v, digits) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [jsonable(v, digits) for v in value]
    if isinstance(value, np.ndarray):
        return jsonable(value.tolist(), digits)
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (np.floating, float)):
        return round(float(value), digits)
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, Path):
        return str(value)
    if hasattr(value, "model_dump"):
        return jsonable(value.model_dump(), digits)
    return value


def verify_compiles(xml_path: Path, written_from: mujoco.MjSpec | None = None) -> mujoco.MjModel:
    """Compile a written scene from another working directory; raise if it does not load.

    Every file the XML names (meshes, textures, height fields, skins) is read where
    ``from_xml_path`` would read it, relative to the XML, and handed to MuJoCo with the XML: the
    same model, and meshes and textures an earlier compile of the same bytes processed come from
    MuJoCo's asset cache instead of being processed again (0.55 s of a 1 M-point scene's
    conversion). XML that names two different files of one base name is loaded from its path.
    ``written_from``: the spec the XML was written from (``to_xml``), which names the same files
    (then the XML is not parsed once more to find them).
    """
    xml_path = Path(xml_path)
    text = xml_path.read_text()
    files = _named_files(xml_path, text, written_from)
    cwd = os.getcwd()
    try:
        os.chdir(tempfile.gettempdir())
        if files is None:
            return mujoco.MjModel.from_xml_path(str(xml_path))
        return mujoco.MjModel.from_xml_string(text, files)
    finally:
        os.chdir(cwd)


def _named_files(xml_path: Path, text: str, spec: mujoco.MjSpec | None = None) -> dict[str, bytes] | None:
    """The files an MJCF text names (or ``spec``, the one it was written from), by the path MuJoCo asks
    for, read relative to ``xml_path``; None when one is missing, base names clash (MuJoCo's virtual
    files match by base name) or the XML does not parse here (then loading it from its path reports
    what is wrong)."""
    if spec is None:
        try:
            spec = mujoco.MjSpec.from_string(text)
        except Exception:
            return None
    if spec.strippath:
        return None
    named = [(spec.meshdir, m.file) for m in spec.meshes] + [(spec.meshdir, h.file) for h in spec.hfields]
    named += [(spec.meshdir, s.file) for s in spec.skins]
    named += [(spec.texturedir, f) for t in spec.textures for f in (t.file, *t.cubefiles)]
    files: dict[str, bytes] = {}
    paths: dict[str, Path] = {}
    for folder, name in named:
        if not name:
            continue
        path = xml_path.parent / folder / name
        key = f"{folder.rstrip('/')}/{name}" if folder and not Path(name).is_absolute() else name
        base = Path(name).name
        if base in paths and paths[base].resolve() != path.resolve() or not path.is_file():
            return None
        if base not in paths:
            paths[base] = path
            files[key] = path.read_bytes()
    return files


def safe_name(text: str) -> str:
    """An MJCF-safe identifier: lowercase letters, digits and underscores."""
    name = re.sub(r"[^a-z0-9_]+", "_", text.lower()).strip("_")
    return name or "object"
