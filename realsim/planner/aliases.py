"""Names a speaker gives things for this one message ("The mug is Falcon, the banana is Sparrow.
Falcon and Sparrow trade places."; "Codename Jam is the strawberry"; "Target is the Rubik's cube,
we call it the Box"; "See the small white object? That's the decoy."; "Extraction point: the gap
between the brick and the tin"): each definition is taken out and every later use of the name is
said as the description it stands for, so the rest of the planner reads plain words.

Of the two sides of "A is B", the description is the side that names a kind of thing the planner
knows (a mug, a red box, the small white object, a place between two things); the name is the
other side, a short noun phrase that is capitalised, marked ("codename", "call it") or said with
"the". When both or neither side name a known thing, the clause is a statement and is left alone.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from realsim.planner.vocab import COLOR_WORDS, GENERIC, KINDS, SYNONYMS

__all__ = ["named"]

# words that make a phrase a description of a thing in the scene
_THING_WORDS = frozenset({*KINDS, *(w for v in KINDS.values() for w in v), *SYNONYMS, *(w for v in SYNONYMS.values() for w in v),
                          *GENERIC, "soda", "cracker", "mustard", "marker", "bottle", "tin", "cylinder", "bowl", "plate", "cube", "box",
                          "brick", "can", "mug", "banana", "strawberry", "drill", "scissors", "pitcher", "cleanser", "bleach"})
_COLOURS = frozenset(COLOR_WORDS)
_PLACE = re.compile(r"^(?:the )?(?:gap|space|spot|place|area|room|slot|middle|point)?\s*(?:right )?(between|in front of|behind|next to|beside|left of|right of"
                    r"|to the left of|to the right of|on top of|inside|in|on)\s+(?:the|that|this)\b", re.I)
_MARK = r"(?:code ?name(?:d)?|code-named|call ?sign|alias|aka|a\.k\.a\.|known as|nicknamed?)"
_DET = r"(?:the|our|my|your|a|an)"
# words a place or a way is said with: never a name's ("it's the same left": no name "same left")
_NOT_NAMES = frozenset({"left", "right", "front", "back", "top", "bottom", "middle", "centre", "center", "side", "same", "other", "way",
                        "end", "edge", "corner", "near", "far", "up", "down", "plan", "idea", "problem", "thing", "deal"})
_PRONOUN = re.compile(r"^(?:it|this|that|they|them|these|those|he|she|you|i|we|me|us|one|here|there|everything|something|nothing)$", re.I)
_STATEMENT = re.compile(r"\b(?:is|are|was|were|be|been|being|not|very|too|so|really|in|on|at|of|to|with|from|and|or|but|if|because)\b", re.I)
_OPENERS = r"(?:(?:and|so|ok|okay|right|now|alright|listen|first|also|then|well),?\s+)*"
_CLAUSE_END = re.compile(r"\s*(?:[.;!?]+|,)\s*")


@dataclass(frozen=True)
class _Definition:
    name: str  # the name as said, lower case, without "codename" or "the"
    meaning: str  # the description it stands for ("the strawberry", "between the brick and the tin")
    start: int  # where the definition's clause lies in the message
    end: int


def _words(phrase: str) -> list[str]:
    return re.findall(r"[a-z]+", phrase.lower())


def _describes_thing(phrase: str) -> bool:
    """Whether ``phrase`` describes a thing or a place the planner can look up."""
    if _PLACE.match(phrase.strip()):
        return True
    words = _words(phrase)
    return bool(words) and words[0] in ("the", "that", "this", "a", "an", "your", "my") and any(
        w in _THING_WORDS or w.rstrip("s") in _THING_WORDS or w in _COLOURS for w in words[1:])


def _as_name(phrase: str, raw: str, marked: bool) -> str | None:
    """``phrase`` as a name (lower case, no article), or None when it cannot be one: a name is one to
    three words, said with "the", capitalised or marked, and is no pronoun, statement or amount."""
    text = re.sub(rf"^(?:{_MARK}\s+)?(?:{_DET}\s+)?", "", phrase.strip(" ,.\"'"), flags=re.I).strip(" \"'")
    words = text.split()
    if not 1 <= len(words) <= 3 or _PRONOUN.match(text) or any(w.lower() in _NOT_NAMES for w in words) or not marked and any(w.lower() in _THING_WORDS and w.lower() not in GENERIC for w in words) or _STATEMENT.search(text) or re.search(r"\d", text) and len(words) == 1:
        return None
    capitalised = any(w[:1].isupper() for w in words) and not raw.lstrip().startswith(words[0]) or any(w[:1].isupper() for w in words[1:])
    said_as_name = re.match(rf"\s*(?:{_MARK}\s+)?(?:the|our)\s", phrase, re.I) is not None
    numbered = len(words) == 2 and words[1].lower() in ("one", "two", "three", "four", "a", "b", "c", "1", "2", "3", "4")
    starts_sentence = raw.lstrip() == phrase.lstrip() or re.match(r"^\s*[A-Z]", phrase) is not None
    if not (marked or capitalised or said_as_name or numbered or (starts_sentence and len(words) <= 2 and words[0][:1].isupper())):
        return None
    return " ".join(w.lower() for w in words)


def _meaning(phrase: str) -> str:
    """The description as it will be said in place of the name ("the gap between X and Y" -> "between X and Y")."""
    phrase = phrase.strip(" ,.\"'")
    if m := _PLACE.match(phrase):
        return phrase[m.start(1):]
    if m := re.match(r"(?:the|that|this|your|my)\b", phrase, re.I):
        return m.group(0).lower() + phrase[m.end():]
    return f"the {phrase}"


_IS = re.compile(rf"^{_OPENERS}(?P<a>.+?)\s+(?:is|=|will be|shall be|becomes|means|stands for)\s+(?P<b>.+?)$", re.I)
_COLON = re.compile(rf"^{_OPENERS}(?P<a>[A-Za-z][\w ]{{0,30}}?)\s*:\s*(?P<b>.+)$")
_CALL = re.compile(rf"^{_OPENERS}(?:(?:we(?:'ll| will| shall)?|i(?:'ll| will)?|let's|let us)\s+)?(?:call|name|dub)\s+(?P<b>it|them|that|this|.+?)\s+(?P<a>(?:{_DET}\s+)?\S+(?:\s\S+)?)$", re.I)
_MARKED = re.compile(rf"^{_OPENERS}(?P<b>.+?),?\s+{_MARK}\s+(?P<a>.+)$", re.I)
_THATS = re.compile(rf"^{_OPENERS}(?:that|this)(?:'s| is)\s+(?P<a>(?:{_DET}\s+)?[\w ]+)$", re.I)
_FIRST_THING = re.compile(r"\b(?:the|that|this)\s+(?:[a-z']+\s+){0,3}[a-z']+\b", re.I)


def _first_thing(text: str) -> str | None:
    """The first description of a thing in ``text`` ("see the small white object lying on ..." -> "the small white object")."""
    for m in _FIRST_THING.finditer(text):
        words = m.group(0).split()
        for k in range(len(words), 1, -1):
            if _describes_thing(" ".join(words[:k])) and (words[k - 1].lower().rstrip("s") in _THING_WORDS or words[k - 1].lower() in _THING_WORDS):
                return " ".join(words[:k])
    return None


def _define(clause: str, last_thing: str | None) -> tuple[str, str] | None:
    """The (name, description) ``clause`` defines, or None."""
    if m := _CALL.match(clause):
        thing = m.group("b")
        meaning = last_thing if _PRONOUN.match(thing) else thing if _describes_thing(thing) else None
        name = _as_name(m.group("a"), clause, marked=True)
        return (name, meaning) if name and meaning else None
    if m := _MARKED.match(clause):
        name = _as_name(m.group("a"), clause, marked=True)
        return (name, m.group("b")) if name and _describes_thing(m.group("b")) else None
    if (m := _THATS.match(clause)) and last_thing and not _describes_thing(m.group("a")):
        name = _as_name(m.group("a"), clause, marked=False)
        return (name, last_thing) if name else None
    if m := _IS.match(clause) or _COLON.match(clause):
        a, b = m.group("a"), m.group("b")
        marked_a = re.match(rf"\s*{_MARK}\b", a, re.I) is not None
        marked_b = re.match(rf"\s*{_MARK}\b", b, re.I) is not None
        thing_a, thing_b = _describes_thing(a) and not marked_a, _describes_thing(b) and not marked_b
        if thing_b and not thing_a and (name := _as_name(a, clause, marked_a)):
            return name, b
        if thing_a and not thing_b and (name := _as_name(b, clause, marked_b)):
            return name, a
    return None


def _definitions(message: str) -> list[_Definition]:
    found: list[_Definition] = []
    last_thing: str | None = None
    pos = 0
    for piece in _CLAUSE_END.split(message):
        start = message.find(piece, pos)
        pos = start + len(piece)
        # "the mug is Falcon and the banana is Sparrow": two definitions joined by "and"
        parts = [piece]
        for joint in (" and ", ": "):  # "the mug is Falcon and the banana is Sparrow", "the strawberry is Rover: Rover goes ..."
            if not _define(piece.strip(), last_thing) and joint in piece:
                parts = piece.split(joint)
                break
        offset = start
        for k, part in enumerate(parts):
            begin = message.find(part, offset)
            begin, offset = (offset if k else begin), begin + len(part)  # a later part's span takes the "and" before it
            clause = part.strip()
            if not clause:
                continue
            if definition := _define(clause, last_thing):
                name, meaning = definition
                found.append(_Definition(name, _meaning(meaning), begin, offset))
                last_thing = _meaning(meaning)
            elif thing := _first_thing(clause):
                last_thing = thing
    return found


def _use(name: str) -> re.Pattern[str]:
    """A later use of ``name``: with or without its article or marker; a name of two or three words
    also by its last word ("the display case" is also "the case"), or a place's by its first word
    ("extraction point" is also "extraction")."""
    words = name.split()
    full = r"\s+".join(re.escape(w) for w in words)
    short = words[0] if words[-1] in ("point", "zone", "spot", "area", "place", "site", "location") else words[-1]
    body = full if len(words) == 1 or short in _THING_WORDS or short in _COLOURS else f"{full}|{re.escape(short)}"
    return re.compile(rf"(?:\b(?:the|our|my|{_MARK})\s+)?(?<![\w-])(?:{body})(?![\w-])", re.I)


def _without(message: str, definitions: list[_Definition]) -> str:
    """``message`` with the clauses of ``definitions`` cut out."""
    pieces, pos = [], 0
    for d in definitions:  # a clause cut out leaves a pause
        pieces.append(message[pos:d.start])
        pos = d.end
    pieces.append(message[pos:])
    text = " ".join(p.strip() for p in pieces)
    text = re.sub(r"^(?:\s*[,.;:]+\s*)+", "", text)
    return re.sub(r"\s*([,.;:?!])(?:\s*[,.;:])+", r"\1", text)


def named(message: str) -> str:
    """``message`` with its name definitions taken out and each name said as what it stands for; a
    "definition" whose name is never used again is a statement ("the can is the problem") and stays."""
    definitions = _definitions(message)
    while definitions and not all(_use(d.name).search(_without(message, definitions)) for d in definitions):
        definitions = [d for d in definitions if _use(d.name).search(_without(message, definitions))]
    if not definitions:
        return message
    text = _without(message, definitions)
    for d in sorted(definitions, key=lambda d: -len(d.name)):
        use = _use(d.name)
        if _PLACE.match(d.meaning):  # "get the Box to extraction": to the place
            text = re.sub(rf"\b(?:to|at|into|in|on|onto)\s+{use.pattern}", d.meaning, text, flags=re.I)
        text = use.sub(d.meaning, text)
    return " ".join(text.split())
