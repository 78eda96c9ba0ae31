"""A place said again more precisely after a comma: "put the can next to the bowl, on the left",
"put the mug by the box, a bit closer to me".

A refinement names a side of the reference as seen from the robot. It turns "next to" (any
side) into that side; after another side already given it shifts the object that way by the amount said (a
few cm when none is), by a push once it stands there; the same side again only stresses it,
unless it says how far.
"""

from __future__ import annotations

import re

from realsim.planner.goals import NextTo, SideOf
from realsim.planner.program import Call
from realsim.planner.pushes import distance
from realsim.planner.steps import Step
from realsim.planner.vocab import VAGUE_DISTANCES

__all__ = ["REFINE", "SHIFT", "refine", "refines"]

SHIFT = 0.03  # m: "a bit further left" after a side is already given
_AMOUNT = (r"(?:(?:about |around |roughly |maybe )?(?:\d+(?:\.\d+)?|a few|a couple of|one|two|three|four|five) ?(?:cm|mm|centimet\w*|millimet\w*|inch\w*)|"
           + "|".join(re.escape(v) for v in sorted(VAGUE_DISTANCES, key=len, reverse=True)) + ")")
_SIDES: tuple[tuple[str, str], ...] = (
    (r"(?:on |to |at |towards? )?(?:the |its |their )?left(?: side| hand side| of it)?", "left"),
    (r"(?:on |to |at |towards? )?(?:the |its |their )?right(?: side| hand side| of it)?", "right"),
    (r"(?:closer|nearer)(?: to (?:me|you|the robot|us))?|(?:towards?|to) (?:me|you|us|the robot)|(?:on|at) (?:the |this |my |your )?(?:near|front) side(?: (?:to|from) (?:me|you|the robot|us))?"
     r"|in front(?: of it)?|at the front|on this side", "front"),
    (r"(?:further|farther)(?: away| back| out)?(?: from (?:me|you|the robot|us))?|(?:on|at) (?:the )?(?:far|back) side(?: from (?:me|you|the robot|us))?|behind(?: it)?|at the back", "behind"),
)
REFINE = re.compile(rf"(?:and |but )?(?:{_AMOUNT} )?(?:more |further |farther )?(?:{'|'.join(f'(?:{s})' for s, _ in _SIDES)})(?: {_AMOUNT})?(?: though| instead| please)?")
"""A clause that only refines where the previous one put something."""
_PUSH_WAY = {"left": "left", "right": "right", "front": "back", "behind": "forward"}


def refines(step: Step | None, clause: str) -> bool:
    """Whether ``clause`` refines ``step``'s place beside another object."""
    return bool(step is not None and step.calls and step.calls[-1].name == "place_beside" and REFINE.fullmatch(clause))


def _side(clause: str) -> str:
    body = re.sub(rf"^(?:and |but )?(?:{_AMOUNT} )?", "", clause)
    for text in (body, re.sub(r"^(?:more|further|farther) ", "", body)):  # "further away"; "further to the left"
        side = next((side for pattern, side in _SIDES if re.fullmatch(rf"(?:{pattern})(?: {_AMOUNT})?(?: though| instead| please)?", text)), None)
        if side is not None:
            return side
    raise ValueError(f"{clause!r} names no side")


def refine(step: Step, clause: str) -> Step:
    """``step`` with its last place beside moved to the side ``clause`` names (see module doc)."""
    last = step.calls[-1]
    obj, ref, side = str(last.args[0]), str(last.args[1]), str(last.args[2])
    way = _side(clause)
    if side == "next":
        goals = [SideOf(obj, ref, way) if isinstance(g, NextTo) and g.obj == obj and g.ref == ref else g for g in step.goals]
        return Step([*step.calls[:-1], Call("place_beside", (obj, ref, way))], goals, step.objects, step.moves_robot)
    said = re.search(_AMOUNT, clause)
    if way == side and not (said and re.search(r"\d|cm|mm|centim|millim|inch", said.group(0))):
        return step  # "in front of the bowl, a little closer to you": the side said again
    dist = (distance(said.group(0)) if said else None) or SHIFT
    return Step([*step.calls, Call("push", (obj, _PUSH_WAY[way], round(dist, 3)))], step.goals, step.objects, step.moves_robot)
