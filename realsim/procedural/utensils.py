"""Cutlery and tools, lying flat: families of :mod:`realsim.procedural.families` (same contract:
a function of the extents ``d``, largest first, returning a :class:`~realsim.procedural.parts.Shape`)."""

from __future__ import annotations

import numpy as np
from manifold3d import Manifold

from realsim.procedural.parts import D, Shape, box, ellipsoid, hull_shape, tube, union


def knife(d: D) -> Shape:
    """A table knife: a flat handle and a thinner blade tapering to the tip, lying flat."""
    length, width, thick = d[0], d[1], d[2]
    grip = length * 0.42
    handle = box(grip, width * 0.8, thick, at=(-length / 2 + grip / 2, 0.0, 0.0))
    x0, x1 = -length / 2 + grip, length / 2
    blade = hull_shape(np.array([[x0, -width / 2, 0], [x0, width / 2, 0], [x1, width * 0.1, 0], [x1, -width * 0.1, 0],
                                 [x0, -width / 2, 0.003], [x0, width / 2, 0.003], [x1, width * 0.1, 0.0015], [x1, -width * 0.1, 0.0015]]))
    return (handle + blade).with_sites(handle=(-length / 2 + grip / 2, 0.0, thick))


def _flat_utensil(d: D, head: Shape, head_len: float) -> Shape:
    length, thick = d[0], 0.005
    bar = box(length - head_len + 0.01, max(d[1] * 0.35, 0.01), thick, at=(-head_len / 2 + 0.005, 0.0, 0.0))  # 1 cm into the head
    return (bar + head).with_sites(handle=(-length / 2 + (length - head_len) * 0.3, 0.0, thick))


def fork(d: D) -> Shape:
    """A fork: a flat handle and a head that curves up towards the tines, lying flat."""
    length, width = d[0], d[1]
    head_len = length * 0.3
    x0, x1 = length / 2 - head_len, length / 2
    # the head curves up towards the tines, as a fork's does (something for fingers to close on)
    head = hull_shape(np.array([[x, y, z] for x, zs in ((x0, (0.0, 0.005)), (x1, (0.008, 0.013))) for y in (-width / 2, width / 2) for z in zs]))
    tines = Manifold.cube([head_len * 0.6, 0.003, 0.04], center=True)
    cut = None
    for yy in (-width / 6, width / 6, 0.0):
        s = tines.translate([length / 2 - head_len * 0.3 + 0.001, yy, 0.0])
        cut = s if cut is None else cut + s
    return _flat_utensil(d, head.minus(cut), head_len)


def spoon(d: D) -> Shape:
    """A spoon: a flat handle and a shallow oval bowl, lying flat."""
    length, width = d[0], d[1]
    head_len = length * 0.33
    e = ellipsoid(head_len / 2, width / 2, 0.012)
    pts = e.hulls[0]
    pts = pts[pts[:, 2] <= 0.0005] + [length / 2 - head_len / 2, 0.0, 0.012]
    head = hull_shape(np.vstack([pts, [[length / 2 - head_len / 2, 0.0, 0.0]]]))
    return _flat_utensil(d, head, head_len)


def hammer(d: D) -> Shape:
    """A hammer lying flat: a handle along x and a head across it at +x (a handle site on the grip)."""
    length, head_w, thick = d[0], d[1], max(d[2], 0.025)
    handle = box(length - 0.03, 0.028, thick * 0.8, at=(-0.015, 0.0, 0.0))
    head = box(0.03, head_w, thick, at=(length / 2 - 0.015, 0.0, 0.0))
    return (handle + head).with_sites(handle=(-length / 2 + length * 0.25, 0.0, thick * 0.8))


def screwdriver(d: D) -> Shape:
    """A screwdriver lying flat: a thick grip and a thin shaft along x."""
    length, r = d[0], d[1] / 2
    grip = length * 0.45
    handle = tube(np.array([[-length / 2, 0.0, r], [-length / 2 + grip, 0.0, r]]), r, 6, phase=True)
    shaft = tube(np.array([[-length / 2 + grip, 0.0, r], [length / 2, 0.0, r]]), max(r * 0.2, 0.0025), 6, phase=True)
    return (handle + shaft).with_sites(handle=(-length / 2 + grip / 2, 0.0, 2 * r))


def wrench(d: D) -> Shape:
    """A wrench lying flat: a bar with an open jaw at each end."""
    length, width, thick = d[0], d[1], max(d[2], 0.006)
    bar = box(length - width, width * 0.45, thick)
    jaws = []
    for sign in (1, -1):
        cx = sign * (length / 2 - width / 2)
        jaws += [box(width, width * 0.3, thick, at=(cx, width * 0.35, 0.0)), box(width, width * 0.3, thick, at=(cx, -width * 0.35, 0.0)),
                 box(width * 0.3, width, thick, at=(cx - sign * width * 0.35, 0.0, 0.0))]
    return union(bar, *jaws).with_sites(handle=(0.0, 0.0, thick))
