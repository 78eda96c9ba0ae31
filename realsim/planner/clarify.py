"""A clarification after a command, "not X, Y": "put the brick next to the marker? not on top of
it, just beside it"; "put the red cube behind the green one? not the blue one, the green";
"no, not the small white one, the big one".

X and Y are both places or both things. When the command named X, Y replaces it ("put the blue
cube on the plate, not the blue one, the green one": the green cube). When it did not, Y must
agree with what the command said (the same kind of place; a thing whose words the command's
phrase has): then the clarification only confirms it and is dropped. Anything else is asked
about; the command is never carried out half-corrected.
"""

from __future__ import annotations

import re

from realsim.errors import InputError
from realsim.planner.lexicon import RELATION_AT, RELATIONS, VERB_ANYWHERE, VERB_START
from realsim.planner.speech import noun_phrases, one_as
from realsim.planner.vocab import NUMBERS

__all__ = ["amount", "clarify"]

_NOT = re.compile(r"(?:^|(?<=[.,;!?]))\s*(?:(?:no|nope|sorry|i mean|well|oh|um|uh|ah)\s*,?\s*)*(?:but )?not (?P<neg>[^,.;!?]+?)\s*(?:[,;.!]+\s*|$)"
                  r"(?:(?:but|just|rather|only|i mean|instead|more like)\s+)*(?P<pos>[^,.;!?]*?)\s*(?:\s(?:instead|please|thanks))?\s*(?=$|[.,;!?])")
_FUNCTION = {"the", "a", "an", "that", "this", "one", "ones", "thing", "object", "it", "them", "of", "right", "just", "directly"}


def _kind(phrase: str) -> str | None:
    """The relation kind a phrase opens with ("beside it": next), or None for a thing."""
    phrase = re.sub(r"^(?:right|just|directly|somewhere)\s+", "", phrase)
    for words, kind in sorted(RELATIONS, key=lambda r: -len(r[0])):
        if re.match(rf"{re.escape(words)}\b", phrase):
            return kind
    return None


def _relation_words(phrase: str) -> str:
    phrase = re.sub(r"^(?:right|just|directly|somewhere)\s+", "", phrase)
    return next(w for w, _ in sorted(RELATIONS, key=lambda r: -len(r[0])) if re.match(rf"{re.escape(w)}\b", phrase))


def _places(text: str) -> list[tuple[int, int, str]]:
    """(start, end, kind) of each relation phrase in ``text``, longest first at each place."""
    out: list[tuple[int, int, str]] = []
    for m in RELATION_AT.finditer(text):
        kind = _kind(m.group(0))
        if kind is not None:
            out.append((m.start(), m.end(), kind))
    return out


def _content(phrase: str) -> set[str]:
    return set(phrase.split()) - _FUNCTION


def clarify(text: str) -> str:
    """``text`` with a "not X, Y" after its command applied or dropped (see the module)."""
    m = _NOT.search(text)
    before = text[: m.start()].strip(" ,.;") if m else ""
    if not m or not before or not VERB_ANYWHERE.search(before) and not RELATION_AT.search(before):
        return text
    neg, pos, after = m.group("neg").strip(), m.group("pos").strip(), text[m.end():]
    if VERB_START.match(pos) or VERB_START.match(neg):  # "... . not the banana. put the can ...": a command of its own
        return text
    neg_kind, pos_kind = _kind(neg), _kind(pos)
    if not pos:  # "put the cube next to the plate, not on top of it": only a place the command did not say
        if neg_kind is not None and neg_kind not in {kind for _, _, kind in _places(before)}:
            return f"{before}{after}"
        said = _places(before)  # "onto the plate... wait, no, in front of it, not on it": the repair already took it back
        if neg_kind is not None and said and said[-1][2] != neg_kind and re.search(
                r"\b(?:wait|no|sorry|actually|i mean|rather)\b", before[max(b for _, b, k in said if k == neg_kind):said[-1][0]]):
            return f"{before}{after}"
        return text
    if (neg_kind is None) != (pos_kind is None):  # "put the mug, not the can, in the bowl": not a clarification
        return text
    asked = InputError(f"{text.strip()!r}: 'not {neg}, {pos}' does not match what the command said; say the whole command again")
    if pos_kind is not None:  # a place: the command's own place must be the one meant
        said = _places(before)
        kinds = {kind for _, _, kind in said}
        if pos_kind in kinds and neg_kind not in kinds:
            return f"{before}{after}"
        last = [(a, b) for a, b, kind in said if kind == neg_kind]
        if last and pos_kind not in kinds:  # "put it on the box, not on it, beside it": the place word replaced
            a, b = last[-1]
            return f"{before[:a]}{_relation_words(pos)}{before[b:]}{after}"
        raise asked
    phrases = [(a, b) for a, b in noun_phrases(before, VERB_START, RELATION_AT)]
    said = [(a, b) for a, b in phrases if _content(neg) and _content(neg) <= set(before[a:b].split())]
    if len(said) == 1:  # the command named X: Y in its place
        a, b = said[0]
        new = pos if re.search(r"\b(?:one|thing|object)$", pos) or len(pos.split()) > 2 else f"{pos} one"
        return f"{before[:a]}{one_as(new, before[a:b].strip())} {before[b:].strip()}".strip() + after
    if not said and _content(pos) and any(_content(pos) <= set(before[a:b].split()) for a, b in phrases):
        return f"{before}{after}"  # only confirms what the command said
    raise asked


_COUNT = rf"(?:\d+(?:\.\d+)?|(?:{'|'.join(sorted((w for w in NUMBERS if ' ' not in w), key=len, reverse=True))})(?:[ -](?:one|two|three|four|five|six|seven|eight|nine))?)"
_UNIT = r"(?:cm|mm|centimet\w*|millimet\w*|inch\w*)"
_AMOUNT = rf"(?:about |around |roughly )?{_COUNT} ?{_UNIT}"
# "make that fifteen": a bare number keeps the unit of the amount it corrects
_NEW_AMOUNT = re.compile(rf"(?:^|(?<=[.,;!?]))\s*(?:(?:oh|no|wait|sorry|actually|um|uh|hmm)\s*,?\s*)*(?:make (?:it|that)|i meant?|(?:no|sorry|actually),?)\s+"
                         rf"((?:about |around |roughly )?{_COUNT}(?: ?{_UNIT})?)(?: instead)?\s*(?=$|[.,;!?])")


def amount(text: str) -> str:
    """A corrected amount after a command ("move the box 10 cm left. oh wait, make it 5 cm"): the
    last amount the command said replaced; asked when it said none."""
    m = _NEW_AMOUNT.search(text)
    before = text[: m.start()].strip(" ,") if m else ""
    if not m or not before:
        return text
    said = list(re.finditer(_AMOUNT, before))
    if not said:
        raise InputError(f"{text.strip()!r}: '{m.group(1)}' corrects no amount the command said; say the whole command again")
    last, new = said[-1], m.group(1)
    if not re.search(rf"{_UNIT}$", new):
        new = f"{new} {re.search(rf'{_UNIT}$', last.group(0)).group(0)}"  # type: ignore[union-attr]
    return f"{before[: last.start()]}{new}{before[last.end():]}{text[m.end():]}"
