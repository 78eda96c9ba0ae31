"""The camera of an organized camera-view capture: its intrinsics and each pixel's optical depth.

A camera view's input frame is the camera's optical frame (+x right, +y down, +z forward), brought
into the world by ``capture.input_to_world``. Its intrinsics are declared in capture.yaml
(``camera: {fx, fy, cx, cy}``) or fitted from the grid itself (:mod:`realsim.perception.intrinsics`).
"""

from __future__ import annotations

import numpy as np

from realsim.perception.intrinsics import Intrinsics, fit_intrinsics
from realsim.scene import Scene

__all__ = ["capture_intrinsics", "optical_depth"]


def _world_to_input(scene: Scene) -> np.ndarray:
    """(4, 4) the world -> camera optical frame transform."""
    return np.linalg.inv(np.asarray(scene.capture.input_to_world, float))


def optical_depth(scene: Scene) -> np.ndarray:
    """(N,) each point's depth along the camera's axis (optical z, m), NaN where no depth."""
    world_to_input = _world_to_input(scene)
    assert scene.points is not None
    out: np.ndarray = scene.points @ world_to_input[2, :3] + world_to_input[2, 3]
    return out


def capture_intrinsics(scene: Scene) -> Intrinsics | None:
    """The intrinsics of a camera-view organized capture: declared in capture.yaml (``camera: {fx, fy,
    cx, cy}``), else fitted from the grid (once per capture); None if neither."""
    cap = scene.capture
    if scene.points is None or scene.grid_shape is None or not cap.camera_view:
        return None
    declared = cap.config.camera
    if declared is not None and declared.fx is not None and declared.fy is not None:
        h, w = scene.grid_shape
        return Intrinsics(declared.fx, declared.fy, (w - 1) / 2 if declared.cx is None else declared.cx,
                          (h - 1) / 2 if declared.cy is None else declared.cy, int(w), int(h))
    if cap.fitted_intrinsics is None:
        world_to_input = _world_to_input(scene)
        idx = np.arange(0, len(scene.points), 7)  # every 7th pixel: plenty for two lines, pixel indices kept
        optical = np.full_like(scene.points, np.nan)
        optical[idx] = scene.points[idx] @ world_to_input[:3, :3].T + world_to_input[:3, 3]
        cap.fitted_intrinsics = fit_intrinsics(optical, scene.grid_shape)
    return cap.fitted_intrinsics
