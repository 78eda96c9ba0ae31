"""A 256x256 PNG thumbnail of an object's visual mesh (MuJoCo's offscreen renderer).

A tiny ``MjSpec`` holds the mesh, a light and a grey backdrop; a free camera looks at it from the
front-left and above. Rendering needs an OpenGL context (``MUJOCO_GL=egl`` on a headless machine);
the caller treats a failure as "no thumbnail".
"""

from __future__ import annotations

import io

import mujoco
import numpy as np
import trimesh
from PIL import Image

from realsim.cache import DiskCache, cache_key

SIZE = 256


def _spec(mesh: trimesh.Trimesh, rgba: tuple[float, float, float, float]) -> mujoco.MjSpec:
    spec = mujoco.MjSpec()
    spec.visual.global_.offwidth = SIZE
    spec.visual.global_.offheight = SIZE
    spec.visual.headlight.ambient = [0.4, 0.4, 0.4]
    spec.visual.headlight.diffuse = [0.5, 0.5, 0.5]
    m = spec.add_mesh()
    m.name = "object"
    m.uservert = np.asarray(mesh.vertices, dtype=np.float64).ravel().tolist()
    m.userface = np.asarray(mesh.faces, dtype=np.int64).ravel().tolist()
    world = spec.worldbody
    extent = float(np.max(mesh.extents))
    world.add_light(pos=[0.0, -extent, 3 * extent + 0.5], dir=[0.0, 0.3, -1.0], diffuse=[0.6, 0.6, 0.6])
    world.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[10 * extent + 1, 10 * extent + 1, 0.01],
                   pos=[0.0, 0.0, float(mesh.bounds[0][2]) - 1e-4], rgba=[0.85, 0.85, 0.85, 1.0])
    world.add_geom(type=mujoco.mjtGeom.mjGEOM_MESH, meshname="object", rgba=[float(c) for c in rgba[:3]] + [1.0])
    return spec


def render_thumbnail(mesh: trimesh.Trimesh, rgba: tuple[float, float, float, float] = (0.7, 0.7, 0.7, 1.0)) -> bytes:
    """PNG bytes (256x256) of ``mesh`` (object frame, Z up) in its colour."""
    model = _spec(mesh, rgba).compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    cam = mujoco.MjvCamera()
    cam.type = mujoco.mjtCamera.mjCAMERA_FREE
    lo, hi = mesh.bounds
    cam.lookat[:] = (lo + hi) / 2
    cam.distance = 2.2 * float(np.linalg.norm(hi - lo)) + 1e-3
    cam.azimuth, cam.elevation = 225.0, -30.0
    with mujoco.Renderer(model, height=SIZE, width=SIZE) as renderer:
        renderer.update_scene(data, camera=cam)
        pixels = renderer.render().copy()
    out = io.BytesIO()
    Image.fromarray(pixels).save(out, format="PNG", optimize=False)
    return out.getvalue()


def thumbnail(mesh: trimesh.Trimesh, rgba: tuple[float, float, float, float], cache: DiskCache) -> bytes:
    """:func:`render_thumbnail`, cached by mesh bytes and colour."""
    v = np.ascontiguousarray(mesh.vertices, dtype=np.float64).tobytes()
    f = np.ascontiguousarray(mesh.faces, dtype=np.int64).tobytes()
    key = cache_key("thumbnail-1", data=v + f, params={"rgba": [round(float(c), 4) for c in rgba], "size": SIZE})
    return cache.get_or_compute(key, lambda: render_thumbnail(mesh, rgba))
