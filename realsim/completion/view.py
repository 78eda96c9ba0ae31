"""What the capture camera saw: its depth image, silhouette veils and the free space in front of it.

The line of sight to every observed pixel is empty space: a point nearer the camera than the captured
depth at its pixel was seen through.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from realsim.perception.capture_camera import capture_intrinsics
from realsim.perception.intrinsics import Intrinsics
from realsim.rowsplit import split_rows
from realsim.scene import Scene

OTHER_SURFACE_TOLERANCE = 0.001  # m: in front of another surface by more than this is free space
SUPPORT_MARGIN = 0.002  # m: a pixel's point this near the support plane shows the support; a point this far above it is off it


@dataclass(frozen=True)
class DepthView:
    """What the capture camera saw: per-pixel depth (m along the optical axis, NaN = nothing)."""

    intrinsics: Intrinsics
    world_to_optical: np.ndarray  # (4, 4), optical units
    scale: float  # optical units per metre
    depth: np.ndarray  # (H, W)
    labels: np.ndarray | None = None  # (H, W) object id per pixel (0 support/background), if known

    @classmethod
    def of(cls, scene: Scene) -> "DepthView | None":
        intr = capture_intrinsics(scene)
        if intr is None:
            return None
        w2o = np.linalg.inv(np.asarray(scene.capture.input_to_world, float))
        scale = float(np.cbrt(abs(np.linalg.det(w2o[:3, :3]))))
        z = (scene.points @ w2o[2, :3] + w2o[2, 3]) / scale
        labels = scene.labels.reshape(intr.height, intr.width) if scene.labels is not None else None
        return cls(intr, w2o, scale, z.reshape(intr.height, intr.width), labels)

    @property
    def camera(self) -> np.ndarray:
        """The camera centre in the world."""
        return np.linalg.inv(self.world_to_optical)[:3, 3]

    def veil(self, tolerance_deg: float = 80.0, where: np.ndarray | None = None) -> np.ndarray:
        """(H, W) mask of veil pixels: mixed depths at silhouettes, seen almost edge-on (a surface whose
        normal, from the grid neighbours, is within ``90 - tolerance_deg`` degrees of perpendicular to the
        ray). Only pixels in ``where`` (default all) are tested."""
        h, w = self.depth.shape
        idx = np.flatnonzero(where.ravel() if where is not None else np.ones(h * w, bool))
        v, u = np.divmod(idx, w)
        inner = (u > 0) & (u < w - 1) & (v > 0) & (v < h - 1)
        idx, v, u = idx[inner], v[inner], u[inner]

        def point(k: np.ndarray) -> np.ndarray:
            kv, ku = np.divmod(k, w)
            z = self.depth.ravel()[k]
            return np.column_stack([(ku - self.intrinsics.cx) / self.intrinsics.fx * z, (kv - self.intrinsics.cy) / self.intrinsics.fy * z, z])

        du = point(idx + 1) - point(idx - 1)
        dv = point(idx + w) - point(idx - w)
        p = point(idx)
        n = np.cross(du, dv)
        with np.errstate(invalid="ignore", divide="ignore"):
            cos = np.abs((n * p).sum(-1)) / (np.linalg.norm(n, axis=-1) * np.linalg.norm(p, axis=-1))
        out = np.zeros(h * w, bool)
        out[idx] = np.nan_to_num(cos, nan=1.0) < np.cos(np.radians(tolerance_deg))
        return out.reshape(h, w)

    def denoised(self, window: int = 5) -> "DepthView":
        """This view with every object pixel's depth taken from the plane fitted (least squares) to
        the depths of the ``window`` x ``window`` pixels around it that show the same object:
        unbiased on surfaces that are flat at that scale, even at a silhouette where only one side
        of the window is the object; other pixels are left as captured."""
        if self.labels is None or not np.any(self.labels > 0):
            return self
        v, u = np.nonzero(self.labels > 0)  # only object pixels are fitted: their windows alone are gathered
        r = window // 2
        depth, labels = np.pad(self.depth, r, constant_values=np.nan).ravel(), np.pad(self.labels, r).ravel()
        wide = self.depth.shape[1] + 2 * r
        at = (v + r) * wide + (u + r)  # each pixel in the padded images, flat
        fitted = split_rows(lambda rows: _window_planes(depth, labels, at[rows], wide, window), len(at))  # each pixel alone
        fit = fitted[:, 0] > 0
        out = self.depth.copy()
        out[v[fit], u[fit]] = fitted[fit, 1]
        return DepthView(self.intrinsics, self.world_to_optical, self.scale, out, self.labels)

    def unveiled(self, veil: np.ndarray, tolerance: float, window: int = 5) -> "DepthView":
        """This view with the ``veil`` pixels (H, W) of objects that continue the surface beside them kept
        (no deeper than the farthest surface pixel of the same object in the ``window`` x ``window``
        pixels around by more than ``tolerance``: the object's own edge, seen edge-on) and the others,
        mixed depths between the object and what lies behind it, set to NaN."""
        if self.labels is None or not np.any(veil & (self.labels > 0)):
            return self
        v, u = np.nonzero(veil & (self.labels > 0))
        r = window // 2
        v0, v1, u0, u1 = max(v.min() - r, 0), min(v.max() + r + 1, self.depth.shape[0]), max(u.min() - r, 0), min(u.max() + r + 1, self.depth.shape[1])
        h, w = v1 - v0, u1 - u0
        surface = np.pad(np.where(veil[v0:v1, u0:u1], np.nan, self.depth[v0:v1, u0:u1]), r, constant_values=np.nan)
        labels = np.pad(self.labels[v0:v1, u0:u1], r)
        centre = labels[r:r + h, r:r + w]
        deepest = np.full((h, w), -np.inf)
        for di in range(window):
            for dj in range(window):
                d = surface[di:di + h, dj:dj + w]
                same = (labels[di:di + h, dj:dj + w] == centre) & np.isfinite(d)
                deepest = np.where(same, np.maximum(deepest, np.nan_to_num(d, nan=-np.inf)), deepest)
        out = self.depth.copy()
        block = out[v0:v1, u0:u1]
        sel = veil[v0:v1, u0:u1] & (centre > 0)
        block[sel] = np.where(block[sel] <= deepest[sel] + tolerance, block[sel], np.nan)
        return DepthView(self.intrinsics, self.world_to_optical, self.scale, out, self.labels)

    def moved_to(self, other: "DepthView", points: np.ndarray) -> np.ndarray:
        """The organized world ``points`` (one per pixel, this view's) moved along their rays to the
        depth ``other`` holds at their pixel (unchanged where either depth is missing)."""
        with np.errstate(invalid="ignore", divide="ignore"):
            factor = np.nan_to_num(other.depth / self.depth, nan=1.0, posinf=1.0, neginf=1.0).ravel()
        camera = self.camera
        return np.asarray(camera + (points - camera) * factor[:, None])

    def noise(self, edge: float = 0.02) -> float:
        """The sensor's depth noise (m, one sigma) on object pixels (all pixels when no labels): the
        spread of second differences along rows (six times the variance of independent noise),
        steps over ``edge`` (silhouettes) left out."""
        d2 = self.depth[:, :-2] - 2 * self.depth[:, 1:-1] + self.depth[:, 2:]
        with np.errstate(invalid="ignore"):
            ok = np.isfinite(d2) & (np.abs(d2) < edge)
        if self.labels is not None and np.count_nonzero(ok & (self.labels[:, 1:-1] > 0)) >= 100:
            ok &= self.labels[:, 1:-1] > 0
        return float(np.std(d2[ok]) / np.sqrt(6.0)) if np.count_nonzero(ok) >= 100 else 0.0

    @cached_property
    def _cell_depth(self) -> np.ndarray:
        """Per image cell (the square between four neighbouring pixel centres, (H-1, W-1)): the nearest
        depth its corners saw (NaN when one of them saw nothing)."""
        d = self.depth
        return np.asarray(np.minimum(np.minimum(d[:-1, :-1], d[1:, :-1]), np.minimum(d[:-1, 1:], d[1:, 1:])))

    def seen_through(self, points: np.ndarray, tolerance: float, own: int | None = None, footprint: bool = True) -> np.ndarray:
        """Mask of world points certainly in the space the camera saw through: nearer than the captured
        depth of all four pixel centres around their image position (a point between an object's last
        pixel and the first pixel past it may be the object's own edge: the pixel footprint) by more than
        ``tolerance`` when one of those pixels shows object ``own`` (its own noisy surface), by more than
        a millimetre when none does (nothing of ``own`` can be in front of that). Without ``footprint``
        only the nearest pixel is asked (voxels coarser than a pixel, whose hull keeps the seen points)."""
        opt = points @ self.world_to_optical[:3, :3].T + self.world_to_optical[:3, 3]
        h, w = self.depth.shape
        with np.errstate(invalid="ignore", divide="ignore"):
            uv = (np.floor if footprint else np.rint)(self.intrinsics.project(opt)) if len(points) else np.zeros((0, 2))
        inside = (opt[:, 2] > 0) & (uv[:, 0] >= 0) & (uv[:, 0] < w - footprint) & (uv[:, 1] >= 0) & (uv[:, 1] < h - footprint)
        cell = uv[inside].astype(np.int64)
        seen = np.full(len(points), np.nan)
        seen[inside] = (self._cell_depth if footprint else self.depth)[cell[:, 1], cell[:, 0]]
        tol = np.full(len(points), tolerance)
        if own is not None and self.labels is not None:
            v, u = cell[:, 1], cell[:, 0]
            corners = [(0, 0), (1, 0), (0, 1), (1, 1)] if footprint else [(0, 0)]
            mine = np.zeros(len(points), bool)
            mine[inside] = np.any([self.labels[v + dv, u + du] == own for dv, du in corners], axis=0)
            tol[~mine] = OTHER_SURFACE_TOLERANCE
        with np.errstate(invalid="ignore"):
            return np.asarray(opt[:, 2] / self.scale < seen - tol)


    def front_hits(self, planes: np.ndarray, corners: np.ndarray, chunk: int = 4096) -> np.ndarray:
        """Where the ray of every pixel centre first meets the convex solid ``planes`` (F, 4: ``n . x <= d``
        as rows ``(n, d)``, world frame) whose vertices are ``corners`` (world points, (N, 3)): its front
        surface at pixel resolution (nothing when a corner lies behind the camera)."""
        opt = corners @ self.world_to_optical[:3, :3].T + self.world_to_optical[:3, 3]
        if not len(corners) or np.any(opt[:, 2] <= 0):
            return np.zeros((0, 3))
        uv = self.intrinsics.project(opt)
        h, w = self.depth.shape
        u0, v0 = np.maximum(np.floor(uv.min(axis=0)).astype(int), 0)
        u1, v1 = np.minimum(np.ceil(uv.max(axis=0)).astype(int), [w - 1, h - 1])
        if u1 < u0 or v1 < v0:
            return np.zeros((0, 3))
        v, u = np.mgrid[v0:v1 + 1, u0:u1 + 1]
        ray = np.column_stack([(u.ravel() - self.intrinsics.cx) / self.intrinsics.fx, (v.ravel() - self.intrinsics.cy) / self.intrinsics.fy, np.ones(u.size)])
        ray = ray @ np.linalg.inv(self.world_to_optical[:3, :3]).T  # world directions (t = 1 at unit optical depth)
        camera = self.camera
        out = []
        for s in range(0, len(ray), chunk):
            d = ray[s:s + chunk] @ planes[:, :3].T  # (n, F): n . direction
            with np.errstate(divide="ignore", invalid="ignore"):
                t = (planes[:, 3] - planes[:, :3] @ camera)[None, :] / d
            enter = np.where(d < 0, t, -np.inf).max(axis=1)
            leave = np.where(d > 0, t, np.inf).min(axis=1)
            hit = (enter <= leave) & (enter > 0) & np.isfinite(enter)
            out.append(camera + enter[hit, None] * ray[s:s + chunk][hit])
        return np.vstack(out)

    def over_support(self, points: np.ndarray, height: float, margin: float = SUPPORT_MARGIN) -> np.ndarray:
        """Mask of world ``points`` more than ``margin`` above the support plane at ``height`` whose
        nearest pixel shows that support (no object there, its point within ``margin`` of the plane) and
        lies beyond them: the camera saw the support through them. The plane is known far better than
        any one pixel's depth, so a thin body is not filled here down to the depth noise."""
        out = np.zeros(len(points), bool)
        if self.labels is None or not len(points):
            return out
        opt = points @ self.world_to_optical[:3, :3].T + self.world_to_optical[:3, 3]
        h, w = self.depth.shape
        with np.errstate(invalid="ignore", divide="ignore"):
            uv = np.rint(self.intrinsics.project(opt))
        inside = (opt[:, 2] > 0) & (points[:, 2] > height + margin) & np.all(np.isfinite(uv), axis=1)
        inside &= (uv[:, 0] >= 0) & (uv[:, 0] < w) & (uv[:, 1] >= 0) & (uv[:, 1] < h)
        u, v = uv[inside, 0].astype(np.int64), uv[inside, 1].astype(np.int64)
        z = self.depth[v, u]
        seen = np.column_stack([(u - self.intrinsics.cx) / self.intrinsics.fx * z, (v - self.intrinsics.cy) / self.intrinsics.fy * z, z]) * self.scale
        world = (seen - self.world_to_optical[:3, 3]) @ np.linalg.inv(self.world_to_optical[:3, :3]).T
        with np.errstate(invalid="ignore"):
            out[inside] = (self.labels[v, u] == 0) & (np.abs(world[:, 2] - height) < margin) & (opt[inside, 2] / self.scale < z)
        return out


def _window_planes(depth: np.ndarray, labels: np.ndarray, at: np.ndarray, wide: int, window: int) -> np.ndarray:
    """Per pixel ``at`` (flat, in the padded ``depth`` and ``labels`` images ``wide`` pixels wide; rows of
    (fitted, depth)) whether a plane was fitted by least squares to the finite depths of its ``window`` x
    ``window`` pixels of its own label (at least 6, not degenerate) and its depth at the pixel's centre
    (NaN when not fitted; see :meth:`DepthView.denoised`)."""
    r = window // 2
    offsets = [(i - r, j - r) for i in range(window) for j in range(window)]
    d = np.stack([depth[at + (di * wide + dj)] for di, dj in offsets])  # (window^2, n)
    centre = labels[at]
    ok = np.stack([labels[at + (di * wide + dj)] == centre for di, dj in offsets]) & np.isfinite(d)
    basis = np.array([[1.0, dj, di] for di, dj in offsets])  # depth = a + b du + c dv: a at the centre
    wgt = ok.astype(float)
    normal = np.tensordot(wgt, basis[:, :, None] * basis[:, None, :], axes=(0, 0))  # small integers: exact in any order
    seen = wgt * np.nan_to_num(d)
    rhs = seen[0] * basis[0][:, None]  # (3, n)
    for k in range(1, len(offsets)):  # summed over the window in order
        rhs += seen[k] * basis[k][:, None]
    fit = (wgt.sum(axis=0) >= 6) & (np.abs(np.linalg.det(normal)) > 1e-6)
    out = np.column_stack([fit, np.full(len(at), np.nan)])
    out[fit, 1] = np.linalg.solve(normal[fit], rhs[:, fit].T[..., None])[:, 0, 0]
    return out
