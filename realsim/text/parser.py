"""Offline parser: a scene description in plain English -> a :class:`~realsim.text.schema.SceneSpec`.

    >>> [(o.label, o.count, o.inside) for o in parse_scene("a bowl with two apples in it").objects]
    [('bowl', 1, None), ('apple', 2, 'bowl')]

The text is cut into sentences and, inside each, into noun phrases and the words between them
(relation markers: on, in, with, of, next to, left of, behind, stacked, a stack of, in a row, ...).
A noun phrase gives a count ("a", "two", "3", "a couple of", a bare plural = several), colour,
size and material words and a noun matched against the size table (longest phrase first); a
support word (table, desk, counter, shelf, floor) names a support instead. Markers then relate
the phrases read so far (the *group*: "a mug and a bowl on the table") to the phrase after them
(or to "it"/"them": the phrase the sentence is about). "with" after a support puts what follows
on it, after a container in it, after anything else on it. What cannot be placed becomes a
warning; objects with no support named go on the first table-like support mentioned (the floor
when only the floor is named, a table when none is).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from realsim.physics.size_table import lookup, normalize_label, singular
from realsim.text.schema import MAX_COUNT, SIZE_WORDS, SUPPORT_DEFAULTS, ObjectSpec, RelationSpec, SceneSpec, SupportSpec

NUMBERS = {"a": 1, "an": 1, "one": 1, "single": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
           "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "couple": 2, "pair": 2, "another": 1, "dozen": 12, "few": 3,
           "several": 4, "some": 3, "both": 2, "bunch": 4, "handful": 4, "lots": 5, "many": 5}
PLURAL_COUNT = 3  # "oranges", "some apples": several
COLORS = {
    "red": (0.8, 0.1, 0.1), "green": (0.15, 0.6, 0.2), "blue": (0.15, 0.3, 0.8), "yellow": (0.95, 0.85, 0.15),
    "orange": (0.95, 0.5, 0.1), "purple": (0.5, 0.2, 0.6), "pink": (0.95, 0.55, 0.7), "white": (0.95, 0.95, 0.95),
    "black": (0.08, 0.08, 0.08), "grey": (0.5, 0.5, 0.5), "gray": (0.5, 0.5, 0.5), "brown": (0.45, 0.3, 0.15),
    "silver": (0.75, 0.75, 0.78), "gold": (0.85, 0.7, 0.25), "beige": (0.9, 0.85, 0.7), "teal": (0.1, 0.55, 0.55),
    "cyan": (0.2, 0.8, 0.85), "navy": (0.1, 0.15, 0.4), "clear": (0.85, 0.92, 0.95), "dark": (0.15, 0.15, 0.15),
}
MATERIALS = {"wooden": (0.6, 0.45, 0.3), "wood": (0.6, 0.45, 0.3), "plastic": None, "metal": (0.7, 0.7, 0.72), "steel": (0.7, 0.7, 0.72),
             "glass": (0.85, 0.92, 0.95), "ceramic": None, "paper": None, "cardboard": (0.75, 0.6, 0.4), "wicker": (0.7, 0.55, 0.35),
             "cast": None, "iron": (0.2, 0.2, 0.2), "porcelain": (0.95, 0.95, 0.95), "aluminium": (0.8, 0.8, 0.82), "aluminum": (0.8, 0.8, 0.82)}
# support words -> (kind, height override); "coffee table" is low
SUPPORTS = {"table": ("table", None), "desk": ("desk", None), "workbench": ("table", 0.9), "bench": ("table", 0.9), "counter": ("counter", None),
            "countertop": ("counter", None), "worktop": ("counter", None), "floor": ("floor", None), "ground": ("floor", None),
            "shelf": ("shelf", None), "bookshelf": ("shelf", None), "island": ("counter", None), "nightstand": ("table", 0.6)}
LOW_TABLES = {"coffee": 0.45, "side": 0.6, "bedside": 0.6}
NOT_SUPPORT_AFTER = {"lamp", "cloth", "mat", "runner", "tennis", "top", "leg", "drawer", "knife", "saw"}
FILLER = {"the", "there", "is", "are", "s", "some", "its", "it", "that", "which", "has", "have", "i", "we", "you", "my", "our", "your",
          "see", "put", "set", "placed", "sitting", "standing", "lying", "sits", "stands", "lies", "rests", "resting", "just", "also",
          "kitchen", "dining", "office", "living", "room", "scene", "here", "me", "image", "empty", "full", "open", "closed", "new",
          "old", "nice", "little", "bit", "each", "other", "them", "they", "those", "these", "this", "up", "down", "out", "around",
          "sort", "kind", "type", "stuff", "things", "thing", "bunch", "got", "sat", "left", "right", "corner", "middle", "center",
          "centre", "edge", "side", "back", "front", "top", "together", "neatly", "too", "else", "whole", "next", "near", "far", "end",
          "be", "should", "want", "like", "would", "let", "make", "made", "with", "of", "and", "or", "but", "so", "at", "to", "onto",
          "each", "every", "could", "please", "setup"}
MASS_NOUNS = r"water|juice|milk|soda|wine|beer|coffee|tea|jam|honey|oil|flour|rice|pasta|cereal|sugar|salt|soup|sauce|cream|butter|food|snacks|candy|sand|soil|dirt"
PRONOUNS = {"it", "them", "this", "that", "these", "those", "one"}
# Marker patterns, longest first; each becomes a token "§<kind>§".
MARKERS: list[tuple[str, str]] = [
    (r"stacked (?:up )?on top of each other|stacked up|(?:stacked|piled) on each other|on top of each other|on top of one another|stacked|piled up|piled", "STACKED"),
    (r"\b(?:a |one )?(?:stack|pile|tower|heap) of", "STACKOF"),
    (r"\b(?:a |one )?(?:row|line) of", "ROWOF"),
    (r"in a (?:row|line)|lined up|side by side|in a neat row", "ROW"),
    (r"(?:to|on|at) the left(?: hand side)? of|left of", "left_of"),
    (r"(?:to|on|at) the right(?: hand side)? of|right of", "right_of"),
    (r"in front of", "in_front_of"),
    (r"behind|in back of|at the back of", "behind"),
    (r"next to|beside|besides|near|nearby|alongside|close to|by", "next_to"),
    (r"(?:on|at|to) the (?:left|right|back|front|far end|near end)(?: side)?(?: of it)?", "REGION"),
    (r"full of|filled with|containing|holding|that holds|which holds|that has|has|have|holds|with", "with"),
    (r"inside of|inside|into|within|in", "in"),
    (r"on top of|ontop of|on to|onto|on|upon|atop|on top", "on"),
    (r"under|underneath|beneath|below", "under"),
    (r"of", "of"),
    (r"and|plus|as well as|also|along with|then|together with|[,]|there is|there are|i've got|i got|is|are|"
     r"sits|stands|lies|sitting|standing|lying|placed|resting|rests|stand|sit|lie", "and"),
    (r"[.;!?:]", "SENT"),
]
REL_MARKERS = {"on", "in", "next_to", "left_of", "right_of", "behind", "in_front_of", "under"}


@dataclass
class Phrase:
    """A noun phrase: an object mention, a support or a pronoun."""

    kind: str  # "object" | "support" | "pronoun"
    spec: ObjectSpec | None = None
    support: str | None = None  # support id
    plural: bool = False
    region: str | None = None
    definite: bool = False  # "the mug": an object already named, when there is one
    each: bool = False  # "next to each plate": one subject per instance of the target


@dataclass
class _State:
    group: list[Phrase] = field(default_factory=list)
    closed: bool = False
    owner: Phrase | None = None  # the phrase before "with"
    listing: bool = False  # phrases after "with" go on / in the owner
    topic: Phrase | None = None
    pending: tuple[str, Phrase] | None = None  # a relation said before its subjects ("on the desk there's ...")
    recent: list[Phrase] = field(default_factory=list)  # object phrases read so far


def _tokens(text: str) -> list[str]:
    """Words and marker tokens (``§kind§``)."""
    s = re.sub(r"([.,;!?:])", r" \1 ", text)
    for pattern, kind in MARKERS:
        s = re.sub(rf"(?<![\w§'])(?:{pattern})(?![\w§'])", f" §{kind}§ ", s)
    return s.split()


def _prepare(text: str) -> str:
    t = text.lower().replace("&", " and ").replace("’", "'")
    t = re.sub(r"\b(a|one) (pair|couple) of\b", "two", t)
    t = re.sub(r"\ba (few|bunch|handful|dozen) of\b", r"\1", t)
    t = re.sub(r"\ba (few|dozen|handful|bunch)\b", r"\1", t)
    t = re.sub(rf"\b(bottle|glass|cup|mug|jar|can|carton|box|bowl|pot|bag|tin|packet)s? of ({MASS_NOUNS})\b", _mass_container, t)
    t = re.sub(r"\b(each|every) (?:one )?of them\b", "", t)
    t = re.sub(r"\bthere's\b", "there is", t)
    t = re.sub(r"\b(?:to|on|at) (its|their) (left|right)(?: side| hand side)?\b", lambda m: f"to the {m.group(2)} of {'it' if m.group(1) == 'its' else 'them'}", t)
    t = re.sub(r"\bin front\b(?! of)", "in front of it", t)
    t = re.sub(r"(\d+)\s*x\b", r"\1", t)
    return t


def _mass_container(m: re.Match) -> str:
    """"a bottle of wine" -> "wine bottle" when the table knows it, else "bottle" (the contents are not modelled)."""
    container, contents = m.group(1), m.group(2)
    found = lookup(f"{contents} {container}")
    return f"{contents} {container}" if found is not None and found.how != "fuzzy" else m.group(0).split(" of ")[0]


IRREGULAR = {"knives": "knife", "glasses": "glass", "dishes": "dish", "boxes": "box", "leaves": "leaf", "loaves": "loaf", "mice": "mouse",
             "potatoes": "potato", "tomatoes": "tomato", "shelves": "shelf", "dice": "dice", "scissors": "scissors", "headphones": "headphones",
             "chopsticks": "chopsticks", "pliers": "pliers", "glass": "glass", "grass": "grass"}


def _singular(text: str) -> str:
    return " ".join(IRREGULAR.get(w) or (w[:-2] if w.endswith("sses") else singular(w)) for w in text.split())


def known(label: str) -> bool:
    """True when the size table knows the label (an exact, alias or close match)."""
    m = lookup(label)
    return m is not None and (m.how != "fuzzy" or m.score >= 0.85)


def _match_noun(words: list[str]) -> tuple[str, int, int] | None:
    """The longest (phrase, start, end) the size table knows (exact/alias first, then fuzzy)."""
    for strict in (True, False):
        for n in range(min(len(words), 4), 0, -1):
            for i in range(len(words) - n, -1, -1):
                phrase = " ".join(words[i: i + n])
                m = lookup(phrase)
                if m is None or (strict and (m.how == "fuzzy" or m.matched not in (phrase, singular(phrase), _singular(phrase), phrase.replace(" ", "")))) \
                        or (not strict and m.score < 0.85):
                    continue  # strict: the whole phrase is a name ("setup laptop" is not; "laptop" is)
                return phrase, i, i + n
    return None


def _phrase(words: list[str]) -> Phrase | None:
    """One noun phrase (words between markers)."""
    words = [w.strip("'\"") for w in words if w.strip("'\"")]
    if not words:
        return None
    if any(w in PRONOUNS for w in words) and not any(w not in FILLER and w not in PRONOUNS and w not in NUMBERS for w in words):
        return Phrase("pronoun", plural=any(w in ("them", "these", "those") for w in words))
    for i, w in enumerate(words):
        if w in SUPPORTS and not (i + 1 < len(words) and words[i + 1] in NOT_SUPPORT_AFTER) and not (i > 0 and words[i - 1] in ("drawer", "bedside") and w != "table"):
            kind, height = SUPPORTS[w]
            if i > 0 and words[i - 1] in LOW_TABLES and kind == "table":
                height = LOW_TABLES[words[i - 1]]
            sup = Phrase("support", support=kind)
            sup.region = str(height) if height is not None else None
            return sup
    count, counted, color, size, material = 1, False, "", "", ""
    rest: list[str] = []
    for i, w in enumerate(words):
        if w.isdigit() and not counted:
            count, counted = max(1, min(int(w), MAX_COUNT)), True
        elif w in NUMBERS and not counted and w not in ("one",) + (() if i + 1 < len(words) else ("few",)):
            count, counted = NUMBERS[w], True
        elif w == "one" and not counted:
            count, counted = 1, True
        elif w in COLORS and i + 1 < len(words):
            color = w
        elif w in SIZE_WORDS and i + 1 < len(words):
            size = "small" if w == "little" else w
        elif w in MATERIALS and i + 1 < len(words):
            material = w
        elif w in FILLER or w in NUMBERS:
            continue
        else:
            rest.append(w)
    if not rest:
        return None
    found = _match_noun(rest)
    if found is not None:
        phrase, _, end = found
        head = rest[end - 1]
    else:
        phrase, head = " ".join(rest[-2:]), rest[-1]
    label = _singular(normalize_label(phrase))
    plural = _singular(head) != head
    if plural and not counted:
        count = PLURAL_COUNT
    spec = ObjectSpec(id=label, label=label, name=label,
                      count=count, color=color, size=size, material=material)
    each = words[0] in ("each", "every")
    return Phrase("object", spec=spec, plural=plural or count > 1, definite=each or (words[0] in ("the", "that", "this", "those", "these") and not counted),
                  each=each)


class _Builder:
    """Collects supports and objects and applies relations between phrases."""

    def __init__(self) -> None:
        self.spec = SceneSpec()
        self.support_order: list[str] = []

    def add_support(self, p: Phrase) -> None:
        kind = p.support or "table"
        if self.spec.support(kind) is None:
            height = float(p.region) if p.region else SUPPORT_DEFAULTS[kind][0]
            self.spec.supports.append(SupportSpec(id=kind, kind=kind, height_m=height, size_m=SUPPORT_DEFAULTS[kind][1]))  # type: ignore[arg-type]
            self.support_order.append(kind)

    def add_object(self, p: Phrase) -> None:
        """Add the phrase's object, or point it at the one already named ("the mug")."""
        assert p.spec is not None
        if p.definite:
            words = set(p.spec.label.split())
            same = [o for o in self.spec.objects if (o.label == p.spec.label or words & set(o.label.split())) and (not p.spec.color or o.color == p.spec.color)]
            if same:
                p.spec = same[-1]
                return
        ids = {o.id for o in self.spec.objects}
        base, k = p.spec.id.replace(" ", "_"), 2
        p.spec.id = base
        while p.spec.id in ids:
            p.spec.id, k = f"{base}_{k}", k + 1
        self.spec.objects.append(p.spec)

    def relate(self, subjects: list[Phrase], rel: str, target: Phrase) -> None:
        """Apply ``subject rel target`` to each subject (a support target sets the support)."""
        for s in subjects:
            if s.spec is None or s is target:
                continue
            if target.kind == "support":
                if rel in ("on", "in"):
                    s.spec.on, s.spec.inside = target.support, None
                elif rel == "under":
                    self.add_support(Phrase("support", support="floor"))
                    s.spec.on, s.spec.inside = "floor", None
                continue
            t = target.spec
            if t is None:
                continue
            if rel == "in":
                s.spec.inside, s.spec.on = t.id, None
            elif rel == "on":
                s.spec.on, s.spec.inside = t.id, None
            elif rel == "under":  # "a book under the mug": the mug is on the book
                if t.on is None and t.inside is None:
                    t.on = s.spec.id
                else:
                    self.spec.warnings.append(f"'{s.spec.display} under {t.display}': {t.display} already rests elsewhere; ignored")
            else:
                if target.each and s.spec.count == 1:  # "a mug next to each plate": one mug per plate
                    s.spec.count = t.count
                if t.id in (s.spec.on, s.spec.inside):  # "a vase with a candle next to it": beside it, not in it
                    s.spec.on = s.spec.inside = None
                s.spec.relations.append(RelationSpec(relation=rel, target=t.id))  # type: ignore[arg-type]

    def with_default(self, owner: Phrase, p: Phrase) -> None:
        """What "X with Y" means for Y: on a support, in a container, else on X."""
        from realsim.procedural.families import CONTAINERS
        from realsim.procedural.generate import kind_for

        if owner.kind == "support":
            self.relate([p], "on", owner)
        elif owner.spec is not None:
            self.relate([p], "in" if kind_for(owner.spec.label) in CONTAINERS else "on", owner)


def _sentences(text: str) -> list[list[str]]:
    out, cur = [], []
    for tok in _tokens(_prepare(text)):
        if tok == "§SENT§":
            if cur:
                out.append(cur)
            cur = []
        else:
            cur.append(tok)
    if cur:
        out.append(cur)
    return out


def _items(tokens: list[str]) -> list[str | Phrase]:
    """Markers (str) and phrases, in order."""
    items: list[str | Phrase] = []
    words: list[str] = []

    def flush() -> None:
        if words:
            # "my kitchen counter has a cutting board": a support word followed by an object: two phrases
            cut = next((i + 1 for i, w in enumerate(words) if w in SUPPORTS and any(v not in FILLER and v not in NUMBERS for v in words[i + 1:])), None)
            for part in ([words[:cut], words[cut:]] if cut else [words]):
                p = _phrase(part)
                if p is not None:
                    items.append(p)
            words.clear()

    for tok in tokens:
        if tok.startswith("§"):
            flush()
            items.append(tok.strip("§"))
        else:
            words.append(tok)
    flush()
    return items


def parse_scene(text: str) -> SceneSpec:
    """Parse a scene description offline (see the module doc)."""
    b = _Builder()
    topic: Phrase | None = None
    for tokens in _sentences(text):
        topic = _sentence(_items(tokens), b, topic)
    _finish(b)
    return b.spec


def _resolve(p: Phrase, st: _State) -> Phrase | None:
    """A pronoun's phrase: the object "with" was said of, else the latest object outside the
    current group agreeing in number ("it": one, "them": several), else the topic."""
    if p.kind != "pronoun":
        return p
    if st.owner is not None and st.owner.kind == "object":
        return st.owner
    for q in reversed(st.recent):
        if q not in st.group and q.spec is not None and (q.spec.count > 1) == p.plural:
            return q
    return st.topic


def _sentence(items: list[str | Phrase], b: _Builder, topic: Phrase | None) -> Phrase | None:
    """Read one sentence; returns what it was about (for "it" in the next one)."""
    st = _State(topic=topic)
    first = True
    i = 0
    stack_next = row_next = False
    while i < len(items):
        it = items[i]
        nxt = items[i + 1] if i + 1 < len(items) else None
        if isinstance(it, Phrase):
            if it.kind == "support":
                b.add_support(it)
                st.topic = it if st.topic is None else st.topic
                if st.owner is None and isinstance(nxt, str) and nxt == "with":
                    st.owner = it
            elif it.kind == "object":
                b.add_object(it)
                st.recent.append(it)
                assert it.spec is not None
                it.spec.stacked |= stack_next and it.spec.count > 1
                it.spec.row |= row_next and it.spec.count > 1
                stack_next = row_next = False
                if st.closed:
                    st.group, st.closed = [], False
                st.group.append(it)
                if st.owner is not None and st.listing and st.owner is not it:
                    b.with_default(st.owner, it)
                if st.pending is not None:
                    b.relate([it], *st.pending)
                if st.topic is None or st.topic.kind == "support" or first:
                    st.topic, first = it, False
            i += 1
            continue
        marker = it
        if marker == "STACKOF":
            stack_next = True
        elif marker == "ROWOF":
            row_next = True
        elif marker == "STACKED":
            objs = [p for p in st.group if p.spec is not None]
            if len(objs) == 1 and objs[0].spec.count > 1:  # type: ignore[union-attr]
                objs[0].spec.stacked = True  # type: ignore[union-attr]
            for lower, upper in zip(objs, objs[1:]):  # "a plate and a bowl stacked": the bowl on the plate
                b.relate([upper], "on", lower)
            if len(objs) == 1 and objs[0].spec.count == 1 and isinstance(nxt, str) and nxt == "on":
                pass  # "stacked on the box": the relation follows
        elif marker == "ROW":
            for p in st.group:
                if p.spec is not None and p.spec.count > 1:
                    p.spec.row = True
        elif marker == "REGION":
            pass  # "on the left": a place on the support, not kept offline
        elif marker == "with":
            prev = next((q for q in reversed(items[:i]) if q != "and"), None)  # "a stack of plates, with ..."
            if isinstance(prev, Phrase) and prev.kind != "pronoun":
                st.owner, st.listing = prev, True
                st.group, st.closed = [], False
        elif marker == "of":
            prev = items[i - 1] if i > 0 else None
            if isinstance(prev, Phrase) and prev.kind == "object" and isinstance(nxt, Phrase) and nxt.kind == "object":
                b.add_object(nxt)
                b.with_default(prev, nxt)
                i += 2
                continue
        elif marker in REL_MARKERS:
            if marker == "on" and not isinstance(nxt, Phrase):  # "... with a glass sitting on top": on what was just named
                nxt = Phrase("pronoun")
                items.insert(i + 1, nxt)
            target = _resolve(nxt, st) if isinstance(nxt, Phrase) else None
            if target is None:
                if isinstance(nxt, Phrase) and nxt.kind == "pronoun" and st.group:
                    b.spec.warnings.append(f"could not tell what {marker.replace('_', ' ')} 'it' refers to")
                i += 1
                continue
            if target.kind == "support":
                b.add_support(target)
            elif target.kind == "object" and target is nxt:
                b.add_object(target)
                st.recent.append(target)
            subjects = [p for p in st.group if p is not target] if not st.closed or marker != "on" else [st.group[-1]] if st.group else []
            if marker not in ("on", "in", "under") or (st.listing and st.owner is not None and target is not st.owner):
                subjects = subjects[-1:]  # "a laptop, a mouse next to the laptop": only the phrase before
            owner = st.owner if st.owner is not None and st.owner.kind == "object" else None
            if owner is not None and target is not owner and owner.spec is not None:  # contents follow their container
                subjects = [owner if p.spec is not None and owner.spec.id in (p.spec.inside, p.spec.on) else p for p in subjects]
            if not st.group:
                st.pending = (marker, target)
                if target.kind == "object" and target is nxt:
                    st.topic = target
            else:
                b.relate(subjects, marker, target)
                st.closed = True
                if target is st.owner:  # "a bowl with two apples in it": the list of contents ends
                    st.listing = False
                if target.kind == "object" and target is nxt:
                    st.group = [target]  # "two cups on a tray and a bowl": the tray is read; a new group follows
            i += 2
            continue
        i += 1
    return st.topic


def _finish(b: _Builder) -> None:
    """Default supports, names, and warnings for what is not in the size table."""
    spec = b.spec
    elevated = [s for s in b.support_order if s != "floor"]
    if not spec.supports or (elevated == [] and any(o.on is None and o.inside is None for o in spec.objects) and "floor" not in b.support_order):
        b.add_support(Phrase("support", support="table"))
    default = elevated[0] if elevated else ("floor" if "floor" in b.support_order else "table")
    for o in [o for o in spec.objects if o.inside and not known(o.label)]:  # "a vase with flowers": not modelled
        spec.warnings.append(f"{o.label!r} in the {o.inside.replace('_', ' ')} is not in the size table: left out")
        spec.objects.remove(o)
    for o in spec.objects:
        if o.on is None and o.inside is None:
            o.on = default
        if not known(o.label):
            spec.warnings.append(f"{o.label!r} is not in the size table: a box of default size stands in")
    used = {o.on for o in spec.objects} | {o.inside for o in spec.objects}
    spec.supports = [s for s in spec.supports if s.id in used] or spec.supports[:1]
