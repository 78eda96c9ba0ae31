"""Moving an object out of the way, and putting another where it stood.

"Move the banana out of the way" carries it to the nearest free spot on the table: one with a
comfortable margin from every other object's footprint and from the footprint it stood on (so
its spot is free afterwards). The spot is chosen within the area the objects already cover
(their footprints' extent, a little beyond, a little more when that is full): that is table
the robot reaches. "Put the mug where
the banana was" then places the mug at the banana's old spot; while the banana still stands
there the planner says so instead of placing one object onto another.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

import numpy as np

from realsim.errors import InputError
from realsim.planner.goals import Aside, Placed
from realsim.planner.program import Call
from realsim.planner.steps import Parser, Step, objects_named
from realsim.planner.types import ObjectInfo

__all__ = ["ASIDE", "WHERE", "aside", "aside_spot", "where_was"]

CLEAR = 0.04  # m: the least gap a spot keeps from other footprints (room for the open fingers)
ROOMY = 0.08  # m: more margin than this buys nothing; then the shorter carry wins
REACH_MARGINS = (0.05, 0.10)  # m the moved footprint may reach beyond the objects' footprints: the nearer first
CELL = 0.01  # m: the grid the spot is searched on

ASIDE = re.compile(r"(.+?) aside")
"""A clause's object phrase before "aside" ("out of the way", "to one side" are read as "aside")."""
WHERE = re.compile(r"(.+?) (?:back )?(?:(?:exactly|precisely|right|just) )?(?:(?:to|in|into|on|at|onto) )?(?:(?:the )?(?:spot|place|position) )?where (.+?)"
                   r" (?:is|was|were|are|sits|sat|stands|stood|lies|lay|used to be|had been|has been|is now|was before)(?: before| standing| sitting)?")
"""``X where Y was``: the object phrase and the phrase naming whose spot."""


def _box(o: ObjectInfo, xy: Sequence[float] | None = None) -> tuple[np.ndarray, np.ndarray]:
    c = np.asarray(o.position[:2] if xy is None else xy, float)
    half = np.asarray(o.size[:2], float) / 2
    return c - half, c + half


def _gaps(lo: np.ndarray, hi: np.ndarray, boxes: list[tuple[np.ndarray, np.ndarray]]) -> np.ndarray:
    """Distances (m) from boxes [lo, hi] (arrays of N x 2) to the nearest of ``boxes``."""
    out = np.full(len(lo), np.inf)
    for blo, bhi in boxes:
        d = np.maximum(0.0, np.maximum(blo - hi, lo - bhi))
        out = np.minimum(out, np.hypot(d[:, 0], d[:, 1]))
    return out


def aside_spot(obj: ObjectInfo, objects: Sequence[ObjectInfo], taken: Sequence[tuple[np.ndarray, np.ndarray]] = ()) -> tuple[float, float] | None:
    """World xy for ``obj``'s centre out of the way: at least :data:`CLEAR` from every other
    object, from ``obj``'s own footprint and from ``taken`` boxes; the most margin (up to
    :data:`ROOMY`), then the shortest carry. None when the objects' area has no such spot."""
    boxes = [_box(o) for o in objects if o.name != obj.name] + [_box(obj), *taken]
    half = np.asarray(obj.size[:2], float) / 2
    for margin in REACH_MARGINS:
        lo = np.min([b[0] for b in boxes], axis=0) - margin + half  # its footprint within the objects' area
        hi = np.max([b[1] for b in boxes], axis=0) + margin - half
        gx, gy = np.arange(lo[0], hi[0] + CELL / 2, CELL), np.arange(lo[1], hi[1] + CELL / 2, CELL)
        grid = np.array(np.meshgrid(gx, gy)).reshape(2, -1).T
        grid = grid[np.all(grid <= hi, axis=1)]
        gap = _gaps(grid - half, grid + half, boxes)
        if (gap >= CLEAR).any():
            break
    else:
        return None
    grid, gap = grid[gap >= CLEAR], gap[gap >= CLEAR]
    carry = np.linalg.norm(grid - np.asarray(obj.position[:2]), axis=1)
    best = np.lexsort((carry, -np.round(np.minimum(gap, ROOMY), 2)))[0]
    return float(grid[best, 0]), float(grid[best, 1])


def aside(phrase: str, p: Parser) -> Step:
    """"Move X out of the way": each named object placed at its :func:`aside_spot`."""
    objs = objects_named(phrase, p)
    p.ctx.set(objs)
    calls, goals = [], []
    for o in objs:
        xy = aside_spot(o, p.objects, p.taken)
        if xy is None:
            raise InputError(f"there is no free spot on the table to move {o.name} out of the way; say where to put it; {p.resolver.listing()}")
        p.taken.append(_box(o, xy))
        calls.append(Call("place", (o.name, [round(xy[0], 3), round(xy[1], 3), round(o.position[2], 3)])))
        goals.append(Aside(o.name, tuple(sorted(x.name for x in p.objects if x.name != o.name))))
    return Step(calls, goals, tuple(o.name for o in objs), aside=True)


def _moved_one(phrase: str, obj: ObjectInfo, p: Parser) -> ObjectInfo:
    """The object ``phrase`` names; of several it could name, the one an earlier step moved
    ("get the soup can out of the way, then put the cube where the can was")."""
    try:
        return p.resolver.resolve(phrase, p.ctx, exclude=[obj.name], allow_plural=False)[0]
    except InputError:
        cands = [o for o in p.resolver.resolve(phrase, p.ctx, exclude=[obj.name], loose=True) if o.name in p.moved]
        if len(cands) != 1:
            raise
        return cands[0]


def where_was(obj_phrase: str, ref_phrase: str, p: Parser) -> Step | None:
    """"Put X where Y was": X placed at Y's starting spot, once an earlier step moved Y away.
    "it" is the object an earlier step moved; None when it is X itself ("put X where it was": back)."""
    last = p.ctx.last[0] if p.ctx.last else None
    pronoun = re.fullmatch(r"(?:it|they|that|that one|this)", ref_phrase)
    if pronoun and (last is None or last.name not in p.moved):
        return None
    objs = objects_named(obj_phrase, p)
    if len(objs) != 1:
        raise InputError(f"one object can go where another was; {obj_phrase!r} names {len(objs)}")
    obj = objs[0]
    if pronoun:
        if last is None or last.name == obj.name:
            return None
        ref = last
    else:
        ref = _moved_one(ref_phrase, obj, p)
    if ref.name not in p.moved:
        raise InputError(f"{ref.name} is still where it is: to put {obj.name} in its place, move it first "
                         f"('move the {ref.label} out of the way, then put the {obj.label} where the {ref.label} was'); {p.resolver.listing()}")
    p.ctx.set([obj])
    xy = (round(ref.position[0], 3), round(ref.position[1], 3))
    return Step([Call("place", (obj.name, [xy[0], xy[1], round(ref.position[2], 3)]))], [Placed(obj.name, xy)], (obj.name,))
