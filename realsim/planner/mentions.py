"""The one thing a stretch of talk names: "mm, the foam brick, the red one, ...", "There's a
strawberry way at the back. Got it?", "Por favor, la banana, ...". Such talk says what a later
"it" means; it asks for nothing itself.
"""

from __future__ import annotations

import re

from realsim.errors import InputError
from realsim.planner.lexicon import MEASURE, STATEMENT_VERB, VERB_START
from realsim.planner.reference import DETERMINERS
from realsim.planner.sentences import cleaned
from realsim.planner.steps import Parser
from realsim.planner.types import ObjectInfo
from realsim.planner.vocab import COLOR_WORDS, GENERIC, NUMBERS, is_plural, singular

__all__ = ["mentioned", "named_alone"]

_UNIT = rf"(?:{MEASURE}|\d+(?:\.\d+)? ?in)\b"
_WAYS = r"(?:left|right|forwards?|backwards?|back|away|closer|nearer|further|farther)\b"
# a way with its amount ("foam brick 4 cm to the right"), not a clock position ("at clock 11") nor talk ("hasn't moved 1 inch")
_AMOUNT = re.compile(rf"{_UNIT}\s+(?:(?:to|towards?|toward) (?:the )?)?{_WAYS}|{_WAYS}\s+(?:by\s+)?{_UNIT}")
_LONGEST = 6  # words in a noun phrase with its colour, size and locator words
_JOINS = {"and", "or", "with", "then"}
_WHERE_ENDS = {"back", "front", "left", "right", "middle", "centre", "center"}  # "the thing farthest back": a locator ends the phrase
_LOCATING = {"other", "between"}  # "(between) the other two blocks": a locator's reference, not a mention
_COUNTS = {w for w in NUMBERS if " " not in w} | {"both", "all"}
_PRONOUN_WORDS = {"one", "ones", "it", "same", "other"}  # "the same one" is what was named before, not a new mention


def _nouns(p: Parser) -> set[str]:
    return ({w for w in p.resolver.scene_words if w not in COLOR_WORDS} | set(GENERIC)) - _PRONOUN_WORDS


def mentioned(text: str, p: Parser) -> list[ObjectInfo]:
    """The first thing ``text`` names and those joined to it by "and", each by a noun phrase that
    names exactly one object (the longest from its start: "the left soda can", not "soda can")."""
    if asked := _asked_which(text, p):
        return asked
    if (pick := re.fullmatch(r"(?:the one|whichever|which ever) .+? among .+", cleaned(text).strip(" .,;"))) is not None:
        try:  # "the one closer to the bowl among the mug and the banana": the pick among those, never among all
            named = p.resolver.resolve(pick.group(0), p.ctx, allow_plural=False)
        except InputError:
            named = []
        return named if len(named) == 1 else []
    words = re.sub(r"[.,;]", " ", cleaned(text)).split()
    nouns = _nouns(p)
    found: list[ObjectInfo] = []
    i = 0
    while i < len(words):
        end, matched = i + 1, False
        if words[i] in DETERMINERS or words[i] in COLOR_WORDS or words[i] in _COUNTS or singular(words[i]) in nouns:
            for j in range(min(len(words), i + _LONGEST), i, -1):
                if (singular(words[j - 1]) not in nouns and words[j - 1] not in _WHERE_ENDS) or _JOINS & set(words[i:j]):
                    continue  # a phrase ends at its noun and names one thing
                phrase = re.sub(r"^(?:a|an|any|some) ", "the ", " ".join(words[i:j]))  # "there's a soda can": only if there is one
                plural = (is_plural(words[j - 1]) and words[j - 1] not in nouns  # "the two soda cans": all of them
                          and not _LOCATING & set(words[max(0, i - 2):j]))  # not "(between) the other two blocks" a locator names
                try:
                    named = p.resolver.resolve(phrase, p.ctx, allow_plural=plural)
                except InputError:
                    continue
                if len(named) == 1 or plural:
                    found += [o for o in named if o not in found]
                    end, matched = j, True
                    break
        if matched and (end >= len(words) or words[end] != "and"):
            found += [o for o in _also_said_of(" ".join(words[end:]), p) if o not in found]
            break  # the first thing named, with those joined to it ("the mug and the bowl"), not later places
        i = end
    return found


def _also_said_of(rest: str, p: Parser) -> list[ObjectInfo]:
    """Things a statement goes on to say something of: "the mug is on the right *and the soup can
    is* on the left" (each the subject of its own "and ... is")."""
    out: list[ObjectInfo] = []
    for m in re.finditer(rf"\band ((?:the|that|this) [a-z ]+?) {STATEMENT_VERB}\b", rest):
        try:
            named = p.resolver.resolve(m.group(1), p.ctx, allow_plural=False)
        except InputError:
            continue
        out += named if len(named) == 1 else []
    return out


def _asked_which(text: str, p: Parser) -> list[ObjectInfo]:
    """The thing a quiz names: "tell me which cube is blue" -> the blue cube, "which one is nearest
    you?" -> the nearest thing; [] when it names none or several."""
    m = re.search(r"\b(?:which|what) (one|thing|object|[a-z]+) (?:is|s) (?:the )?([a-z ]+?)\s*[?.!]?$", text.lower())
    if not m:
        return []
    noun, said = m.groups()
    for phrase in (f"the {said} {noun}", f"the {noun} {said}", f"the {said}"):
        try:
            found = p.resolver.resolve(phrase, p.ctx, allow_plural=False)
        except InputError:
            continue
        if len(found) == 1:
            return found
    return []


def named_alone(text: str, p: Parser) -> bool:
    """Whether ``text`` is talk that names things and asks nothing of them; those things are then
    what "it" or "them" means. A request ("put the teapot away") is never talk."""
    if VERB_START.match(cleaned(text)) or _AMOUNT.search(text):  # an amount ("foam brick 4 cm to the right") asks something
        return False
    found = mentioned(text, p)
    if found:
        p.ctx.set(found)
    return bool(found)
