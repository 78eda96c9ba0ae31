"""Speech as people say it, before it is read as a command: self-repairs ("the soup can in the
mug no no in the bowl", "the soup can uh the tomato one"), narration ("now the robot will place
..."), the robot addressed without a comma, words said twice, "like" as a filler, and the object
said before its verb ("the red fruit put in front of the banana").

The verb and relation patterns come from :mod:`realsim.planner.phrasing` (which calls this), so
the two never disagree on what a verb or a place is.
"""

from __future__ import annotations

import re

from realsim.errors import InputError

__all__ = ["object_first", "repair"]

_MARKER = re.compile(r"(?:^|(?<=[\s,]))(no no|no wait|no sorry|no|sorry|wait|i mean|uh+|um+|er+|erm)(?=[\s,])")
_WEAK = re.compile(r"(?:uh+|um+|er+|erm)")
_NARRATION = re.compile(r"^(?:(?:now|alright|all right|ok|okay|so|class|everyone|kids|guys|and|then)\s+)*"
                        r"(?:(?:watch|look|see)(?: closely| carefully)?(?: everyone| class| kids)?\s+(?:as |how )?(?:the robot|it)\s+"
                        r"|(?:the robot|it|you|we)\s+(?:will|is going to|s going to|are going to|re going to|gonna|shall|is about to)\s+(?:now\s+)?)")
_ADDRESS = re.compile(r"^(?:hey |ok |okay |alright )?(?:robot|franka|panda|class|everyone)\s+(?=\w)")


def repair(text: str, verb: re.Pattern[str], relation: re.Pattern[str]) -> str:
    """``text`` (lower case, punctuation kept) with what the speaker took back replaced by what
    they said instead; ``verb`` / ``relation`` match a command verb / a place at a text's start."""
    text = re.sub(r"\b(\w+)(?: \1\b)+", r"\1", text)  # "bowl bowl", "no no"
    text = re.sub(r"(?<!\bi )(?<!\bd )(?<!would )(?<!\byou )\blike\b(?! (?:to|this|that)\b)", " ", text)  # "put it like right there"
    text = " ".join(text.split())
    for _ in range(4):
        step = _one_repair(text, verb, relation)
        if step == text:
            break
        text = step
    text = _ADDRESS.sub("", _NARRATION.sub("", text))
    return _NARRATION.sub("", text)


def _one_repair(text: str, verb: re.Pattern[str], relation: re.Pattern[str]) -> str:
    for m in reversed(list(_MARKER.finditer(text))):
        before, after = text[: m.start()].strip(" ,"), text[m.end():].strip(" ,")
        if not before or not after:
            continue
        weak = bool(_WEAK.fullmatch(m.group(1)))
        said = re.sub(r"^(?:just|rather|instead|actually)\s+", "", after)
        if verb.match(said) and not weak:  # "put the mug in the bowl no sorry just pick up the bowl"
            # "..., actually no, take it out again": an undo of what was done, so what was done stays
            return f"{before}, {said}" if re.search(r"\b(?:it|them)\b", said) else said
        if relation.match(said):  # "the soup can in the mug no no in the bowl"
            places = list(relation.finditer(before))
            if places:
                return f"{before[: places[-1].start()].rstrip()} {said}"
        start = max([m.end() for m in verb.finditer(before)] + [m.end() for m in relation.finditer(before)], default=0)
        if re.match(r"(?:the|that|this|a|an)\s", said) and re.match(r"\s*(?:the|that|this|a|an)\s", before[start:]):
            if re.search(r"(?:^|\s)(?:the|that|this|a|an)\s", before[:start]) and not weak:  # which of two does it replace?
                raise InputError(f"{text!r}: '{said}' could replace either thing named before it; say the whole command again")
            return f"{before[:start].rstrip()} {said}".strip()  # "put the soup can uh the tomato one behind the bowl"
        if weak:
            return f"{before} {after}"
    return text


def object_first(clause: str, verb: re.Pattern[str]) -> str | None:
    """"the red fruit put in front of the banana", "bowl slide it back toward me": the verb
    first, or None when no command verb follows the opening words."""
    for m in verb.finditer(clause):
        head = clause[: m.start()].strip()
        if not head or verb.match(clause):
            return None
        tail = re.sub(r"^(?:it|them)\b\s*", "", clause[m.end():].strip())
        head = re.sub(r"^(?:please\s+)?|\s+you$", "", head)
        return f"{m.group(0).strip()} {head} {tail}".strip()
    return None
