"""A photo alone becomes a scene: Claude describes it in the text path's schema.

``photo`` stage: one structured Claude call through :mod:`realsim.llm` (the image in, a
:class:`~realsim.text.schema.SceneSpec` out: supports with heights and sizes, objects with
counts, sizes, colours (RGB), positions on the support as seen from the camera, what rests on
what), validated and repaired once (:func:`realsim.text.claude.request_scene`), cached on disk.
The spec goes to the ``text`` stage (procedural objects in the photo's colours, arranged near
the photo's positions, relations kept). Without a key the stage fails at once: a photo needs
ANTHROPIC_API_KEY (or a scan, mesh or text).

``photo_backdrop`` stage (after compose): the photo copied into the output's assets and shown
on a visual-only board behind the support (what the viewer and the preview render show).
"""

from __future__ import annotations

import io
from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np

from realsim import llm
from realsim.cache import DiskCache
from realsim.errors import InputError
from realsim.scene import Scene
from realsim.text.photo_input import NEEDS_KEY
from realsim.understanding.calls import CallLog, image_block
from realsim.understanding.photo import read_photo

PHOTO_SCENE_PROMPT = "scene_photo.md"


@dataclass(frozen=True)
class PhotoParams:
    """Parameters of the photo stage."""

    use_cache: bool = True  # reuse Claude's description of the same photo (same prompt, model)


def require_key() -> None:
    """InputError (exit 2) when no API key is configured."""
    if not llm.available():
        raise InputError(NEEDS_KEY)


def photo_scene(scene: Scene, params: PhotoParams = PhotoParams()) -> Scene:
    """Ask Claude for the scene in the photo; the validated, clamped spec becomes ``scene.scene_spec``."""
    from realsim.text.claude import request_scene
    from realsim.text.schema import SUPPORT_DEFAULTS, SupportSpec, clamp

    require_key()
    path = scene.capture.photo
    if not path:
        raise InputError("the photo pipeline needs a photo: pass photo.jpg/png/webp or a folder holding photo.*")
    image, media_type = read_photo(Path(path))
    content = [image_block(image, media_type), {"type": "text", "text": "Describe the scene in this photo with report_scene."}]
    log = CallLog()
    try:
        spec = request_scene(content, PHOTO_SCENE_PROMPT, cache=DiskCache(enabled=params.use_cache), log=log)
    finally:
        scene.llm = log.record()
    if not spec.objects:
        raise InputError(f"{path}: Claude saw no objects a robot could handle in the photo; use a photo of a tabletop, or --text")
    if not spec.supports:
        spec.supports.append(SupportSpec(id="table", kind="table", height_m=SUPPORT_DEFAULTS["table"][0], size_m=SUPPORT_DEFAULTS["table"][1]))
    spec, notes = clamp(spec)
    for note in notes:
        scene.warn(f"photo: {note}")
    scene.scene_spec = spec
    return scene


@dataclass(frozen=True)
class BackdropParams:
    """Where the photo board stands: behind the primary support, facing the robot's side."""

    enabled: bool = True
    height: float = 0.9  # m, board height (width follows the photo's aspect)
    gap: float = 0.3  # m behind the support's back edge


def photo_backdrop(scene: Scene, params: BackdropParams = BackdropParams()) -> Scene:
    """Copy the photo into assets/ and show it on a visual-only board behind the support."""
    from PIL import Image

    from realsim.scene import primary_support

    path = scene.capture.photo
    if not params.enabled or not path or scene.spec is None or not scene.planes:
        return scene
    with Image.open(path) as im:
        img = im.convert("RGB")
    img.thumbnail((1024, 1024))
    buf = io.BytesIO()
    img.save(buf, format="PNG")
    name = "photo.png"
    scene.assets[name] = buf.getvalue()
    spec = scene.spec
    spec.assets = {**dict(spec.assets), name: scene.assets[name]}
    spec.add_texture(name="photo", file=name, type=mujoco.mjtTexture.mjTEXTURE_2D)
    mat = spec.add_material(name="photo")
    mat.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = "photo"
    support = primary_support(scene)
    half = np.asarray(support.rect_size) / 2
    c, s = np.cos(support.rect_yaw), np.sin(support.rect_yaw)
    back = support.rect_center + np.array([-s, c]) * (half[1] + params.gap)
    w = params.height * img.width / img.height
    z = support.height + params.height / 2 + 0.05
    # a plane's +z faces the viewer: rotate it upright, facing -y (towards the front of the support)
    quat = np.zeros(4)
    mujoco.mju_euler2Quat(quat, np.array([np.pi / 2, 0.0, support.rect_yaw]), "xyz")
    spec.worldbody.add_geom(name="photo_backdrop", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[w / 2, params.height / 2, 0.01],
                            pos=[float(back[0]), float(back[1]), float(z)], quat=quat.tolist(), material="photo", group=2,
                            contype=0, conaffinity=0)
    scene.photo_asset = f"assets/{name}"
    return scene
