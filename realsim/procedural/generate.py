"""Procedural objects: a label (+ colour, size word, seed) -> a CSG mesh sized from the size table.

Dimensions are the size table's typical extents (``dims``) times a seeded variation (and the
size word: "small", "large"), clipped so the largest extent stays inside the table's
``size: [min, typical, max]``. Unknown labels get a box or cylinder primitive.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import trimesh

from realsim.physics.size_table import lookup
from realsim.procedural import shapes

SIZE_WORDS = {"tiny": 0.7, "small": 0.82, "little": 0.82, "mini": 0.75, "medium": 1.0, "big": 1.2, "large": 1.22, "huge": 1.4, "tall": 1.15, "giant": 1.4}
DEFAULT_DIMS = (0.10, 0.08, 0.08)  # m, largest first, for labels the size table does not know
DEFAULT_SIZE = (0.03, 0.10, 0.40)

# Size-table category -> builder kind.
KIND_BY_CATEGORY = {
    "mug": "mug", "cup": "cup", "glass": "cup", "bowl": "bowl", "pot": "bowl", "plate": "plate", "bottle": "bottle",
    "can": "can", "soda_can": "can", "box": "box", "cracker_box": "box", "sugar_box": "box", "gelatin_box": "box",
    "book": "book", "jar": "jar", "tray": "tray", "trash_bin": "bin", "basket": "bin", "food_container": "tray",
    "drawer": "drawer_cabinet", "cabinet": "drawer_cabinet", "candle": "cylinder", "apple": "cylinder",
}
# Words that pick a builder whatever the size table says.
KIND_BY_WORD = {"drawer": "drawer_cabinet", "dresser": "drawer_cabinet", "hinged": "hinged_box", "jewelry": "hinged_box",
                "jewellery": "hinged_box", "chest": "hinged_box", "bin": "bin", "tray": "tray", "jar": "jar"}
DEFAULT_COLORS = {
    "mug": (0.85, 0.85, 0.82), "cup": (0.75, 0.85, 0.95), "bowl": (0.9, 0.88, 0.8), "plate": (0.95, 0.95, 0.95),
    "bottle": (0.35, 0.6, 0.85), "can": (0.75, 0.1, 0.1), "box": (0.85, 0.65, 0.3), "book": (0.2, 0.35, 0.6),
    "jar": (0.8, 0.9, 0.85), "tray": (0.4, 0.4, 0.45), "bin": (0.3, 0.45, 0.3), "drawer_cabinet": (0.6, 0.45, 0.3),
    "hinged_box": (0.55, 0.35, 0.2), "cylinder": (0.6, 0.6, 0.6), "primitive_box": (0.6, 0.6, 0.6),
}
ARTICULATED = {"drawer_cabinet", "hinged_box"}
# Labels of the parts of articulated objects (size-table categories for their physics).
PART_LABELS = {"drawer_cabinet": ("cabinet", "drawer"), "hinged_box": ("box", "box lid")}


@dataclass
class Part:
    """One rigid part of a generated object (object frame: base centre at the origin)."""

    label: str
    mesh: trimesh.Trimesh
    color: tuple[float, float, float]


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


def kind_for(label: str) -> str:
    """The builder for a label: a word rule, the size-table category, or a primitive."""
    words = label.lower().replace("_", " ").split()
    for w in words:
        if w in KIND_BY_WORD:
            return KIND_BY_WORD[w]
    m = lookup(label)
    if m is not None and m.category.name in KIND_BY_CATEGORY:
        return KIND_BY_CATEGORY[m.category.name]
    dims = table_dims(label)
    return "cylinder" if abs(dims[1] - dims[2]) < 0.1 * dims[1] and m is not None and m.category.form != "solid" else "primitive_box"


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


def _normalized(mesh: trimesh.Trimesh) -> tuple[trimesh.Trimesh, np.ndarray]:
    """The mesh moved so its base centre is the origin, and the shift applied."""
    lo, hi = mesh.bounds
    shift = -np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]])
    mesh = mesh.copy()
    mesh.apply_translation(shift)
    return mesh, shift


def generate(label: str, rng: np.random.Generator, size_word: str | None = None, color: tuple[float, float, float] | None = None,
             kind: str | None = None, variation: float = 0.08) -> Generated:
    """Build the object ``label`` (seeded), sized from the size table, coloured as asked."""
    kind = kind or kind_for(label)
    d0, d1, d2 = table_dims(label)
    lo, typ, hi = size_range(label)
    factor = SIZE_WORDS.get(size_word or "", 1.0) * float(rng.uniform(1 - variation, 1 + variation))
    # keep the largest extent inside the table's range (a small margin inside for the handle etc.)
    factor = float(np.clip(factor, lo * 1.03 / d0, hi * 0.97 / d0))
    d0, d1, d2 = d0 * factor, d1 * factor, d2 * factor
    rgb = tuple(float(c) for c in (color or DEFAULT_COLORS.get(kind, (0.6, 0.6, 0.6))))
    joint = None
    notes: list[str] = []
    if kind == "mug":
        diameter = d1 * 0.9
        main = shapes.mug(d1, diameter)
    elif kind == "cup":
        main = shapes.cup(d0, d1)
    elif kind == "bowl":
        main = shapes.bowl(d2, d0)
    elif kind == "plate":
        main = shapes.plate(d2, d0)
    elif kind == "bottle":
        main = shapes.bottle(d0, d1)
    elif kind == "can":
        main = shapes.can(d0, d1)
    elif kind == "jar":
        main = shapes.jar(d0, d1)
    elif kind == "cylinder":
        main = shapes.cylinder(d0, d1)
    elif kind == "box":
        upright = "cereal" in label or "cracker" in label or (lookup(label) is not None and lookup(label).category.name in ("cracker_box", "sugar_box"))
        main = shapes.box(d1, d2, d0) if upright else shapes.box(d0, d1, d2)
    elif kind == "book":
        main = shapes.book(d0, d1, d2)
    elif kind == "tray":
        main = shapes.tray(d0, d1, max(d2, 0.03))
    elif kind == "bin":
        main = shapes.bin_(d1, d2, d0)
    elif kind == "drawer_cabinet":
        # a tabletop drawer unit: the table's cabinet is furniture-sized, so scale it down to bench size
        y = float(np.clip(0.42 * factor, lo * 1.01, hi * 0.99))  # the table's cabinet range (largest extent)
        x, z = 0.30 * y / 0.42, 0.26 * y / 0.42
        carcass, drawer, info = shapes.drawer_cabinet(x, y, z)
        return _articulated(label, kind, carcass, drawer, info, "slide", rgb, (x, y, z))
    elif kind == "hinged_box":
        x, y, z = 0.22 * factor, 0.16 * factor, 0.10 * factor
        base, lid, info = shapes.hinged_box(x, y, z)
        return _articulated(label, kind, base, lid, info, "hinge", rgb, (x, y, z))
    else:
        kind = "primitive_box"
        main = shapes.box(d1, d2, d0) if d0 > 2.5 * d2 and d2 > 0.04 else shapes.box(d0, d1, d2)
        notes.append(f"no procedural model for {label!r}: a box primitive from the size table")
    mesh, _ = _normalized(shapes.to_trimesh(main))
    return Generated(label, kind, [Part(label, mesh, rgb)], joint, tuple(float(v) for v in mesh.extents), notes)  # type: ignore[arg-type]


def _articulated(label: str, kind: str, parent, child, info: dict, jtype: str, rgb, dims) -> Generated:
    pmesh, sp = _normalized(shapes.to_trimesh(parent))
    cmesh, sc = _normalized(shapes.to_trimesh(child))
    child_pos = np.asarray(info["offset"]) + sp - sc
    anchor = np.asarray(info.get("hinge_pos", [0.0, 0.0, 0.0])) + sc
    plabel, clabel = PART_LABELS[kind]
    darker = tuple(float(c) * 0.8 for c in rgb)
    handle = tuple(float(v) for v in np.asarray(info["handle"]) + sc) if "handle" in info else None
    joint = Joint(jtype, tuple(info["axis"]), tuple(info["range"]), tuple(float(v) for v in child_pos), tuple(float(v) for v in anchor),
                  handle=handle)  # type: ignore[arg-type]
    return Generated(label, kind, [Part(plabel, pmesh, rgb), Part(clabel, cmesh, darker)], joint, tuple(float(v) for v in dims))  # type: ignore[arg-type]


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
