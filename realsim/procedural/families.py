"""Families of everyday objects built from convex pieces (:mod:`realsim.procedural.parts`).

Every family is a function of the object's extents ``d`` (largest first, from the size table,
already scaled) returning a :class:`~realsim.procedural.parts.Shape` in the object frame (Z up;
the caller moves the base centre to the origin) with named sites where a hand or a program
needs them: ``handle`` (and ``handle_2``), ``rim`` and ``cavity`` of open containers, ``lid``,
``spout``, ``stem``, ``hinge``. Articulated families (drawer cabinet, hinged box, laptop) return
an :class:`Articulated` with the parent, the child and the joint.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import numpy as np
from manifold3d import Manifold

from realsim.procedural.parts import D, Shape, arc, box, cylinder, ellipsoid, hull_shape, open_box, rounded_slab, tube, union, vessel
from realsim.procedural.utensils import fork, hammer, knife, screwdriver, spoon, wrench


@dataclass
class Articulated:
    """A parent, a child hanging on it (closed pose, parent frame) and the joint between them."""

    parent: Shape
    child: Shape
    joint: str  # "slide" | "hinge"
    axis: tuple[float, float, float]
    range: tuple[float, float]
    hinge_pos: tuple[float, float, float] = (0.0, 0.0, 0.0)  # joint anchor, parent frame
    child_sites: dict[str, tuple[float, float, float]] = field(default_factory=dict)


# ---------------------------------------------------------------- open containers and tableware
def mug(d: D) -> Shape:
    """A mug sized by the table's (height, diameter): see :func:`mug_hd`."""
    return mug_hd(d[1], d[1] * 0.9)


def mug_hd(h: float, dia: float) -> Shape:
    """A mug of height ``h`` and body diameter ``dia``: a cylindrical vessel, a ring handle on +x."""
    r = dia / 2
    body = vessel([(r, 0.0), (r, h)], wall=0.005, bottom=0.008, segments=1)
    hr = h * 0.28
    path = arc((r - 0.002, 0.0, h * 0.52), hr, -75, 75, "xz", 7)
    path = np.vstack([[r - 0.004, 0.0, path[0, 2]], path, [r - 0.004, 0.0, path[-1, 2]]])  # ends inside the wall
    handle = tube(path, max(0.0045, h * 0.04), 8)
    return (body + handle).with_sites(handle=(r + hr, 0.0, h * 0.52))


def cup(d: D) -> Shape:
    """A cup: a tapered open vessel, thin wall, no handle."""
    h, r = d[0], d[1] / 2
    return vessel([(r * 0.78, 0.0), (r, h)], wall=0.004, bottom=0.006, segments=2)


def glass(d: D) -> Shape:
    """A drinking glass: a nearly straight open vessel with a thick bottom."""
    h, r = d[0], d[1] / 2
    return vessel([(r * 0.9, 0.0), (r, h)], wall=0.003, bottom=0.008, segments=2)


def bowl(d: D) -> Shape:
    """A bowl of the table's diameter and height: see :func:`bowl_hd`."""
    return bowl_hd(d[2], d[0])


def bowl_hd(h: float, dia: float) -> Shape:
    """A bowl: a foot and a curved wall rising to a wide rim."""
    R = dia / 2
    foot = R * 0.5
    t = np.linspace(0.0, 1.0, 6)
    outer = [(foot + (R - foot) * np.sin(v * np.pi / 2), h * (1 - np.cos(v * np.pi / 2))) for v in t]
    return vessel(outer, wall=0.004, bottom=0.005, segments=2)


def plate(d: D) -> Shape:
    """A plate: a low dish, a foot and a flared rim (at least 15 mm high)."""
    R, h = d[0] / 2, max(d[2], 0.015)
    return vessel([(R * 0.55, 0.0), (R * 0.65, h * 0.35), (R, h)], wall=0.005, bottom=0.005, segments=1)


def vase(d: D) -> Shape:
    """Vase, flower pot, bucket: a tapered open vessel."""
    h, r = d[0], d[1] / 2
    return vessel([(r * 0.75, 0.0), (r, h)], wall=0.006, bottom=0.01, segments=2)


def pan(d: D) -> Shape:
    """A frying pan: a shallow vessel and a long handle on +x at rim height."""
    r, h = d[1] / 2, max(d[2], 0.03)
    body = vessel([(r * 0.85, 0.0), (r, h)], wall=0.004, bottom=0.005, segments=1)
    length = max(d[0] - d[1], 0.08)
    path = np.array([[r - 0.004, 0.0, h * 0.8], [r + length * 0.4, 0.0, h * 0.95], [r + length, 0.0, h * 1.05]])
    handle = tube(path, [0.009, 0.008, 0.009], 6)
    return (body + handle).with_sites(handle=(r + length * 0.7, 0.0, h))


def pot(d: D) -> Shape:
    """A cooking pot: a deep vessel with two loop handles (+x and -x)."""
    r, h = d[1] / 2, d[2]
    body = vessel([(r, 0.0), (r, h)], wall=0.002, bottom=0.005, segments=2)
    loops = []
    zh = h - 0.045  # the loops sit below the rim, leaving the rim free for a pinch
    for sign in (1, -1):
        path = arc((0.0, 0.0, 0.0), 0.02, -60, 60, "xz", 5)
        path = np.vstack([[-0.02, 0.0, path[0, 2]], path, [-0.02, 0.0, path[-1, 2]]])  # ends inside the wall
        path = np.column_stack([sign * (r - 0.002 + path[:, 0]), path[:, 1], zh + path[:, 2]])
        loops.append(tube(path, 0.005, 6))
    return union(body, *loops).with_sites(handle=(r + 0.02, 0.0, zh), handle_2=(-r - 0.02, 0.0, zh))


def kettle(d: D) -> Shape:
    """A kettle: a closed tapered body with a lid, an arched handle over the top and a spout."""
    h, r = d[0] * 0.75, d[2] / 2 * 1.1
    body = vessel([(r, 0.0), (r * 0.75, h)], wall=0.003, bottom=0.006, segments=1, closed_top=0.01)
    knob = cylinder(0.015, 0.012).moved(z=h + 0.008)
    path = arc((0.0, 0.0, h * 0.7), r * 0.8, 10, 170, "xz", 9)
    top = h + 0.045  # the arch clears the lid knob: fingers close around it from above
    path[:, 2] = h * 0.7 + (path[:, 2] - h * 0.7) * (top - h * 0.7) / (r * 0.8)
    handle = tube(path, 0.009, 8)
    spout = tube(np.array([[r * 0.85, 0.0, h * 0.25], [r * 1.2, 0.0, h * 0.55], [r * 1.35, 0.0, h * 0.7]]), [0.014, 0.01, 0.008], 8)
    return union(body, knob, handle, spout).with_sites(handle=(0.0, 0.0, top), lid=(0.0, 0.0, h + 0.025), spout=(r * 1.35, 0.0, h * 0.7))


def teapot(d: D) -> Shape:
    """A teapot: a bulbous closed body with a lid knob, a spout (+x) and a loop handle (-x)."""
    R, h = d[1] / 2, d[1] * 0.8
    t = np.linspace(0.0, 1.0, 7)
    outer = [(R * (0.65 + 0.35 * np.sin(v * np.pi)), h * v) for v in t]
    outer[-1] = (R * 0.55, h)
    body = vessel(outer, wall=0.005, bottom=0.006, segments=2, closed_top=0.008)
    knob = cylinder(0.02, 0.012, 0.006).moved(z=h + 0.006)
    reach = max(d[0] / 2 - R, 0.03)
    spout = tube(np.array([[R * 0.8, 0.0, h * 0.3], [R + reach * 0.5, 0.0, h * 0.55], [R + reach, 0.0, h * 0.85]]), [0.013, 0.009, 0.006], 8)
    loop = arc((-R * 0.9, 0.0, h * 0.5), h * 0.28, 100, 260, "xz", 7)
    loop = np.vstack([[-R * 0.6, 0.0, loop[0, 2]], loop, [-R * 0.6, 0.0, loop[-1, 2]]])  # ends inside the body
    handle = tube(loop, 0.006, 8)
    return union(body, knob, spout, handle).with_sites(handle=(-R * 0.9 - h * 0.28, 0.0, h * 0.5), lid=(0.0, 0.0, h + 0.028),
                                                       spout=(R + reach, 0.0, h * 0.85))


def tray(d: D) -> Shape:
    """A tray: a shallow open box (at least 30 mm high) with a handle site on its +x rim."""
    return open_box(d[0], d[1], max(d[2], 0.03), wall=0.006).with_sites(handle=(d[0] / 2 - 0.003, 0.0, max(d[2], 0.03)))


def basket(d: D) -> Shape:
    """A woven-look basket: tapered open box, slots cut in the visual walls only."""
    x, y, z = d[0], d[1], d[2]
    shape = open_box(x, y, z, wall=0.006, taper=0.88)
    slots = [Manifold.cube([0.012, y * 1.2, z * 0.18], center=True).translate([sx, 0.0, z * 0.55]) for sx in np.linspace(-x * 0.3, x * 0.3, 5)]
    cut = slots[0]
    for s in slots[1:]:
        cut = cut + s
    return shape.minus(cut)


def crate(d: D) -> Shape:
    """A crate: a thick-walled open box with hand holes in the short (x) walls."""
    x, y, z = d[0], d[1], d[2]
    shape = open_box(x, y, z, wall=0.012, bottom=0.012)
    hole = Manifold.cube([x * 1.2, min(0.09, y * 0.4), 0.03], center=True).translate([0.0, 0.0, z - 0.035])
    return shape.minus(hole).with_sites(handle=(x / 2 - 0.006, 0.0, z - 0.035), handle_2=(-x / 2 + 0.006, 0.0, z - 0.035))


def bin_(d: D) -> Shape:
    """A bin (trash bin, tall storage bin): a tall tapered open box."""
    return open_box(d[1], d[2], d[0], wall=0.005, bottom=0.015, taper=0.85)


# ---------------------------------------------------------------- closed containers and solids
def bottle(d: D) -> Shape:
    """A bottle: a round body, a shoulder and a narrow neck (a lid site on top)."""
    h, r = d[0], d[1] / 2
    neck = max(r * 0.32, 0.009)
    body_h, shoulder_h = h * 0.62, h * 0.2
    t = np.linspace(0.0, 1.0, 6)
    rings = [(r, 0.0), (r, body_h)] + [(neck + (r - neck) * np.cos(v * np.pi / 2), body_h + shoulder_h * np.sin(v * np.pi / 2)) for v in t[1:]]
    lower = np.vstack([_ring_pts(rr, z) for rr, z in rings])
    upper = np.vstack([_ring_pts(neck, body_h + shoulder_h), _ring_pts(neck, h * 0.93), _ring_pts(neck * 1.15, h * 0.93), _ring_pts(neck * 1.15, h)])
    return union(hull_shape(lower), hull_shape(upper)).with_sites(lid=(0.0, 0.0, h))


def _ring_pts(r: float, z: float, n: int = 20) -> np.ndarray:
    t = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    return np.column_stack([r * np.cos(t), r * np.sin(t), np.full(n, z)])


def can(d: D) -> Shape:
    """A can: a cylinder with rolled-in top and bottom rims (a lid site on top)."""
    h, r = d[0], d[1] / 2
    pts = np.vstack([_ring_pts(r * 0.88, 0.0), _ring_pts(r, h * 0.06), _ring_pts(r, h * 0.94), _ring_pts(r * 0.9, h)])
    return hull_shape(pts).with_sites(lid=(0.0, 0.0, h))


def jar(d: D) -> Shape:
    """A jar: a cylinder under a slightly narrower lid band (a lid site on top)."""
    h, r = d[0], d[1] / 2
    return union(cylinder(h * 0.86, r), cylinder(h * 0.14, r * 0.9).moved(z=h * 0.86)).with_sites(lid=(0.0, 0.0, h))


def cylinder_(d: D) -> Shape:
    """A plain upright cylinder (candle, tube)."""
    return cylinder(d[0], d[1] / 2)


def box_(d: D) -> Shape:
    """A closed box lying on its largest face (phone, remote, soap, block)."""
    return box(d[0], d[1], d[2])


def upright_box(d: D) -> Shape:
    """A closed box standing on its smallest face's long edge (cereal box, carton)."""
    return box(d[1], d[2], d[0])


def book(d: D) -> Shape:
    """A closed book lying flat, the pages' fore-edge inset a little (visual only)."""
    x, y, z = d[0], d[1], d[2]
    cover = min(0.003, z * 0.15)
    shape = box(x, y, z)
    pages = Manifold.cube([0.01, y - 0.004, z - 2 * cover], center=True).translate([x / 2, 0.0, z / 2])  # fore-edge inset (visual)
    return shape.minus(pages).with_sites(handle=(0.0, y / 2, z / 2))


def cutting_board(d: D) -> Shape:
    """A cutting board: a rounded slab with a hanging hole near +x (a handle site there)."""
    x, y, z = d[0], d[1], max(d[2], 0.012)
    board = rounded_slab(x, y, z, 0.02)
    hole = Manifold.cylinder(z * 3, 0.012, 0.012, 24).translate([x / 2 - 0.03, 0.0, -z])
    return board.minus(hole).with_sites(handle=(x / 2 - 0.03, 0.0, z))


def lamp(d: D) -> Shape:
    """A desk lamp: a heavy round base, a stem and a conical shade."""
    h, shade = d[0], d[1]
    base_r = shade * 0.38
    base = cylinder(0.025, base_r, base_r * 0.92)
    stem = cylinder(h * 0.65, 0.011).moved(z=0.025)
    lampshade = cylinder(h * 0.32, shade / 2, shade * 0.3).moved(z=h * 0.68)
    return union(base, stem, lampshade).with_sites(stem=(0.0, 0.0, h * 0.4), handle=(0.0, 0.0, h * 0.4))


def fruit(d: D) -> Shape:
    """A round fruit or vegetable (apple, orange, tomato, potato, egg) with a small flat where it rests."""
    rx, ry, rz = d[0] / 2, d[1] / 2, d[2] / 2
    e = ellipsoid(rx, ry, rz)
    pts = e.hulls[0]
    pts = pts[pts[:, 2] > -0.85 * rz]
    flat = np.column_stack([_ring_pts(0.5 * min(rx, ry), -0.85 * rz, 16)[:, :2], np.full(16, -0.85 * rz)])
    return hull_shape(np.vstack([pts, flat]))


def banana(d: D) -> Shape:
    """A banana: a tapered tube bent upward at both ends, lying on its side."""
    length, width, thick = d[0], d[1], d[2]
    t = np.linspace(-1.0, 1.0, 7)
    bend = width - thick
    radii = thick / 2 * (1 - 0.55 * t ** 2)
    # section centres at their radius: the flat underside lies on the table (no rocking)
    path = np.column_stack([t * length / 2 * 0.95, bend * (1 - t ** 2) - bend / 2, radii * np.cos(np.pi / 8)])
    return tube(path, radii, 8, phase=True)


def carrot(d: D) -> Shape:
    """A carrot: a tapering tube lying flat, flat on its underside."""
    length, r = d[0], d[1] / 2
    radii = np.array([r, r * 0.7, r * 0.12])
    path = np.column_stack([[-length / 2, 0.0, length / 2], np.zeros(3), radii * np.cos(np.pi / 8)])  # flat underside
    return tube(path, radii, 8, phase=True)


def pen(d: D) -> Shape:
    """A pen or marker: a thin hexagonal tube lying along x."""
    length, r = d[0], d[1] / 2
    return tube(np.array([[-length / 2, 0.0, 0.0], [length / 2, 0.0, 0.0]]), r, 6, phase=True)


def ball(d: D) -> Shape:
    """A ball of the table's diameter."""
    r = d[0] / 2
    return ellipsoid(r, r, r)


# ---------------------------------------------------------------- articulated
def drawer_cabinet(d: D, wall: float = 0.012) -> Articulated:
    """A cabinet carcass open at the front (+x) and a drawer with a handle that slides along +x."""
    y = d[0]
    x, z = 0.30 * y / 0.42, 0.26 * y / 0.42
    carcass = union(box(x, y, wall), box(x, y, wall, at=(0, 0, z - wall)), box(x, wall, z, at=(0, -y / 2 + wall / 2, 0)),
                    box(x, wall, z, at=(0, y / 2 - wall / 2, 0)), box(wall, y, z, at=(-x / 2 + wall / 2, 0, 0)))
    gap = 0.003
    dx, dy, dz = x - wall - gap, y - 2 * wall - 2 * gap, z - 2 * wall - 2 * gap
    tray_ = open_box(dx, dy, dz, wall=wall)
    panel = box(wall, y - 0.004, z - 0.004, at=(dx / 2 + wall / 2, 0.0, -wall - gap + 0.002))
    hw = min(0.10, dy * 0.5)
    handle = box(0.025, hw, 0.018, at=(dx / 2 + wall + 0.0125, 0.0, dz / 2 - 0.009))
    drawer = union(tray_, panel, handle)
    offset = np.array([x / 2 - dx / 2, 0.0, wall + gap])
    child = drawer.moved(*offset)
    return Articulated(carcass, child, "slide", (1.0, 0.0, 0.0), (0.0, round(0.75 * dx, 4)),
                       child_sites={"handle": (dx / 2 + wall + 0.0125 + offset[0], 0.0, dz / 2 + offset[2])})


def hinged_box(d: D, wall: float = 0.006) -> Articulated:
    """An open box and its lid, hinged along the back (-x) top edge; the lid has a front tab."""
    x, y, z = d[0], d[1], d[2]
    lid_t = max(wall, 0.008)
    base_h = z - lid_t
    base = open_box(x, y, base_h, wall=wall)
    lid = union(box(x, y, lid_t), box(0.015, y * 0.3, lid_t * 0.8, at=(x / 2 + 0.0075, 0.0, 0.0))).moved(z=base_h + 0.001)
    return Articulated(base.with_sites(hinge=(-x / 2, 0.0, base_h)), lid, "hinge", (0.0, -1.0, 0.0), (0.0, 1.9), (-x / 2, 0.0, base_h + 0.001),
                       child_sites={"handle": (x / 2 + 0.015, 0.0, base_h + 0.001 + lid_t / 2), "lid": (0.0, 0.0, base_h + lid_t)})


def laptop(d: D) -> Articulated:
    """A closed laptop: a base and a screen lid hinged along the back (-x) edge."""
    w, depth, t = d[0], d[1], max(d[2], 0.015)
    base_t, lid_t = t * 0.6, t * 0.4
    base = box(depth, w, base_t)
    lid = box(depth, w, lid_t).moved(z=base_t + 0.001)
    return Articulated(base.with_sites(hinge=(-depth / 2, 0.0, base_t)), lid, "hinge", (0.0, -1.0, 0.0), (0.0, 2.0), (-depth / 2, 0.0, base_t + 0.001),
                       child_sites={"handle": (depth / 2, 0.0, base_t + 0.001 + lid_t / 2), "lid": (0.0, 0.0, base_t + 0.001 + lid_t)})


Builder = Callable[[D], "Shape | Articulated"]

FAMILIES: dict[str, Builder] = {
    "mug": mug, "cup": cup, "glass": glass, "bowl": bowl, "plate": plate, "vase": vase, "pan": pan, "pot": pot, "kettle": kettle,
    "teapot": teapot, "tray": tray, "basket": basket, "crate": crate, "bin": bin_, "bottle": bottle, "can": can, "jar": jar,
    "cylinder": cylinder_, "box": box_, "upright_box": upright_box, "book": book, "cutting_board": cutting_board, "lamp": lamp,
    "fruit": fruit, "banana": banana, "carrot": carrot, "pen": pen, "ball": ball, "knife": knife, "fork": fork, "spoon": spoon,
    "hammer": hammer, "screwdriver": screwdriver, "wrench": wrench, "drawer_cabinet": drawer_cabinet, "hinged_box": hinged_box,
    "laptop": laptop,
}
# Families whose cavity holds things (checked with a 3 cm ball).
CONTAINERS = {"mug", "cup", "glass", "bowl", "vase", "pan", "pot", "tray", "basket", "crate", "bin"}
