"""Units a speaker makes up for one message ("advance it one square - call a square five
centimetres"; "one file over to the left, a file's about six centimetres"; "two steps back, where a
step is an inch"): the definition is taken out and each count of the made-up unit is said in the
unit it was defined by ("one square" -> "5 centimetres").
"""

from __future__ import annotations

import re

from realsim.planner.vocab import NUMBERS

__all__ = ["made_up_units"]

_REAL = r"(?:cm|mm|m|in|inch(?:es)?|centimet(?:er|re)s?|millimet(?:er|re)s?|met(?:er|re)s?|foot|feet|ft)"
_AMOUNT = r"(\d+(?:\.\d+)?|an?|one|two|three|four|five|six|seven|eight|nine|ten|twelve|fifteen|twenty|half an?)"
_APPROX = r"(?:about |roughly |around |approximately |some |just |exactly |precisely |maybe )?"
# "call a square five centimetres", "a file's about six centimetres", "a square is 5 cm", "one square = 5 cm", "where a step is an inch"
_DEFINE = (
    re.compile(rf"\b(?:let s |lets |we ll |we will |i ll |just )?(?:call|make|count|treat|take) (?:a|one|each) ([a-z]+) (?:as |to be |being |=\s*)?{_APPROX}{_AMOUNT} ?({_REAL})\b(?! (?:wide|tall|high|long|across|thick|deep))"),
    re.compile(rf"\b(?:where |with |if |and )?(?:a|one|each) ([a-z]+)(?:'s| is| s| being| equals| means| =)\s+{_APPROX}{_AMOUNT} ?({_REAL})\b(?! (?:wide|tall|high|long|across|thick|deep))"),
)
_EXCLUDED = frozenset({"distance", "length", "width", "height", "depth", "total", "maximum", "minimum", "gap", "move", "push", "nudge", "inch", "centimetre", "centimeter", "millimetre", "millimeter", "metre", "meter", "foot", "bit", "little", "touch", "hair",
                       "tad", "smidge", "lot", "few", "couple"})


def _number(word: str) -> float:
    if word.startswith("half"):
        return 0.5
    return float(NUMBERS.get(word, 1 if word in ("a", "an") else word))


def made_up_units(message: str) -> str:
    """``message`` with made-up units said in real ones (lower case when one is found)."""
    text = message.lower()
    units: dict[str, tuple[float, str]] = {}
    for pattern in _DEFINE:
        for m in list(pattern.finditer(text)):
            unit = m.group(1)
            if unit in _EXCLUDED or unit.rstrip("s") in _EXCLUDED:
                continue
            units.setdefault(unit, (_number(m.group(2)), m.group(3)))
            text = text.replace(m.group(0), " ", 1)
    if not units:
        return message
    for unit, (size, real) in units.items():
        text = re.sub(rf"\b{_AMOUNT} {re.escape(unit)}(?:s|es)?\b", lambda m: f"{_number(m.group(1)) * size:g} {real}", text)
    text = re.sub(r"\s*[-–—,;:]\s*(?=[-–—,;:.])", "", text)  # the pause left where a definition was
    return " ".join(text.split())
