"""Procedural objects: a label (+ colour, size word, seed) -> parts with collision pieces and sites.

The family (:mod:`realsim.procedural.families`) comes from a word rule or the size-table
category; dimensions are the table's typical extents (``dims``) times a seeded variation (and
the size word: "small", "large"), clipped so the largest extent stays inside the table's
``size: [min, typical, max]``. Unknown labels get a box from the table's defaults (noted).
Each part carries its convex collision pieces and named sites (``handle``, ``rim``, ``lid``,
``hinge``, ...) in the part's frame (base centre at the origin).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import trimesh

from realsim.physics.size_table import lookup
from realsim.procedural.families import CONTAINERS, FAMILIES, Articulated
from realsim.procedural.parts import Shape, to_trimesh

SIZE_WORDS = {"tiny": 0.7, "small": 0.82, "little": 0.82, "mini": 0.75, "medium": 1.0, "big": 1.2, "large": 1.22, "huge": 1.4, "tall": 1.15,
              "giant": 1.4, "short": 0.85, "long": 1.15, "wide": 1.15, "thin": 0.9}
DEFAULT_DIMS = (0.10, 0.08, 0.08)  # m, largest first, for labels the size table does not know
DEFAULT_SIZE = (0.03, 0.10, 0.40)

# Size-table category -> family.
KIND_BY_CATEGORY = {
    "mug": "mug", "cup": "cup", "glass": "glass", "bowl": "bowl", "pot": "pot", "pan": "pan", "plate": "plate", "bottle": "bottle",
    "wine_bottle": "bottle", "mustard_bottle": "bottle", "bleach_cleanser": "bottle", "wash_bottle": "bottle", "soap_dispenser": "bottle",
    "can": "can", "soda_can": "can", "chips_can": "can", "box": "box", "cracker_box": "upright_box", "sugar_box": "upright_box",
    "milk_carton": "upright_box", "gelatin_box": "box", "book": "book", "jar": "jar", "tray": "tray", "trash_bin": "bin",
    "basket": "basket", "crate": "crate", "bucket": "vase", "vase": "vase", "flower_pot": "vase", "food_container": "tray",
    "drawer": "drawer_cabinet", "cabinet": "drawer_cabinet", "candle": "cylinder", "apple": "fruit", "orange": "fruit", "potato": "fruit", "egg": "fruit",
    "vegetable": "fruit", "banana": "banana", "carrot": "carrot", "teapot": "teapot", "kettle": "kettle", "pitcher": "kettle",
    "knife": "knife", "fork": "fork", "spoon": "spoon", "spatula": "spoon", "ladle": "spoon", "chopsticks": "pen",
    "cutting_board": "cutting_board", "laptop": "laptop", "lamp": "lamp", "hammer": "hammer", "screwdriver": "screwdriver",
    "wrench": "wrench", "pliers": "wrench", "marker": "pen", "pen": "pen", "flashlight": "pen", "toothbrush": "pen",
    "ball": "ball", "golf_ball": "ball", "soccer_ball": "ball", "phone": "box", "remote_control": "box", "tablet": "box",
    "keyboard": "box", "sponge": "box", "soap_bar": "box", "toy_block": "box", "rubiks_cube": "box", "foam_brick": "box",
    "dice": "box", "picture_frame": "box", "stapler": "box", "tape_measure": "box", "computer_mouse": "fruit", "bread": "fruit",
    "strawberry": "fruit", "beaker": "glass", "flask": "vase", "test_tube": "glass", "petri_dish": "plate", "towel": "box",
}
# Words that pick a family whatever the size table says.
KIND_BY_WORD = {"drawer": "drawer_cabinet", "drawers": "drawer_cabinet", "dresser": "drawer_cabinet", "hinged": "hinged_box",
                "jewelry": "hinged_box", "jewellery": "hinged_box", "chest": "hinged_box", "lidded": "hinged_box", "bin": "bin",
                "tray": "tray", "jar": "jar", "crate": "crate", "basket": "basket", "laptop": "laptop", "skillet": "pan"}
DEFAULT_COLORS = {
    "mug": (0.85, 0.85, 0.82), "cup": (0.75, 0.85, 0.95), "glass": (0.8, 0.9, 0.95), "bowl": (0.9, 0.88, 0.8), "plate": (0.95, 0.95, 0.95),
    "bottle": (0.35, 0.6, 0.85), "can": (0.75, 0.1, 0.1), "box": (0.85, 0.65, 0.3), "upright_box": (0.85, 0.65, 0.3),
    "book": (0.2, 0.35, 0.6), "jar": (0.8, 0.9, 0.85), "tray": (0.4, 0.4, 0.45), "bin": (0.3, 0.45, 0.3), "basket": (0.7, 0.55, 0.35),
    "crate": (0.75, 0.6, 0.4), "vase": (0.7, 0.4, 0.3), "pan": (0.15, 0.15, 0.15), "pot": (0.7, 0.7, 0.72), "kettle": (0.75, 0.75, 0.78),
    "teapot": (0.9, 0.9, 0.88), "knife": (0.75, 0.75, 0.78), "fork": (0.75, 0.75, 0.78), "spoon": (0.75, 0.75, 0.78),
    "cutting_board": (0.65, 0.5, 0.3), "laptop": (0.5, 0.5, 0.52), "lamp": (0.9, 0.85, 0.7), "fruit": (0.8, 0.15, 0.1),
    "banana": (0.95, 0.85, 0.2), "carrot": (0.95, 0.5, 0.1), "pen": (0.1, 0.2, 0.7), "ball": (0.8, 0.9, 0.2), "hammer": (0.5, 0.35, 0.2),
    "screwdriver": (0.85, 0.2, 0.1), "wrench": (0.6, 0.6, 0.62), "drawer_cabinet": (0.6, 0.45, 0.3), "hinged_box": (0.55, 0.35, 0.2),
    "cylinder": (0.6, 0.6, 0.6), "primitive_box": (0.6, 0.6, 0.6),
}
FRUIT_COLORS = {"orange": (0.95, 0.5, 0.1), "lemon": (0.95, 0.85, 0.2), "lime": (0.4, 0.7, 0.2), "egg": (0.95, 0.9, 0.8),
                "potato": (0.7, 0.55, 0.35), "bread": (0.8, 0.6, 0.35), "pear": (0.7, 0.8, 0.3), "peach": (0.95, 0.6, 0.4)}
BENCH_DIMS = {"drawer_cabinet": (0.42, 0.30, 0.26), "hinged_box": (0.22, 0.16, 0.10)}
ARTICULATED = {"drawer_cabinet", "hinged_box", "laptop"}
# Labels of the parts of articulated objects (size-table categories for their physics).
PART_LABELS = {"drawer_cabinet": ("cabinet", "drawer"), "hinged_box": ("box", "box lid"), "laptop": ("laptop", "laptop lid")}


@dataclass
class Part:
    """One rigid part of a generated object (object frame: base centre at the origin).

    ``hulls`` are its convex collision pieces (point arrays), ``sites`` named points (handle,
    rim, lid, hinge, ...) in the same frame.
    """

    label: str
    mesh: trimesh.Trimesh
    color: tuple[float, float, float]
    hulls: list[np.ndarray] = field(default_factory=list)
    sites: dict[str, tuple[float, float, float]] = field(default_factory=dict)


@dataclass
class Joint:
    """How a child part hangs on its parent: a slide or hinge joint."""

    type: str  # "slide" | "hinge"
    axis: tuple[float, float, float]  # in the child frame
    range: tuple[float, float]
    child_pos: tuple[float, float, float]  # child frame origin in the parent frame (closed)
    pos: tuple[float, float, float] = (0.0, 0.0, 0.0)  # joint anchor in the child frame
    damping: float = 2.0
    handle: tuple[float, float, float] | None = None  # where a hand pulls the child, in the child frame


@dataclass
class Generated:
    """A procedural object: its main part, and for articulated objects a child part and joint."""

    label: str
    kind: str
    parts: list[Part]
    joint: Joint | None = None
    dims: tuple[float, float, float] = (0.0, 0.0, 0.0)  # extents of the whole object (x, y, z)
    notes: list[str] = field(default_factory=list)

    @property
    def container(self) -> bool:
        """True for families with an open cavity (things can be put in)."""
        return self.kind in CONTAINERS


def kind_for(label: str) -> str:
    """The family for a label: a word rule, the size-table category, or a primitive box."""
    words = label.lower().replace("_", " ").split()
    for w in words:
        if w in KIND_BY_WORD:
            return KIND_BY_WORD[w]
    m = lookup(label)
    if m is not None and m.category.name in KIND_BY_CATEGORY and (m.how != "fuzzy" or m.score >= 0.85):
        return KIND_BY_CATEGORY[m.category.name]
    return "primitive_box"


def table_dims(label: str) -> tuple[float, float, float]:
    """Typical extents (largest first) from the size table, padded to three values."""
    m = lookup(label)
    dims = list(m.category.dims) if m is not None else list(DEFAULT_DIMS)
    while len(dims) < 3:
        dims.append(dims[-1])
    return (float(dims[0]), float(dims[1]), float(dims[2]))


def size_range(label: str) -> tuple[float, float, float]:
    """(min, typical, max) of the largest extent from the size table."""
    m = lookup(label)
    return tuple(m.category.size) if m is not None else DEFAULT_SIZE  # type: ignore[return-value]


def _part(label: str, shape: Shape, color: tuple[float, float, float], shift: np.ndarray | None = None) -> tuple[Part, np.ndarray]:
    """The shape moved so its base centre is the origin (or by ``shift``), as a Part; and the shift."""
    if shift is None:
        bb = np.asarray(shape.solid.bounding_box(), float)
        lo, hi = bb[:3], bb[3:]
        shift = -np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]])
    s = shape.moved(*shift)
    return Part(label, to_trimesh(s.solid), color, s.hulls, dict(s.sites)), shift


def generate(label: str, rng: np.random.Generator, size_word: str | None = None, color: tuple[float, float, float] | None = None,
             kind: str | None = None, variation: float = 0.08, dims: tuple[float, float, float] | None = None,
             at_least: float = 0.0) -> Generated:
    """Build the object ``label`` (seeded), sized from the size table (or ``dims``, largest first), coloured as asked.

    ``at_least``: a lower bound (m) on the largest extent, within the table's range (a container
    made big enough for what is said to be in it)."""
    kind = kind or kind_for(label)
    d0, d1, d2 = table_dims(label)
    lo, _, hi = size_range(label)
    rel = SIZE_WORDS.get(size_word or "", 1.0) * float(rng.uniform(1 - variation, 1 + variation))
    factor = float(np.clip(max(rel, at_least / d0), lo * 1.03 / d0, hi * 0.97 / d0))  # the largest extent stays inside the table's range
    d = (d0 * factor, d1 * factor, d2 * factor)
    if kind in BENCH_DIMS:  # furniture-sized table entries scaled down to tabletop pieces
        d = tuple(v * float(np.clip(rel, 0.8, 1.25)) for v in BENCH_DIMS[kind])  # type: ignore[assignment]
    notes: list[str] = []
    if dims is not None:  # measured sizes (a photo): clamped to the table's range of the largest extent
        given = sorted((float(v) for v in dims), reverse=True)
        scale = float(np.clip(given[0], lo, hi)) / given[0] if given[0] > 0 else 1.0
        d = tuple(max(v * scale, 0.004) for v in given)  # type: ignore[assignment]
        if abs(scale - 1.0) > 1e-6:
            notes.append(f"{label}: size {given[0]:.3f} m clamped into the size table's {lo:.3f}..{hi:.3f} m")
    base_kind = kind
    if kind == "primitive_box":
        notes.append(f"no procedural model for {label!r}: a box primitive from the size table")
        base_kind = "box"
    default = FRUIT_COLORS.get(label.split()[-1], DEFAULT_COLORS.get(kind, (0.6, 0.6, 0.6)))
    rgb = tuple(float(c) for c in (color or default))
    built = FAMILIES[base_kind](d)  # type: ignore[arg-type]
    if isinstance(built, Articulated):
        return _articulated(label, kind, built, rgb)  # type: ignore[arg-type]
    part, _ = _part(label, built, rgb)  # type: ignore[arg-type]
    return Generated(label, kind, [part], None, tuple(float(v) for v in part.mesh.extents), notes)  # type: ignore[arg-type]


def _articulated(label: str, kind: str, art: Articulated, rgb: tuple[float, float, float]) -> Generated:
    """Parent and child as parts with their own base-centred frames, and the joint between them."""
    plabel, clabel = PART_LABELS[kind]
    parent, sp = _part(plabel, art.parent, rgb)
    child_shape = art.child.with_sites(**art.child_sites)
    child, sc = _part(clabel, child_shape, tuple(float(c) * 0.8 for c in rgb))  # type: ignore[arg-type]
    child_pos = sp - sc  # child frame origin in the parent frame (closed)
    anchor = np.asarray(art.hinge_pos) + sc
    handle = child.sites.get("handle")
    joint = Joint(art.joint, art.axis, art.range, tuple(float(v) for v in child_pos), tuple(float(v) for v in anchor),  # type: ignore[arg-type]
                  handle=tuple(float(v) for v in handle) if handle else None)  # type: ignore[arg-type]
    child.sites = {k: v for k, v in child.sites.items() if k != "handle"}  # the joint's handle site is written by compose
    verts = np.vstack([parent.mesh.vertices, child.mesh.vertices + child_pos])
    dims = tuple(float(v) for v in verts.max(axis=0) - verts.min(axis=0))
    return Generated(label, kind, [parent, child], joint, dims)  # type: ignore[arg-type]


def write_ply(mesh: trimesh.Trimesh, color: tuple[float, float, float], path: Path) -> Path:
    """Write the mesh with a uniform vertex colour as a binary PLY (deterministic bytes)."""
    m = trimesh.Trimesh(mesh.vertices, mesh.faces, process=False)
    rgba = np.array([*(np.clip(color, 0, 1) * 255).round().astype(np.uint8), 255], dtype=np.uint8)
    m.visual.vertex_colors = np.tile(rgba, (len(m.vertices), 1))
    path.parent.mkdir(parents=True, exist_ok=True)
    data = trimesh.exchange.ply.export_ply(m, encoding="binary")
    if not path.exists() or path.read_bytes() != data:
        tmp = path.with_suffix(".tmp")
        tmp.write_bytes(data)
        tmp.replace(path)
    return path
