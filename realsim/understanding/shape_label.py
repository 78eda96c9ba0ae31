"""Labels from shape alone: the size-table category nearest to a cluster's dimensions.

Offline (no key) a scan cluster is named by the category whose typical extents are closest in
log scale to its own, among categories of the same kind of shape: round (two of the category's
typical extents equal: cans, cups, bowls, bottles) for a cylinder, the rest for a box. The
largest extent must fall inside the category's size range (a 10 % tolerance).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh

from realsim.physics.size_table import ObjectCategory, load_objects

ROUND_TOL = 0.12  # two extents within 12 % of each other make a round category
MAX_DISTANCE = 0.35  # log-extent RMS distance beyond which no label is given (about 40 % off per extent)


@dataclass(frozen=True)
class ShapeLabel:
    """The size-table label whose extents best match a shape, how far off it is, and the shape word."""

    label: str
    distance: float  # RMS of log extent ratios
    shape: str  # "cylinder" | "box"


# Categories whose typical extents look round but whose shape is boxy (cubes, furniture, appliances).
BOXY = frozenset({"rubiks_cube", "dice", "toy_block", "foam_brick", "table", "chair", "drawer", "refrigerator", "toaster",
                  "shoe", "power_drill", "speaker", "tape_measure", "milk_carton", "stuffed_animal", "clock", "lamp"})


# Rectangular prisms: what a box-like cluster (its solid fills its oriented bounding box) can be.
PRISMS = frozenset({"cutting_board", "tray", "food_container", "cracker_box", "sugar_box", "gelatin_box", "box", "milk_carton",
                    "bread", "book", "phone", "remote_control", "keyboard", "laptop", "rubiks_cube", "foam_brick", "toy_block",
                    "dice", "sponge", "soap_bar", "picture_frame", "speaker", "tablet", "monitor", "cabinet", "drawer",
                    "microwave", "refrigerator", "toaster", "shelf", "test_tube_rack"})
BOX_FILL = 0.9  # solid volume / oriented bounding box volume of a rectangular prism


def is_round(cat: ObjectCategory) -> bool:
    """Whether a category is round in plan (two of its typical extents alike) and not listed as boxy."""
    if cat.name in BOXY:
        return False
    d = sorted(cat.dims, reverse=True)
    if len(d) < 3:
        return False
    return abs(d[0] - d[1]) <= ROUND_TOL * d[0] or abs(d[1] - d[2]) <= ROUND_TOL * d[1]


def is_cylinder(mesh: trimesh.Trimesh | None, size: np.ndarray) -> bool:
    """An upright cylinder: round footprint (x ~ y) filling ~pi/4 of its bounding box."""
    size = np.asarray(size, float)
    if mesh is None or size.min() <= 0:
        return False
    if abs(size[0] - size[1]) > 0.1 * max(size[0], size[1]):
        return False
    fill = float(abs(mesh.volume)) / float(np.prod(size))
    return abs(fill - np.pi / 4) < 0.06


def is_prism(mesh: trimesh.Trimesh | None) -> bool:
    """A rectangular prism: the solid fills its oriented bounding box."""
    if mesh is None or not mesh.is_volume:
        return False
    try:
        obb = float(mesh.bounding_box_oriented.volume)
    except Exception:  # degenerate hulls: no oriented box
        return False
    return obb > 0 and float(mesh.volume) / obb >= BOX_FILL


def ranked_labels(size: np.ndarray, cylinder: bool, *, prism: bool = False, exclude: tuple[str, ...] = ()) -> list[ShapeLabel]:
    """Categories of the right kind of shape (round for ``cylinder``, prisms for ``prism``, else the
    other non-round ones) whose size range admits the largest extent, nearest first."""
    dims = np.sort(np.maximum(np.asarray(size, float), 1e-3))[::-1]
    out: list[ShapeLabel] = []
    for name, cat in load_objects().items():
        if name in exclude or len(cat.dims) < 3 or is_round(cat) != cylinder:
            continue
        if not cylinder and prism and name not in PRISMS:
            continue
        lo, _, hi = cat.size
        if not (0.9 * lo <= dims[0] <= 1.1 * hi):
            continue
        ref = np.sort(np.asarray(cat.dims[:3], float))[::-1]
        dist = float(np.sqrt(np.mean(np.log(dims / ref) ** 2)))
        out.append(ShapeLabel(name, dist, "cylinder" if cylinder else "box" if prism else "irregular"))
    return sorted(out, key=lambda s: (s.distance, s.label))


def label_from_shape(size: np.ndarray, cylinder: bool, *, prism: bool = False, exclude: tuple[str, ...] = ()) -> ShapeLabel | None:
    """The nearest category by extents among round (``cylinder``), prism (``prism``) or other
    non-round categories, or None."""
    ranked = ranked_labels(size, cylinder, prism=prism, exclude=exclude)
    if not ranked or ranked[0].distance > MAX_DISTANCE:
        return None
    return ranked[0]
