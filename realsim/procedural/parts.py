"""Shapes made of known convex pieces: a smooth CSG solid for looks, the pieces for collision.

A :class:`Shape` holds a watertight manifold3d solid (the visual mesh and the mass properties)
and the convex point sets it is made of (the collision hulls: no decomposition needed, cavities
stay open by construction), plus named sites (``handle``, ``rim``, ``lid``, ``hinge``, ...) in
the object frame. Builders here are the primitives the families in
:mod:`realsim.procedural.shapes` are assembled from.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import trimesh
from manifold3d import CrossSection, Manifold, OpType
from scipy.spatial.transform import Rotation

SEGMENTS = 48  # circular resolution of the visual solid
WEDGES = 16  # angular pieces of a revolved wall (chord error 2 % of the radius)
Site = tuple[float, float, float]
D = tuple[float, float, float]  # an object's extents, largest first (what every family is a function of)


@dataclass
class Shape:
    """A solid, its convex pieces (point arrays) and named sites, all in one frame."""

    solid: Manifold
    hulls: list[np.ndarray]
    sites: dict[str, Site] = field(default_factory=dict)

    def __add__(self, other: Shape) -> Shape:
        return Shape(self.solid + other.solid, self.hulls + other.hulls, {**self.sites, **other.sites})

    def transformed(self, rot: np.ndarray, shift: np.ndarray) -> Shape:
        """``rot @ p + shift`` applied to the solid, the pieces and the sites."""
        m = np.hstack([rot, np.asarray(shift, float).reshape(3, 1)])
        return Shape(self.solid.transform(m), [h @ rot.T + shift for h in self.hulls],
                     {k: tuple(float(v) for v in rot @ np.asarray(p) + shift) for k, p in self.sites.items()})  # type: ignore[misc]

    def moved(self, x: float = 0.0, y: float = 0.0, z: float = 0.0) -> Shape:
        return self.transformed(np.eye(3), np.array([x, y, z]))

    def rotated(self, euler_deg: tuple[float, float, float], order: str = "xyz") -> Shape:
        return self.transformed(Rotation.from_euler(order, euler_deg, degrees=True).as_matrix(), np.zeros(3))

    def with_sites(self, **sites: Site) -> Shape:
        return Shape(self.solid, self.hulls, {**self.sites, **{k: tuple(float(v) for v in p) for k, p in sites.items()}})  # type: ignore[misc]

    def minus(self, cut: Manifold) -> Shape:
        """A visual-only cut (slots, engraving): the collision pieces are kept."""
        return Shape(self.solid - cut, self.hulls, self.sites)


def to_trimesh(m: Manifold) -> trimesh.Trimesh:
    """A manifold as a trimesh."""
    mesh = m.to_mesh()
    verts = np.asarray(mesh.vert_properties, dtype=np.float64)[:, :3]
    faces = np.asarray(mesh.tri_verts, dtype=np.int64)
    return trimesh.Trimesh(verts, faces, process=False)


def hull_shape(points: np.ndarray) -> Shape:
    """The convex hull of ``points`` as a one-piece shape."""
    pts = np.asarray(points, dtype=np.float64)
    return Shape(Manifold.hull_points(pts), [pts])


def union(*shapes: Shape) -> Shape:
    out = shapes[0]
    for s in shapes[1:]:
        out = out + s
    return out


def box(x: float, y: float, z: float, at: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> Shape:
    """An axis-aligned box with its base centred at ``at``."""
    c = np.array([[sx * x / 2, sy * y / 2, sz * z] for sx in (-1, 1) for sy in (-1, 1) for sz in (0, 1)]) + np.asarray(at)
    return hull_shape(c)


def _ring(r: float, z: float, n: int, phase: float = 0.0) -> np.ndarray:
    t = np.linspace(0.0, 2 * np.pi, n, endpoint=False) + phase
    return np.column_stack([r * np.cos(t), r * np.sin(t), np.full(n, z)])


def cylinder(h: float, r: float, r_top: float | None = None, sides: int = 24) -> Shape:
    """A (truncated) cone or cylinder along +z from z = 0; ``sides`` < 12 gives a prism."""
    r_top = r if r_top is None else r_top
    pts = np.vstack([_ring(r, 0.0, sides), _ring(r_top, h, sides)])
    if sides >= 12:
        return Shape(Manifold.cylinder(h, r, r_top, SEGMENTS), [pts])
    return hull_shape(pts)


def ellipsoid(rx: float, ry: float, rz: float, n: int = 96) -> Shape:
    """An ellipsoid centred at the origin."""
    i = np.arange(n) + 0.5
    phi, theta = np.arccos(1 - 2 * i / n), np.pi * (1 + 5 ** 0.5) * i
    pts = np.column_stack([np.cos(theta) * np.sin(phi), np.sin(theta) * np.sin(phi), np.cos(phi)]) * [rx, ry, rz]
    pts = np.vstack([pts, [[0, 0, rz], [0, 0, -rz]]])
    return Shape(Manifold.sphere(1.0, SEGMENTS).scale([rx, ry, rz]), [pts])


def tube(path: np.ndarray, radius: float | np.ndarray, sides: int = 8, phase: bool = False) -> Shape:
    """A chain of convex pieces along a 3-D polyline (handles, spouts, bananas, arches).

    With ``phase`` a horizontal tube lies on a flat face of its polygonal section (no rolling)."""
    path = np.asarray(path, dtype=np.float64)
    radii = np.broadcast_to(np.asarray(radius, dtype=np.float64), (len(path),))
    sections = []
    for i, p in enumerate(path):
        d = path[min(i + 1, len(path) - 1)] - path[max(i - 1, 0)]
        d /= np.linalg.norm(d)
        a = np.cross(d, [0.0, 0.0, 1.0]) if abs(d[2]) < 0.9 else np.cross(d, [1.0, 0.0, 0.0])
        a /= np.linalg.norm(a)
        b = np.cross(d, a)
        t = np.linspace(0.0, 2 * np.pi, sides, endpoint=False) + ((np.pi / 2 - np.pi / sides) % (2 * np.pi / sides) if phase else 0.0)
        sections.append(p + radii[i] * (np.outer(np.cos(t), a) + np.outer(np.sin(t), b)))
    # consecutive pieces overlap by 0.5 mm so their union is one connected solid
    pieces = []
    for i in range(len(path) - 1):
        d = path[i + 1] - path[i]
        d = 0.0005 * d / max(np.linalg.norm(d), 1e-9)
        pieces.append(np.vstack([sections[i] - (d if i > 0 else 0.0), sections[i + 1] + (d if i < len(path) - 2 else 0.0)]))
    return Shape(pieces_solid(pieces), pieces)


def pieces_solid(pieces: list[np.ndarray]) -> Manifold:
    """The union of the convex hulls of ``pieces``."""
    return Manifold.batch_boolean([Manifold.hull_points(p) for p in pieces], OpType.Add)


def arc(center: tuple[float, float, float], radius: float, start_deg: float, end_deg: float, plane: str = "xz", n: int = 7) -> np.ndarray:
    """Points on a circular arc in the ``xz`` or ``yz`` plane through ``center``."""
    t = np.radians(np.linspace(start_deg, end_deg, n))
    c = np.asarray(center, dtype=np.float64)
    u, v = (np.array([1.0, 0, 0]), np.array([0, 0, 1.0])) if plane == "xz" else (np.array([0, 1.0, 0]), np.array([0, 0, 1.0]))
    return c + radius * (np.outer(np.cos(t), u) + np.outer(np.sin(t), v))


def vessel(outer: list[tuple[float, float]], wall: float, bottom: float, segments: int = 2, wedges: int = WEDGES,
           closed_top: float = 0.0) -> Shape:
    """A revolved container: ``outer`` (r, z) from the foot (z = 0) up to the rim, monotonic in z.

    The wall is ``wall`` thick (measured across), the floor ``bottom`` thick. Collision pieces: a
    floor disc and ``segments`` x ``wedges`` wall wedges, so the cavity stays open. With
    ``closed_top`` > 0 a lid of that thickness closes it (a teapot, a kettle). Sites: ``rim``
    (on the rim, +y side) and ``cavity`` (centre of the floor).
    """
    prof = np.asarray(outer, dtype=np.float64)
    h = float(prof[-1, 1])
    inner = [(max(r - wall, 0.002), z) for r, z in prof if z >= bottom]
    r_at = lambda z: float(np.interp(z, prof[:, 1], prof[:, 0]))  # noqa: E731
    if not inner or inner[0][1] > bottom:
        inner.insert(0, (max(r_at(bottom) - wall, 0.002), bottom))
    poly = [(0.0, 0.0), *map(tuple, prof), *reversed(inner), (0.0, bottom)]
    solid = CrossSection([np.asarray(poly)]).revolve(SEGMENTS)
    levels = np.linspace(bottom, h, segments + 1)  # walls stand on the floor disc: only the disc touches the table
    pieces = [np.vstack([_ring(r_at(0.0), 0.0, 24), _ring(r_at(bottom), bottom, 24)])]
    step = 2 * np.pi / wedges
    for z0, z1 in zip(levels[:-1], levels[1:]):
        for k in range(wedges):
            a0, a1 = k * step, (k + 1) * step
            pts = []
            for z in (z0, z1):
                for r in (r_at(z), max(r_at(z) - wall, 0.001)):
                    for a in (a0, a1):
                        pts.append([r * np.cos(a), r * np.sin(a), z])
            pieces.append(np.asarray(pts))
    rim_r = r_at(h) - wall / 2
    shape = Shape(solid, pieces, {"rim": (0.0, rim_r, h), "cavity": (0.0, 0.0, bottom)})
    if closed_top > 0:
        lid = cylinder(closed_top + 0.001, r_at(h), r_at(h) * 0.98).moved(z=h - 0.001)  # overlapping the wall: one solid
        shape = Shape(shape.solid + lid.solid, shape.hulls + lid.hulls, {"lid": (0.0, 0.0, h + closed_top)})
    return shape


def open_box(x: float, y: float, z: float, wall: float, bottom: float | None = None, taper: float = 1.0) -> Shape:
    """An open rectangular container (tray, crate, basket, bin, drawer): a floor and four walls,
    wider at the top by ``1 / taper``. Sites: ``rim`` (the middle of the +y wall's top) and ``cavity``."""
    bottom = wall if bottom is None else bottom
    bx, by = x * taper, y * taper
    lerp = lambda z_: (bx + (x - bx) * z_ / z, by + (y - by) * z_ / z)  # noqa: E731

    def slab(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> np.ndarray:
        pts = []
        for zz in (z0, z1):
            wx, wy = lerp(zz)
            for fx in (x0, x1):
                for fy in (y0, y1):
                    # each wall follows the taper: fractions of the current outer half-extent
                    pts.append([fx * wx / 2, fy * wy / 2, zz])
        return np.asarray(pts)

    fx, fy = 1 - 2 * wall / x, 1 - 2 * wall / y
    pieces = [slab(-1, 1, -1, 1, 0.0, bottom),  # the walls stand on the floor slab: only it touches the table
              slab(-1, -fx, -1, 1, bottom, z), slab(fx, 1, -1, 1, bottom, z),
              slab(-fx, fx, -1, -fy, bottom, z), slab(-fx, fx, fy, 1, bottom, z)]
    return Shape(pieces_solid(pieces), pieces, {"rim": (0.0, y / 2 - wall / 2, z), "cavity": (0.0, 0.0, bottom)})


def rounded_slab(x: float, y: float, z: float, corner: float) -> Shape:
    """A flat slab with rounded corners (cutting board, tablet)."""
    corner = min(corner, x / 2 - 1e-4, y / 2 - 1e-4)
    pts = []
    for sx in (-1, 1):
        for sy in (-1, 1):
            c = np.array([sx * (x / 2 - corner), sy * (y / 2 - corner)])
            for t in np.linspace(0, np.pi / 2, 5):
                d = np.array([sx * np.cos(t), sy * np.sin(t)]) * corner
                pts += [[*(c + d), 0.0], [*(c + d), z]]
    return hull_shape(np.asarray(pts))
