"""Where a thing is, said loosely, put in the one form the resolver reads: an intensified side
("way over on the left", "all the way on the right", "furthest left") as the extreme ("the
leftmost"), and an intensified front or back ("right up front", "at the very back", "way in the
back") as "at the front" / "at the back". A relation to another object ("to the left of the box")
is never touched.
"""

from __future__ import annotations

import re

__all__ = ["positions"]

_BOOST = r"(?:way|all the way|far|very|right|just|really)\s+(?:(?:over|out|up|down|back)\s+)?"
_NOT_OF = r"(?!\s+(?:hand )?(?:side |end |edge )?of\b)"


def positions(text: str) -> str:
    """``text`` with loosely said positions in their plain form (see the module)."""
    text = re.sub(rf"\b{_BOOST}(on|at|in) (?:the )?(?:very |far |extreme )?(left|right)(?: hand)?(?: side| end| edge)?\b{_NOT_OF}", r"on the far \2", text)
    text = re.sub(rf"\b(?:{_BOOST})?(?:at|in|on) the (?:very |far |extreme )(front|back)\b{_NOT_OF}", r"at the \1", text)
    text = re.sub(rf"\b{_BOOST}(?:at|in|on) the (front|back)\b{_NOT_OF}", r"at the \1", text)
    text = re.sub(rf"\b(?:right |way )?up front\b{_NOT_OF}", "at the front", text)
    text = re.sub(r"\bthe ((?!(?:furthest|farthest|most)\b)[a-z]+(?: [a-z]+)?) (?:furthest|farthest|most) (?:to the |on the )(left|right)\b", r"the \2most \1", text)
    return re.sub(r"\b(?:(?:that is |thats |that s |which is |which s )?(?:the )?(?:furthest|farthest|most) (?:to the |on the )?|(?:on |to )?the (?:far|very) )(left|right)\b",
                  r"the \1most", text)

