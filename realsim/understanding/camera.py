"""Project world points into the capture camera's image (normalized coordinates).

An organized cloud is a camera view in the optical frame (+x right, +y down, +z forward); load
and levelling compose every transform into ``capture.input_to_world``, so the camera sits at its
translation and looks along the mapped +z. Intrinsics come from ``capture.yaml``
(``camera: {fx, fy, cx, cy}`` or ``camera: {fovy_deg}``), else are fitted from the organized grid
(:func:`realsim.appearance.capture_intrinsics`), else come from the grid shape with a default
vertical field of view; ``cx = (W - 1) / 2`` (pixel centres at integers).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from realsim.appearance import capture_intrinsics
from realsim.intrinsics import Intrinsics
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


def _num(d: dict[str, Any], key: str) -> float | None:
    v = d.get(key)
    return float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) else None


def capture_camera(scene: Scene) -> CaptureCamera | None:
    """The capture camera of a camera-view scan, or None (not a camera view / no grid)."""
    meta = scene.capture.metadata
    if scene.grid_shape is None or not meta.get("camera_view"):
        return None
    h, w = int(scene.grid_shape[0]), int(scene.grid_shape[1])
    cam = meta.get("camera") if isinstance(meta.get("camera"), dict) else {}
    fx, fy, cx, cy = (_num(cam, k) for k in ("fx", "fy", "cx", "cy"))
    fitted = capture_intrinsics(scene) if fx is None or fy is None else None
    if fitted is not None:  # the organized grid's own intrinsics
        fx, fy, cx, cy = fitted.fx, fitted.fy, fitted.cx, fitted.cy
    if fx is None or fy is None:
        fovy = _num(cam, "fovy_deg") or DEFAULT_FOVY_DEG
        fx = fy = 0.5 * h / math.tan(math.radians(fovy) / 2)
    cx = (w - 1) / 2 if cx is None else cx
    cy = (h - 1) / 2 if cy is None else cy
    return CaptureCamera(np.linalg.inv(np.asarray(scene.capture.input_to_world, float)), Intrinsics(fx, fy, cx, cy, w, h))
