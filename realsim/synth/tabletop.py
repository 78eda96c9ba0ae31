"""A synthetic RGB-D tabletop capture with known ground truth: the bundled example.

The repository ships no fetched data, so the example the README runs is made here: a
procedural room (floor, table, five household objects) built with ``mujoco.MjSpec``, rendered
by MuJoCo's offscreen renderer as a Kinect-like RGB-D camera on a tripod would see it, and
back-projected to an organized point cloud in the camera *optical* frame (+x right, +y down,
+z forward, metres), exactly like a real Kinect capture.

``make_tabletop_capture(dest, seed)`` writes into ``dest/``:

- ``scene.pcd``: organized ``height x width`` cloud, ``DATA binary_compressed``, fields
  ``x y z rgb label``. Pixels with no surface within ``MAX_RANGE`` are NaN (label 0).
  Depth carries seeded noise along each ray (about 1 mm at 0.5 m, 2 mm at 1.5 m).
- ``capture.yaml``: units, the up axis in the capture frame, the object id -> name labels.
- ``ground_truth.json``: world frame (Z up, floor at z = 0): the table top height and extent,
  the camera pose (4x4, camera optical frame -> world), the intrinsics, and per object its id,
  name, shape, size, base-centre position, yaw and what it rests on.

Per-pixel ``label`` follows the mOSD convention (see ``../shared/README.md``):
``0`` = no point (NaN); ``1..9`` = support furniture, never objects: ``1`` = the table's top
surface, ``2`` = other table parts (the slab's edges, the legs), ``3`` = the floor;
``label >= 20``: object id ``label // 10``, so the k-th object (k = 1, 2, ...) has label
``10 * (k + 1)`` and id ``k + 1`` (ids 2..6). The floor is kept in view (mOSD crops it away)
so that a pipeline has both a floor and a table to find.

The same seed gives byte-identical files on the same machine (the layout and the noise come
from ``numpy.random.default_rng(seed)``; MuJoCo's CPU renderer is deterministic).

Rendering needs an OpenGL context (``MUJOCO_GL=egl`` on a headless machine, set by the package).
"""

from __future__ import annotations

import json
import math
import os
import tempfile
from pathlib import Path

import mujoco
import numpy as np

from realsim.destination import normal_permissions
from realsim.errors import InputError, RealsimError
from realsim.perception.pcd_io import write_pcd
from realsim.synth.tabletop_layout import (
    LABEL_FLOOR,
    LABEL_NONE,
    LABEL_TABLE_OTHER,
    LABEL_TABLE_TOP,
    LEG_SIZE,
    MAX_RANGE,
    MIN_VISIBLE_PIXELS,
    TABLE_HEIGHT,
    TABLE_SIZE,
    TABLE_THICKNESS,
    TOP_SURFACE_TOL,
    CameraPose,
    PlacedObject,
    TabletopLayout,
    sample_layout,
)

__all__ = [
    "LABEL_NONE", "LABEL_TABLE_TOP", "LABEL_TABLE_OTHER", "LABEL_FLOOR", "MAX_RANGE", "TabletopLayout", "PlacedObject",
    "CameraPose", "sample_layout", "build_spec", "render_rgbd", "backproject", "make_tabletop_capture",
]


def build_spec(layout: TabletopLayout, width: int = 640, height: int = 480) -> mujoco.MjSpec:
    """The layout as an ``MjSpec``: static geoms, two lights and the camera ``kinect``."""
    spec = mujoco.MjSpec()
    spec.modelname = f"synthetic_tabletop_{layout.seed}"
    spec.visual.global_.offwidth = max(width, 640)
    spec.visual.global_.offheight = max(height, 480)
    # No multisampling: an anti-aliased segmentation image would blend geom ids at edges.
    spec.visual.quality.offsamples = 0
    spec.visual.quality.shadowsize = 2048
    spec.stat.extent = 2.0  # znear = 0.01 * extent = 2 cm, zfar = 50 * extent
    spec.stat.center = [0.0, 0.0, TABLE_HEIGHT]
    spec.visual.headlight.ambient = [0.25, 0.25, 0.25]
    spec.visual.headlight.diffuse = [0.35, 0.35, 0.35]
    spec.visual.headlight.specular = [0.0, 0.0, 0.0]

    wb = spec.worldbody
    light = wb.add_light(name="ceiling", pos=[0.4, -0.6, 2.6], dir=[-0.15, 0.25, -1.0])
    light.type = mujoco.mjtLightType.mjLIGHT_DIRECTIONAL
    light.diffuse = [0.6, 0.6, 0.6]
    light.castshadow = True

    wb.add_geom(name="floor", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[4.0, 4.0, 0.05],
                rgba=[0.52, 0.50, 0.47, 1.0])
    top_half = [TABLE_SIZE[0] / 2, TABLE_SIZE[1] / 2, TABLE_THICKNESS / 2]
    wb.add_geom(name="table_top", type=mujoco.mjtGeom.mjGEOM_BOX, size=top_half,
                pos=[0.0, 0.0, TABLE_HEIGHT - TABLE_THICKNESS / 2],
                rgba=[0.78, 0.68, 0.52, 1.0])
    leg_h = TABLE_HEIGHT - TABLE_THICKNESS
    for i, (sx, sy) in enumerate([(-1, -1), (1, -1), (1, 1), (-1, 1)]):
        wb.add_geom(
            name=f"table_leg{i}", type=mujoco.mjtGeom.mjGEOM_BOX,
            size=[LEG_SIZE / 2, LEG_SIZE / 2, leg_h / 2],
            pos=[sx * (top_half[0] - 0.06), sy * (top_half[1] - 0.06), leg_h / 2],
            rgba=[0.45, 0.36, 0.26, 1.0],
        )

    for obj in layout.objects:
        body = wb.add_body(name=f"obj{obj.id}_{obj.name}", pos=list(obj.position),
                           quat=[math.cos(obj.yaw / 2), 0.0, 0.0, math.sin(obj.yaw / 2)])
        sx, sy, sz = obj.size
        if obj.shape == "box":
            body.add_geom(name=f"obj{obj.id}", type=mujoco.mjtGeom.mjGEOM_BOX,
                          size=[sx / 2, sy / 2, sz / 2], pos=[0, 0, sz / 2], rgba=list(obj.rgba))
        else:
            body.add_geom(name=f"obj{obj.id}", type=mujoco.mjtGeom.mjGEOM_CYLINDER,
                          size=[sx / 2, sz / 2, 0], pos=[0, 0, sz / 2], rgba=list(obj.rgba))

    cam = layout.camera
    wb.add_camera(name="kinect", pos=list(cam.position), quat=list(cam.mujoco_quat()),
                  fovy=cam.fovy_deg)
    return spec


def _geom_labels(model: mujoco.MjModel) -> np.ndarray:
    """Label per geom id (before the top-surface / edge split of the table)."""
    labels = np.zeros(model.ngeom, dtype=np.int64)
    for g in range(model.ngeom):
        name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_GEOM, g) or ""
        if name == "floor":
            labels[g] = LABEL_FLOOR
        elif name == "table_top":
            labels[g] = LABEL_TABLE_TOP
        elif name.startswith("table_leg"):
            labels[g] = LABEL_TABLE_OTHER
        elif name.startswith("obj"):
            labels[g] = 10 * int(name[3:])
    return labels


def render_rgbd(
    model: mujoco.MjModel, width: int, height: int, camera: str = "kinect"
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """RGB (H, W, 3) uint8, depth (H, W) float64 metres along the optical axis, geom id per
    pixel (H, W) int64 (-1 where no geom). Row 0 is the top of the image."""
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    try:
        renderer = mujoco.Renderer(model, height=height, width=width)
    except Exception as exc:  # noqa: BLE001 - a missing GL platform surfaces in many forms
        detail = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        raise RealsimError(
            "MuJoCo could not create an OpenGL context for offscreen rendering "
            f"({detail}); set MUJOCO_GL=egl (or osmesa) before Python starts"
        ) from exc
    try:
        renderer.update_scene(data, camera=camera)
        rgb = renderer.render().copy()
        renderer.enable_depth_rendering()
        renderer.update_scene(data, camera=camera)
        depth = renderer.render().astype(np.float64)
        renderer.disable_depth_rendering()
        renderer.enable_segmentation_rendering()
        renderer.update_scene(data, camera=camera)
        seg = renderer.render()
        renderer.disable_segmentation_rendering()
    finally:
        renderer.close()
    geom = np.where(seg[..., 1] == int(mujoco.mjtObj.mjOBJ_GEOM), seg[..., 0], -1)
    return rgb, depth, geom.astype(np.int64)


def intrinsics(width: int, height: int, fovy_deg: float) -> tuple[float, float, float, float]:
    """(fx, fy, cx, cy) of MuJoCo's camera in pixel units; pixel (u, v) has its centre at
    (u, v), so cx = (W - 1) / 2."""
    f = 0.5 * height / math.tan(math.radians(fovy_deg) / 2)
    return f, f, (width - 1) / 2, (height - 1) / 2


def backproject(depth: np.ndarray, fovy_deg: float) -> np.ndarray:
    """Depth (H, W) along the optical axis -> points (H, W, 3) in the optical frame."""
    h, w = depth.shape
    fx, fy, cx, cy = intrinsics(w, h, fovy_deg)
    u = np.arange(w, dtype=np.float64)[None, :]
    v = np.arange(h, dtype=np.float64)[:, None]
    x = (u - cx) / fx * depth
    y = (v - cy) / fy * depth
    return np.stack([x, y, depth], axis=-1)


def _depth_sigma(z: np.ndarray) -> np.ndarray:
    """Kinect-like axial noise (Nguyen et al. 2012, softened): ~1.2 mm at 1 m, 2.3 mm at 1.5 m."""
    return 0.0008 + 0.0012 * (z - 0.4) ** 2


# --------------------------------------------------------------------------------------------
# the capture


def _capture(layout: TabletopLayout, width: int, height: int
             ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    model = build_spec(layout, width, height).compile()
    rgb, depth, geom = render_rgbd(model, width, height)
    per_geom = _geom_labels(model)
    labels = np.where(geom >= 0, per_geom[np.clip(geom, 0, None)], LABEL_NONE)
    valid = (geom >= 0) & (depth > 0) & (depth <= MAX_RANGE)
    labels[~valid] = LABEL_NONE
    pts = backproject(np.where(valid, depth, np.nan), layout.camera.fovy_deg)
    # Table pixels off the top surface (the slab's edges) are "other table parts".
    world = pts.reshape(-1, 3) @ layout.camera.rotation.T + layout.camera.position
    off_top = np.abs(world[:, 2] - layout.table_height) > TOP_SURFACE_TOL
    flat = labels.reshape(-1)
    flat[(flat == LABEL_TABLE_TOP) & off_top] = LABEL_TABLE_OTHER
    return rgb, pts, flat.reshape(labels.shape)


def make_tabletop_capture(dest: Path | str, seed: int = 0, width: int = 640,
                          height: int = 480) -> Path:
    """Render the seeded synthetic tabletop and write ``scene.pcd``, ``capture.yaml`` and
    ``ground_truth.json`` into ``dest`` (created if needed). Returns ``dest``."""
    dest = Path(dest)
    if width < 64 or height < 48:
        raise InputError(f"image size {width}x{height} is too small; use at least 64x48")
    if dest.exists() and not dest.is_dir():
        raise InputError(f"{dest}: exists and is not a folder; pass a folder for the capture")

    layout = None
    for attempt in range(20):
        layout = sample_layout(seed, attempt)
        rgb, pts, labels = _capture(layout, width, height)
        counts = [int(np.count_nonzero(labels == o.pcd_label)) for o in layout.objects]
        min_px = MIN_VISIBLE_PIXELS * (width * height) / (640 * 480)
        if min(counts) >= min_px:
            break
    assert layout is not None

    rng = np.random.default_rng([seed, 7919])
    z = pts[..., 2]
    noise = rng.standard_normal(z.shape) * _depth_sigma(np.nan_to_num(z, nan=1.0))
    pts = pts * ((z + noise) / z)[..., None]

    dest.mkdir(parents=True, exist_ok=True)
    write_pcd(dest / "scene.pcd", pts.reshape(-1, 3), colors=rgb.reshape(-1, 3),
              labels=labels.reshape(-1), grid_shape=(height, width),
              encoding="binary_compressed")
    _write_text(dest / "capture.yaml", _capture_yaml(layout))
    _write_text(dest / "ground_truth.json", _ground_truth_json(layout, width, height))
    return dest


def _write_text(path: Path, text: str) -> None:
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as fh:
            fh.write(text)
        normal_permissions(Path(tmp))
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _capture_yaml(layout: TabletopLayout) -> str:
    lines = [
        f"# Synthetic RGB-D tabletop capture made by realsim.synth.tabletop (seed {layout.seed}).",
        "# Ground truth (world frame, Z up) for checking a conversion: ground_truth.json.",
        "sensor: synthetic_kinect  # environment: scene.pcd (organized, label field)",
        "units: m",
        'up: "-y"  # camera optical frame: +x right, +y down, +z forward',
        "# label field: 0 no point, 1..9 support furniture, >= 20 object id = label // 10",
        "labels:  # object id -> name",
    ]
    lines += [f"  {o.id}: {o.name}" for o in layout.objects]
    return "\n".join(lines) + "\n"


def _r(x: float | np.ndarray, nd: int = 6) -> object:
    if isinstance(x, np.ndarray | list | tuple):
        return [_r(v, nd) for v in x]
    v = round(float(x), nd)
    return 0.0 if v == 0 else v  # no "-0.0"


def _ground_truth_json(layout: TabletopLayout, width: int, height: int) -> str:
    cam = layout.camera
    fx, fy, cx, cy = intrinsics(width, height, cam.fovy_deg)
    objects = []
    for o in layout.objects:
        objects.append({
            "id": o.id,
            "label": o.name,
            "pcd_label": o.pcd_label,
            "shape": o.shape,
            "size": _r(o.size),
            "position": _r(o.position),
            "yaw": _r(o.yaw),
            "quat_wxyz": _r([math.cos(o.yaw / 2), 0.0, 0.0, math.sin(o.yaw / 2)]),
            "color": _r(o.rgba[:3], 3),
            "support": "table" if o.resting_on is None else "object",
            "resting_on": o.resting_on,
        })
    touching = [[2, 3]]
    gt = {
        "generator": "realsim.synth.tabletop",
        "seed": layout.seed,
        "units": "m",
        "world_frame": "right-handed, Z up, floor at z = 0",
        "camera": {
            "pose_optical_to_world": _r(cam.optical_to_world()),
            "optical_frame": "+x right, +y down, +z forward",
            "fovy_deg": cam.fovy_deg,
            "width": width,
            "height": height,
            "fx": _r(fx),
            "fy": _r(fy),
            "cx": _r(cx),
            "cy": _r(cy),
            "max_range": MAX_RANGE,
        },
        "floor": {"height": 0.0, "pcd_label": LABEL_FLOOR},
        "table": {
            "height": layout.table_height,
            "center": [0.0, 0.0],
            "size": list(layout.table_size),
            "yaw": 0.0,
            "thickness": TABLE_THICKNESS,
            "pcd_label": LABEL_TABLE_TOP,
        },
        "pcd_labels": {
            "0": "no point (NaN)",
            "1": "table top surface",
            "2": "other table parts (edges, legs)",
            "3": "floor",
            ">=20": "object id = label // 10",
        },
        "objects": objects,
        "touching": touching,
    }
    return json.dumps(gt, indent=2) + "\n"
