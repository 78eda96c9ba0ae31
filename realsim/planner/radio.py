"""A command said over a radio: call signs and procedure words around it ("Robot, this is Sam,
over.", "Base to robot, come in.", "How copy? Over.", "Roger, out.").

Rule: only in a text that uses radio procedure (a piece that is only "over", "over and out",
"roger", "copy", "how copy", "do you read me", "come in", "wilco" or "ten four"), the pieces that
are only procedure words or a call sign ("this is Sam", "Jo here", "control to robot") are
dropped. A piece that names anything else is kept whole, so no object, place or distance goes.
"""

from __future__ import annotations

import re

__all__ = ["radio"]

_PROCEDURE = (r"over(?: and out)?|out|roger(?: that| roger)?|copy(?: that)?|(?:how|do you) copy|(?:do )?you copy|(?:do you )?read me|do you read(?: me)?"
              r"|how do you read(?: me)?|come in|wilco|ten four|10 4|affirmative|(?:standing|stand) by(?: for (?:(?:further |new |the next )?(?:tasking|tasks?|instructions|orders)))?|say again|go ahead|over to you|break|message ends|end of message")
_STATION = r"(?:robot|arm|franka|panda|base|control|command|ops|operator|station|unit|team|lab|bench|desk|kitchen|tower)"
_CALL_SIGN = (rf"(?:robot|arm|franka|panda)(?: \w+)?|(?:this is|it s|its) [a-z]+(?: [a-z]+)?(?: here)?|[a-z]+ here|{_STATION}(?: \w+)? (?:to|calling) {_STATION}(?: \w+)?"
              rf"|(?:robot|arm|franka|panda),? (?:this is|it s) [a-z]+")
_PIECE = re.compile(r"[^.,;:!?]+[.,;:!?]*")
_IS_PROCEDURE = re.compile(rf"(?:(?:{_PROCEDURE})\s*)+")
_IS_CALL = re.compile(rf"(?:{_CALL_SIGN})")
_OBJECT_WORDS = re.compile(r"\b(?:the|a|an|that|this|it|them|cm|mm|inch|inches|left|right|front|behind|back|forward)\b")


def _words(piece: str) -> str:
    return " ".join(re.sub(r"[^a-z0-9 ]+", " ", piece).split())


def _is_call(words: str) -> bool:
    """A call sign alone: "this is sam", "jo here", "control to robot" (never "this is the mug")."""
    name = re.sub(r"^(?:(?:robot|arm|franka|panda) )?(?:this is|it s|its) ", "", words)
    return bool(_IS_CALL.fullmatch(words)) and not _OBJECT_WORDS.search(name)


def radio(text: str) -> str:
    """``text`` (lower case, punctuation kept) without radio procedure and call signs (see the module)."""
    pieces = _PIECE.findall(text)
    if not any(_IS_PROCEDURE.fullmatch(_words(p)) for p in pieces if _words(p)):
        return text
    kept = [p for p in pieces if not (_words(p) and (_IS_PROCEDURE.fullmatch(_words(p)) or _is_call(_words(p))))]
    out = "".join(kept).strip(" ,;:")
    return out if _words(out) else text
