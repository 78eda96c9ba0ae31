"""Which of several objects an order picks: an extreme ("the leftmost"), an ordinal ("the second
from the right"), the middle one, the one nearest or farthest from a reference, or a corner ("at
the front on the right": first along both directions). Directions are the robot's; "nearest" and
"farthest" rank by distance from the robot's base when it is known (a thing far off to one side is
not nearer than one just ahead), things as far from it by their depth along its forward axis, and
along that axis alone when the base is not known, like "front" and "back".
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable

from realsim.errors import InputError
from realsim.planner import relations
from realsim.planner.attributes import pts
from realsim.planner.types import ObjectInfo

__all__ = ["EXTREMES", "TIE", "middle_of", "ordered"]

TIE = 0.02  # m: objects closer than this along a direction are level ("the leftmost" of two side by side)
# robot-frame orderings: (axis, sign); axis 0 forward (away from the robot), 1 left
EXTREMES: dict[str, tuple[int, float]] = {
    "leftmost": (1, 1.0), "left most": (1, 1.0), "left": (1, 1.0), "rightmost": (1, -1.0), "right most": (1, -1.0), "right": (1, -1.0),
    "farthest": (0, 1.0), "furthest": (0, 1.0), "far": (0, 1.0), "back": (0, 1.0), "rear": (0, 1.0), "backmost": (0, 1.0),
    "nearest": (0, -1.0), "closest": (0, -1.0), "near": (0, -1.0), "front": (0, -1.0), "frontmost": (0, -1.0),
}

RADIAL = ("nearest", "closest", "near", "farthest", "furthest", "far")  # by distance from the base when it is known


def ordered(found: list[ObjectInfo], order: tuple[str, object], ordinal: int | None, phrase: str,
            robot_xy: Callable[[ObjectInfo], tuple[float, float]], distinguish: Callable[[list[ObjectInfo]], list[str]],
            radial: bool = False) -> list[ObjectInfo]:
    """The one of ``found`` that ``order`` (kind, argument) picks; ``robot_xy`` gives an object's
    (forward, left) in the robot's frame, ``distinguish`` lists candidates for an error; with
    ``radial`` (``robot_xy`` measured from the base) "nearest" / "farthest" rank by distance."""
    kind, arg = order
    if kind in ("near", "far"):  # the gap to the reference, its distance breaking ties
        ref = arg
        assert isinstance(ref, ObjectInfo)
        choose = min if kind == "near" else max
        return [choose(found, key=lambda o: relations.xy_gap(pts(o), pts(ref)) + 1e-3 * math.dist(o.position[:2], ref.position[:2]))]
    if kind == "middle":
        ys = sorted(found, key=lambda o: robot_xy(o)[1])
        if isinstance(arg, int) and arg != len(ys):  # "the middle of the three" when five match: not sure which
            raise InputError(f"{phrase.strip()!r}: {arg} said, but {len(ys)} match: {', '.join(distinguish(ys))}; say which one")
        if len(ys) % 2 == 0:
            raise InputError(f"{phrase.strip()!r}: there is no middle one of {len(ys)}: {', '.join(distinguish(ys))}")
        return [ys[len(ys) // 2]]
    if kind == "corner":  # "at the front on the right": first along both ways, else not clear
        assert isinstance(arg, tuple)
        firsts = [ordered(found, ("extreme", w), None, phrase, robot_xy, distinguish, radial)[0] for w in arg]
        if firsts[0] is not firsts[1]:
            raise InputError(f"{phrase.strip()!r} is ambiguous: {', '.join(distinguish(firsts))}; say which one")
        return [firsts[0]]
    axis, sign = EXTREMES[str(arg)]

    def along(o: ObjectInfo) -> float:  # a side: along its direction; nearest / farthest: the distance from the base
        return math.hypot(*robot_xy(o)) if radial and str(arg) in RADIAL else robot_xy(o)[axis]

    ranked = sorted(found, key=lambda o: -sign * along(o))
    k = 1 if ordinal is None else ordinal
    if k == -1:
        return [ranked[-1]]
    if k > len(ranked):
        raise InputError(f"there is no {phrase.strip()!r}: only {len(ranked)} such objects")
    pick = ranked[k - 1]
    ties = [o for o in ranked if o is not pick and abs(along(o) - along(pick)) < TIE]
    if ties and radial and str(arg) in RADIAL and ordinal is None:  # as far from the base: the one ahead or behind the others
        return ordered([pick, *ties], order, None, phrase, robot_xy, distinguish, radial=False)
    if ties:  # level with another along that direction: which one is meant is not clear
        raise InputError(f"{phrase.strip()!r} is ambiguous: {', '.join(distinguish([pick, *ties]))} are level; say which one")
    return [pick]


_COUNTS = {"three": 3, "five": 5, "seven": 7, "two": 2, "four": 4, "six": 6}


def middle_of(text: str) -> tuple[str, int | None]:
    """"the block in the middle of the three (blocks)" -> ("the block in the middle", 3); "of them",
    "of all" say no count; text without it is returned as is with None."""
    m = re.fullmatch(r"(.+?\b(?:in|at) the (?:middle|center|centre)) of (?:the |these |those |all )?(them|all|two|three|four|five|six|seven|\d)(?: (?:ones?|\w+s|of them))?", text)
    if not m:
        return text, None
    said = m.group(2)
    return m.group(1), None if said in ("them", "all") else _COUNTS.get(said) or int(said)
