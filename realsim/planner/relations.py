"""Spatial relations between objects, decided on their surface points and contacts.

One implementation serves the goal checks (:mod:`realsim.planner.goals`) and the robot's own
report after a place (:mod:`realsim.robot.robot`), so the two never contradict each other.
Every function takes world-frame surface samples (N x 3, metres) of the objects and, when the
simulation provides it, ``touching``: the owners of what the object is in contact with
("world" for static geometry such as the table, "robot", or another object's name). Without
contacts only the geometry decides. Each returns a :class:`Relation`: whether it holds and the
numbers that decided it.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from scipy.spatial import ConvexHull, QhullError, cKDTree

WORLD = "world"
ROBOT = "robot"
LEVEL_TOL = 0.03  # m: two objects stand on the same surface when their bottoms differ by less
HULL_TOL = 0.005  # m: a point this far outside a footprint still counts as over it


@dataclass(frozen=True)
class Relation:
    """Whether a relation holds, and the measured values behind the answer."""

    ok: bool
    measured: str

    def __post_init__(self) -> None:
        object.__setattr__(self, "ok", bool(self.ok))  # never a numpy bool


def _xy_hull(pts: np.ndarray) -> np.ndarray | None:
    """Hull equations (a, b, c) with a*x + b*y + c <= 0 inside, unit normals; None if degenerate."""
    try:
        return ConvexHull(pts[:, :2]).equations
    except (QhullError, ValueError):
        return None


def _over(points_xy: np.ndarray, hull: np.ndarray | None, tol: float = HULL_TOL) -> np.ndarray:
    """Which xy points lie over a footprint hull (within ``tol``)."""
    if hull is None:
        return np.zeros(len(points_xy), bool)
    return np.all(points_xy @ hull[:, :2].T + hull[:, 2] <= tol, axis=1)


def _base(pts: np.ndarray) -> np.ndarray:
    """The object's lowest band of points: what it stands on."""
    bottom, top = float(pts[:, 2].min()), float(pts[:, 2].max())
    return pts[pts[:, 2] <= bottom + max(0.005, min(0.02, 0.3 * (top - bottom)))]


def _centre(pts: np.ndarray) -> np.ndarray:
    return (pts.min(axis=0) + pts.max(axis=0)) / 2


def xy_gap(a: np.ndarray, b: np.ndarray, samples: int = 600) -> float:
    """Smallest horizontal distance between two point sets (0 when their footprints overlap)."""
    step_a, step_b = max(1, len(a) // samples), max(1, len(b) // samples)
    d, _ = cKDTree(b[::step_b, :2]).query(a[::step_a, :2])
    overlap = _over(a[::step_a, :2], _xy_hull(b), 0.0).any() or _over(b[::step_b, :2], _xy_hull(a), 0.0).any()
    return 0.0 if overlap else float(d.min())


def _contact_note(touching: set[str] | None) -> str:
    if touching is None:
        return ""
    return "; touching " + (", ".join(sorted(touching)) if touching else "nothing")


def inside(obj: np.ndarray, container: np.ndarray, touching: set[str] | None = None, container_name: str = "") -> Relation:
    """``obj`` rests in ``container``: its base lies over the container's footprint, its bottom is
    below the rim and above the container's bottom, and (with contacts) it rests on the container
    or on what lies in it, not on the table, and the hand has let go."""
    base = _base(obj)
    frac = float(_over(base[:, :2], _xy_hull(container)).mean())
    bottom = float(obj[:, 2].min())
    floor, rim = float(container[:, 2].min()), float(container[:, 2].max())
    ok = frac >= 0.9 and bottom < rim - 0.003 and bottom > floor - 0.005
    if touching is not None:
        ok = ok and WORLD not in touching and ROBOT not in touching and bool(touching)
    measured = (f"{frac:.0%} of its base over the container, bottom {bottom - floor:+.3f} m above the container's "
                f"bottom (rim at {rim - floor:.3f} m){_contact_note(touching)}")
    return Relation(ok, measured)


def on(obj: np.ndarray, support: np.ndarray, touching: set[str] | None = None, support_name: str = "", tolerance: float = 0.03) -> Relation:
    """``obj`` rests on top of ``support``: its centre over the support's footprint, its bottom at
    the support's top under it, and (with contacts) touching the support but not the table."""
    c = _centre(obj)
    over = bool(_over(c[None, :2], _xy_hull(support), 0.01)[0])
    lo, hi = obj[:, :2].min(axis=0) - 0.005, obj[:, :2].max(axis=0) + 0.005
    under = support[np.all((support[:, :2] >= lo) & (support[:, :2] <= hi), axis=1)]
    bottom = float(obj[:, 2].min())
    gap = bottom - float(under[:, 2].max()) if len(under) else np.inf
    ok = over and abs(gap) <= tolerance
    if touching is not None:
        ok = ok and support_name in touching and WORLD not in touching and ROBOT not in touching
    return Relation(ok, f"centre {'over' if over else 'not over'} the support, gap bottom-to-top {gap:+.3f} m "
                        f"(|gap| <= {tolerance:.3f}){_contact_note(touching)}")


def _level(obj: np.ndarray, ref: np.ndarray) -> float:
    return float(obj[:, 2].min() - ref[:, 2].min())


def next_to(obj: np.ndarray, ref: np.ndarray, touching: set[str] | None = None, max_gap: float = 0.10) -> Relation:
    """``obj`` stands beside ``ref`` on the same surface: horizontal gap at most ``max_gap``, not
    over it (on or in it), not held."""
    gap = xy_gap(obj, ref)
    dz = _level(obj, ref)
    c_over = bool(_over(_centre(obj)[None, :2], _xy_hull(ref), 0.0)[0])
    ok = gap <= max_gap and abs(dz) < LEVEL_TOL and not c_over
    if touching is not None:
        ok = ok and ROBOT not in touching
    return Relation(ok, f"gap {gap:.3f} m (<= {max_gap:.2f}), bottoms differ {dz:+.3f} m, centre "
                        f"{'over' if c_over else 'not over'} it{_contact_note(touching)}")


def side_of(obj: np.ndarray, ref: np.ndarray, direction: Sequence[float], touching: set[str] | None = None,
            max_gap: float = 0.15, side: str = "") -> Relation:
    """``obj`` lies on the ``direction`` side of ``ref`` (a world xy unit vector): past ``ref``'s
    extent along it (overlap up to 1 cm), roughly in line across it, within ``max_gap``, on
    the same surface."""
    d = np.asarray(direction, float)[:2]
    d = d / np.linalg.norm(d)
    perp = np.array([-d[1], d[0]])
    a_o, a_r = obj[:, :2] @ d, ref[:, :2] @ d
    p_o, p_r = obj[:, :2] @ perp, ref[:, :2] @ perp
    gap = float(a_o.min() - a_r.max())
    beyond = float((a_o.min() + a_o.max()) / 2 - a_r.max())
    lateral = abs(float((p_o.min() + p_o.max()) / 2 - (p_r.min() + p_r.max()) / 2))
    allowed = float(np.ptp(p_r) / 2 + np.ptp(p_o) / 2) + 0.02
    dz = _level(obj, ref)
    ok = gap >= -0.01 and beyond > 0 and gap <= max_gap and lateral <= allowed and abs(dz) < LEVEL_TOL
    if touching is not None:
        ok = ok and ROBOT not in touching
    return Relation(ok, f"{side + ' ' if side else ''}gap {gap:+.3f} m (-0.01 to {max_gap:.2f}), off the line "
                        f"{lateral:.3f} m (<= {allowed:.3f}), bottoms differ {dz:+.3f} m{_contact_note(touching)}")


def between(obj: np.ndarray, a: np.ndarray, b: np.ndarray, touching: set[str] | None = None) -> Relation:
    """``obj`` lies between ``a`` and ``b``: its centre between their facing sides along the line
    joining them, and near that line."""
    ca, cb, c = _centre(a)[:2], _centre(b)[:2], _centre(obj)[:2]
    u = cb - ca
    length = float(np.linalg.norm(u))
    if length < 1e-6:
        return Relation(False, "the two references are at the same place")
    u /= length
    perp = np.array([-u[1], u[0]])
    t = float((c - ca) @ u)
    a_edge, b_edge = float(((a[:, :2] - ca) @ u).max()), float(((b[:, :2] - ca) @ u).min())
    lateral = abs(float((c - ca) @ perp))
    allowed = 0.5 * min(np.ptp(a[:, :2] @ perp), np.ptp(b[:, :2] @ perp)) + 0.04
    dz = min(abs(_level(obj, a)), abs(_level(obj, b)))
    ok = a_edge - 0.01 <= t <= b_edge + 0.01 and lateral <= allowed and dz < LEVEL_TOL
    if touching is not None:
        ok = ok and ROBOT not in touching
    return Relation(ok, f"centre {t:.3f} m along the line (between {a_edge:.3f} and {b_edge:.3f}), {lateral:.3f} m off it "
                        f"(<= {allowed:.3f}){_contact_note(touching)}")


def moved_tolerance(distance: float) -> tuple[float, float]:
    """How far a move of ``distance`` m may end off it: (along the direction, sideways), m."""
    return max(0.02, 0.4 * distance), max(0.03, 0.5 * distance)


def moved(start: Sequence[float], end: Sequence[float], direction: Sequence[float], distance: float) -> Relation:
    """An object moved about ``distance`` m along the world xy unit vector ``direction``: within
    max(2 cm, 40 %) along it and at most max(3 cm, half the distance) sideways."""
    ux, uy = float(direction[0]), float(direction[1])
    dx, dy = float(end[0]) - float(start[0]), float(end[1]) - float(start[1])
    along, across = dx * ux + dy * uy, abs(-dx * uy + dy * ux)
    tol, sideways = moved_tolerance(distance)
    ok = abs(along - distance) <= tol and across <= sideways
    return Relation(ok, f"moved {along:.3f} m along (target {distance:.3f} +- {tol:.3f}), {across:.3f} m sideways")


def box_points(centre: Sequence[float], size: Sequence[float], n: int = 5) -> np.ndarray:
    """Surface samples of an axis-aligned box: the geometry of an object known only by its extents."""
    g = np.linspace(-0.5, 0.5, n)
    grid = np.array(np.meshgrid(g, g, g, indexing="ij")).reshape(3, -1).T
    shell = grid[np.any(np.abs(grid) == 0.5, axis=1)]
    return np.asarray(centre, float) + shell * np.asarray(size, float)
