"""Offline rule-based planner: a small English grammar to the same program text Claude writes.

Understands, joined by "then", "and", commas or semicolons::

    pick up / grab / lift / take X            put / place / drop / set / move X on / in / into Y
    stack X on Y                              put X next to / beside / left of / behind Y
    push / slide / move X left|right|forward|back (by) N cm|mm|m|inches
    open / close the drawer|door (X)          open / close the gripper, release
    go home / return home / reset             put X down

Objects are matched against labels, aliases, colour names and body names, tolerating articles,
plurals, a few synonyms ("cup" finds a mug) and typos; "it" is the last object named. Anything
it cannot read raises :class:`InputError` that lists the scene's objects.
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Sequence
from dataclasses import dataclass

from realsim.errors import InputError
from realsim.planner.goals import DIRECTIONS, AtHome, DrawerClosed, DrawerOpen, Goal, Inside, Lifted, Moved, NextTo, On
from realsim.planner.types import ObjectInfo, Plan

SYNONYMS: dict[str, tuple[str, ...]] = {
    "cup": ("mug", "glass"),
    "mug": ("cup",),
    "can": ("tin", "soup can", "tomato soup can", "chips can", "potted meat can"),
    "tin": ("can",),
    "box": ("carton", "cracker box", "sugar box", "gelatin box", "pudding box", "block"),
    "block": ("cube", "box", "wood block", "foam brick"),
    "cube": ("block",),
    "dish": ("plate",),
    "plate": ("dish",),
    "bottle": ("mustard bottle", "bleach cleanser"),
    "ball": ("tennis ball", "baseball", "softball"),
    "container": ("bowl", "basket", "bin", "box"),
    "bin": ("basket", "container"),
}
COLORS = (
    "red", "green", "blue", "yellow", "orange", "purple", "pink", "black", "white", "gray",
    "grey", "brown", "silver", "gold",
)
STOPWORDS = {"the", "a", "an", "that", "this", "my", "your", "its", "some", "of", "please", "object", "thing", "one"}
NUMBER_WORDS = {
    "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8, "nine": 9,
    "ten": 10, "fifteen": 15, "twenty": 20, "thirty": 30, "half": 0.5,
}
UNITS = {
    "cm": 0.01, "centimeter": 0.01, "centimetre": 0.01, "mm": 0.001, "millimeter": 0.001,
    "millimetre": 0.001, "m": 1.0, "meter": 1.0, "metre": 1.0, "in": 0.0254, "inch": 0.0254,
    "inche": 0.0254, "ft": 0.3048, "foot": 0.3048, "feet": 0.3048,
}
DEFAULT_PUSH = 0.10  # m, when no distance is given
VAGUE_DISTANCES = {"a bit": 0.05, "a little": 0.05, "slightly": 0.03, "a lot": 0.20}
DIRECTION_WORDS = {
    "left": "left", "right": "right", "forward": "forward", "forwards": "forward", "ahead": "forward",
    "away": "forward", "back": "back", "backward": "back", "backwards": "back", "toward me": "back",
    "towards me": "back", "closer": "back",
}
HELP = (
    "the offline planner understands: pick up X; put X on/in/next to Y; stack X on Y; "
    "push X left/right/forward/back by N cm; open/close the drawer; open/close the gripper; go home "
    "(joined by 'then', 'and' or commas); set ANTHROPIC_API_KEY to use Claude for free-form commands"
)

_VERBS = (
    "pick", "grab", "lift", "take", "grasp", "raise", "hold", "put", "place", "drop", "set", "move",
    "stack", "insert", "transfer", "push", "slide", "shove", "nudge", "open", "close", "shut", "go",
    "return", "reset", "release", "home", "bring", "carry", "drag",
)


def _singular(word: str) -> str:
    if len(word) > 3 and word.endswith("ies"):
        return word[:-3] + "y"
    if len(word) > 3 and word.endswith(("ches", "shes", "xes", "sses")):
        return word[:-2]
    if len(word) > 3 and word.endswith("s") and not word.endswith(("ss", "us", "is")):
        return word[:-1]
    return word


def _norm(text: str) -> str:
    s = text.lower().replace("_", " ").replace("-", " ")
    s = re.sub(r"[^a-z0-9. ]+", " ", s)
    return " ".join(_singular(w) for w in s.split())


def _words(text: str) -> list[str]:
    return [w for w in _norm(text).split() if w not in STOPWORDS]


@dataclass(frozen=True)
class _Match:
    obj: ObjectInfo
    score: float


class ObjectResolver:
    """Finds the scene object a noun phrase means."""

    def __init__(self, objects: Sequence[ObjectInfo]):
        self.objects = list(objects)

    def listing(self) -> str:
        if not self.objects:
            return "the scene has no objects"
        items = [f"{o.name} ({(o.color + ' ') if o.color else ''}{o.label})" for o in self.objects]
        return "objects in the scene: " + ", ".join(items)

    def _names(self, o: ObjectInfo) -> list[str]:
        names = [_norm(o.label), _norm(o.name), *(_norm(a) for a in o.aliases)]
        return [n for n in dict.fromkeys(names) if n]

    def _score(self, phrase_words: list[str], o: ObjectInfo) -> float:
        colors = [w for w in phrase_words if w in COLORS]
        nouns = [w for w in phrase_words if w not in COLORS]
        color = (o.color or "").lower().replace("grey", "gray")
        if colors and color and all(c.replace("grey", "gray") not in color for c in colors):
            return 0.0
        if colors and not color and not nouns:
            return 0.0
        color_bonus = 0.5 if colors and color else 0.0
        if not nouns:
            return 1.0 + color_bonus if colors else 0.0
        phrase = " ".join(nouns)
        best = 0.0
        for name in self._names(o):
            name_words = name.split()
            if phrase == name:
                best = max(best, 3.0)
            elif all(w in name_words for w in nouns):
                best = max(best, 2.0 + 0.1 * len(nouns))
            elif name_words and name_words[-1] == nouns[-1]:
                best = max(best, 1.8)  # same head noun: "soup can" vs "can"
            elif any(w in name_words for w in nouns):
                best = max(best, 1.2)
            else:
                ratio = difflib.SequenceMatcher(None, phrase, name).ratio()
                if ratio >= 0.8:
                    best = max(best, 1.0 + ratio / 2)
        if best < 1.2:
            for word in nouns:
                for syn in SYNONYMS.get(word, ()):
                    if any(syn == n or syn in n.split() or n.endswith(" " + syn) for n in self._names(o)):
                        best = max(best, 1.5)
        return best + color_bonus if best > 0 else 0.0

    def resolve(self, phrase: str, *, want: str | None = None) -> ObjectInfo:
        """The object ``phrase`` names; ``want`` (an affordance) breaks ties and fills 'the drawer'."""
        words = _words(phrase)
        if not words:
            raise InputError(f"which object? nothing named in {phrase!r}; {self.listing()}")
        scored = [_Match(o, self._score(words, o)) for o in self.objects]
        if want:
            scored = [_Match(m.obj, m.score + (0.3 if want in m.obj.affordances and m.score > 0 else 0.0)) for m in scored]
            if not any(m.score > 0 for m in scored) and words[-1] in (want, "drawer", "door"):
                scored = [_Match(o, 1.0) for o in self.objects if want in o.affordances]
        scored = sorted((m for m in scored if m.score > 0), key=lambda m: -m.score)
        if not scored:
            raise InputError(f"no object matches {phrase.strip()!r}; {self.listing()}")
        if len(scored) > 1 and scored[1].score >= scored[0].score - 1e-9:
            tied = [m.obj for m in scored if m.score >= scored[0].score - 1e-9]
            options = ", ".join(f"{o.name} ({(o.color + ' ') if o.color else ''}{o.label})" for o in tied)
            raise InputError(f"{phrase.strip()!r} is ambiguous: {options}; name it by colour or body name")
        return scored[0].obj


@dataclass
class _Step:
    code: list[str]
    goals: list[Goal]
    objects: tuple[str, ...]  # objects whose state the step changes


def _distance(text: str) -> float | None:
    for phrase, value in VAGUE_DISTANCES.items():
        if re.search(rf"\b{phrase}\b", text):
            return value
    numbers = "|".join(NUMBER_WORDS)
    m = re.search(rf"(?<![a-z0-9.])(\d+(?:\.\d+)?|\.\d+|{numbers})\s*(cm|mm|m|in|inch|inches|inche|ft|foot|feet|centimet(?:er|re)s?|millimet(?:er|re)s?|met(?:er|re)s?)\b", text)
    if not m:
        return None
    raw, unit = m.group(1), m.group(2)
    if raw in NUMBER_WORDS:
        value = float(NUMBER_WORDS[raw])
    else:
        try:
            value = float(raw)
        except ValueError:
            return None
    unit = unit.rstrip("s") if unit not in ("s",) else unit
    scale = UNITS.get(unit) or UNITS.get(unit[:-1] if unit.endswith("e") else unit)
    if scale is None:
        for key, s in UNITS.items():
            if unit.startswith(key) and len(key) > 2:
                scale = s
                break
    if scale is None:
        return None
    dist = value * scale
    if not 0.0 < dist <= 1.0:
        raise InputError(f"push distance {dist:.3f} m is out of range (0 to 1 m)")
    return dist


def _direction(text: str) -> str | None:
    for phrase in sorted(DIRECTION_WORDS, key=len, reverse=True):
        if re.search(rf"\b{phrase}\b", text):
            return DIRECTION_WORDS[phrase]
    return None


_PUSH_TAIL = (
    r"\b(?:by|about|around|roughly|some|to the|to|toward|towards|a bit|a little|slightly|a lot|"
    + "|".join(sorted(DIRECTION_WORDS, key=len, reverse=True))
    + "|" + "|".join(NUMBER_WORDS) + r")\b|(?<![a-z])\.?\d"
)

_RELATIONS = (
    (r"on top of|onto|on", "on"),
    (r"inside of|inside|into|in", "in"),
    (r"next to|beside|near|by|alongside", "next"),
    (r"to the left of|left of", "left"),
    (r"to the right of|right of", "right"),
    (r"in front of", "front"),
    (r"behind|in back of", "behind"),
)


class RulePlanner:
    """The offline planner; its programs use the same primitives as Claude's."""

    name = "rules"

    def plan(self, command: str, scene_objects: list[ObjectInfo]) -> Plan:
        program, goals = parse(command, scene_objects)
        return Plan(program=program, goals=goals, planner=self.name)


def split_command(command: str) -> list[str]:
    """Split a command into clauses at 'then', 'and', commas, semicolons and full stops; clauses
    without a verb are glued back ("the salt and pepper")."""
    text = command.strip().lower()
    text = re.sub(r"\b(after that|afterwards|and then|please)\b", ",", text)
    parts = [p.strip() for p in re.split(r"\s*(?:,|;|\.(?!\d)|\bthen\b|\band\b)\s*", text) if p and p.strip()]
    parts = [re.sub(r"^(?:(?:first|next|finally|now|also|lastly)\s+)+", "", p) for p in parts]
    clauses: list[str] = []
    for part in filter(None, parts):
        first = part.split()[0] if part.split() else ""
        if clauses and first not in _VERBS:
            clauses[-1] = f"{clauses[-1]} and {part}"
        else:
            clauses.append(part)
    return clauses


def parse(command: str, objects: Sequence[ObjectInfo]) -> tuple[str, list[Goal]]:
    """Program text and goals for ``command``; raises :class:`InputError` when it cannot."""
    resolver = ObjectResolver(objects)
    clauses = split_command(command)
    if not clauses:
        raise InputError(f"the command is empty; {HELP}")
    steps: list[_Step] = []
    last: list[ObjectInfo | None] = [None]
    for clause in clauses:
        steps.append(_parse_clause(clause, resolver, last))
    lines = [f"# {command.strip()}"]
    for step in steps:
        lines.extend(step.code)
    return "\n".join(lines) + "\n", _final_goals(steps)


def _final_goals(steps: list[_Step]) -> list[Goal]:
    """Keep only goals not undone by later steps (a lifted mug later placed; home then moved)."""
    goals: list[Goal] = []
    for i, step in enumerate(steps):
        later_objects = {o for s in steps[i + 1 :] for o in s.objects}
        later_moves_robot = any(not (s.goals and isinstance(s.goals[0], AtHome)) for s in steps[i + 1 :])
        for g in step.goals:
            if isinstance(g, AtHome):
                if not later_moves_robot:
                    goals.append(g)
            elif getattr(g, "obj", None) not in later_objects:
                goals.append(g)
    return goals


def _obj(phrase: str, resolver: ObjectResolver, last: list[ObjectInfo | None], want: str | None = None) -> ObjectInfo:
    words = _words(phrase)
    if words in (["it"], ["them"], ["thi"]) or (not words and phrase.strip() in ("it", "them")):
        if last[0] is None:
            raise InputError(f"'it' does not refer to anything yet; name the object; {resolver.listing()}")
        return last[0]
    o = resolver.resolve(phrase, want=want)
    last[0] = o
    return o


def _q(name: str) -> str:
    return repr(name)


def _parse_clause(clause: str, resolver: ObjectResolver, last: list[ObjectInfo | None]) -> _Step:
    c = " ".join(clause.replace("'", " ").split())
    c = re.sub(r"^(can you|could you|would you|i want you to|now|also)\s+", "", c)

    if re.fullmatch(r"(go|return|move|come)( back)?( to)?( the)? home( position| pose)?|reset|home|go back home|return to home( position)?|(go|move) to( the)? home( position| pose)?", c):
        return _Step(["go_home()"], [AtHome()], ())

    m = re.fullmatch(r"(open|close|shut) (?:the )?(gripper|hand|fingers)|release(?: it)?|let go(?: of it)?|drop it", c)
    if m:
        if c.startswith(("release", "let go", "drop")) or m.group(1) == "open":
            return _Step(["open_gripper()"], [], ())
        return _Step(["close_gripper()"], [], ())

    m = re.fullmatch(r"(open|pull open|pull out|close|shut|push in|push closed)\s+(.+?)(\s+(?:all the way|fully|please))?", c)
    if m and (m.group(1) in ("open", "close", "shut") or any(w in m.group(2) for w in ("drawer", "door", "cabinet"))):
        want = "door" if "door" in m.group(2) else "drawer"
        o = _obj(m.group(2), resolver, last, want=want)
        if m.group(1) in ("open", "pull open", "pull out"):
            return _Step([f"open_drawer({_q(o.name)})"], [DrawerOpen(o.name, 0.3 if want == "door" else 0.05)], (o.name,))
        return _Step([f"close_drawer({_q(o.name)})"], [DrawerClosed(o.name)], (o.name,))

    m = re.fullmatch(r"(?:push|slide|shove|nudge|move|drag|shift) (.+)", c)
    if m and _direction(m.group(1)) and not re.search(r"\b(on|onto|into|inside|next to|beside|of)\b", m.group(1)):
        rest = m.group(1)
        cut = re.search(_PUSH_TAIL, rest)
        obj_phrase = rest[: cut.start()] if cut else rest
        o = _obj(obj_phrase, resolver, last)
        tail = rest[len(obj_phrase) :]
        direction = _direction(tail)
        if direction is None:
            raise InputError(f"which way? say left, right, forward or back in {clause!r}")
        dist = _distance(tail) or DEFAULT_PUSH
        return _Step(
            [f"push({_q(o.name)}, {direction!r}, {dist:.3f})"],
            [Moved(o.name, DIRECTIONS[direction], round(dist, 3))],
            (o.name,),
        )

    m = re.fullmatch(r"(?:stack|put|place|set|drop|move|insert|transfer|bring|carry|lay|position) (.+?) (down|back down)", c) or re.fullmatch(
        r"(?:put|set|place|lay) down (.+)", c
    )
    if m:
        o = _obj(m.group(1), resolver, last)
        code = [f"p, q = object_pose({_q(o.name)})", f"place({_q(o.name)}, [p[0], p[1], p[2]])"]
        return _Step(code, [], (o.name,))

    rel_pattern = "|".join(p for p, _ in _RELATIONS)
    m = re.fullmatch(
        rf"(?:stack|put|place|set|drop|move|insert|transfer|bring|carry|lay|position|pick up|take|grab) (.+?) (?:and )?(?:(?:put|place) (?:it )?)?({rel_pattern}) (.+)",
        c,
    )
    if m:
        rel = next(kind for pat, kind in _RELATIONS if re.fullmatch(pat, m.group(2)))
        o = _obj(m.group(1), resolver, last)
        want = {"on": "support", "in": "container"}.get(rel)
        target = resolver.resolve(m.group(3), want=want)
        if target.name == o.name:
            raise InputError(f"cannot put {o.name} {m.group(2)} itself")
        return _relation_step(o, rel, target)

    m = re.fullmatch(r"(?:pick up|pick|grab|lift|lift up|take|grasp|raise|hold|get)\s+(.+?)(?:\s+up)?", c)
    if m:
        o = _obj(m.group(1), resolver, last)
        return _Step([f"grasp({_q(o.name)})"], [Lifted(o.name)], (o.name,))

    raise InputError(f"cannot understand {clause!r}; {HELP}")


def _relation_step(o: ObjectInfo, rel: str, target: ObjectInfo) -> _Step:
    if rel == "on":
        return _Step([f"place_on({_q(o.name)}, {_q(target.name)})"], [On(o.name, target.name)], (o.name,))
    if rel == "in":
        return _Step([f"place_in({_q(o.name)}, {_q(target.name)})"], [Inside(o.name, target.name)], (o.name,))
    # beside the target: offset by both half-widths plus a 3 cm gap, on the requested side
    gap = 0.03
    if rel == "next":
        side_y = 1.0 if o.position[1] >= target.position[1] else -1.0
        dx, dy = 0.0, side_y * (target.size[1] / 2 + o.size[1] / 2 + gap)
    else:
        axis = {"left": (0.0, 1.0), "right": (0.0, -1.0), "front": (-1.0, 0.0), "behind": (1.0, 0.0)}[rel]
        ext = target.size[0] / 2 + o.size[0] / 2 if axis[0] else target.size[1] / 2 + o.size[1] / 2
        dx, dy = axis[0] * (ext + gap), axis[1] * (ext + gap)
    code = [
        f"p, q = object_pose({_q(target.name)})",
        f"place({_q(o.name)}, [p[0] + {dx:.3f}, p[1] + {dy:.3f}, p[2] - {target.size[2] / 2:.3f} + {o.size[2] / 2:.3f}])",
    ]
    return _Step(code, [NextTo(o.name, target.name)], (o.name,))
