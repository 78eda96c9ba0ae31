"""How closely a written scene reproduces its capture, seen from the capture camera.

The scene is rendered (RGB, depth, segmentation) at keyframe ``initial`` from camera
``capture`` with the capture's intrinsics, and compared with the capture's own RGB-D on every
pixel that has captured depth and shows no robot: depth median error, share of pixels within
1 cm, colour PSNR and SSIM (Gaussian window, sigma 1.5, on luma; the SSIM map is averaged over
the compared pixels, and pixels outside them take the rendered value in both images so they add
no structure).
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np
from scipy.ndimage import gaussian_filter

from realsim.perception.intrinsics import Intrinsics

ROBOT_PREFIX = "panda/"


@dataclass(frozen=True)
class RGBD:
    """An image pair: RGB float in [0, 1] (H, W, 3) and planar depth in metres (H, W), NaN = none."""

    rgb: np.ndarray
    depth: np.ndarray


@dataclass(frozen=True)
class Fidelity:
    """Capture-vs-render figures over the compared pixels."""

    pixels: int
    depth_median_mm: float
    within_1cm: float  # share in [0, 1]
    psnr_db: float
    ssim: float


def capture_rgbd(optical: np.ndarray, colors: np.ndarray | None, grid_shape: tuple[int, int], metres_per_unit: float = 1.0) -> RGBD:
    """The capture's own RGB-D image from its organized cloud (optical frame, input units)."""
    h, w = grid_shape
    pts = np.asarray(optical, float).reshape(h, w, 3)
    depth = pts[..., 2] * metres_per_unit
    depth = np.where(np.isfinite(depth) & (depth > 0), depth, np.nan)
    rgb = np.zeros((h, w, 3)) if colors is None else np.nan_to_num(np.asarray(colors, float).reshape(h, w, 3))
    return RGBD(rgb, depth)


def set_camera_intrinsics(model: mujoco.MjModel, camera: str, intr: Intrinsics) -> None:
    """Give ``camera`` of a compiled model the pinhole intrinsics ``intr`` (sensor in pixel units)."""
    cam = model.camera(camera).id
    fields = intr.mujoco_camera()
    model.cam_sensorsize[cam] = fields["sensor_size"]
    model.cam_resolution[cam] = [intr.width, intr.height]
    model.cam_intrinsic[cam] = [*fields["focal_pixel"], *fields["principal_pixel"]]
    model.cam_fovy[cam] = intr.fovy_deg


def _initial_data(model: mujoco.MjModel) -> mujoco.MjData:
    data = mujoco.MjData(model)
    key = next((k for k in range(model.nkey) if model.key(k).name == "initial"), 0 if model.nkey else None)
    if key is not None:
        mujoco.mj_resetDataKeyframe(model, data, key)
    mujoco.mj_forward(model, data)
    return data


def render_rgbd(model: mujoco.MjModel, intr: Intrinsics, camera: str = "capture", data: mujoco.MjData | None = None,
                robot_prefix: str = ROBOT_PREFIX) -> tuple[RGBD, np.ndarray]:
    """RGB-D of ``model`` (keyframe ``initial`` when ``data`` is None) from ``camera`` with ``intr``,
    and the mask of pixels showing the robot (bodies named ``robot_prefix...``)."""
    set_camera_intrinsics(model, camera, intr)
    model.vis.global_.offwidth = max(model.vis.global_.offwidth, intr.width)
    model.vis.global_.offheight = max(model.vis.global_.offheight, intr.height)
    data = _initial_data(model) if data is None else data
    with mujoco.Renderer(model, height=intr.height, width=intr.width) as renderer:
        renderer.update_scene(data, camera=camera)
        rgb = renderer.render().astype(float) / 255.0
        renderer.enable_depth_rendering()
        renderer.update_scene(data, camera=camera)
        depth = renderer.render().astype(float)
        renderer.disable_depth_rendering()
        renderer.enable_segmentation_rendering()
        renderer.update_scene(data, camera=camera)
        seg = renderer.render()
    robot_geoms = np.array([model.body(model.geom_bodyid[g]).name.startswith(robot_prefix) for g in range(model.ngeom)] + [False])
    ids = np.where((seg[..., 1] == int(mujoco.mjtObj.mjOBJ_GEOM)) & (seg[..., 0] >= 0), seg[..., 0], model.ngeom)
    robot = robot_geoms[ids]
    far = depth >= 0.99 * model.vis.map.zfar * model.stat.extent
    depth[far] = np.nan
    return RGBD(rgb, depth), robot


def psnr(a: np.ndarray, b: np.ndarray) -> float:
    """PSNR in dB of two [0, 1] arrays (same shape)."""
    mse = float(np.mean((a - b) ** 2))
    return float("inf") if mse == 0 else float(10 * np.log10(1.0 / mse))


def _luma(rgb: np.ndarray) -> np.ndarray:
    return rgb @ np.array([0.299, 0.587, 0.114])


def ssim_map(a: np.ndarray, b: np.ndarray, sigma: float = 1.5) -> np.ndarray:
    """Per-pixel SSIM of two grey images in [0, 1] (Wang et al. 2004, Gaussian window)."""
    c1, c2 = 0.01**2, 0.03**2
    mu_a, mu_b = gaussian_filter(a, sigma), gaussian_filter(b, sigma)
    saa = gaussian_filter(a * a, sigma) - mu_a**2
    sbb = gaussian_filter(b * b, sigma) - mu_b**2
    sab = gaussian_filter(a * b, sigma) - mu_a * mu_b
    return ((2 * mu_a * mu_b + c1) * (2 * sab + c2)) / ((mu_a**2 + mu_b**2 + c1) * (saa + sbb + c2))


def compare(render: RGBD, capture: RGBD, exclude: np.ndarray | None = None) -> Fidelity:
    """Figures over pixels with captured depth, outside ``exclude`` (e.g. the robot)."""
    mask = np.isfinite(capture.depth)
    if exclude is not None:
        mask &= ~exclude
    n = int(mask.sum())
    if n == 0:
        return Fidelity(0, float("nan"), float("nan"), float("nan"), float("nan"))
    err = np.abs(np.where(np.isfinite(render.depth), render.depth, np.inf) - capture.depth)[mask]
    cap_rgb = np.where(mask[..., None], capture.rgb, render.rgb)
    s = ssim_map(_luma(render.rgb), _luma(cap_rgb))[mask]
    return Fidelity(n, float(np.median(err) * 1000), float(np.mean(err <= 0.01)), psnr(render.rgb[mask], capture.rgb[mask]), float(np.mean(s)))
