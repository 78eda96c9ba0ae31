"""Project world points into the capture camera's image (normalized coordinates).

An organized cloud is a camera view in the optical frame (+x right, +y down, +z forward); load
and levelling compose every transform into ``capture.input_to_world``, so the camera sits at its
translation and looks along the mapped +z. Intrinsics come from ``capture.yaml``
(``camera: {fx, fy, cx, cy}`` or ``camera: {fovy_deg}``), else are fitted from the organized grid
(:func:`realsim.perception.capture_camera.capture_intrinsics`), else come from the grid shape with a default
vertical field of view; ``cx = (W - 1) / 2`` (pixel centres at integers).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from realsim.perception.capture_camera import capture_intrinsics
from realsim.perception.intrinsics import Intrinsics
from realsim.scene import Scene

DEFAULT_FOVY_DEG = 45.0  # Kinect v1: 43-45 deg vertical


@dataclass(frozen=True)
class CaptureCamera:
    """The capture's pinhole camera placed in the world."""

    world_to_optical: np.ndarray  # (4, 4)
    intrinsics: Intrinsics

    def project(self, points: np.ndarray) -> np.ndarray:
        """(N, 2) normalized image coordinates in [0, 1] (x right, y down); NaN behind the camera."""
        p = np.asarray(points, float).reshape(-1, 3) @ self.world_to_optical[:3, :3].T + self.world_to_optical[:3, 3]
        k = self.intrinsics
        return (k.project(p) + 0.5) / np.array([k.width, k.height], float)


def capture_camera(scene: Scene) -> CaptureCamera | None:
    """The capture camera of a camera-view scan, or None (not a camera view / no grid)."""
    if scene.grid_shape is None or not scene.capture.camera_view:
        return None
    world_to_optical = np.linalg.inv(np.asarray(scene.capture.input_to_world, float))
    known = capture_intrinsics(scene)  # declared in capture.yaml, else fitted from the grid
    if known is not None:
        return CaptureCamera(world_to_optical, known)
    h, w = int(scene.grid_shape[0]), int(scene.grid_shape[1])
    declared = scene.capture.config.camera
    fovy = declared.fovy_deg if declared is not None and declared.fovy_deg is not None else DEFAULT_FOVY_DEG
    f = 0.5 * h / math.tan(math.radians(fovy) / 2)
    cx = declared.cx if declared is not None and declared.cx is not None else (w - 1) / 2
    cy = declared.cy if declared is not None and declared.cy is not None else (h - 1) / 2
    return CaptureCamera(world_to_optical, Intrinsics(f, f, cx, cy, w, h))
