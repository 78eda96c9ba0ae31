"""The ``rooms`` layout: several tables at different heights in one room, objects on each.

Real rooms hold more than one support: a desk and a lower side table, a kitchen table and a
counter, a coffee table before a sofa. A main table (top 0.70-0.78 m) stands with one or two
more tables beside and behind it, each 5-40 cm higher or lower (tops 0.40-0.95 m, every two at
least 5 cm apart) and 0.3-0.8 m from it edge to edge (centres 0.85-1.85 m apart); the floor
grows to hold them, and a wall stands behind them on request (``SceneSpec.wall``). The main
table carries the stacked and touching pairs, every other table one object. Seeded.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from realsim.synth.meshes import box_mesh
from realsim.synth.scene import (
    _STACK_BASE,
    PART_BACKGROUND,
    PART_FLOOR,
    Furniture,
    GtObject,
    GtSupport,
    SceneSpec,
    SynthScene,
    assemble,
    box_parts,
    place_on,
    table_parts,
)

HEIGHT_GAP = (0.05, 0.40)  # m: how much higher or lower another table's top is than the main one's
TOP_RANGE = (0.40, 0.95)  # m: tops of the other tables stay within this
EDGE_GAP = (0.3, 0.8)  # m: floor between the main table and another, edge to edge
_WOOD = np.array([0.72, 0.58, 0.42])
_FLOOR_MARGIN = 0.4  # m of floor around the furniture


def _other_height(main: float, rng: np.random.Generator) -> float:
    """A top 5-40 cm above or below ``main`` that stays within TOP_RANGE."""
    lo, hi = HEIGHT_GAP
    below = (lo, min(hi, main - TOP_RANGE[0]))
    above = (lo, min(hi, TOP_RANGE[1] - main))
    gap_lo, gap_hi = below if rng.random() < 0.5 else above
    sign = -1.0 if (gap_lo, gap_hi) == below else 1.0
    return round(main + sign * float(rng.uniform(gap_lo, gap_hi)), 4)


def _tables(rng: np.random.Generator) -> list[GtSupport]:
    """The main table at the origin, then one or two others: beside it (+x), then behind it (+y);
    every top at least HEIGHT_GAP[0] from every other."""
    h = round(float(rng.uniform(0.70, 0.78)), 4)
    sx, sy = round(float(rng.uniform(1.0, 1.2)), 3), round(float(rng.uniform(0.7, 0.8)), 3)
    tables = [GtSupport("table", "table", h, (0.0, 0.0), (sx, sy), 0.0, 0.04)]
    for k in range(int(rng.integers(1, 3))):
        size = (round(float(rng.uniform(0.5, 0.7)), 3), round(float(rng.uniform(0.45, 0.6)), 3))
        gap = float(rng.uniform(*EDGE_GAP))
        slide = float(rng.uniform(-0.15, 0.15))
        if k == 0:
            centre = (round(sx / 2 + gap + size[0] / 2, 3), round(slide, 3))
        else:
            centre = (round(slide - 0.2, 3), round(sy / 2 + gap + size[1] / 2, 3))
        top = _other_height(h, rng)
        while min(abs(top - t.height) for t in tables) < HEIGHT_GAP[0]:
            top = _other_height(h, rng)
        tables.append(GtSupport(f"table_{k + 2}", "table", top, centre, size, 0.0, 0.04))
    return tables


def _floor(tables: list[GtSupport], spec: SceneSpec) -> tuple[GtSupport, Furniture]:
    """A floor slab under all the tables (at least ``spec.floor_size``), centred on them."""
    lo = np.min([np.subtract(t.center, np.divide(t.size, 2)) for t in tables], axis=0) - _FLOOR_MARGIN
    hi = np.max([np.add(t.center, np.divide(t.size, 2)) for t in tables], axis=0) + _FLOOR_MARGIN
    size = np.maximum(hi - lo, spec.floor_size)
    centre = (lo + hi) / 2
    slab = 0.05
    floor = box_mesh((float(size[0]), float(size[1]), slab), (float(centre[0]), float(centre[1]), -slab / 2))
    gt = GtSupport("floor", "floor", 0.0, (float(centre[0]), float(centre[1])), (float(size[0]), float(size[1])), 0.0, slab)
    return gt, [(floor, box_parts(floor, 0.0, PART_FLOOR, PART_BACKGROUND), np.array([0.55, 0.52, 0.48]))]


def _share(names: list[str], tables: int, stacked: bool) -> list[list[str]]:
    """The object names per table: one for every other table (never the stack's base, which is
    drawn into a stacked set), the rest on the main table."""
    movable = [n for n in names if not (stacked and n == _STACK_BASE)]
    others = [[movable[-(k + 1)]] if k < len(movable) - 1 else [] for k in range(tables - 1)]
    taken = {n for o in others for n in o}
    return [[n for n in names if n not in taken], *others]


def make_rooms(spec: SceneSpec, names: list[str], rng: np.random.Generator) -> SynthScene:
    """The seeded rooms scene with ``names`` shared over its tables (see the module docstring)."""
    tables = _tables(rng)
    floor, furniture = _floor(tables, spec)
    for i, table in enumerate(tables):
        furniture += table_parts(table, _WOOD * (1.0 - 0.12 * i))
    if spec.wall:
        back = max(t.center[1] + t.size[1] / 2 for t in tables) + 0.02
        wall = box_mesh((floor.size[0], 0.1, 1.6), (floor.center[0], back + 0.05, 0.8))
        furniture.append((wall, box_parts(wall, None, 0, PART_BACKGROUND), np.array([0.88, 0.86, 0.80])))
    objects: list[GtObject] = []
    for i, (table, group) in enumerate(zip(tables, _share(names, len(tables), spec.stacked))):
        if not group:
            continue
        alone = spec if i == 0 else dataclasses.replace(spec, stacked=False, touching=False)
        placed = place_on(alone, group, table, furniture, rng)
        shift = len(objects)
        for obj in placed:
            obj.id += shift
            obj.resting_on = None if obj.resting_on is None else obj.resting_on + shift
            obj.touching = [t + shift for t in obj.touching]
        objects += placed
    return assemble(spec, [floor, *tables], furniture, objects)
