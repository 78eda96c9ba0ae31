"""Where to release a held object: spots within a target's free area, hand yaws and heights.

A place that cannot reach its first release pose tries what a person would: the hand turned
about the vertical, another spot within the container's cavity or the support's top (nearer the
robot first), a slightly higher release. These functions only propose; the robot checks
each pose with IK and a planned path before moving.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.spatial import ConvexHull, Delaunay, QhullError, cKDTree

from realsim.robot.params import PlaceParams


@dataclass(frozen=True)
class ReleaseParams:
    """How many alternatives a place tries."""

    ring: int = 6  # spots around the centre of the free area
    yaws: tuple[float, ...] = (0.0, 0.5, -0.5, 1.0, -1.0, np.pi / 2)  # rad the hand turns about the vertical
    drops: tuple[float, ...] = (0.01, 0.03, 0.05)  # m above the surface at release
    max_poses: int = 48  # the first spot's yaws, three yaws at each of two rings of six, then higher releases
    tilts: tuple[float, ...] = tuple(np.round(np.arange(0.1, 0.61, 0.05), 2))  # rad an object longer than a container's opening is tipped, one end first
    lean_reach: tuple[float, ...] = (0.85, 0.6, 0.35)  # of the opening's radius past its centre the low end of a tipped object goes
    lean_mass: float = 0.5  # of the opening's radius the tipped object's centre may lie off its centre (it slides in, not out)
    underside_cell: float = 0.015  # m: the lowest point of the held object in each cell this wide meets the surface first


def footprint_radius(obj_pts: np.ndarray) -> float:
    """Half the object's largest horizontal extent about its footprint centre (m)."""
    xy = obj_pts[:, :2]
    c = (xy.min(axis=0) + xy.max(axis=0)) / 2
    return float(np.linalg.norm(xy - c, axis=1).max())


def footprint_ring(obj_pts: np.ndarray, n: int = 8, frac: float = 0.5) -> np.ndarray:
    """(n + 1, 2) offsets from the object's footprint centre: the centre and ``frac`` of the way
    to the footprint's edge in ``n`` directions. A release spot whose support is level under all
    of them keeps the object's centre of mass well over its support (not off the table edge)."""
    xy = obj_pts[:, :2] - (obj_pts[:, :2].min(axis=0) + obj_pts[:, :2].max(axis=0)) / 2
    ang = 2 * np.pi * np.arange(n) / n
    dirs = np.column_stack([np.cos(ang), np.sin(ang)])
    off = np.angle(np.exp(1j * (np.arctan2(xy[:, 1], xy[:, 0])[:, None] - ang[None, :])))  # each point's angle from each direction
    dist = np.where(np.abs(off) <= min(np.pi / n, 0.1), np.linalg.norm(xy, axis=1)[:, None], 0.0)  # the footprint's radius along each direction
    return np.vstack([np.zeros(2), frac * dist.max(axis=0)[:, None] * dirs])


def cavity_centre(container_pts: np.ndarray) -> tuple[np.ndarray, float]:
    """Centre of a container's opening (its top band of points) and the inner radius there."""
    top = float(container_pts[:, 2].max())
    band = container_pts[container_pts[:, 2] > top - 0.02, :2]
    centre = (band.min(axis=0) + band.max(axis=0)) / 2
    lo, hi = container_pts[:, :2].min(axis=0), container_pts[:, :2].max(axis=0)
    inner = band[np.linalg.norm(band - centre, axis=1) < 0.45 * float(np.min(hi - lo))]
    if len(inner) < 3:
        centre = np.median(band, axis=0)
    r_in = float(np.linalg.norm(band - centre, axis=1).min())
    return centre, r_in


def top_area(support_pts: np.ndarray) -> tuple[np.ndarray, float]:
    """Centre of a support's top face and the radius of the largest circle about it on that face."""
    top = float(support_pts[:, 2].max())
    face = support_pts[support_pts[:, 2] > top - 0.01, :2]
    centre = face.mean(axis=0)
    try:
        eq = ConvexHull(face).equations
        r_in = float(max(0.0, -(eq[:, :2] @ centre + eq[:, 2]).max()))
    except (QhullError, ValueError):
        r_in = 0.0
    return centre, r_in


def spots(centre: np.ndarray, slack: float, base_xy: np.ndarray, ring: int = 6) -> list[np.ndarray]:
    """``centre`` first, then points on rings of radius ``slack / 2`` and ``0.9 slack`` about it,
    nearer the robot base first (rings only when there is at least 1 cm of slack)."""
    out = [np.asarray(centre, float)]
    if slack >= 0.01:
        ang = 2 * np.pi * np.arange(ring) / ring
        for frac in (0.5, 0.9):  # an inner ring, then one near the edge of the free area
            ringed = [centre + frac * slack * np.array([np.cos(a), np.sin(a)]) for a in ang]
            ringed.sort(key=lambda p: float(np.linalg.norm(p - base_xy)))
            out += ringed
    return out


def side_spots(o: np.ndarray, r: np.ndarray, d: np.ndarray, gap: float, pl: PlaceParams) -> list[tuple[float, np.ndarray]]:
    """(cost, xy) of spots for the object ``o``'s centre on the unit ``d`` side of ``r`` (points):
    over the side relation's sector (nearer or further out, down to the least gap it accepts,
    off the line as far as it allows), the spot ``gap`` straight out first."""
    perp = np.array([-d[1], d[0]])
    oc = (o[:, :2].min(axis=0) + o[:, :2].max(axis=0)) / 2
    rc = (r[:, :2].min(axis=0) + r[:, :2].max(axis=0)) / 2
    base = float(((r[:, :2] - rc) @ d).max()) + float(((o[:, :2] - oc) @ -d).max())
    allowed = float(np.ptp(r[:, :2] @ perp) + np.ptp(o[:, :2] @ perp)) / 2 + pl.side_slack - pl.beside_margin
    lats = [0.0] + [sgn * k * pl.beside_step for k in range(1, int(allowed / pl.beside_step) + 1) for sgn in (1.0, -1.0)]
    least = pl.overlap_margin - pl.side_overlap - gap  # a little into r's extent: beside a round corner, off the line
    alongs = [*pl.beside_along, *(np.arange(min(pl.beside_along) - pl.overlap_step, least, -pl.overlap_step).tolist() + [least]
                                   if least < min(pl.beside_along) else [])]
    return [(abs(along) + abs(lat), rc + d * (base + gap + along) + perp * lat) for along in alongs for lat in lats]


def free_first(spot_list: list[np.ndarray], occupied_xy: np.ndarray) -> list[np.ndarray]:
    """``spot_list`` ordered by the distance to the nearest of ``occupied_xy`` (what already lies
    in a container), farthest first: the free part of the cavity before the rest; unchanged when
    nothing is there."""
    if not len(occupied_xy) or not spot_list:
        return spot_list
    gap = cKDTree(occupied_xy).query(np.asarray(spot_list))[0]
    return [spot_list[i] for i in np.argsort(-gap, kind="stable")]


def free_radius(centre: np.ndarray, r_in: float, blockers: list[np.ndarray], cell: float = 0.004) -> float:
    """Radius of the largest circle within a container's opening (``centre``, inner radius
    ``r_in``) clear of the ``blockers`` (xy points of each thing already in it that rises to the
    rim; a thing's footprint hull counts as filled)."""
    g = np.arange(-r_in, r_in + cell / 2, cell)
    grid = np.array(np.meshgrid(g, g)).reshape(2, -1).T
    grid = grid[np.linalg.norm(grid, axis=1) <= r_in] + np.asarray(centre)
    room = r_in - np.linalg.norm(grid - centre, axis=1)
    for b in blockers:
        room = np.minimum(room, cKDTree(b).query(grid)[0])
        try:
            room[Delaunay(b).find_simplex(grid) >= 0] = 0.0
        except (QhullError, ValueError):
            pass  # too few points for a hull: their distance alone counts
    return float(max(room.max(), 0.0))


def narrowest(pts: np.ndarray) -> float:
    """The object's footprint width across its long axis (m)."""
    a = long_axis(pts)
    return float(np.ptp(pts[:, :2] @ np.array([-a[1], a[0]])))


def underside(pts: np.ndarray, cell: float) -> np.ndarray:
    """The lowest point in each ``cell``-wide xy cell of ``pts``: what meets a surface first as
    the object is lowered."""
    keys = np.floor(pts[:, :2] / cell).astype(np.int64)
    order = np.lexsort((pts[:, 2], keys[:, 1], keys[:, 0]))
    k = keys[order]
    first = np.ones(len(k), bool)
    first[1:] = np.any(k[1:] != k[:-1], axis=1)
    out: np.ndarray = pts[order][first]
    return out


def long_axis(pts: np.ndarray) -> np.ndarray:
    """Unit xy direction of the object's longest horizontal extent (its footprint's principal axis)."""
    xy = pts[:, :2] - pts[:, :2].mean(axis=0)
    _, vecs = np.linalg.eigh(xy.T @ xy)
    axis: np.ndarray = vecs[:, -1]
    return axis


def release_poses(spot_list: list[np.ndarray], params: ReleaseParams = ReleaseParams(), limit: bool = True) -> list[tuple[np.ndarray, float, float]]:
    """(xy, hand yaw change, drop height) to try, in order: every yaw at the first spot, the
    other spots, then higher releases at the first spot (a tall object dropped from higher may
    tip: the last resort); at most ``params.max_poses`` with ``limit``."""
    first = params.drops[0]
    out = [(spot_list[0], yaw, first) for yaw in params.yaws]
    out += [(xy, yaw, first) for xy in spot_list[1:] for yaw in params.yaws[:3]]
    out += [(spot_list[0], yaw, drop) for drop in params.drops[1:] for yaw in params.yaws[:3]]
    return out[: params.max_poses] if limit else out
