"""Constructive solid geometry (manifold3d) of everyday objects, in the object frame.

Every builder returns a watertight :class:`trimesh.Trimesh` in metres, Z up, the base centred at
the origin (the convention of :mod:`realsim.assets`). Hollow objects (mug, cup, bowl, tray, bin,
drawer) have real cavities, so the convex decomposition keeps them open.
"""

from __future__ import annotations

import numpy as np
import trimesh
from manifold3d import CrossSection, Manifold

SEGMENTS = 48  # circular resolution: enough for smooth rims, few faces for CoACD


def to_trimesh(m: Manifold) -> trimesh.Trimesh:
    """A manifold as a trimesh (base centred at the origin is the caller's job)."""
    mesh = m.to_mesh()
    verts = np.asarray(mesh.vert_properties, dtype=np.float64)[:, :3]
    faces = np.asarray(mesh.tri_verts, dtype=np.int64)
    return trimesh.Trimesh(verts, faces, process=True)


def _revolve(profile: list[tuple[float, float]]) -> Manifold:
    """Revolve an (r, z) polygon (r >= 0, counter-clockwise) around Z."""
    return CrossSection([np.asarray(profile, dtype=np.float64)]).revolve(SEGMENTS)


def _box(x: float, y: float, z: float) -> Manifold:
    """A box with its base centred at the origin."""
    return Manifold.cube([x, y, z], center=True).translate([0.0, 0.0, z / 2])


def _torus(major: float, minor: float) -> Manifold:
    """A torus around Z, centred at the origin."""
    return CrossSection.circle(minor, 16).translate([major, 0.0]).revolve(SEGMENTS)


def mug(height: float, diameter: float, wall: float = 0.005) -> Manifold:
    """A hollow cylindrical mug with a thick bottom and a ring handle on +x."""
    r = diameter / 2
    body = Manifold.cylinder(height, r, r, SEGMENTS)
    hr = height * 0.28  # handle ring radius (centre line)
    ht = max(wall * 1.2, 0.006)  # handle thickness
    handle = _torus(hr, ht / 2).rotate([90.0, 0.0, 0.0]).translate([r, 0.0, height * 0.52])
    handle = handle - Manifold.cylinder(height, r - wall / 2, r - wall / 2, SEGMENTS)  # no handle inside
    cavity = Manifold.cylinder(height, r - wall, r - wall, SEGMENTS).translate([0.0, 0.0, max(wall * 1.6, 0.008)])
    return (body + handle) - cavity


def cup(height: float, diameter: float, wall: float = 0.004) -> Manifold:
    """A tapered open cup (tumbler): narrower base, open top."""
    r_top, r_bot = diameter / 2, diameter / 2 * 0.78
    base = max(wall * 1.5, 0.006)
    profile = [(0.0, 0.0), (r_bot, 0.0), (r_top, height), (r_top - wall, height), (r_bot - wall + (r_top - r_bot) * base / height, base), (0.0, base)]
    return _revolve(profile)


def bowl(height: float, diameter: float, wall: float = 0.004) -> Manifold:
    """A bowl: a foot ring and a curved wall rising to a wide open rim."""
    R = diameter / 2
    foot = R * 0.45
    n = 10
    outer = [(foot + (R - foot) * np.sin(t * np.pi / 2), height * (1 - np.cos(t * np.pi / 2))) for t in np.linspace(0, 1, n)]
    bottom = max(wall * 1.5, 0.005)
    inner_foot = foot - wall
    inner = [(inner_foot + (R - wall - inner_foot) * np.sin(t * np.pi / 2), bottom + (height - bottom) * (1 - np.cos(t * np.pi / 2))) for t in np.linspace(1, 0, n)]
    profile = [(0.0, 0.0), *outer, *inner, (0.0, bottom)]
    return _revolve(profile)


def plate(height: float, diameter: float) -> Manifold:
    """A plate: a flat well and a raised, sloped rim."""
    R = diameter / 2
    well = R * 0.62
    floor = max(height * 0.35, 0.004)
    profile = [(0.0, 0.0), (well * 0.8, 0.0), (R, height * 0.7), (R, height), (R - 0.006, height), (well, floor), (0.0, floor)]
    return _revolve(profile)


def bottle(height: float, diameter: float) -> Manifold:
    """A closed bottle: body, rounded shoulder, neck and cap (a closed container)."""
    r = diameter / 2
    neck_r = max(r * 0.32, 0.009)
    body_h = height * 0.62
    shoulder_h = height * 0.2
    n = 8
    shoulder = [(neck_r + (r - neck_r) * np.cos(t * np.pi / 2), body_h + shoulder_h * np.sin(t * np.pi / 2)) for t in np.linspace(0, 1, n)]
    profile = [(0.0, 0.0), (r * 0.92, 0.0), (r, 0.006), *shoulder, (neck_r, height * 0.93), (neck_r * 1.15, height * 0.93), (neck_r * 1.15, height), (0.0, height)]
    return _revolve(profile)


def can(height: float, diameter: float) -> Manifold:
    """A beverage/food can: a cylinder with a narrower base chime and a top rim."""
    r = diameter / 2
    profile = [(0.0, 0.0), (r * 0.85, 0.0), (r, height * 0.08), (r, height * 0.92), (r * 0.9, height * 0.985), (r * 0.88, height), (0.0, height)]
    return _revolve(profile)


def jar(height: float, diameter: float) -> Manifold:
    """A jar with a slightly wider screw lid."""
    r = diameter / 2
    body = Manifold.cylinder(height * 0.82, r, r, SEGMENTS)
    neck = Manifold.cylinder(height * 0.06, r * 0.85, r * 0.85, SEGMENTS).translate([0.0, 0.0, height * 0.82])
    lid = Manifold.cylinder(height * 0.12, r * 0.9, r * 0.9, SEGMENTS).translate([0.0, 0.0, height * 0.88])
    return body + neck + lid


def box(x: float, y: float, z: float) -> Manifold:
    """A closed rectangular box (cereal box, carton)."""
    return _box(x, y, z)


def book(x: float, y: float, z: float) -> Manifold:
    """A closed book lying flat: covers slightly larger than the page block (fore-edge inset)."""
    cover = min(0.003, z * 0.15)
    pages = _box(x - 0.004, y - 0.002, z - 2 * cover).translate([0.002, 0.0, cover])
    bottom = _box(x, y, cover)
    top = _box(x, y, cover).translate([0.0, 0.0, z - cover])
    spine = _box(cover, y, z).translate([-x / 2 + cover / 2, 0.0, 0.0])
    return bottom + top + spine + pages


def tray(x: float, y: float, z: float, wall: float = 0.006) -> Manifold:
    """An open rectangular tray."""
    return _box(x, y, z) - _box(x - 2 * wall, y - 2 * wall, z).translate([0.0, 0.0, wall])


def bin_(x: float, y: float, z: float, wall: float = 0.005) -> Manifold:
    """An open bin, wider at the top."""
    taper = 0.85
    outer = CrossSection.square([x * taper, y * taper], center=True).extrude(z, scale_top=(1 / taper, 1 / taper))
    inner = CrossSection.square([x * taper - 2 * wall, y * taper - 2 * wall], center=True).extrude(z, scale_top=((x - 2 * wall) / (x * taper - 2 * wall), (y - 2 * wall) / (y * taper - 2 * wall)))
    return outer - inner.translate([0.0, 0.0, wall])


def cylinder(height: float, diameter: float) -> Manifold:
    """A plain closed cylinder (fallback primitive)."""
    return Manifold.cylinder(height, diameter / 2, diameter / 2, SEGMENTS)


def drawer_cabinet(x: float, y: float, z: float, wall: float = 0.012) -> tuple[Manifold, Manifold, dict]:
    """A cabinet carcass open at the front (+x) and a drawer that fits it.

    Returns (carcass, drawer, info) with the drawer in the carcass frame (closed position) and
    ``info`` holding the slide axis, the travel, the drawer's base offset and its handle's centre.
    """
    carcass = _box(x, y, z) - _box(x, y - 2 * wall, z - 2 * wall).translate([wall, 0.0, wall])
    gap = 0.003
    dx, dy, dz = x - wall - gap, y - 2 * wall - 2 * gap, z - 2 * wall - 2 * gap
    front = wall
    tray_ = _box(dx, dy, dz) - _box(dx - 2 * wall, dy - 2 * wall, dz).translate([0.0, 0.0, wall])
    panel = _box(front, y - 0.004, z - 0.004).translate([dx / 2 + front / 2, 0.0, -wall - gap + 0.002])
    handle_w, handle_h = min(0.10, dy * 0.5), 0.018
    handle = _box(0.025, handle_w, handle_h).translate([dx / 2 + front + 0.0125, 0.0, dz / 2 - handle_h / 2])
    drawer = tray_ + panel + handle
    # The drawer's own frame has its origin at the base centre of its tray (the panel reaches below
    # it); in the carcass frame that point is at ``offset`` when the drawer is closed.
    offset = [round(x / 2 - dx / 2, 6), 0.0, wall + gap]
    handle_centre = [dx / 2 + front + 0.0125, 0.0, dz / 2]  # in the drawer's (shape) frame
    info = {"axis": [1.0, 0.0, 0.0], "range": [0.0, round(0.75 * dx, 4)], "offset": offset, "handle": handle_centre}
    return carcass, drawer, info


def hinged_box(x: float, y: float, z: float, wall: float = 0.006) -> tuple[Manifold, Manifold, dict]:
    """An open box and its lid, hinged along the back (-x) top edge."""
    lid_t = max(wall, 0.008)
    base_h = z - lid_t
    base = _box(x, y, base_h) - _box(x - 2 * wall, y - 2 * wall, base_h).translate([0.0, 0.0, wall])
    lid = _box(x, y, lid_t)
    info = {"axis": [0.0, -1.0, 0.0], "range": [0.0, 1.9], "offset": [0.0, 0.0, base_h + 0.001], "hinge_pos": [-x / 2, 0.0, 0.0]}
    return base, lid, info
