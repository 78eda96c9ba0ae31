"""The rule planner's working state and the arrangements it makes of several objects at once.

A :class:`Step` is what one clause does (calls, the goals to check, the objects it moves); a
:class:`Parser` holds the scene and what earlier clauses referred to. The arrangements here go
beyond one relation to one target: swapping two objects, putting several "next to each other"
or "on each other", "the other side" of a reference (opposite to where the object is now), and
"do that again".
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import Any

from realsim.errors import InputError
from realsim.planner.goals import Goal, Moved, NextTo, On, Placed
from realsim.planner.lexicon import PARTICLES
from realsim.planner.program import Call
from realsim.planner.reference import Context, Resolver
from realsim.planner.types import ObjectInfo

__all__ = ["EACH_OTHER", "SWAP", "Parser", "Step", "each_other", "objects_named", "other_side", "repeat", "swap"]


@dataclass
class Step:
    """What one clause does: its calls, the goals to check, the objects whose state it changes."""

    calls: list[Call]
    goals: list[Goal]
    objects: tuple[str, ...] = ()
    moves_robot: bool = True
    pending: str = ""  # a plural "take" that a later "put them ..." carries out, else this error
    aside: bool = False  # moves its objects out of the way (a later step that moves them anyway makes it a grasp)


@dataclass
class Parser:
    """The scene as the planner reads it and the context earlier clauses left ("it", "there")."""

    objects: Sequence[ObjectInfo]
    robot_yaw: float = 0.0
    robot_base: tuple[float, float] | None = None  # world xy of the robot base, when known
    ctx: Context = field(default_factory=Context)
    moved: set[str] = field(default_factory=set)  # objects earlier clauses moved
    taken: list[Any] = field(default_factory=list)  # xy boxes (lo, hi) earlier clauses moved objects to

    def __post_init__(self) -> None:
        self.resolver = Resolver(self.objects, self.robot_yaw, self.robot_base)
        self.by_name = {o.name: o for o in self.objects}


SWAP = re.compile(r"(?:swap|switch|exchange|trade|interchange)(?: around| over)?(?: the (?:positions|places|spots|seats|squares|locations) of| where| places of)?"
                  r" (.+?)(?: (?:and|with|for) (.+?))?(?: (?:are|is|around|round|over|places|positions|spots|seats|squares|sit))*")
EACH_OTHER = re.compile(r"(?:each other|one another|one other|together)")


def _away_side(p: Parser, a: ObjectInfo, b: ObjectInfo) -> str:
    """The side of ``b`` away from ``a`` along the axis they differ most on (robot frame)."""
    (af, al), (bf, bl) = p.resolver.robot_xy(a), p.resolver.robot_xy(b)
    return ("left" if bl > al else "right") if abs(bl - al) >= abs(bf - af) else ("behind" if bf > af else "front")


def swap(a_phrase: str, b_phrase: str | None, p: Parser) -> Step:
    """Each object where the other was: the first steps aside (beyond the second, away from its
    own spot), the second goes to the first's spot, then the first to the second's. Without
    ``b_phrase``, ``a_phrase`` names both ("swap the soda cans")."""
    split = re.fullmatch(r"(.+?) (?:in|an|n|end) (.+)", a_phrase) if b_phrase is None else None
    if split:  # "swap the cube in the can": speech-to-text's "and", when the phrase names no two objects itself
        try:
            if len(objects_named(a_phrase, p)) == 2:
                split = None
        except InputError:
            pass
    if split:
        a_phrase, b_phrase = split.group(1), split.group(2)
    if b_phrase is None:
        pair = objects_named(a_phrase, p)
        if len(pair) != 2:
            raise InputError(f"a swap takes two objects; {a_phrase!r} names {len(pair)}; {p.resolver.listing()}")
        a, b = pair
    else:
        a = p.resolver.resolve(a_phrase, p.ctx, allow_plural=False)[0]
        b = p.resolver.resolve(b_phrase, Context(p.ctx.last), exclude=[a.name], allow_plural=False)[0]
    side = _away_side(p, a, b)
    pa, pb = [round(v, 3) for v in a.position], [round(v, 3) for v in b.position]
    p.ctx.set([a, b])
    return Step([Call("place_beside", (a.name, b.name, side)), Call("place", (b.name, pa)), Call("place", (a.name, pb))],
                [Placed(a.name, (pb[0], pb[1])), Placed(b.name, (pa[0], pa[1]))], (a.name, b.name))


def repeat(steps: list[Step]) -> Step:
    """The last step once more ("push the cube 3 cm left, then do that again"): a push's goal is
    then the distance of both pushes."""
    last = next((s for s in reversed(steps) if s.calls), None)
    if last is None:
        raise InputError("'again' repeats nothing: say what to do first")
    pushed = {str(c.args[0]): float(c.args[2]) for c in last.calls if c.name == "push" and isinstance(c.args[2], (int, float))}
    goals = [replace(g, distance=round(g.distance + pushed.get(g.obj, 0.0), 3)) if isinstance(g, Moved) else g for g in last.goals]
    return Step(list(last.calls), goals, last.objects, last.moves_robot)


def other_side(p: Parser, obj: ObjectInfo, ref: ObjectInfo) -> str:
    """"the other side of the bowl": the side of ``ref`` opposite to where ``obj`` is now."""
    return _away_side(p, obj, ref)


def each_other(objs: list[ObjectInfo], kind: str, p: Parser) -> Step:
    """Several objects "next to each other" (each beside the first) or "on each other" (a tower,
    the biggest at the bottom)."""
    if len(objs) < 2:
        raise InputError(f"'each other' needs two or more objects, got {len(objs)}; {p.resolver.listing()}")
    p.ctx.set(objs)
    if kind == "on":
        tower = sorted(objs, key=lambda o: -float(o.size[0] * o.size[1] * o.size[2]))
        return Step([Call("place_on", (o.name, below.name)) for below, o in zip(tower, tower[1:])],
                    [On(o.name, below.name) for below, o in zip(tower, tower[1:])], tuple(o.name for o in tower[1:]))
    first, rest = objs[0], objs[1:]
    return Step([Call("place_beside", (o.name, first.name, "next")) for o in rest],
                [NextTo(o.name, first.name) for o in rest], tuple(o.name for o in rest))



def objects_named(phrase: str, p: Parser, want: str | None = None, exclude: Sequence[str] = ()) -> list[ObjectInfo]:
    """The objects a phrase names, with a trailing particle ("up", "over") and a leading "up/back/down" dropped."""
    phrase = re.sub(rf"(?<!the){PARTICLES}$", "", " " + phrase).strip()  # "the thing in the back" keeps its "back"
    phrase = re.sub(r"^(?:up|back|down)\s+", "", phrase)
    if re.match(r"(?:off|off of|from|out of) (?:the|that|this|it|them)\b", phrase):  # "off the green cube, down on the table": where from, never what
        raise InputError(f"{phrase!r} says where something comes from, not what it is; name the object")
    objs = p.resolver.resolve(phrase, p.ctx, want=want, exclude=exclude)
    return objs
