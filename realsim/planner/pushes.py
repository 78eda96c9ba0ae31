"""Pushes in words: whether a clause is a push ("push the mug left", not "put it left of the
box"), which way, and how far ("5 cm", "two inches", "a bit")."""

from __future__ import annotations

import re

from realsim.errors import InputError
from realsim.planner.lexicon import SURFACES
from realsim.planner.vocab import DIRECTION_WORDS, NUMBERS, UNITS, VAGUE_DISTANCES

_DIR_ALT = "|".join(re.escape(w) for w in sorted(DIRECTION_WORDS, key=len, reverse=True))
_NUM_ALT = "|".join(re.escape(w) for w in sorted(NUMBERS, key=len, reverse=True)) + "|half|a few"
_FEW = 3.0  # "a few inches": about three
_UNIT_ALT = r"cm|mm|m|in|inch|inches|inche|ft|foot|feet|centimet(?:er|re)s?|millimet(?:er|re)s?|met(?:er|re)s?"
TAIL = re.compile(rf"\b(?:by|about|around|roughly|some|approximately|like|to the|to|toward|towards|over to the|over|{_DIR_ALT}|{_NUM_ALT}|"
                   + "|".join(re.escape(v) for v in VAGUE_DISTANCES) + r")\b|(?<![a-z])\.?\d")


NOT_OBJECT = re.compile(r"\b(?:by|about|around|roughly|approximately|toward|towards|to the|over to)\b|(?<![a-z])\.?\d|"
                         + "|".join(rf"\b{re.escape(v)}\b" for v in VAGUE_DISTANCES))


def has_direction(text: str) -> bool:
    """Whether the text names a direction to push in (left, away, toward the robot, ...)."""
    return bool(re.search(rf"(?<![a-z])(?:{_DIR_ALT})(?![a-z])", text))


def is_push(rest: str) -> bool:
    """A direction word outside any object relation ("push the mug left", not "put it left of the box")."""
    if re.search(r"\b(?:left|right) (?:of|side of)\b|\bin front of\b|\bbehind\b|\bnext to\b|\bbeside\b|\bbetween\b|\b(?:in|into|onto|inside|on top of)\b"
                 r"|\b(?:closer|nearer) to (?!(?:me|you|the robot|yourself)\b)|\b(?:further|farther)(?: away)? from (?!(?:me|you|the robot|yourself)\b)", rest):
        return False
    return bool(re.search(rf"(?<![a-z])(?:{_DIR_ALT})(?![a-z])", rest)) or distance(rest) is not None


def distance(text: str) -> float | None:
    """The distance said in the text, in metres ("5 cm", "a bit"), or None."""
    for phrase, value in sorted(VAGUE_DISTANCES.items(), key=lambda kv: -len(kv[0])):
        if re.search(rf"\b{re.escape(phrase)}\b", text):
            return value
    m = re.search(rf"(?<![a-z0-9.])(\d+(?:\.\d+)?|\.\d+|half(?: of)? an?|{_NUM_ALT}|a)\s*(?:and a half\s*)?({_UNIT_ALT})\b", text)
    if not m:
        return None
    raw, unit = m.group(1), m.group(2)
    raw = "half" if raw.startswith("half") else raw  # "half an inch"
    value = {"a": 1.0, "half": 0.5, "a few": _FEW}.get(raw) or float(NUMBERS.get(raw, 0) or raw) if raw not in NUMBERS else float(NUMBERS[raw])
    if "and a half" in m.group(0):
        value += 0.5
    unit = unit[:-1] if unit.endswith("s") and unit not in ("s",) else unit
    scale = UNITS.get(unit) or next((s for k, s in UNITS.items() if len(k) > 2 and unit.startswith(k)), None)
    if scale is None:
        return None
    dist = float(value) * scale
    if not 0.0 < dist <= 1.0:
        raise InputError(f"push distance {dist:.3f} m is out of range (0 to 1 m)")
    return dist


_MEASURE = re.compile(r"\s+(?:(?:about |around |roughly |some )?(\d+(?:\.\d+)?|a few|a couple(?: of)?) ?(?:cm|mm|centimet\w*|millimet\w*|inch\w*)"
                      r"|a (?:bit|little|tad)(?: more)?|slightly|directly|just|diagonally|immediately|straight|somewhere"
                      rf"|(?:down )?(?:on|onto) {SURFACES}|down)$")


def beside_measure(obj_phrase: str, kind: str) -> str:
    """The object phrase without how it sits by the target ("the mug 10 cm | to the left of the
    bowl", "the mug down on the table | behind the box"); a side relation allows at most 15 cm."""
    while m := _MEASURE.search(obj_phrase):
        if m.group(1) and kind not in ("in", "on") and distance(m.group(0)) is not None and (distance(m.group(0)) or 0.0) > 0.15:
            raise InputError(f"a place beside an object is at most 15 cm from it, not {m.group(0).strip()}; "
                             "to move something a distance say 'move X N cm left'")
        obj_phrase = obj_phrase[: m.start()]
    return obj_phrase
