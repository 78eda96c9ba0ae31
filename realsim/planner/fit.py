"""Whether a thing can go *in* another: only what holds things (the scene's ``container`` or
``drawer`` affordance) does, and only what passes its opening (the thing's narrower footprint side
under the container's narrower footprint side). An unsure "in" is refused with the reason, never
turned into an Inside goal ("fit the box inside the can", "put it in the mustard bottle")."""

from __future__ import annotations

from realsim.errors import InputError
from realsim.planner.types import ObjectInfo

HOLDS = ("container", "drawer")  # affordances of things that hold things
OPENING = 0.95  # the share of a container's footprint its opening spans (its walls take the rest)


def holds_things(obj: ObjectInfo) -> bool:
    """Whether ``obj`` is an open container or a drawer."""
    return any(a in obj.affordances for a in HOLDS)


def check_fits(obj: ObjectInfo, container: ObjectInfo, listing: str) -> None:
    """Raise :class:`InputError` unless ``obj`` can be put in ``container``."""
    if not holds_things(container):
        raise InputError(f"{container.name} ({container.label}) is not an open container, so nothing can be put "
                         f"inside it; say where beside it (left of, behind, on ...); {listing}")
    need, opening = min(obj.size[:2]), OPENING * min(container.size[:2])
    if need >= opening:
        raise InputError(f"{obj.name} ({obj.label}, {need * 100:.0f} cm across at its narrowest) does not fit in "
                         f"{container.name} ({container.label}, opening about {opening * 100:.0f} cm); {listing}")


def held_in(target_phrase: str, target: ObjectInfo, place: ObjectInfo | None, listing: str) -> ObjectInfo:
    """The container "in it" names: ``target`` if it holds things, else the place just used if that
    does ("put the banana next to the bowl, we want the strawberry in it too"), else refused."""
    if target_phrase not in ("it", "them") or holds_things(target):
        return target
    if place is None or not holds_things(place):
        raise InputError(f"'in it': {target.name} holds nothing; name the container; {listing}")
    return place
