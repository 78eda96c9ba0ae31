"""Chat about people around a command: "She wants the banana closer to her.", "..., honey wants
them together", "The little one keeps grabbing it.", "We're lining them up.".

Rule: a sentence, or the last comma piece of one, whose subject is a person (a pronoun other
than "I" and "you", or a word for a family member, a child, a colleague or a term of
endearment) and whose verb is a statement (wants, keeps, is, likes, ...) is talk, but only when
another part of the text holds a command verb, and only when it names no place by a thing
("we need the mug in the bowl" is kept: a request). "She wants you to put ...", "Dana asked me
to pass this on: ..." and "she wants it next to the bottle" are requests through her: the command
stays, without its opening.
"""

from __future__ import annotations

import re

from realsim.planner.lexicon import RELATION_AT, VERB_ANYWHERE

__all__ = ["people"]

_WHO = (r"(?:she|he|they|we|(?:my|our|the|your|his|her) (?:little |baby |youngest |eldest |oldest |older |younger |new )?"
        r"(?:one|son|daughter|kid|kids|child|children|boy|girl|boys|girls|wife|husband|partner|mum|mom|mother|dad|father|baby|boss|colleague"
        r"|colleagues|friend|friends|guest|guests|family|team|toddler|grandson|granddaughter|grandkids|neighbour|neighbor|roommate|flatmate)"
        r"|honey|sweetie|darling|hubby|grandma|grandpa|granny|mum|mom|dad|everyone|everybody|somebody|someone"
        r"|(?:the |our |my |your |this )?(?:buyer|customer|client|bidder|winning bidder|winner|gentleman|lady|owner|audience|crowd|judges?|boss|chef|teacher))")
_SAYS = (r"(?:s|re|is|are|was|were|wants?|wanted|likes?|liked|loves?|needs?|keeps?|kept|has|have|had|will|ll|d|would|gets?|got|can|could"
         r"|might|always|never|just|hates?|prefers?|thinks?|says?|said|asked|asks)")
_REMARK = re.compile(rf"(?:(?:and|but|oh|because|cause|so|cos)\s+)?{_WHO}\s*'?\s*{_SAYS}\b[^.!?;]*")
_THROUGH = re.compile(rf"^\s*{_WHO}\s+(?:wants?|would like|d like|needs?|asked(?: for)?|asks)\s+(?:you|the robot)\s+to\s+")
# a request passed on: "Dana asked me to pass this on: ...", "Coach told me to tell you to ...", "my flatmate says ..."
_RELAY = re.compile(rf"^\s*(?:(?:{_WHO}|[a-z]+) (?:asked|told) me(?: to (?:pass (?:this|it|that) (?:on|along)|tell you|ask you|let you know|say))?"
                    rf"|{_WHO} (?:says|said))(?: that)?\s*[:,-]*\s*(?:to (?=[a-z]+ (?:the|it|them|that|this|all|both|a)\b))?")
# her wish with a place is a request through her: "she wants it next to the mustard bottle"
_WISH = re.compile(rf"^(\s*){_WHO} (?:wants|would like|d like|needs|asked for|asks for)\s+(?!you\b|the robot\b|to\b)")
_COMMAND = re.compile(rf"{VERB_ANYWHERE.pattern}|\b(?:swap|switch|exchange|trade)\b")
_PLACE = re.compile(rf"{RELATION_AT.pattern}\s+(?:the|a|an|this|that|my|your|it|them)\b")


def people(text: str) -> str:
    """``text`` (lower case, punctuation kept) without its remarks about people (see the module)."""
    sentences = re.findall(r"[^.!?;]+[.!?;]*", text)
    kept: list[str] = []
    for i, sentence in enumerate(sentences):
        sentence = _RELAY.sub("", _THROUGH.sub("", sentence))
        if _PLACE.search(sentence):
            sentence = _WISH.sub(r"\1i want ", sentence)
        others = "".join(s for j, s in enumerate(sentences) if j != i)
        body = sentence.rstrip(" .!?;")
        if _is_remark(body) and _COMMAND.search(others):
            continue
        head, _, tail = body.rpartition(",")
        if head and _is_remark(tail) and _COMMAND.search(head):  # "put X next to Y, honey wants them together"
            sentence = head + sentence[len(body):]
        kept.append(sentence)
    return "".join(kept) if kept else text


def _is_remark(piece: str) -> bool:
    piece = piece.strip()
    return bool(_REMARK.fullmatch(piece)) and not _PLACE.search(piece)
