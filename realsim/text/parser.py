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
from realsim.text.builder import Builder, Phrase
from realsim.text.schema import MAX_COUNT, SIZE_WORDS, ObjectSpec, SceneSpec
from realsim.text.vocabulary import (
    COLORS,
    FILLER,
    FIXTURES,
    LOW_TABLES,
    MARKERS,
    MASS_NOUNS,
    MATERIALS,
    MEASURES,
    NOT_SUPPORT_AFTER,
    NUMBERS,
    PARTS,
    PLURAL_COUNT,
    PREAMBLE,
    PRONOUNS,
    REGIONS,
    REL_MARKERS,
    SUPPORTS,
    VAGUE,
)


@dataclass
class _State:
    group: list[Phrase] = field(default_factory=list)
    closed: bool = False
    owner: Phrase | None = None  # the phrase before "with"
    listing: bool = False  # phrases after "with" go on / in the owner
    topic: Phrase | None = None
    pending: tuple[str, Phrase] | None = None  # a relation said before its subjects ("on the desk there's ...")
    recent: list[Phrase] = field(default_factory=list)  # object phrases read so far
    region: tuple[float, float] | None = None  # "on the left, a toolbox": where on its support the next object goes


def _tokens(text: str) -> list[str]:
    """Words and marker tokens (``§kind§``)."""
    s = re.sub(r"([.,;!?:])", r" \1 ", text)
    for pattern, kind in MARKERS:
        s = re.sub(rf"(?<![\w§'])(?:{pattern})(?![\w§'])", f" §{kind}§ ", s)
    return s.split()


def _prepare(text: str) -> str:
    t = text.lower().replace("&", " and ").replace("’", "'")
    t = re.sub(PREAMBLE, "", t.strip())
    t = re.sub(r"\b(a|one) (pair|couple) of\b", "two", t)
    t = re.sub(r"\ba (few|bunch|handful|dozen) of\b", r"\1", t)
    t = re.sub(r"\ba (few|dozen|handful|bunch)\b", r"\1", t)
    t = re.sub(rf"\b({MEASURES}) of\b", "", t)  # "a loaf of bread", "two slices of cake": the food itself
    t = re.sub(rf"\b(bottle|glass|cup|mug|jar|can|carton|box|bowl|pot|bag|tin|packet)s? of ({MASS_NOUNS})\b", _mass_container, t)
    t = re.sub(r"\b(each|every) (?:one )?of them\b", "", t)
    t = re.sub(r"\bthere's\b", "there is", t)
    t = re.sub(r"\b(i|you|we|they|he|she)'(?:d|ll|ve|re|m)\b", r"\1", t)  # "you'd find", "we've got": who, not what
    t = re.sub(r"\b(?:to|on|at) (its|their) (left|right)(?: side| hand side)?\b", lambda m: f"to the {m.group(2)} of {'it' if m.group(1) == 'its' else 'them'}", t)
    t = re.sub(r"\bin front\b(?! of)", "in front of it", t)
    t = re.sub(r"(\d+)\s*x\b", r"\1", t)
    return t


def _mass_container(m: re.Match[str]) -> str:
    """"a bottle of wine" -> "wine bottle" when the table knows it, else "bottle" (the contents are not modelled)."""
    container, contents = m.group(1), m.group(2)
    found = lookup(f"{contents} {container}")
    return f"{contents} {container}" if found is not None and found.how != "fuzzy" else m.group(0).split(" of ")[0]


IRREGULAR = {"knives": "knife", "glasses": "glass", "dishes": "dish", "boxes": "box", "leaves": "leaf", "loaves": "loaf", "mice": "mouse",
             "potatoes": "potato", "tomatoes": "tomato", "shelves": "shelf", "dice": "dice", "scissors": "scissors", "headphones": "headphones",
             "chopsticks": "chopsticks", "pliers": "pliers", "glass": "glass", "grass": "grass"}


def _singular(text: str) -> str:
    return " ".join(IRREGULAR.get(w) or (w[:-2] if w.endswith("sses") else singular(w)) for w in text.split())


def _match_noun(words: list[str]) -> tuple[str, int, int] | None:
    """The longest (phrase, start, end) the size table knows (exact/alias first, then fuzzy)."""
    for strict in (True, False):
        for n in range(min(len(words), 4), 0, -1):
            for i in range(len(words) - n, -1, -1):
                phrase = " ".join(words[i: i + n])
                m = lookup(phrase)
                if m is None or (strict and (m.how == "fuzzy" or m.matched not in (phrase, singular(phrase), _singular(phrase), phrase.replace(" ", "")))):
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
    count, counted, vague, color, size, material = 1, False, False, "", "", ""
    rest: list[str] = []
    for i, w in enumerate(words):
        if w.isdigit() and not counted:
            count, counted = max(1, min(int(w), MAX_COUNT)), True
        elif w in NUMBERS and not counted and w not in ("one",) + (() if i + 1 < len(words) else ("few",)):
            count, counted, vague = NUMBERS[w], True, w in VAGUE
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
        typo = lookup(phrase)
        if typo is not None and typo.how == "fuzzy":  # "bannanas": named as the word meant, still several
            phrase, head = typo.matched, (typo.matched + "s" if _singular(head) != head else typo.matched)
    else:
        phrase, head = " ".join(rest[-2:]), rest[-1]
    label = _singular(normalize_label(phrase))
    plural = _singular(head) != head
    if plural and not counted:
        count = PLURAL_COUNT
    if vague:  # "some apples": several, not a number said; "some cheese": a quantity of it, one object
        counted, count = False, count if plural else 1
    spec = ObjectSpec(id=label, label=label, name=label,
                      count=count, color=color, size=size, material=material)
    each = words[0] in ("each", "every")
    return Phrase("object", spec=spec, plural=plural or count > 1, definite=each or (words[0] in ("the", "that", "this", "those", "these") and not counted),
                  each=each, counted=counted)


def _sentences(text: str) -> list[tuple[list[str], str]]:
    """The sentences' tokens, each with the punctuation that ends it ("" at the end)."""
    out: list[tuple[list[str], str]] = []
    cur: list[str] = []
    for tok in _tokens(_prepare(text)):
        if tok.startswith("§SENT"):
            if cur:
                out.append((cur, tok[5:-1]))
            cur = []
        else:
            cur.append(tok)
    if cur:
        out.append((cur, ""))
    return out


def _items(tokens: list[str]) -> list[str | Phrase]:
    """Markers (str) and phrases, in order."""
    items: list[str | Phrase] = []
    words: list[str] = []

    def flush() -> None:
        if words:
            # two phrases: "my kitchen counter has a cutting board" (a support word, then an object), "behind the
            # kettle a jar" (an article after a known noun starts the next phrase)
            cuts = {i + 1 for i, w in enumerate(words) if w in SUPPORTS and any(v not in FILLER and v not in NUMBERS for v in words[i + 1:])}
            cuts |= {i for i, w in enumerate(words) if i > 0 and w in ("a", "an", "the") and _match_noun(words[:i]) is not None}
            bounds = [0, *sorted(cuts), len(words)]
            for part in (words[lo:hi] for lo, hi in zip(bounds, bounds[1:])):
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
    b = Builder()
    topic: Phrase | None = None
    heading: list[ObjectSpec] = []
    for tokens, end in _sentences(text):
        before = len(b.spec.objects)
        topic = _sentence(_items(tokens), b, topic)
        if heading and len(b.spec.objects) > before:
            _expand_heading(b, heading, b.spec.objects[before:])
        heading = [o for o in b.spec.objects[before:] if o.id in b.uncounted] if end == ":" else []
    b.finish()
    return b.spec


def _expand_heading(b: Builder, heading: list[ObjectSpec], members: list[ObjectSpec]) -> None:
    """"Toys on the floor: a duck, a ball and a car": the bare plural before a colon names the
    objects listed after it; they take its place (and where it was)."""
    for h in heading:
        b.spec.objects.remove(h)
        for o in members:
            if o.on is None and o.inside is None:
                o.on, o.inside = h.on, h.inside
        for o in b.spec.objects:  # what was said to stand on or in the heading now refers to nothing
            o.relations = [r for r in o.relations if r.target != h.id]


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


def _sentence(items: list[str | Phrase], b: Builder, topic: Phrase | None) -> Phrase | None:
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
            elif it.kind == "object" and st.listing and st.owner is not None and st.owner.kind == "object" and it.spec.label in PARTS:  # type: ignore[union-attr]
                b.add_part(st.owner, it.spec.label)  # type: ignore[union-attr]
            elif it.kind == "object":
                b.add_object(it)
                st.recent.append(it)
                assert it.spec is not None
                it.spec.stacked |= stack_next and it.spec.count > 1
                it.spec.row |= row_next and it.spec.count > 1
                stack_next = row_next = False
                if st.region is not None:
                    it.spec.position, st.region = st.region, None
                if st.closed:
                    st.group, st.closed = [], False
                st.group.append(it)
                if st.pending is not None:  # "on the table there's a plate with cheese": the plate on the table
                    b.relate([it], *st.pending)
                if st.owner is not None and st.listing and st.owner is not it:
                    b.with_default(st.owner, it)  # ... and the cheese on the plate
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
            if objs and objs[-1].spec.count > 1:  # type: ignore[union-attr]  # "a rack, and three plates stacked": the plates
                objs[-1].spec.stacked, objs = True, []  # type: ignore[union-attr]
            for lower, upper in zip(objs, objs[1:]):  # "two books and a tablet stacked": the tablet on the books, and
                lower.spec.stacked |= lower.spec.count > 1  # type: ignore[union-attr]
                b.relate([upper], "on", lower)
            st.group = objs[:1] or st.group  # "... stacked on the desk": the bottom of the stack stands there
            if len(objs) == 1 and objs[0].spec.count == 1 and isinstance(nxt, str) and nxt == "on":  # type: ignore[union-attr]
                pass  # "stacked on the box": the relation follows
        elif marker == "ROW":
            for p in st.group:
                if p.spec is not None and p.spec.count > 1:
                    p.spec.row = True
        elif marker.startswith("REGION_"):  # "a toolbox on the left": where on its support
            if st.group and not st.closed:
                for p in st.group:
                    p.spec.position = REGIONS[marker[7:]]  # type: ignore[union-attr]
                st.closed = True
            else:
                st.region = REGIONS[marker[7:]]
        elif marker == "ALSO":  # "a bowl holding lemons, plus a salt shaker": the list of contents ends
            st.listing, st.closed = False, True
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
            grouped = nxt if nxt in ("STACKOF", "ROWOF") and i + 2 < len(items) and isinstance(items[i + 2], Phrase) else None
            if grouped is not None:  # "left of a stack of two books": the books are the target, stacked
                del items[i + 1]
                nxt = items[i + 1]
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
                if target.spec is not None and target.spec.label in FIXTURES:  # "by the fridge": where, not what
                    b.spec.warnings.append(f"'{target.spec.label}' is part of the room: not built; what is {marker.replace('_', ' ')} it stays on its support")
                    st.closed = True
                    i += 2
                    continue
                b.add_object(target)
                st.recent.append(target)
                if grouped is not None and target.spec is not None and target.spec.count > 1:
                    target.spec.stacked |= grouped == "STACKOF"
                    target.spec.row |= grouped == "ROWOF"
            subjects = [p for p in st.group if p is not target] if not st.closed or marker != "on" else [st.group[-1]] if st.group else []
            if marker not in ("on", "in", "under") or (st.listing and st.owner is not None and target is not st.owner):
                subjects = subjects[-1:]  # "a laptop, a mouse next to the laptop": only the phrase before
            owner = st.owner if st.owner is not None and st.owner.kind == "object" else None
            if owner is not None and target is not owner and owner.spec is not None:  # contents follow their container
                subjects = [owner if p.spec is not None and owner.spec.id in (p.spec.inside, p.spec.on) else p for p in subjects]
            after = items[i + 2] if i + 2 < len(items) else None  # "..., and behind the kettle a jar": said before its subject
            if not st.group or (items[i - 1] == "and" and isinstance(after, Phrase) and after.kind == "object"):
                st.group, st.closed, st.pending = [], False, (marker, target)
                if target.kind == "object" and target is nxt:
                    st.topic = target
            else:
                b.relate(subjects, marker, target)
                st.closed = True
                if target is st.owner or target.kind == "support":  # "a bowl with two apples in it", "a vase with
                    st.listing = False  # flowers on the table and two coasters": the list of contents ends
                if target.kind == "object" and target is nxt:
                    st.group = [target]  # "two cups on a tray and a bowl": the tray is read; a new group follows
            i += 2
            continue
        i += 1
    return st.topic
