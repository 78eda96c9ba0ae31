"""A plane refitted by least squares on the points in a shrinking band of it, iterated to a
fixed point; each pass tests only the points near the starting plane while a bound shows that
no other point can be in its band."""

from __future__ import annotations

import numpy as np

from realsim.geometry import fit_plane

__all__ = ["refine_plane"]


def refine_plane(points: np.ndarray, normal: np.ndarray, d: float, band: float, passes: int = 3, max_passes: int = 12) -> tuple[np.ndarray, float, np.ndarray]:
    """Refit a plane on the points within a band of it: the band shrinks for ``passes`` passes,
    then the fit is iterated until its inlier set stops changing.

    Iterating to a fixed point makes the result independent of small differences in the
    starting plane (multi-threaded RANSAC does not always return the same model), so the same
    input gives the same plane. Returns the normal, offset and the final inlier mask.
    Each pass tests only the points near the starting plane while a bound shows that no other
    point can be in its band (:class:`_NearPlane`): the same masks as testing every point.
    """
    near = _NearPlane(points, normal, d, _SHORTLIST_BANDS * band)
    sub = near.points
    mask = np.zeros(len(sub), dtype=bool)
    for i in range(max_passes):
        width = band * (0.6 ** min(i, passes - 1))
        if sub is near.points and not near.holds(normal, d, width):
            mask, sub = near.widen(mask), points  # the plane moved too far: every point from here on
        new_mask = np.abs(sub @ normal + d) < width
        if new_mask.sum() < 3:
            break
        if i >= passes and np.array_equal(new_mask, mask):
            break
        mask = new_mask
        new_normal, new_d = fit_plane(sub[mask])
        if new_normal @ normal < 0:
            new_normal, new_d = -new_normal, -new_d
        normal, d = new_normal, new_d
    return normal, d, (near.widen(mask) if sub is near.points else mask)


_SHORTLIST_BANDS = 10.0  # refine_plane tests first the points within this many bands of the starting plane


class _NearPlane:
    """The points within ``reach`` of a plane (n0, d0), in input order, and the test that a plane
    (n, d) has no point beyond them within ``width``: for any point p outside,
    |p.n + d| >= reach - |(p - c).(n - n0)| - |c.(n - n0) + d - d0| >= reach - R |n - n0| - |c.(n - n0) + d - d0|,
    c the centre of the points' bounding box and R its half diagonal."""

    def __init__(self, points: np.ndarray, normal: np.ndarray, d: float, reach: float) -> None:
        self.total, self.normal, self.d, self.reach = len(points), normal, d, reach
        self.index = np.flatnonzero(np.abs(points @ normal + d) < reach)
        self.points = points[self.index]
        lo, hi = (points.min(axis=0), points.max(axis=0)) if len(points) else (np.zeros(3), np.zeros(3))
        self.centre, self.radius = (lo + hi) / 2, float(np.linalg.norm(hi - lo)) / 2

    def holds(self, normal: np.ndarray, d: float, width: float) -> bool:
        """True when no point beyond the shortlist lies within ``width`` of the plane (n, d)."""
        turn = normal - self.normal
        slack = self.radius * float(np.linalg.norm(turn)) + abs(float(self.centre @ turn) + d - self.d)
        return self.reach - slack > width * (1 + 1e-9) + 1e-12

    def widen(self, mask: np.ndarray) -> np.ndarray:
        """A mask over the shortlist as a mask over every point."""
        out = np.zeros(self.total, dtype=bool)
        out[self.index[mask]] = True
        return out


def level_unless_resolved(points: np.ndarray, normal: np.ndarray, up: np.ndarray, resolution: float) -> np.ndarray:
    """``up`` (the scene's common support normal: gravity) for a plane of ``points`` whose fitted
    ``normal`` departs from it by no more than the capture resolves, else ``normal``.

    A capture places each surface point to within its ``resolution`` (a fused sweep's voxel, a
    sparse cloud's cell: a top seen at grazing angles has its crossings on voxel layers, its
    border rounded down), so across the plane's span L along its tilt the fit may lean by
    atan(resolution / L) with no tilt there at all. Every support of a room shares gravity; one
    whose tilt is within that bound takes it."""
    tilt = normal - (normal @ up) * up
    size = float(np.linalg.norm(tilt))
    if size == 0.0:
        return up
    along = points @ (tilt / size)
    span = float(along.max() - along.min()) if len(along) else 0.0
    lean = float(np.arctan2(size, abs(float(normal @ up))))
    return up if span > 0.0 and lean <= np.arctan2(resolution, span) else normal
