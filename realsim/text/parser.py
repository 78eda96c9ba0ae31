"""Offline parser: a scene description in English -> objects (label, count, colour, size) and a support.

    >>> parse_description("a kitchen table with a red mug, a large bowl and two soda cans").objects[0]
    ObjectRequest(label='mug', count=1, color='red', size='')

Clauses are split at commas, "and", "with", "plus" and ";"; each clause gives a count ("a",
"two", "3", "a pair of"), colour and size words, and a noun phrase matched against the size
table (longest phrase first, exact names and aliases before fuzzy matches). Unknown nouns are
kept (they become primitives sized from the table's defaults). Support words ("table",
"counter", "floor", "desk", "shelf") pick the support instead of making objects.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from realsim.physics.size_table import lookup, normalize_label, singular

NUMBERS = {"a": 1, "an": 1, "one": 1, "single": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
           "nine": 9, "ten": 10, "couple": 2, "pair": 2, "another": 1, "dozen": 12, "few": 3, "several": 3, "some": 2, "both": 2}
COLORS = {
    "red": (0.8, 0.1, 0.1), "green": (0.15, 0.6, 0.2), "blue": (0.15, 0.3, 0.8), "yellow": (0.95, 0.85, 0.15),
    "orange": (0.95, 0.5, 0.1), "purple": (0.5, 0.2, 0.6), "pink": (0.95, 0.55, 0.7), "white": (0.95, 0.95, 0.95),
    "black": (0.08, 0.08, 0.08), "grey": (0.5, 0.5, 0.5), "gray": (0.5, 0.5, 0.5), "brown": (0.45, 0.3, 0.15),
    "silver": (0.75, 0.75, 0.78), "gold": (0.85, 0.7, 0.25), "beige": (0.9, 0.85, 0.7), "teal": (0.1, 0.55, 0.55),
    "cyan": (0.2, 0.8, 0.85), "navy": (0.1, 0.15, 0.4), "wooden": (0.6, 0.45, 0.3), "clear": (0.85, 0.92, 0.95),
}
SIZES = ("tiny", "small", "little", "mini", "medium", "big", "large", "huge", "tall", "giant")
SUPPORTS = {  # word -> (kind, height m, size [w, d] m)
    "table": ("table", 0.75, (1.2, 0.8)), "desk": ("table", 0.75, (1.4, 0.7)), "workbench": ("table", 0.9, (1.5, 0.75)),
    "counter": ("counter", 0.9, (1.8, 0.65)), "countertop": ("counter", 0.9, (1.8, 0.65)), "worktop": ("counter", 0.9, (1.8, 0.65)),
    "floor": ("floor", 0.0, (2.0, 2.0)), "ground": ("floor", 0.0, (2.0, 2.0)), "shelf": ("shelf", 1.0, (1.0, 0.4)),
}
STOP = {"the", "of", "on", "in", "at", "there", "is", "are", "next", "to", "beside", "near", "some", "with", "its", "top", "it",
        "kitchen", "dining", "wooden", "set", "scene", "has", "have", "which", "that", "lying", "standing", "sitting", "placed",
        "empty", "full", "open", "closed", "new", "old", "sits", "stands", "lies", "each", "other", "by", "from", "for", "me", "image"}
PLURAL_ONLY = {"glasses": "glass", "boxes": "box", "dishes": "dish", "knives": "knife"}


@dataclass
class ObjectRequest:
    """One kind of object asked for."""

    label: str
    count: int = 1
    color: str = ""
    size: str = ""

    @property
    def rgb(self) -> tuple[float, float, float] | None:
        return COLORS.get(self.color)


@dataclass
class SceneRequest:
    """A parsed description: the support and the objects on it."""

    support: str = "table"  # table | counter | floor | shelf
    support_height: float = 0.75
    support_size: tuple[float, float] = (1.2, 0.8)
    objects: list[ObjectRequest] = field(default_factory=list)
    text: str = ""
    parser: str = "offline"
    notes: list[str] = field(default_factory=list)

    def total(self) -> int:
        return sum(o.count for o in self.objects)


def _match_noun(words: list[str]) -> tuple[str, int, int] | None:
    """The longest (label, start, end) phrase the size table knows (exact/alias first, then fuzzy)."""
    best = None
    for strict in (True, False):
        for n in range(min(len(words), 4), 0, -1):
            for i in range(len(words) - n, -1, -1):
                phrase = " ".join(words[i : i + n])
                m = lookup(phrase)
                if m is None or (strict and m.how == "fuzzy"):
                    continue
                best = (phrase, i, i + n)
                break
            if best:
                return best
    return None


def _clauses(text: str) -> list[str]:
    text = text.lower().replace("&", " and ")
    text = re.sub(r"\ba (pair|couple) of\b", "two", text)
    text = re.sub(r"\bof (water|juice|milk|soda|wine|beer|cereal|coffee|tea|jam|sugar)\b", "", text)  # "a bottle of water"
    text = re.sub(r"[.;:!?()]", ",", text)
    parts = re.split(r",|\band\b|\bwith\b|\bplus\b|\balso\b|\bas well as\b|\bbeside\b|\bnext to\b|\bnear\b", text)
    return [p.strip() for p in parts if p.strip()]


def parse_clause(clause: str) -> tuple[ObjectRequest | None, str | None]:
    """(object request or None, support word or None) of one clause."""
    words = [w for w in re.findall(r"[a-z0-9\-]+", clause)]
    support = None
    for i, w in enumerate(words):
        if w in SUPPORTS and not (i + 1 < len(words) and words[i + 1] in ("lamp", "cloth", "mat", "runner", "tennis", "top")):
            support = w
    count, color, size = 1, "", ""
    rest: list[str] = []
    counted = False
    for w in words:
        if w.isdigit() and not counted:
            count, counted = max(1, min(int(w), 20)), True
        elif w in NUMBERS and not counted:
            count, counted = NUMBERS[w], True
        elif w in COLORS and w != "wooden":
            color = w
        elif w in SIZES:
            size = w
        elif w in SUPPORTS or w in STOP or w in NUMBERS:
            continue
        else:
            rest.append(PLURAL_ONLY.get(w, w))
    if not rest:
        return None, support
    found = _match_noun(rest)
    if found is not None:
        phrase, _, end = found
        # keep a known head noun's modifiers that the table knows too ("soda can", "cereal box")
        label = singular(normalize_label(phrase))
    else:
        label = singular(normalize_label(" ".join(rest[-2:])))
    return ObjectRequest(label=label, count=count, color=color, size=size), support


def parse_description(text: str) -> SceneRequest:
    """Parse a scene description offline (no network)."""
    req = SceneRequest(text=text)
    support_word = None
    for clause in _clauses(text):
        obj, sup = parse_clause(clause)
        if sup is not None and support_word is None:
            support_word = sup
        if obj is None:
            continue
        m = lookup(obj.label)
        if m is not None and m.category.name in ("table", "shelf", "floor", "counter") and obj.label.split()[-1] in SUPPORTS:
            continue
        for existing in req.objects:
            if existing.label == obj.label and existing.color == obj.color and existing.size == obj.size:
                existing.count += obj.count
                break
        else:
            req.objects.append(obj)
    if support_word is not None:
        req.support, req.support_height, req.support_size = SUPPORTS[support_word]
    for o in req.objects:
        if lookup(o.label) is None:
            req.notes.append(f"{o.label!r} is not in the size table: a primitive of default size stands in")
    return req
