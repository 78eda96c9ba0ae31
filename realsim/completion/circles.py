"""Circles fitted to points: the footprint arcs of round objects and the rims of containers."""

from __future__ import annotations

import numpy as np


def fit_circle(xy: np.ndarray) -> tuple[np.ndarray, float, float]:
    """Algebraic (Kasa) circle fit: centre, radius and RMS radial residual."""
    a = np.column_stack([2 * xy, np.ones(len(xy))])
    b = (xy**2).sum(axis=1)
    sol, *_ = np.linalg.lstsq(a, b, rcond=None)
    centre = sol[:2]
    radius = float(np.sqrt(max(sol[2] + centre @ centre, 1e-12)))
    rms = float(np.sqrt(np.mean((np.linalg.norm(xy - centre, axis=1) - radius) ** 2)))
    return centre, radius, rms


def arc_coverage_deg(xy: np.ndarray, centre: np.ndarray, bins: int = 72) -> float:
    angles = np.arctan2(xy[:, 1] - centre[1], xy[:, 0] - centre[0])
    hist, _ = np.histogram(angles, bins=bins, range=(-np.pi, np.pi))
    return float(np.count_nonzero(hist) * 360.0 / bins)
