"""What an object looks like in words and in space, for reading noun phrases: its colours (the
scene's own naming, the capture's colour, and the colours its kind usually has), its extent for
size words, ordinal names, and whether a locator relation ("the can next to the bowl") holds.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

import numpy as np

from realsim.errors import InputError
from realsim.planner import relations
from realsim.planner.types import ObjectInfo
from realsim.planner.vocab import BIG, COLOR_WORDS, MATERIAL_KINDS, SIZE_AXIS, TYPICAL_COLORS, name_words, norm


def colors_of(o: ObjectInfo) -> set[str]:
    """Every colour word ``o`` may be called by: the colour words in its label or name, else its
    measured ``color`` and the usual colours of its kind ("banana": yellow, :data:`TYPICAL_COLORS`)."""
    out = {COLOR_WORDS[w] for w in norm(o.label).split() + norm(o.name).split() if w in COLOR_WORDS}
    if out:  # the scene's own naming (itself read from the capture) decides
        return out
    if o.color:
        out.add(COLOR_WORDS.get(o.color.lower(), o.color.lower()))
    for w in name_words(o.label):
        out.update(TYPICAL_COLORS.get(w, ()))
    return out


def usual_colour_pick(nouns: list[str], objs: list[ObjectInfo]) -> list[ObjectInfo]:
    """The one of ``objs`` whose colour is the usual colour of the kind ``nouns`` name ("the
    cracker box" between a white and a red box: the red one), else ``objs`` unchanged."""
    usual = {c for w in nouns for c in TYPICAL_COLORS.get(w, ())}
    hits = [o for o in objs if colors_of(o) & usual]
    return hits if len(hits) == 1 else objs


def usual_material_pick(words: list[str], objs: list[ObjectInfo]) -> list[ObjectInfo]:
    """Those of ``objs`` whose kind is usually made of the material ``words`` say ("the cardboard
    one" among cans, a mug and a cereal box: the box), when that leaves some; else ``objs``."""
    kinds = {k for w in words for k in MATERIAL_KINDS.get(w, ())}
    hits = [o for o in objs if kinds & {*name_words(o.label), *name_words(o.name)}]
    return hits if hits and kinds else objs


_OBLONG = frozenset({"rectangular", "oblong", "elongated"})
_ROUND = frozenset({"round", "cylindrical", "circular"})


def footprint_shape_pick(words: list[str], objs: list[ObjectInfo]) -> list[ObjectInfo]:
    """Of ``objs`` that their names do not tell apart, those whose footprint has the shape ``words`` say:
    "rectangular" one side at least 1.25 times the other, "round" within 1.15 ("the rectangular tin"
    of a round and a flat can); else ``objs``."""
    aspect = {o.name: (fp := o.footprint or (max(o.size[:2]), min(o.size[:2])))[0] / max(1e-6, fp[1]) for o in objs}
    hits = ([o for o in objs if aspect[o.name] >= 1.25] if _OBLONG & set(words)
            else [o for o in objs if aspect[o.name] < 1.15] if _ROUND & set(words) else [])
    return hits or objs


# hues a measured colour is easily named as instead (a yellow box measured orange)
NEIGHBOUR_HUES = {"yellow": ("orange",), "orange": ("yellow", "red"), "red": ("orange", "pink"), "pink": ("red", "purple"),
                  "purple": ("pink", "blue"), "blue": ("purple",), "white": ("gray",), "gray": ("white", "black"), "black": ("gray",)}


def neighbour_colour_pick(scored: list[tuple[ObjectInfo, float]], colors: list[str]) -> list[tuple[ObjectInfo, float]]:
    """When the noun names one object outright and its colour is not the said one: it, if its
    measured colour is a neighbouring hue ("the yellow cereal box" measured orange); else none
    (of several cubes, "the purple cube" is none of them)."""
    named = [(o, s) for o, s in scored if s >= 1.5]
    hits = [(o, s) for o, s in named if len(named) == 1 and o.color and all(
        any(n in colors_of(o) for n in (c, *NEIGHBOUR_HUES.get(c, ()))) for c in colors)]
    return hits if len(hits) == 1 else []


def between_of(head: str, refs_phrase: str, cands: list[ObjectInfo], resolve_all: Callable[[str], list[ObjectInfo]]) -> list[ObjectInfo]:
    """Of ``cands``, those between the two objects ``refs_phrase`` names; "the other two" are the
    two others that ``head`` names ("the cube in between the other two": the middle cube);
    ``resolve_all`` gives every object a phrase may mean."""
    if re.fullmatch(r"(?:the )?other (?:two|2|ones)(?: \w+)?", refs_phrase):
        kin = resolve_all(head)
        pairs = {o.name: [k for k in kin if k.name != o.name] for o in kin}
    else:
        refs = resolve_all(refs_phrase)
        pairs = {o.name: [r for r in refs if r.name != o.name] for o in cands}
    return [o for o in cands if len(pairs.get(o.name, [])) == 2
            and relations.between(pts(o), pts(pairs[o.name][0]), pts(pairs[o.name][1])).ok]


def nth(k: int) -> str:
    """"second" for 2."""
    return {1: "first", 2: "second", 3: "third", 4: "fourth", 5: "fifth"}.get(k, f"{k}th")


def pts(o: ObjectInfo) -> np.ndarray:
    """The corners of ``o``'s box."""
    return relations.box_points(o.position, o.size)


def _volume(o: ObjectInfo, word: str) -> float:
    axis = SIZE_AXIS.get(word)
    if axis == 2:
        return float(o.size[2])
    if axis == -1:
        return float(max(o.size))
    if axis == -2:
        return float(min(o.size[:2]))
    return float(np.prod(o.size))


def left_order(i: int, n: int) -> str:
    """The place of the ``i``-th of ``n`` objects counted from the robot's left: leftmost, second from the left..., rightmost."""
    return "leftmost" if i == 0 else "rightmost" if i == n - 1 else f"{nth(i + 1)} from the left"


def ranked_by_size(objs: list[ObjectInfo], word: str) -> list[ObjectInfo]:
    """``objs`` from the most to the least ``word`` (tall: height; long: extent; else volume):
    "the biggest" is the first, "the two smallest" the first two by "smallest"."""
    return sorted(objs, key=lambda o: _volume(o, word), reverse=word in BIG)


SIZE_MARGIN = 0.15  # sizes closer than this (relative) are not told apart by eye


def size_pick(objs: list[ObjectInfo], word: str, k: int) -> list[ObjectInfo]:
    """The ``k`` most ``word`` of ``objs``. When the ``k``-th and the next do not differ clearly in
    the size compared, a comparison ("bigger", "tallest") is refused with :class:`InputError` (three
    equal cubes have no "bigger" one) and a plain size word ("the tall can") picks nothing: every
    object about as ``word`` as the ``k``-th is kept, so another word must tell them apart or the
    caller asks which one (two equal cans are not told apart by "tall"), unless the scene's own name
    of exactly one of them carries the word."""
    ranked = ranked_by_size(objs, word)
    if len(ranked) > k:
        a, b = _volume(ranked[k - 1], word), _volume(ranked[k], word)
        if abs(a - b) < SIZE_MARGIN * max(a, b, 1e-9):
            close = [o for o in ranked if abs(_volume(o, word) - a) < SIZE_MARGIN * max(a, 1e-9)]
            if re.search(r"(?:er|est)$", word):
                raise InputError(f"{word!r} is ambiguous: {', '.join(o.name for o in close)} are about the same size; "
                                 "say which one another way")
            named = [o for o in close if word in re.split(r"[^a-z]+", f"{o.name} {o.label}".lower())]
            if k == 1 and len(named) == 1:  # the scene's own name says it ("left_tall_white_can")
                return named
            return ranked[:k - 1] + [o for o in close if o not in ranked[:k - 1]]
    return ranked[:k]


def relation_holds(rel: str, o: ObjectInfo, ref: ObjectInfo, forward: np.ndarray, left: np.ndarray) -> bool:
    """Whether ``o`` is ``rel`` (next, on, in, left, right, behind, front) of ``ref``; directions in the robot's frame."""
    a, b = pts(o), pts(ref)
    if rel == "next":
        return relations.xy_gap(a, b) <= 0.12
    if rel == "on":
        return relations.on(a, b, tolerance=0.03).ok
    if rel == "in":
        return relations.inside(a, b).ok or (relations.xy_gap(a, b) == 0.0 and a[:, 2].min() < b[:, 2].max())
    d = {"left": left, "right": -left, "behind": forward, "front": -forward}[rel]
    return relations.side_of(a, b, d, max_gap=0.3).ok


def next_over(rel: str, cands: Sequence[ObjectInfo], ref: ObjectInfo, forward: np.ndarray, left: np.ndarray) -> list[ObjectInfo]:
    """"the thing to the right of the can" when nothing stands squarely to its right: the one object
    whose centre lies beyond the can's own side in that direction and nearest along it (the next one over)."""
    d = {"left": left, "right": -left, "behind": forward, "front": -forward}[rel][:2]
    centre, half = np.asarray(ref.position[:2], float), float(np.abs(np.asarray(ref.size[:2], float)) @ np.abs(d)) / 2
    beyond = [(float((np.asarray(o.position[:2], float) - centre) @ d), o) for o in cands if o.name != ref.name]
    beyond = sorted(((s, o) for s, o in beyond if s > half), key=lambda t: t[0])
    if not beyond or (len(beyond) > 1 and beyond[1][0] - beyond[0][0] < 0.02):  # two as near: the speaker is asked
        return [o for s, o in beyond if s - beyond[0][0] < 0.02] if beyond else []
    return [beyond[0][1]]


def holding(head: str, held_phrase: str, resolve_all: Callable[[str], list[ObjectInfo]],
            holds: Callable[[str, ObjectInfo, ObjectInfo], bool], phrase: str) -> list[ObjectInfo]:
    """"the bowl with the strawberry": the one object ``head`` names that holds (in or on it) what
    ``held_phrase`` names; refused when none or several do ("put the banana in the bowl with the
    strawberry" may mean both go in: the speaker is asked, the strawberry is never the target)."""
    held = resolve_all(held_phrase)
    hits = [o for o in resolve_all(head) if o not in held and all(holds("in", h, o) or holds("on", h, o) for h in held)]
    if len(hits) != 1:
        raise InputError(f"{phrase.strip()!r}: {len(hits) or 'no'} {head} hold{'s' if len(hits) < 2 else ''} {held_phrase}; "
                         f"to move things together say 'put X and Y in Z'")
    return hits
