"""Whether a thing can go *in* another: only an open container (the scene's ``container``
affordance) holds things, and only what passes its opening (the thing's narrower footprint side
under the container's narrower footprint side). An unsure "in" is refused with the reason, never
turned into an Inside goal ("fit the box inside the can", "put it in the mustard bottle")."""

from __future__ import annotations

from realsim.errors import InputError
from realsim.planner.types import ObjectInfo

OPENING = 0.95  # the share of a container's footprint its opening spans (its walls take the rest)


def check_fits(obj: ObjectInfo, container: ObjectInfo, listing: str) -> None:
    """Raise :class:`InputError` unless ``obj`` can be put in ``container``."""
    if "container" not in container.affordances:
        raise InputError(f"{container.name} ({container.label}) is not an open container, so nothing can be put "
                         f"inside it; say where beside it (left of, behind, on ...); {listing}")
    need, opening = min(obj.size[:2]), OPENING * min(container.size[:2])
    if need >= opening:
        raise InputError(f"{obj.name} ({obj.label}, {need * 100:.0f} cm across at its narrowest) does not fit in "
                         f"{container.name} ({container.label}, opening about {opening * 100:.0f} cm); {listing}")


def held_in(target_phrase: str, target: ObjectInfo, place: ObjectInfo | None, listing: str) -> ObjectInfo:
    """The container "in it" names: ``target`` if it holds things, else the place just used if that
    does ("put the banana next to the bowl, we want the strawberry in it too"), else refused."""
    if target_phrase not in ("it", "them") or "container" in target.affordances:
        return target
    if place is None or "container" not in place.affordances:
        raise InputError(f"'in it': {target.name} holds nothing; name the container; {listing}")
    return place
