"""Requests said as wishes: "it would be nice if the brick were in front of the bottle", "I'd like
the blue cube stacked on the red one", "I was hoping the can could end up left of the box".

Rule: a wish frame (it would be nice / lovely / great if ..., I'd like / love / want / prefer ...,
I was hoping ...) whose object is a noun phrase with a determiner and whose end is a place word
and a target is the request to put that object there, as is a question whether it could go there ("could the
can perhaps go in front of the box?", "is there any way the mug could end up ..."). A wish without a place ("I'd like the mug")
is left alone: it is read as the take it asks for, or refused. Two things wished swapped ("I'd like the mug and
the bowl to have traded places") are the swap.
"""

from __future__ import annotations

import re

from realsim.planner.lexicon import RELATIONS

__all__ = ["as_request"]

_THING = r"(it|them|(?:the|that|this|those|these|my|both|all(?: the)?)(?: (?!(?:closest|nearest|farthest|furthest|closer|nearer|further|farther)\b)[a-z']+)+?)"
# a place the object is wished at; "to", "by", "over" and the like also say which one ("the can closest to the bowl")
_PLACE = "|".join(re.escape(w) for w, _ in sorted(RELATIONS, key=lambda r: -len(r[0]))
                  if w not in ("to", "by", "over", "above", "near", "nearby", "toward", "towards", "closer to", "nearer to", "close to", "against"))
_STATE = (r"(?:(?:to be|to go|to end up|to sit|to stand|could be|would be|were to be|could end up|would end up|could go|could sit|might be|can be"
          r"|were|was|is|are|ended up|end up|be|found its way|could find its way|made its way|somehow found its way|got) )?(?:(?:sitting|standing|resting|lying|placed|put|set|moved|stacked|sat|stood|set down|put down) )?"
          r"(?:(?:neatly|nicely|carefully|properly|tidily|gently|right|just|over) )*")
_FRAMES = (
    r"(?:it|that|things)(?: would| ?'d| will| might)? be (?:(?:really|so|very|quite|rather) )?(?:nice|lovely|great|good|grand|wonderful|helpful|ideal"
    r"|better|perfect|cool|neat|awesome|brilliant|handy|fab|fabulous) if ",
    r"i(?: was| ?'m| am| have been| ?'ve been| ?'d been)? (?:(?:sort of|kind of|kinda|really|rather|just) )?hoping (?:that )?",
    r"i(?: would| ?'d)? (?:much |far )?rather (?:have )?", r"(?:make|have) (?:it )?so (?:that )?",
    r"(?:i|we)(?: would| ?'d| will| ?'ll)? (?:feel|be) (?:(?:a lot|much|so|far) )?(?:better|happier|calmer|more comfortable|safer) (?:with |if )",
    r"(?:i|we)(?: would| ?'d| will| ?'ll)? be (?:(?:ever so|so|very|really|most|eternally|truly|forever|super|awfully) )*"
    r"(?:grateful|thankful|happy|glad|delighted|pleased|obliged|chuffed|thrilled|relieved) if ",
    r"i(?: should| would| ?'d| will| do)? (?:(?:very much|really|so|quite|rather|much|sort of|kind of|kinda|honestly|actually|also|just) )*(?:like|love|want|prefer|wish) (?:to (?:see|have|find|come back to) |it if )?",
    r"(?:what|the picture) i(?: ?'m| am| have) (?:picturing|imagining|envisioning|seeing|got in mind|in mind) is ",
    r"(?:the way i(?: would| ?'d)? (?:like|want) (?:it|things|them)(?: is| to be)?|what i(?: ?'m| am) after is|what i(?: ?'d| would)? (?:like|want|need) is"
    r"|all i (?:want|need) is|my goal is|the goal is|ideally|in the end|in my (?:head|mind|mind ?'?s eye))[:,]? ",
)
# asked, not told: "could the can perhaps go in front of the box?", "is there any way the mug could end up left of the bowl?"
_WHOLE_THING = r"((?:the|that|this|my)(?: (?!(?:could|might|would|may|should|will|perhaps|maybe|possibly)\b)[a-z']+)+)"  # greedy: "the tall white can perhaps go" keeps "can" in the thing
_SOFT = r"(?:(?:perhaps|maybe|possibly|please|just|somehow) )*"
_GOES = (r"(?:go|end up|sit|be|stand|move|get|be put|be placed|be moved|be set|rest) (?:(?:neatly|nicely|right|just|over|somewhere|someplace|anywhere) )*"
         rf"(?=(?:{_PLACE}|where) )")
_START = r"(?:^|(?<=[.,;!?] )|(?<=\bthen )|(?<=\band ))(?:(?:maybe|perhaps|possibly) )?"
_ASKED = (re.compile(rf"{_START}(?:(?:but|and|so) )?(?:(?:is there (?:any|a|some) (?:way|chance)|(?:is there )?any chance|is it (?:at all )?possible|would it be possible"
                     r"|(?:i )?(?:don ?'?t|do not) suppose|(?:i )?(?:wonder|was wondering|am wondering|m wondering) (?:if|whether)) (?:that )?"
                     rf"|(?:could|can|might|would|may) (?:you (?:have|get|let|make) )?){_WHOLE_THING} {_SOFT}(?:(?:could|can|might|would) {_SOFT})?{_GOES}"),
          re.compile(rf"{_START}{_WHOLE_THING} {_SOFT}(?:could|might|would|can) {_SOFT}{_GOES}"))
# said as how it would look: "it would look better standing beside the bowl", "the mug would be happier in the bowl"
_BETTER = re.compile(rf"{_START}(?:(?:but|and|so|honestly|really) )?(it|they|them|{_WHOLE_THING}) (?:would|d|will|might|could) (?:look|be|sit|fit|feel|go)(?: so| much| a lot| far| way)?"
                     r" (?:better|nicer|best|good|great|lovely|neater|tidier|happier|right|perfect)(?: (?:standing|sitting|resting|placed|put|set|lying))?"
                     rf"(?: (?:if (?:it|they) (?:were|was|went|sat|stood)|(?:over )?there|instead))? (?=(?:{_PLACE}) )")
# two things wished swapped: "I'd like the mug and the bowl to have traded places", "I want them switched round"
_SWAPPED = re.compile(rf"(?:^|(?<=[.,;!?] ))(?:(?:but|and|so) )?(?:{'|'.join(_FRAMES)}){_THING} (?:to )?(?:have )?(?:been )?"
                      r"(?:traded|swapped|switched|exchanged|trade|swap|switch|exchange)(?: (?:places|positions|spots|seats|squares|round|around|over))?\b")
_WISH = re.compile(rf"(?:^|(?<=[.,;!?] ))(?:(?:but|and|so|though|although|yet) )?(?:{'|'.join(_FRAMES)}){_THING} {_STATE}(?=(?:{_PLACE}) )")


def as_request(text: str) -> str:
    """``text`` (lower case) with every wish for an object to be at a place turned into "put X ..."."""
    text = _SWAPPED.sub(lambda m: f"swap {m.group(1)}", text)
    text = _WISH.sub(lambda m: f"put {m.group(1)} ", text)
    text = _BETTER.sub(lambda m: f"put {m.group(1)} ", text)
    for asked in _ASKED:
        text = asked.sub(lambda m: f"put {m.group(1)} ", text)
    return text
