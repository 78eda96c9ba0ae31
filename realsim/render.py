"""Offscreen rendering of a scene (MUJOCO_GL=egl renders on the CPU)."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import mujoco
import numpy as np
from PIL import Image

from realsim.scene_format import KEYFRAME, SCENE_XML, scene_xml


def overview_camera(model: mujoco.MjModel) -> mujoco.MjvCamera:
    """A free camera looking at the scene's objects from the front and above."""
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    cam = mujoco.MjvCamera()
    cam.type = mujoco.mjtCamera.mjCAMERA_FREE
    free_bodies = [model.jnt_bodyid[j] for j in range(model.njnt) if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE]
    if free_bodies:
        pts = data.xpos[free_bodies]
        centre = pts.mean(axis=0)
        spread = float(np.max(np.ptp(pts, axis=0))) if len(pts) > 1 else 0.3
    else:
        centre, spread = model.stat.center.copy(), float(model.stat.extent) / 2
    cam.lookat[:] = centre
    cam.distance = max(0.8, 2.2 * spread + 0.5)
    cam.azimuth = 180.0
    cam.elevation = -40.0
    return cam


def render_image(model: mujoco.MjModel, data: mujoco.MjData | None = None, *, camera: str | None = None,
                 width: int = 960, height: int = 720) -> np.ndarray:
    """RGB image (H, W, 3) of the model in ``data`` (keyframe ``initial`` when None)."""
    if data is None:
        data = mujoco.MjData(model)
        if model.nkey:
            initial = [k for k in range(model.nkey) if model.key(k).name == KEYFRAME]
            mujoco.mj_resetDataKeyframe(model, data, initial[0] if initial else 0)
    mujoco.mj_forward(model, data)
    with _offscreen(model, width, height), mujoco.Renderer(model, height=height, width=width) as renderer:
        if camera is not None:
            renderer.update_scene(data, camera=camera)
        else:
            renderer.update_scene(data, camera=overview_camera(model))
        image: np.ndarray = renderer.render().copy()
        return image


@contextmanager
def _offscreen(model: mujoco.MjModel, width: int, height: int) -> Iterator[None]:
    """``model``'s offscreen buffer sized to the picture for the block (the renderer allocates and
    clears the whole buffer; the pixels drawn into a ``width`` x ``height`` viewport are the same), and
    no shadow map when no light casts shadows (none is drawn). A picture larger than the buffer is
    still refused by the renderer."""
    size, shadow = (model.vis.global_.offwidth, model.vis.global_.offheight), model.vis.quality.shadowsize
    model.vis.global_.offwidth, model.vis.global_.offheight = min(width, size[0]), min(height, size[1])  # never larger
    if not np.any(model.light_castshadow):
        model.vis.quality.shadowsize = 0
    try:
        yield
    finally:
        (model.vis.global_.offwidth, model.vis.global_.offheight), model.vis.quality.shadowsize = size, shadow


def render_file(scene_xml: Path, out_png: Path, camera: str | None = None, width: int = 960, height: int = 720) -> Path:
    """Render ``scene_xml`` at keyframe ``initial`` to a PNG."""
    model = mujoco.MjModel.from_xml_path(str(scene_xml))
    Image.fromarray(render_image(model, camera=camera, width=width, height=height)).save(out_png)
    return out_png


PREVIEW_FILE = "preview.png"


def render_scene(scene: Path, out_png: Path, camera: str | None = None, width: int = 960, height: int = 720,
                 model: mujoco.MjModel | None = None) -> Path:
    """Render an output folder (or its scene.xml) at keyframe ``initial`` to ``out_png``.

    ``camera`` names a camera of the model (``capture`` is the capture's viewpoint when the
    input was a camera view); None is the overview camera. Unknown cameras are an InputError.
    ``model`` is the folder's scene.xml already loaded (the writer's compile check), or None.
    """
    from realsim.errors import InputError

    if model is None:
        model = mujoco.MjModel.from_xml_path(str(scene_xml(scene)))
    if camera is not None:
        names = [model.camera(i).name for i in range(model.ncam)]
        if camera not in names:
            raise InputError(f"--camera {camera!r}: the scene has {'cameras ' + ', '.join(names) if names else 'no cameras'}; omit --camera for the overview")
    width = min(width, model.vis.global_.offwidth)
    height = min(height, model.vis.global_.offheight)
    data = mujoco.MjData(model)
    key = next((k for k in range(model.nkey) if model.key(k).name == KEYFRAME), 0 if model.nkey else None)
    if key is not None:
        mujoco.mj_resetDataKeyframe(model, data, key)
    out_png = Path(out_png)
    out_png.parent.mkdir(parents=True, exist_ok=True)
    Image.fromarray(render_image(model, data, camera=camera, width=width, height=height)).save(out_png)
    return out_png


def write_preview(folder: Path, width: int = 640, height: int = 480, model: mujoco.MjModel | None = None) -> Path | None:
    """Write ``folder/preview.png`` (overview at keyframe ``initial``); None if rendering is unavailable.

    Meant for the end of a conversion: a machine without an offscreen GL context (no EGL/OSMesa)
    still gets its scene, only without the preview. The picture is cached under the folder's
    content, so a rerun that writes the same files copies it instead of rendering. ``model`` is
    the folder's scene.xml already loaded (not loaded again), or None.
    """
    from realsim.cache import BlobStore, DiskCache, output_key

    folder = Path(folder)
    out = folder / PREVIEW_FILE
    if not (folder / SCENE_XML).is_file():
        return None
    key = output_key("preview", data=_folder_digest(folder), params={"width": width, "height": height})
    cache = DiskCache()
    digest = cache.get(key)  # the same files rendered before: the same picture
    png = BlobStore(cache.root).get(digest) if digest else None
    if png is not None:
        out.write_bytes(png)
        return out
    try:
        render_scene(folder, out, width=width, height=height, model=model)
    except Exception:  # no GL context here: the scene is still valid
        return None
    cache.put(key, BlobStore(cache.root).put(out.read_bytes()))
    return out


def _folder_digest(folder: Path) -> bytes:
    """SHA-256 of what a render of a scene folder reads: scene.xml and assets/ (names and contents)."""
    import hashlib

    h = hashlib.sha256()
    files = [folder / "scene.xml", *(p for p in (folder / "assets").rglob("*") if p.is_file())]
    for path in sorted(files):
        h.update(f"{path.relative_to(folder).as_posix()}\0".encode())
        h.update(hashlib.sha256(path.read_bytes()).digest())
    return h.digest()
