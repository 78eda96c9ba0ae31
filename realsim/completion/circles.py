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


def corner_rms(xy: np.ndarray, step_deg: float = 2.0, max_points: int = 3000) -> float:
    """RMS distance of ``xy`` from the nearest of two perpendicular lines fitted to them: the corner of
    a prism's footprint (a camera sees at most two faces of a box; one face is a corner with one line
    unseen). Each orientation tries the four corners whose lines lie at the points' 2nd/98th
    percentiles across it; the best is kept. Against :func:`fit_circle`'s residual it tells a round
    side from a flat one."""
    xy = xy[:: max(1, len(xy) // max_points)] - xy.mean(axis=0)
    best = float("inf")
    for theta in np.radians(np.arange(0.0, 90.0, step_deg)):
        u = xy @ np.array([np.cos(theta), np.sin(theta)])
        v = xy @ np.array([-np.sin(theta), np.cos(theta)])
        for a in np.percentile(u, [2, 98]):
            du = np.abs(u - a)
            for b in np.percentile(v, [2, 98]):
                best = min(best, float(np.sqrt(np.mean(np.minimum(du, np.abs(v - b)) ** 2))))
    return best
