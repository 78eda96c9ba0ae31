"""Pinhole intrinsics of an organized cloud, fitted from its own grid.

An organized cloud is a depth image back-projected: the point in row ``v``, column ``u`` lies on
the ray ``u = fx X/Z + cx``, ``v = fy Y/Z + cy`` (optical frame: +x right, +y down, +z forward;
pixel centres at integers). A least-squares line per axis over the valid pixels recovers the
intrinsics the capture was made with, so a MuJoCo camera can reproduce the photo pixel for pixel.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

MAX_RMS_PX = 1.0  # residual beyond which the grid is not one pinhole view (a stitched or resampled cloud)
MIN_POINTS = 100


@dataclass(frozen=True)
class Intrinsics:
    """Pinhole intrinsics in pixels (pixel centres at integers) and the image size."""

    fx: float
    fy: float
    cx: float
    cy: float
    width: int
    height: int
    rms_px: float = 0.0  # fit residual

    def project(self, optical: np.ndarray) -> np.ndarray:
        """(N, 2) pixel coordinates (u right, v down) of optical-frame points; NaN behind the camera."""
        p = np.asarray(optical, float).reshape(-1, 3)
        z = np.where(p[:, 2] > 1e-9, p[:, 2], np.nan)
        return np.column_stack([self.fx * p[:, 0] / z + self.cx, self.fy * p[:, 1] / z + self.cy])

    @property
    def fovy_deg(self) -> float:
        return float(np.degrees(2 * np.arctan2(self.height / 2, self.fy)))

    def mujoco_camera(self) -> dict[str, list[float]]:
        """``MjsCamera`` fields giving these intrinsics (``sensor_size`` in pixel units).

        MuJoCo's principal point is the offset of the optical axis from the sensor centre, with
        the image shifting opposite to it (checked by rendering a marker at a known ray).
        """
        return {
            "sensor_size": [float(self.width), float(self.height)],
            "resolution": [float(self.width), float(self.height)],
            "focal_pixel": [float(self.fx), float(self.fy)],
            "principal_pixel": [float((self.width - 1) / 2 - self.cx), float((self.height - 1) / 2 - self.cy)],
        }

    def record(self) -> dict[str, float | int]:
        return {"fx": round(self.fx, 3), "fy": round(self.fy, 3), "cx": round(self.cx, 3), "cy": round(self.cy, 3),
                "width": self.width, "height": self.height, "rms_px": round(self.rms_px, 4)}


def fit_intrinsics(optical: np.ndarray, grid_shape: tuple[int, int]) -> Intrinsics | None:
    """Intrinsics of an organized cloud (optical-frame points, NaN kept, row-major ``grid_shape``).

    None when too few pixels are valid or the grid is not a single pinhole projection.
    """
    h, w = int(grid_shape[0]), int(grid_shape[1])
    pts = np.asarray(optical, float).reshape(h * w, 3)
    ok = np.all(np.isfinite(pts), axis=1) & (pts[:, 2] > 1e-6)
    if ok.sum() < MIN_POINTS:
        return None
    idx = np.flatnonzero(ok)
    step = max(1, len(idx) // 50000)  # a subset is plenty for two 2-parameter lines
    idx = idx[::step]
    rows, cols = np.divmod(idx, w)
    p = pts[idx]
    params, rms = [], []
    for ratio, pix in ((p[:, 0] / p[:, 2], cols), (p[:, 1] / p[:, 2], rows)):
        a = np.column_stack([ratio, np.ones_like(ratio)])
        sol, *_ = np.linalg.lstsq(a, pix.astype(float), rcond=None)
        params.append(sol)
        rms.append(float(np.sqrt(np.mean((a @ sol - pix) ** 2))))
    (fx, cx), (fy, cy) = params
    if fx <= 0 or fy <= 0 or max(rms) > MAX_RMS_PX:
        return None
    return Intrinsics(float(fx), float(fy), float(cx), float(cy), w, h, max(rms))
