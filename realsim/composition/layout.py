"""Place objects on a support by seeded rejection sampling: inside it, apart, upright.

Footprints are convex polygons (the xy convex hull of the object's collision hulls, rotated by
the sampled yaw); two footprints may not come closer than ``clearance``. Already present
objects (for example the ones segmented from a scan) are obstacles.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.spatial import ConvexHull, QhullError

from realsim.errors import InputError
from realsim.geometry import inside_convex_polygon, polygon_and_rectangle, polygons_apart
from realsim.perception.capture_config import DeclaredSupport
from realsim.scene import SupportPlane


@dataclass(frozen=True)
class LayoutParams:
    """Parameters of the placement."""

    clearance: float = 0.04  # m between footprints (room for the gripper)
    edge_margin: float = 0.05  # m between a footprint and the support's edge
    attempts_per_object: int = 400
    random_yaw: bool = True
    # m: keep objects within this distance of the middle of the support's first long edge, where a
    # robot can stand and reach them all (None: anywhere). Falls back to the whole support when
    # they do not fit.
    reach_radius: float | None = None


def reach_anchor(support: SupportPlane) -> np.ndarray:
    """The middle of the support rectangle's long edge on its local -y (or -x) side, world xy."""
    c, half = np.asarray(support.rect_center, float), np.asarray(support.rect_size, float) / 2
    local = np.array([0.0, -half[1]]) if half[0] >= half[1] else np.array([-half[0], 0.0])
    cy, sy = np.cos(support.rect_yaw), np.sin(support.rect_yaw)
    return c + np.array([[cy, -sy], [sy, cy]]) @ local


def footprint(points_xy: np.ndarray) -> np.ndarray:
    """Convex footprint polygon (counter-clockwise) of an object's vertices projected to xy."""
    try:
        return points_xy[ConvexHull(points_xy).vertices]
    except (QhullError, ValueError):
        lo, hi = points_xy.min(axis=0) - 0.005, points_xy.max(axis=0) + 0.005
        return np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])


def _rotate(poly: np.ndarray, yaw: float) -> np.ndarray:
    c, s = np.cos(yaw), np.sin(yaw)
    return poly @ np.array([[c, s], [-s, c]])


def declared_support(support: DeclaredSupport | None) -> SupportPlane:
    """The plane of a declared support (``capture.yaml``'s ``support:``, validated there), or a
    default 1.2 x 0.8 m table at 0.75 m."""
    support = support or DeclaredSupport()
    size = np.asarray(support.size, dtype=np.float64)
    corners = _rotate(np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]]) * size / 2, -support.yaw) + np.asarray(support.center, dtype=np.float64)
    polygon, rect_center, rect_size, rect_yaw = polygon_and_rectangle(corners)
    return SupportPlane(1, support.kind, np.array([0.0, 0.0, 1.0]), support.height, polygon, rect_center, rect_size, rect_yaw, 0, observed=False)


def place_on_support(
    footprints: list[np.ndarray],
    support: SupportPlane,
    obstacles: list[np.ndarray],
    rng: np.random.Generator,
    params: LayoutParams = LayoutParams(),
) -> list[tuple[np.ndarray, float]]:
    """Sampled (xy, yaw) per footprint (object frame, origin at the base centre), largest first.

    With ``params.reach_radius`` the objects are first kept within reach of one long edge (see
    :class:`LayoutParams`). Raises InputError when an object does not fit after
    ``attempts_per_object`` tries.
    """
    if params.reach_radius is not None:
        state = rng.bit_generator.state
        try:
            return _place(footprints, support, obstacles, rng, params, reach_anchor(support))
        except InputError:
            rng.bit_generator.state = state  # the fallback draws as if the reach region had not been tried
    return _place(footprints, support, obstacles, rng, params, None)


def _place(footprints: list[np.ndarray], support: SupportPlane, obstacles: list[np.ndarray], rng: np.random.Generator,
           params: LayoutParams, anchor: np.ndarray | None) -> list[tuple[np.ndarray, float]]:
    order = sorted(range(len(footprints)), key=lambda i: -ConvexHull(footprints[i]).volume if len(footprints[i]) >= 3 else 0)
    placed: list[np.ndarray] = list(obstacles)
    result: dict[int, tuple[np.ndarray, float]] = {}
    lo, hi = support.polygon.min(axis=0), support.polygon.max(axis=0)
    if anchor is not None:
        lo, hi = np.maximum(lo, anchor - params.reach_radius), np.minimum(hi, anchor + params.reach_radius)
    for i in order:
        for _ in range(params.attempts_per_object):
            yaw = float(rng.uniform(-np.pi, np.pi)) if params.random_yaw else 0.0
            xy = rng.uniform(lo, hi)
            poly = _rotate(footprints[i], yaw) + xy
            if not np.all(inside_convex_polygon(poly, support.polygon, -params.edge_margin)):
                continue
            if anchor is not None and np.linalg.norm(poly - anchor, axis=1).max() > params.reach_radius:
                continue
            if all(polygons_apart(poly, other, params.clearance) for other in placed):
                placed.append(poly)
                result[i] = (xy, yaw)
                break
        else:
            raise InputError(
                f"cannot place {len(footprints)} objects on a {support.rect_size[0]:.2f} x {support.rect_size[1]:.2f} m "
                "support without overlap: declare a larger support in capture.yaml"
            )
    return [result[i] for i in range(len(footprints))]


# ---------------------------------------------------------------- resting on other objects
Piece = tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]  # facet planes (n, d: n.p + d <= 0 inside), xy min, xy max, vertices xy


def hull_pieces(hulls: list[np.ndarray]) -> list[Piece]:
    """Facet planes, xy bounds and vertices (xy) of each convex point set."""
    out = []
    for pts in hulls:
        pts = np.asarray(pts, float)
        try:
            hull = ConvexHull(pts)
        except (QhullError, ValueError):
            continue
        out.append((hull.equations, pts[:, :2].min(axis=0), pts[:, :2].max(axis=0), pts[hull.vertices, :2]))
    return out


def moved_pieces(pieces: list[Piece], xy: np.ndarray, yaw: float, z: float = 0.0) -> list[Piece]:
    """The pieces turned by ``yaw`` about z and moved by (``xy``, ``z``)."""
    c, s = np.cos(yaw), np.sin(yaw)
    rot = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    t = np.array([xy[0], xy[1], z])
    out = []
    for eq, _, _, verts in pieces:
        n = eq[:, :3] @ rot.T
        v = verts @ rot[:2, :2].T + t[:2]
        out.append((np.column_stack([n, eq[:, 3] - n @ t]), v.min(axis=0), v.max(axis=0), v))
    return out


def vertical_extent(pieces: list[Piece], xy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(lowest, highest) z of the convex pieces along vertical lines through ``xy`` (N, 2); NaN
    where no piece is crossed. Exact for convex pieces given by their facet planes."""
    lo = np.full(len(xy), np.nan)
    hi = np.full(len(xy), np.nan)
    for eq, blo, bhi, _ in pieces:
        idx = np.nonzero(np.all(xy >= blo - 1e-9, axis=1) & np.all(xy <= bhi + 1e-9, axis=1))[0]
        if len(idx) == 0:
            continue
        n, d = eq[:, :3], eq[:, 3]
        c = -(d[None, :] + xy[idx] @ n[:, :2].T)  # n_z z <= c
        nz = n[:, 2]
        up, down, flat = nz > 1e-9, nz < -1e-9, np.abs(nz) <= 1e-9
        zmax = (c[:, up] / nz[up]).min(axis=1) if up.any() else np.full(len(idx), np.inf)
        zmin = (c[:, down] / nz[down]).max(axis=1) if down.any() else np.full(len(idx), -np.inf)
        ok = (zmin <= zmax + 1e-9) & np.isfinite(zmin) & np.isfinite(zmax)
        if flat.any():
            ok &= np.all(c[:, flat] >= -1e-9, axis=1)
        sel = idx[ok]
        lo[sel] = np.fmin(lo[sel], zmin[ok])
        hi[sel] = np.fmax(hi[sel], zmax[ok])
    return lo, hi


def rest_height(child: list[np.ndarray], below: list[np.ndarray], xy: np.ndarray, yaw: float, step: float = 0.004) -> float | None:
    """z of the child's frame origin lowered onto ``below`` (see :func:`rest_contact`), or None."""
    found = rest_contact(hull_pieces(child), hull_pieces(below), xy, yaw, step)
    return None if found is None else found[0]


def rest_contact(child: list[Piece], below: list[Piece], xy: np.ndarray, yaw: float, step: float = 0.004,
                 touch: float = 0.0015) -> tuple[float, np.ndarray] | None:
    """(z of the child's frame origin, xy of the contacts) when it is lowered at (``xy``, ``yaw``)
    onto the convex pieces ``below`` (world frame) until it touches them; None when nothing is under it.

    ``child`` are its pieces in its own frame (:func:`hull_pieces`). Vertical lines are sampled on a
    ``step`` grid over the child's footprint and through every vertex of both, so rims are not missed.
    """
    child_w = moved_pieces(child, np.asarray(xy, float), yaw)
    lo = np.min([p[1] for p in child_w], axis=0)
    hi = np.max([p[2] for p in child_w], axis=0)
    n = np.maximum(np.ceil((hi - lo) / step).astype(int) + 1, 2)
    gx, gy = np.meshgrid(np.linspace(lo[0], hi[0], min(n[0], 90)), np.linspace(lo[1], hi[1], min(n[1], 90)))
    # the grid plus every vertex of both (the highest and lowest points of convex pieces are vertices)
    verts = [p[3] for p in child_w] + [p[3][np.all(p[3] >= lo, axis=1) & np.all(p[3] <= hi, axis=1)] for p in below]
    samples = np.vstack([np.column_stack([gx.ravel(), gy.ravel()]), *verts])
    bottom, _ = vertical_extent(child_w, samples)
    keep = np.isfinite(bottom)
    samples, bottom = samples[keep], bottom[keep]
    _, top = vertical_extent(below, samples)
    gap = top - bottom
    ok = np.isfinite(gap)
    if not ok.any():
        return None
    z = float(gap[ok].max())
    return z, samples[ok][gap[ok] > z - touch]  # and the xy where it touches
