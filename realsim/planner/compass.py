"""Compass directions a speaker sets up for one message ("North is the far end of the table, west is
your left. Place the green cube due west of the red cube."; "Treat the far edge as north. Slide the
box four inches north."): the bearing said is turned into the robot's own directions (forward,
back, left, right) and the set-up clause is taken out. Only a message that says where one compass
point lies is read this way; the other points follow by turning (east is a quarter turn clockwise
from north, seen from above), so "north is your left" makes east forward.
"""

from __future__ import annotations

import re

__all__ = ["bearings"]

_POINTS = {"north": 0, "east": 90, "south": 180, "west": 270}  # clockwise from north, seen from above
_POINT = r"(north|east|south|west)"
# the robot's directions, clockwise from forward; the words each is said with in a set-up clause (first match wins)
_CUES: tuple[tuple[int, re.Pattern[str]], ...] = (
    (270, re.compile(r"\bleft\b")),
    (90, re.compile(r"\bright\b")),
    (180, re.compile(r"\b(?:toward|towards|to) (?:you|me|us|the robot|your base)\b|\bnear(?:est)? (?:side|edge|end)\b|\bbehind you\b|\bbackwards?\b|\bback\b")),
    (0, re.compile(r"\baway\b|\bforwards?\b|\bahead\b|\bstraight out\b|\bout from\b|\bfar(?:ther|thest)?\b|\bin front of you\b|\bstraight on\b")),
)
_MOTION = {0: "forward", 90: "right", 180: "back", 270: "left"}
_RELATION = {0: "behind", 90: "to the right of", 180: "in front of", 270: "to the left of"}
_EXTREME = {0: "farthest", 90: "rightmost", 180: "nearest", 270: "leftmost"}
_SIDE = {0: "far", 90: "right", 180: "near", 270: "left"}
_ACTION = re.compile(r"\b(?:put|place|move|push|slide|shift|nudge|set|lift|pick|bring|take|get|swap|drop|carry|sit|go|goes)\b|\d")
_CLAUSE = re.compile(r"[^.,;:!?]+(?:[.,;:!?]+|$)")


def _setup(clause: str) -> tuple[str, int] | None:
    """(compass point, robot direction) a set-up clause says ("north is away from you"), else None."""
    points = re.findall(rf"\b{_POINT}\b", clause)
    if len(set(points)) != 1 or _ACTION.search(clause):
        return None
    for angle, cue in _CUES:
        if cue.search(clause):
            return points[0], angle
    return None


def bearings(message: str) -> str:
    """``message`` with its compass set-up taken out and its compass words said as the robot's directions."""
    text = message
    if not re.search(rf"\b{_POINT}\b", text, re.I):
        return message
    lower = text.lower()
    turn: int | None = None
    cut: list[tuple[int, int]] = []
    for m in _CLAUSE.finditer(lower):
        parts = re.split(r"\band\b", m.group(0))
        found = [_setup(p) for p in parts]
        if not any(found):
            continue
        if not all(found):  # "north is away from you and push the box north": only a whole set-up clause goes
            continue
        point, angle = found[0]  # type: ignore[misc]
        turn = turn if turn is not None else (angle - _POINTS[point]) % 360
        cut.append((m.start(), m.end()))
    if turn is None:
        return message
    for start, end in reversed(cut):
        lower = lower[:start] + lower[end:]
    lower = re.sub(r"\b(?:bearings|compass|directions|orientation)\s*:\s*", "", lower)

    def way(point: str) -> int:
        return (_POINTS[point.lower()] + turn) % 360

    text = lower
    text = re.sub(rf"\b(?:(?:on|to|at) )?the {_POINT}(?:ern)? (?:side|end|edge) of\b", lambda m: _RELATION[way(m.group(1))], text)
    text = re.sub(rf"\b(?:due |directly |just |straight )?{_POINT} of\b", lambda m: _RELATION[way(m.group(1))], text)
    text = re.sub(rf"\b(?:the )?(?:more|most|further|farther) {_POINT}(?:erly|ern|ward)?( one)? of\b",
                  lambda m: f"the {_SIDE[way(m.group(1))]} one of", text)
    text = re.sub(rf"\b(?:most {_POINT}(?:erly|ern)|{_POINT}(?:ern)?most)\b", lambda m: _EXTREME[way(m.group(1) or m.group(2))], text)
    text = re.sub(rf"\b{_POINT}(?:ern|erly)\b", lambda m: _SIDE[way(m.group(1))], text)
    text = re.sub(rf"\b{_POINT}(?:wards?)?\b", lambda m: _MOTION[way(m.group(1))], text)
    text = re.sub(r"^\s*(?:then\s+)?", "", " ".join(text.split()))
    return text
