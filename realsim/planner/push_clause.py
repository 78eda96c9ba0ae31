"""Push clauses: "push the left can 5 cm forward" (a way and a distance) and "push the mug
toward the bowl" / "nudge it away from the can" (a way relative to another object)."""

from __future__ import annotations

import re

from realsim.errors import InputError
from realsim.planner.goals import DIRECTIONS, Moved
from realsim.planner.program import Call
from realsim.planner.pushes import NOT_OBJECT, TAIL, distance, has_direction
from realsim.planner.reference import Context
from realsim.planner.steps import Parser, Step, objects_named, other_side
from realsim.planner.vocab import DIRECTION_WORDS

__all__ = ["DEFAULT_PUSH", "TOWARD", "push_clause", "push_relative"]

DEFAULT_PUSH = 0.10  # m, when no distance is given
# "toward", "closer to", "up against", "next to" another object (a push verb: along the way to it,
# stopping short of it), or "away from" it
TOWARD = re.compile(r"(.+?) (towards?|(?:closer|nearer) to|(?:right |all the way )?up (?:to|against)|against|(?:right )?next to|beside"
                    r"|(?:further|farther)(?: away)? from|away from) (?!(?:me|you|yourself|the robot|us|the camera)\b)(.+)")
_PUSH_WAY = {"left": "left", "right": "right", "behind": "forward", "front": "back"}
_OPPOSITE = {"left": "right", "right": "left", "forward": "back", "back": "forward"}


def push_clause(rest: str, p: Parser, clause: str) -> Step:
    """A push by a way word and a distance; the object phrase ends where the way begins."""
    objs, tail, first_error = None, "", None
    for cut in [*TAIL.finditer(rest), None]:  # "push the left can forward": "left" names the can, not the way
        obj_phrase = rest[: cut.start()].strip() if cut else rest
        if (not obj_phrase or NOT_OBJECT.search(obj_phrase) or re.search(r"\b(?:of|the|a|an)$", obj_phrase)
                or re.search(r"\b(?:closer|nearer|further|farther)(?: away)?$", obj_phrase)  # "the one closer | to me": a pick, unfinished
                or (cut is not None and not has_direction(rest[cut.start():]))):
            continue
        try:
            objs = objects_named(obj_phrase, p)
        except InputError as exc:
            first_error = first_error or exc
            continue
        tail = rest[cut.start():] if cut else ""
        break
    if objs is None:
        raise first_error or InputError(f"push what? {clause!r}: name the object and a way (left, right, forward, back)")
    direction = None
    for phrase in sorted(DIRECTION_WORDS, key=len, reverse=True):
        if re.search(rf"(?<![a-z]){re.escape(phrase)}(?![a-z])", tail):
            direction = DIRECTION_WORDS[phrase]
            break
    if direction is None:
        raise InputError(f"which way? say left, right, forward or back in {clause!r}")
    dist = distance(tail) or DEFAULT_PUSH
    p.ctx.set(objs)
    return Step([Call("push", (o.name, direction, round(dist, 3))) for o in objs],
                [Moved(o.name, DIRECTIONS[direction], round(dist, 3)) for o in objs], tuple(o.name for o in objs))


def push_relative(m: re.Match[str], dist: float | None, p: Parser) -> Step:
    """A :data:`TOWARD` match: along the robot-frame axis on which the two objects differ most;
    toward stops short of the other object (1 cm gap) when no distance is said."""
    obj_phrase, ref_phrase = (NOT_OBJECT.split(g, maxsplit=1)[0].strip() for g in (m.group(1), m.group(3)))
    obj = p.resolver.resolve(obj_phrase, p.ctx, allow_plural=False)[0]
    ref = p.resolver.resolve(ref_phrase, Context(p.ctx.last), exclude=[obj.name], allow_plural=False)[0]
    direction = _PUSH_WAY[other_side(p, obj, ref)]
    if "from" in m.group(2):
        direction = _OPPOSITE[direction]
    elif dist is None:
        (of, ol), (rf, rl) = p.resolver.robot_xy(obj), p.resolver.robot_xy(ref)
        half = 0.5 * (max(obj.size[:2]) + max(ref.size[:2]))  # the footprints' reach along the way, at most
        gap = abs(ol - rl if direction in ("left", "right") else of - rf) - half - 0.01
        if gap < 0.01:
            raise InputError(f"{obj.name} already touches {ref.name}: there is no room to push it toward it")
        dist = min(DEFAULT_PUSH, gap)
    dist = round(dist if dist is not None else DEFAULT_PUSH, 3)
    p.ctx.set([obj])
    return Step([Call("push", (obj.name, direction, dist))], [Moved(obj.name, DIRECTIONS[direction], dist)], (obj.name,))
