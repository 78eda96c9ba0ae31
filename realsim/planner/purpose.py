"""A purpose said before the request it leads to: "I'm heating up soup later, so the soup can
should be next to the bowl", "I want to read the label on the box, so the can on top of it has to
go somewhere else", "I'm about to set a coffee down where the can is, so clear it away".

Rule: a sentence that opens with the speaker's own plan or want (I'm / I want / I need / I'm
about to / we're ... ) and goes on with ", so ..." is the request after "so"; the plan before it
only lends its last named thing to a leading "it" of the request. What must stop being where it is
("X can't stay where it is", "X has to go somewhere else") is X put aside, and a reach or view
tail ("where I can reach it") or a hoped-for result after the request ("..., and then they can be
friends") says nothing about where X goes.
"""

from __future__ import annotations

import re

__all__ = ["purpose"]

_SPEAKER = r"(?:i(?:'m| m|m| am)|im|i(?:'ll| ll| will)|i(?:'ve| ve| have) got to|i (?:want|need|have|plan|intend|would like|d like|'d like)|we(?:'re| re| are)|we (?:want|need|have)|my plan is)"
_SO = re.compile(rf"(?:^|(?<=[.;!?] ))({_SPEAKER}\b[^.;!?]*?),?\s+so(?: that)?\s+(?!(?:i|we|you|it|they) (?:can|could|may|will) (?:see|reach|get|grab|use|read)\b)([^.;!?]+)")
_THING = re.compile(r"\b(?:the|my|your|that|this) (?!(?:way|time|moment|end|label|shot|photo|picture|list|idea|plan)\b)[a-z']+(?: (?!(?:and|so|then|where|is|on|in|down|up|with|for|to|of)\b)[a-z']+)*")
_LEAD_PRONOUN = re.compile(r"^((?:(?!\b(?:the|my|your|that|this)\b)[a-z' ,])*?)\b(it|them)\b")
_AWAY = re.compile(r"\b((?:the|my|your|that|this) [a-z' ]+?) (?:can(?:'t| t|not|t) stay (?:where it is|there|where it sits|put)|(?:has|needs|will have|must|ought) (?:to )?(?:go|move|be moved|be put)"
                   r" (?:somewhere else|elsewhere|away|out of the way|out of (?:the|my) (?:way|shot|picture|photo|frame)))\b")
_REACH = re.compile(r",?\s*\b(?:(?:where|so) (?:i|we|you) (?:can|could|will) (?:reach|grab|get|see|use|read) (?:it|them|to it)"
                    r"|where (?:it|they)(?:'s| s| is| are|'ll| ll| will be| can be| d be| would be)? (?:safe|safer|secure|stable|steady|out of the way|fine|okay|ok))\b")
# the result hoped for, said after the request: "..., and then they can be friends", "... so it'll look tidier"
_RESULT = re.compile(r",?\s+(?:and |so |so that )(?:then )?(?:they|it|we|he|she|everything|that|this)(?:'ll| ll| will|'d| d| can| could| would| might| should)?"
                     r" (?:be|look|stay|sit|feel|have|keep|get along|match)\b[^.;!?]*")
_BACK_ON = re.compile(r"\s(?:that(?:'s| s| is) |which is )?(?:sitting|standing|resting|lying|perched|sat|stacked) (?:on top of|on|atop|in|inside|next to|beside|behind|in front of) (?:it|them)\b")


def purpose(text: str) -> str:
    """``text`` (lower case, punctuation kept) with a leading purpose reduced to its request."""
    def request(m: re.Match[str]) -> str:
        reason, said = m.group(1), _BACK_ON.sub("", m.group(2))
        things = _THING.findall(reason)
        if things and (p := _LEAD_PRONOUN.match(said)):
            said = f"{p.group(1)}{things[-1]}{said[p.end():]}"
        return said
    text = _SO.sub(request, text)
    text = _AWAY.sub(r"put \1 aside", text)
    return _RESULT.sub("", _REACH.sub("", text))
