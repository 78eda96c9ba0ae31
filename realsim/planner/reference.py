"""Which scene objects a noun phrase means: "the big can", "the second box from the right",
"all the fruit", "it", "the mug next to the bowl".

A phrase is read as: quantifier, ordinal or extreme, colour and size words, a noun (matched
against labels, aliases and body names, with synonyms, kinds such as "fruit" and typos), and
an optional locator ("on the left", "next to the bowl", "closest to you"). Directions are the
robot's (it faces the table like the person talking to it). A singular phrase must name exactly
one object; otherwise :class:`InputError` lists the candidates, so a wrong object is never
acted on.
"""

from __future__ import annotations

import difflib
import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from realsim.errors import InputError
from realsim.planner import noun_phrase, typos, vocab
from realsim.planner.attributes import (
    between_of,
    colors_of,
    footprint_shape_pick,
    holding,
    left_order,
    neighbour_colour_pick,
    next_over,
    relation_holds,
    size_pick,
    usual_colour_pick,
    usual_material_pick,
)
from realsim.planner.clock import AT_CLOCK, bearing_gap
from realsim.planner.core_noun import core_words
from realsim.planner.ordering import EXTREMES, middle_of, ordered
from realsim.planner.types import ObjectInfo
from realsim.planner.vocab import BIG, COLOR_WORDS, GENERIC, KINDS, NUMBERS, ORDINALS, SMALL, SYNONYMS, has_part, is_plural, name_words, norm, record, singular

DETERMINERS = {"the", "a", "an", "my", "your", "our", "some", "any", "of", "that", "this", "these", "those",
               "le", "la", "les", "el", "los", "las", "der", "die", "das", "den", "dem", "il", "lo", "un", "une", "una", "ein", "eine"}  # mixed in
SINGULAR_PRONOUNS = {"it", "this", "that", "this one", "that one", "the same one", "same one", "the same", "same", "itself",
                     "the one", "same thing", "the same thing", "that thing", "this thing", "it again", "the object", "one"}
PLURAL_PRONOUNS = {"them", "they", "those", "these", "both", "both of them", "all of them", "them all", "all of those",
                   "all of these", "those ones", "these ones", "the two", "both objects"}
_SAID_WHERE = r"(?:that is |thats |which is |that |which |sitting |lying |standing |(?:that |which )?(?:sits|stands|lies|is sitting|is standing|is lying) )?"
LOCATOR_RELATIONS = (
    (rf"{_SAID_WHERE}(?:right )?(?:next to|beside|near|by|close to)", "next"),
    (r"(?:that is |thats |which is |that |which |sitting |lying )?(?:on top of|on)", "on"),
    (r"(?:that is |thats |which is |that |which |sitting |lying )?(?:inside of|inside|in(?! front of\b))", "in"),
    (r"(?:that is |thats |which is |that |which |sitting |lying |hanging )?(?:right |just |directly )?(?:above|over)", "above"),  # on or in it
    (r"(?:that is |thats |which is |that |which |sitting |lying )?(?:right |just |directly )?(?:under|underneath|below|beneath)", "under"),
    (rf"{_SAID_WHERE}(?:just |directly |immediately )?(?:to the left of|left of)", "left"),
    (rf"{_SAID_WHERE}(?:just |directly |immediately )?(?:to the right of|right of)", "right"),
    (rf"{_SAID_WHERE}(?:right |just |directly |immediately )?behind", "behind"),
    (rf"{_SAID_WHERE}(?:right |just |directly |immediately )?in front of", "front"),
    (r"(?:that is |thats |which is )?(?:out of|out from|from inside|from within|from|off of|off)", "from"),  # where it is now
)


_TWO_TONE = re.compile(rf"\b({'|'.join(COLOR_WORDS)})(?:-| and |-and-)({'|'.join(COLOR_WORDS)}) (\w+)")
# what a thing is made of or its state: words the scene records nothing of, never a noun
UNCHECKED = frozenset({"plastic", "metal", "metallic", "aluminium", "aluminum", "steel", "wooden", "wood", "cardboard", "paper", "ceramic",
                       "porcelain", "rubber", "fake", "real", "empty", "full", "clean", "dirty", "new", "old", "shiny", "matte",
                       "deep", "shallow", "pointy", "plain", "squeezy", "squeeze"})
# "the right one", "the bigger one", "the one on the left": said of several just named, one of them
_AMONG_NAMED = re.compile(r"(?:the )?(?:(?:left|right|front|back|near|far|middle|first|second|third|last|\w+er|\w+est|\w+most)(?: hand)? one"
                          r"|one (?:on|at|in) the (?:left|right|front|back|middle)(?: side)?)")
# the one of a kind not named yet: "the last one", "the remaining cube", "the one left over", "the last can left"
_REMAINING = re.compile(r"(?:the )?(?:last|remaining|leftover|left over|only other)(?: one)?|(?:the )?(?:remaining|leftover) (\w+(?: \w+)?)"
                        r"|(?:the )?(?:only |last )?(?:one|(\w+)) (?:that is |that s |thats |which is )?(?:left over|left$|still left|remaining)")
# words in a scene's own names that describe rather than name ("obj3_left_tall_white_can"):
# the resolver reads them as colour, size and position, never as the noun
_DESCRIPTIVE = frozenset(COLOR_WORDS) | frozenset(BIG) | frozenset(SMALL) | frozenset(EXTREMES) | frozenset(ORDINALS) | {
    "from", "middle", "center", "centre", "most"}


@dataclass
class Context:
    """What earlier clauses referred to ("it", "them", "the other one")."""

    last: list[ObjectInfo] = field(default_factory=list)
    place: ObjectInfo | None = None  # the last target ("put the can in there too")
    seen: list[ObjectInfo] = field(default_factory=list)  # every object referred to so far ("the last one": of a kind, the one not yet named)

    def set(self, objs: list[ObjectInfo]) -> None:
        if objs:
            self.last = list(objs)
            self.seen += [o for o in objs if o not in self.seen]


def describe(o: ObjectInfo) -> str:
    """An object as a candidate is listed to the user: its name and label, with its measured colour
    unless its name or label already says one (that is the colour it answers to: :func:`colors_of`)."""
    named = any(w in COLOR_WORDS for w in norm(o.label).split() + norm(o.name).split())
    return f"{o.name} ({(o.color + ' ') if o.color and not named else ''}{o.label})"


class Resolver:
    """Resolves noun phrases against ``objects``; ``robot_yaw`` turns left/right into the world."""

    def __init__(self, objects: Sequence[ObjectInfo], robot_yaw: float = 0.0, robot_base: tuple[float, float] | None = None):
        self.objects = list(objects)
        self.base = np.zeros(2) if robot_base is None else np.asarray(robot_base, float)
        self.radial = robot_base is not None  # "nearest you" as a distance from the base (else along its forward axis)
        c, s = math.cos(robot_yaw), math.sin(robot_yaw)
        self.forward, self.left = np.array([c, s]), np.array([-s, c])
        self._words = {o.name: self._name_sets(o) for o in self.objects}
        self._said = self.scene_words = {w for names in self._words.values() for n in names for w in n}  # the scene's name words
        # the nouns that name a whole object: a name's last word, or its word before "with" ("cup with handle": a cup)
        self._heads = {singular((n[: n.index("with")] if "with" in n else n)[-1]) for names in self._words.values() for n in names if n and n[0] != "with"}

    # --- vocabulary of one object -----------------------------------------------------------
    def _name_sets(self, o: ObjectInfo) -> list[list[str]]:
        """Word lists naming ``o``: its label and body name first (primary), then other names."""
        names = [name_words(o.label), name_words(o.name), *(name_words(a) for a in o.aliases)]
        rec = record(o.label)
        if rec is not None:
            names.append(name_words(rec[0]))
        out: list[list[str]] = []
        for n in names:
            n = [w for w in n if w not in _DESCRIPTIVE]
            if n and n not in out:
                out.append(n)
        return out

    def _primary(self, o: ObjectInfo) -> list[list[str]]:
        return [[w for w in name_words(t) if w not in _DESCRIPTIVE] for t in (o.label, o.name)]

    def color_of(self, o: ObjectInfo) -> str | None:
        """A colour word in the object's name or label (the scene's own naming) first, else its
        ``color`` field (measured from the capture)."""
        for w in norm(o.label).split() + norm(o.name).split():
            if w in COLOR_WORDS:
                return COLOR_WORDS[w]
        if o.color:
            return COLOR_WORDS.get(o.color.lower(), o.color.lower())
        return None

    def kinds_of(self, o: ObjectInfo) -> set[str]:
        words = {w for n in self._primary(o) for w in n}
        rec = record(o.label)
        out = {k for k, members in KINDS.items() if words & set(members)}
        out |= {"fruit"} if rec is not None and rec[1] == "fruit" else set()
        return out | ({"container"} if "container" in o.affordances else set())

    def listing(self) -> str:
        if not self.objects:
            return "the scene has no objects"
        return "objects in the scene: " + ", ".join(describe(o) for o in self.objects)

    def _at_clock(self, pool: list[ObjectInfo], hour: int, phrase: str) -> ObjectInfo:
        """The one of ``pool`` nearest ``hour`` o'clock from the robot's base; two whose gaps differ by less
        than a quarter hour are not told apart."""
        ranked = sorted(pool, key=lambda o: bearing_gap(*self.robot_xy(o), hour))
        if len(ranked) > 1 and bearing_gap(*self.robot_xy(ranked[1]), hour) - bearing_gap(*self.robot_xy(ranked[0]), hour) < math.radians(7.5):
            raise InputError(f"{phrase.strip()!r} is ambiguous: {describe(ranked[0])} and {describe(ranked[1])} lie near {hour} o'clock; say which one")
        return ranked[0]

    def robot_xy(self, o: ObjectInfo) -> tuple[float, float]:
        p = np.asarray(o.position[:2], float) - self.base
        return float(p @ self.forward), float(p @ self.left)

    # --- noun scoring -----------------------------------------------------------------------
    def noun_score(self, nouns: list[str], o: ObjectInfo) -> float:
        """How well ``nouns`` name ``o`` (0: not at all; 3 exact; ~2 all words; 1.8 same head noun;
        1.5 synonym or kind; ~1.2 fuzzy)."""
        if not nouns or all(w in GENERIC for w in nouns):
            return 1.0
        nouns = [w for w in nouns if w not in GENERIC] or nouns
        phrase = " ".join(nouns)
        best = 0.0
        primary = self._primary(o)
        for name in self._words[o.name]:
            if name not in primary:  # another word for it (shared by every can): below its own label
                if nouns == name:
                    best = max(best, 2.05)
                elif all(w in name for w in nouns):
                    best = max(best, 1.95 + 0.01 * len(nouns))
                elif name[-1] == nouns[-1]:
                    best = max(best, 1.75)
                continue
            if nouns == name:
                best = max(best, 3.0)
            elif all(w in name for w in nouns):
                best = max(best, 2.2 + 0.1 * len(nouns))
            elif name[-1] == nouns[-1] or (len(nouns) == 1 and nouns[0] in name):
                best = max(best, 1.8 if name[-1] == nouns[-1] else 1.7)
            elif any(w in name for w in nouns) and nouns[-1] in {w for n in self._words[o.name] for w in n}:
                best = max(best, 1.6)
            else:
                ratio = difflib.SequenceMatcher(None, phrase, " ".join(name)).ratio()
                if ratio >= 0.8:
                    best = max(best, 1.0 + ratio / 4)
        if best < 1.5:
            head = nouns[-1]
            all_words = {w for n in self._words[o.name] for w in n}
            if any(s in all_words or s in " ".join(" ".join(n) for n in self._words[o.name]) for s in SYNONYMS.get(head, ())):
                best = max(best, 1.5)
            elif head in KINDS and head in self.kinds_of(o):
                best = max(best, 1.4)  # a member of the kind, below a synonym ("dish": the bowl before the mug)
        if best >= 1.5 and any(s in name for w in nouns for s in SYNONYMS.get(w, ()) for name in primary):
            best += 0.01  # a synonym of its own label breaks a tie of aliases every can shares ("spam": the potted meat)
        return best

    # --- the phrase -------------------------------------------------------------------------
    def resolve(self, phrase: str, ctx: Context, *, want: str | None = None, exclude: Sequence[str] = (),
                allow_plural: bool = True, loose: bool = False) -> list[ObjectInfo]:
        """The objects ``phrase`` names (one, unless the phrase is plural or a quantity); with
        ``loose`` an ambiguous phrase gives all its candidates instead of an error."""
        text = norm(phrase)
        if m := AT_CLOCK.fullmatch(text):  # "the soup can at your ten o'clock": the one whose bearing is nearest
            return [self._at_clock(self.resolve(m.group(1), ctx, want=want, exclude=exclude, loose=True), int(m.group(2)), phrase)]
        m = re.fullmatch(r"(?:an?|any|either|(?:any )?one of(?: the| those| these)?|any of(?: the| those| these)?) (.+)", text)
        if m and not re.search(r"\band\b|,", text):  # "a can", "one of the cans": any one will do, the nearest
            pool = self.resolve(m.group(1), ctx, want=want, exclude=exclude, loose=True)
            return [min(pool, key=lambda o: (round(self.robot_xy(o)[0], 3), -self.robot_xy(o)[1]))]
        m = re.fullmatch(r"(?:the )?(\w+er)(?: one)? (?:of|out of|among) (?:the |these |those )?(two|2|three|3|four|4|both)(?: of them| things| objects)?", text)
        if m and ({"two": 2, "both": 2, "three": 3, "four": 4}.get(m.group(2)) or int(m.group(2))) == len(self.objects):
            text = f"{m.group(1)[:-2]}est thing"  # "the smaller of the two" where the scene holds two things: of them all
        text = noun_phrase.normalize(text)
        m = re.fullmatch(r"(.+?) among (.+)", text)
        if m:  # "the one closer to you among the banana and the mug": the pick among exactly those (realsim.planner.topic)
            listed = [part for part in re.split(r"\s+and\s+|\s+or\s+|\s*,\s*", m.group(2)) if part]
            head = singular(listed[-1].split()[-1])  # "the red and green cubes": the red cube and the green cube
            listed = [f"{part} {head}" if all(w in COLOR_WORDS or w in BIG or w in SMALL or w in DETERMINERS for w in part.split()) else part
                      for part in listed[:-1]] + [re.sub(r"\w+$", head, listed[-1])]
            pool = {o.name for part in listed for o in self.resolve(part, Context(), allow_plural=False)}
            others = [o.name for o in self.objects if o.name not in pool]
            return self.resolve(m.group(1), ctx, want=want, exclude=[*exclude, *others], allow_plural=allow_plural, loose=loose)
        m = re.fullmatch(r"(.+?)\s+with\s+(.+)", text)  # "the cube with many colours": what it has, when that is no scene object
        if m and not {singular(w) for w in m.group(2).split()} & self._heads:  # "the cup with the handle": a part it has
            text = m.group(1)
            having = {o.name for o in self.objects if has_part(m.group(2), {w for n in self._words[o.name] for w in n})}
            if having and (others := [o.name for o in self.objects if o.name not in having]):  # "the thing with the handle": the mug, not the bowl
                return self.resolve(text, ctx, want=want, exclude=[*exclude, *others], allow_plural=allow_plural, loose=loose)
        elif m:  # "the bowl with the strawberry (in it)": the one holding it, never the strawberry
            return holding(m.group(1), re.sub(r"\s+(?:in|on) (?:it|them)$", "", m.group(2)), self._all, lambda k, o, r: relation_holds(k, o, r, self.forward, self.left), phrase)
        if not text:
            raise InputError(f"which object? nothing named in {phrase.strip()!r}; {self.listing()}")
        if re.fullmatch(r"(?:far |very )?(?:left|right|front|back|middle|center|centre|end|side|top|bottom)(?: side| end| hand side)?", text):
            raise InputError(f"{phrase.strip()!r} is a place, not an object; {self.listing()}")
        if text in SINGULAR_PRONOUNS or text in PLURAL_PRONOUNS:
            if not ctx.last:
                raise InputError(f"{phrase.strip()!r} does not refer to anything yet; name the object; {self.listing()}")
            if text.endswith("one") and len(ctx.last) > 1:  # "two soda cans ..., that one goes in the bowl": one of them, not both
                raise InputError(f"{phrase.strip()!r} is ambiguous: {', '.join(self._distinguish(list(ctx.last)))}; say which one")
            return list(ctx.last)
        m = re.fullmatch(r"(?:obj|object|item|thing|number|no)\s*#?\s*(\d+)((?: [a-z]+)*)", text)  # "object 3", "obj4", "obj1_cube": the scene's numbering
        if m:
            numbered = [o for o in self.objects if re.match(rf"obj{int(m.group(1))}(?:_|$)", o.name) and o.name not in exclude
                        and set(m.group(2).split()) <= set(name_words(o.name))]  # the body name said whole: its words must be its own
            if not numbered:
                raise InputError(f"there is no object {m.group(1)}{m.group(2)}; {self.listing()}")
            return numbered
        m = re.fullmatch(r"(?:that |this )?same (.+)", text)  # "that same cube": the cube just named
        if m and ctx.last and m.group(1) not in ("one", "ones", "thing", "object"):
            return self.resolve(m.group(1), Context(), want=want, exclude=[o.name for o in self.objects if o not in ctx.last])
        m = _REMAINING.fullmatch(text)
        if m and ctx.seen:  # "red cube on the plate, the green one on it, and the last one next to the plate": the cube not yet named
            rest = self.resolve(m.group(1) or m.group(2) or ctx.seen[-1].label, Context(), want=want, loose=True,
                                exclude=[*exclude, *(o.name for o in ctx.seen)])
            if len(rest) == 1:
                return rest
        m = re.fullmatch(r"(?:the )?other(?: one)?|(?:the )?other (.+)", text)
        if m:
            noun = m.group(1) or (ctx.last[0].label if ctx.last else "")
            if not noun:
                raise InputError(f"'the other one' does not refer to anything yet; {self.listing()}")
            taken = {o.name for o in ctx.last}
            rest = [o for o in self.objects if o.name not in {*exclude, *taken}]
            if not m.group(1) and len(rest) == 1 and len(ctx.last) == 1:  # "put it inside the other one": of two, the one not taken
                return rest
            return self.resolve(noun, Context(), want=want, exclude=[*exclude, *taken], allow_plural=False, loose=loose)
        text = _TWO_TONE.sub(lambda m: m.group(0) if is_plural(m.group(3)) else f"{m.group(1)} {m.group(2)} {m.group(3)}", text)  # "the red and white can": one can
        text = re.sub(r"^both (?:of )?(?=.+\s+and\s+)", "", text)  # "both the banana and the strawberry": a list
        parts = [p for p in re.split(r"\s*,\s*|\s+and\s+|\s+as well as\s+|\s+plus\s+", text) if p]
        if len(parts) > 1 and allow_plural and not re.search(r"\bbetween\b", parts[0]):  # "the cube between X and Y" is one
            out: list[ObjectInfo] = []
            for p in parts:  # "the left can and the other one": the other of those named before it
                for o in self.resolve(p, Context(out) if out and re.match(r"(?:the )?other\b", p) else ctx, want=want, exclude=exclude):
                    if o not in out:
                        out.append(o)
            return out
        m = re.fullmatch(r"(.+?)\s+(?:except(?: for)?|but(?: not)?|other than|apart from|besides|excluding|save for|not including)\s+(.+)", text)
        if m:
            excluded = self.resolve(m.group(2), Context(), allow_plural=True)
            return self.resolve(m.group(1), ctx, want=want, exclude=[*exclude, *(o.name for o in excluded)])
        m = re.fullmatch(r"(.+?)\s+(?:(?:that|which|who)\s+)?(?:(?:is|are|s)\s+)?(?:not|isnt|arent)\s+(.+)", text)
        if m:  # "the fruit that is not the banana", "the can that isn't red", "the cube not on the plate"
            np_said = re.match(r"(?:the|a|an|that|this) ", m.group(2))
            negated = m.group(2) if np_said else f"{m.group(1)} that is {m.group(2)}"
            excluded = self.resolve(negated, Context(), allow_plural=True, loose=True)
            return self.resolve(m.group(1), ctx, want=want, exclude=[*exclude, *(o.name for o in excluded)], allow_plural=allow_plural)
        return self._single_phrase(text, phrase, ctx, want, exclude, allow_plural, loose)

    def _single_phrase(self, text: str, phrase: str, ctx: Context, want: str | None, exclude: Sequence[str],
                       allow_plural: bool, loose: bool = False) -> list[ObjectInfo]:
        cands = [o for o in self.objects if o.name not in exclude]
        said = _generic_as_object(text)
        verbatim = [o for o in cands if said in (_generic_as_object(norm(o.label)), _generic_as_object(" ".join(name_words(o.name))))]
        if len(verbatim) == 1:  # the scene's own name said word for word ("the second from left yellow object"; "thing" for "object")
            return verbatim
        if len(ctx.last) >= 2 and _AMONG_NAMED.fullmatch(text):  # "the two cans are crammed. slide the right one ...": of those two
            cands = [o for o in cands if o in ctx.last] or cands
        text = re.sub(r"^(?:whichever|whatever)(?: one| thing)? (?:is|s) (?:the )?(\w+est|\w+most)$", r"\1 thing", text)  # "whatever is tallest"
        m = re.fullmatch(r"(.+?) (?:that is|that s|thats|which is|that are|which are|is|are) ((?:\w+ )?\w+)", text)
        if m and all(w in COLOR_WORDS or w in BIG or w in SMALL for w in m.group(2).split()):
            text = f"{m.group(2)} {m.group(1)}"  # "the cube that is red": the red cube
        text = re.sub(r"^(?:whichever|whatever|which ever|the one of the|one of the) (.+?) (?:is|are|that is|that are) ", r"\1 ", text)
        # a comparative with nothing to compare to but the speaker: "the can that is closer", "the one more to the left"
        for pattern, extreme in vocab.COMPARATIVES:
            text = re.sub(rf"^(.+?) (?:that is |that s |thats |which is |is |are )?{pattern}$", rf"{extreme} \1", text)
        text = re.sub(r"^(?:closer|nearer) (?!to )", "nearest ", re.sub(r"^(?:farther|further) (?!from )", "farthest ", text))
        # locators that name another object: "the can next to the bowl", "the cup closest to the plate"
        order: tuple[str, object] | None = None
        located = False
        m = re.fullmatch(r"(.+?)\s+(?:that is |thats |which is |that s |sitting |standing |lying |resting )?(?:on|at|atop) (?:the |your )?"
                         r"(?:table|counter|desk|worktop|tabletop|surface|floor|ground)(?: top| surface)?", text)
        if m:  # "the red can on the table": one standing on no other object
            text = m.group(1)
            cands = [o for o in cands if not any(r.name != o.name and relation_holds("on", o, r, self.forward, self.left) for r in self.objects)] or cands
        m = re.fullmatch(r"(.+?)\s+(?:that is |thats |which is |that s |sitting |standing |(?:that |which )?(?:sits|stands|lies) )?(?:right |directly |just )?(?:in )?between (.+)", text)
        if m:  # "the cube between the red and the green one", "the cube in between the other two"
            text, cands, located = m.group(1), between_of(m.group(1), m.group(2), cands, self._all), True
        m = re.fullmatch(r"(.+?)\s+(?:that is |thats |which is )?(?:(closest|nearest|closer|nearer)(?: to)?|(?:farthest|furthest|further|farther)(?: away)? from)"
                         r" (?!(?:to )?(?:me|you|the robot)$)(.+)", text)
        if m:
            ref = self.resolve(m.group(3), Context(), allow_plural=False)[0]
            text, order = m.group(1), ("near" if m.group(2) else "far", ref)
            cands = [o for o in cands if o.name != ref.name]
        else:
            for pattern, rel in LOCATOR_RELATIONS:
                m = re.fullmatch(rf"(.+?)\s+{pattern}\s+(?!the (?:left|right|far left|far right|front|back|middle|center|centre|end)(?: side| end)?$)(.+)", text)
                if m and not re.fullmatch(r"(?:the )?(?:left|right|front|back|middle|center|centre)(?: side| end| one)?|me|you|the robot", m.group(2)):
                    ref_phrase = m.group(2)
                    if re.fullmatch(r"(?:the|that|this) (?:\w+ )?one", ref_phrase):  # "the small white object off the big one": a big white object
                        kind = " ".join(w for w in m.group(1).split() if w not in DETERMINERS and w not in BIG and w not in SMALL)
                        ref_phrase = re.sub(r"\bone$", kind, ref_phrase) if kind else ref_phrase
                    try:  # every object the reference may mean: the relation itself may tell them apart
                        refs = self.resolve(ref_phrase, Context(ctx.last), allow_plural=True, loose=True)
                    except InputError:
                        continue
                    text, around = m.group(1), cands
                    rels = ("in", "on") if rel in ("from", "above") else ("on",) if rel == "under" else (rel,)
                    cands = [o for o in cands if any(o.name != r.name and (relation_holds(k, r, o, self.forward, self.left) if rel == "under"
                                                                           else relation_holds(k, o, r, self.forward, self.left))
                                                     for r in refs for k in rels)]
                    adjacent = re.search(r"\b(?:immediately|directly|just)\b", m.group(0)[len(m.group(1)): m.start(2)])
                    if (not cands or (adjacent and len(cands) > 1)) and len(refs) == 1 and rel in ("left", "right", "behind", "front"):
                        # nothing squarely there, or "immediately to its right" of several: the next one over
                        cands = next_over(rel, cands or around, refs[0], self.forward, self.left)
                    located = len(cands) == 1  # the relation alone says which
                    break
        # positional locators: "at the front on the right" (a corner), "on the left", "in the back", "closest to you", "in the middle"
        m = re.fullmatch(r"(.+?)\s+(?:at|in|on) the (?:very )?(front|back)(?: corner)?(?:,? (?:on|to|at) the)? (?:far )?(left|right)(?: corner| side)?", text)
        if m:
            text, order = m.group(1), ("corner", (m.group(2), m.group(3)))
        text, count = middle_of(text)  # "the block in the middle of the three"
        m = None if m else re.fullmatch(r"(.+?)\s+(?:that is |thats |which is |that s |is )?(?:(?:on|to|at|in) the (far )?(left|right|front|back|middle|center|centre)(?: side| end| one)?"
                         r"|(closest|nearest|closer|nearer)(?: to)? (?:me|you|the robot)|(farthest|furthest|farther|further)(?: away)? from (?:me|you|the robot))", text)
        if m:
            text = m.group(1)
            word = m.group(3) or ("nearest" if m.group(4) else "farthest")
            order = ("middle", count) if word in ("middle", "center", "centre") else ("extreme", word)
        words = text.split()
        # ordinal "second from the right", "the third can from the left", "the last box"
        ordinal: int | None = None
        m = re.search(r"\b(first|second|third|fourth|fifth|1st|2nd|3rd|4th|5th|last)\b", text)
        if m:
            idx = -1 if m.group(1) == "last" else ORDINALS[m.group(1)]
            d = re.search(r"\bfrom (?:the )?(left|right|front|back|far end|near end)\b", text)
            side = d.group(1) if d else (order[1] if order and order[0] == "extreme" else "left")
            side = {"far end": "back", "near end": "front"}.get(str(side), str(side))
            ordinal = idx
            order = ("extreme", side)
            text = re.sub(r"\bfrom (?:the )?(?:left|right|front|back|far end|near end)\b", " ", text)
            text = re.sub(rf"\b{m.group(1)}\b", " ", text)
            words = text.split()
        quantity: int | None = None
        plural = False
        if words and words[0] in ("all", "every", "each", "both", "everything"):
            plural = True
            if words[0] == "both":
                quantity = 2
            words = [w for w in words[1:] if w not in ("of", "the")] or (["thing"] if words[0] == "everything" else [])
        joined = " ".join(words)
        for phrase_n, n in sorted(NUMBERS.items(), key=lambda kv: -len(kv[0])):
            m = re.match(rf"(?:the )?((?:\w+(?:est|most) )?){phrase_n}\b\s*", joined)  # "the two biggest", "the biggest two"
            if m and n > 1:
                quantity, plural, joined = n, True, m.group(1) + joined[m.end():]
                break
        m = re.match(r"(?:the )?(\d+)\s+(.+)", joined)
        if m and int(m.group(1)) > 1:
            quantity, plural, joined = int(m.group(1)), True, m.group(2)
        words = [typos.spelled(w, self._said) for w in joined.split() if w not in DETERMINERS]  # misspellings read
        colors = [COLOR_WORDS[w] for w in words if w in COLOR_WORDS]
        sizes = [w for w in words if w in BIG or w in SMALL]
        extreme_words = [w for w in words if w in EXTREMES and w not in ("near", "far")]
        if extreme_words and order is None:
            order = ("extreme", extreme_words[-1])
        elif extreme_words and order is not None and order[0] == "extreme" and EXTREMES[extreme_words[-1]][0] != EXTREMES[str(order[1])][0]:
            order = ("corner", (str(order[1]), extreme_words[-1]))  # "the rightmost thing, closest to you": first both ways, else asked
        if any(w in ("middle", "center", "centre", "central") for w in words):
            order = ("middle", None)
        skip = set(COLOR_WORDS) | set(BIG) | set(SMALL) | set(EXTREMES) | {"middle", "center", "centre", "central", "one", "ones", "most", "colored", "coloured"}
        skip |= UNCHECKED - self._said  # "the round empty one", "the plastic bowl": what the scene cannot tell, unless its names say it
        nouns_raw = [w for w in words if w not in skip]
        if any(is_plural(w) for w in nouns_raw[-1:]):
            plural = True
        nouns = [singular(w) for w in nouns_raw]
        if plural and not allow_plural:
            plural = False
        # noun
        scored = [(o, self.noun_score(nouns, o)) for o in cands]
        if want:
            scored = [(o, s + (0.3 if s > 0 and want in o.affordances else 0.0)) for o, s in scored]
        scored = [(o, s) for o, s in scored if s > 0]
        core = core_words(nouns_raw, self._said) if not scored else None
        if core is not None:  # "omg that cereal box is": the cereal box
            scored = [(o, s) for o in cands if (s := self.noun_score([singular(w) for w in core], o)) > 0]
        if colors and scored:  # a colour decides before the noun's score does ("the blue one" is not the plate)
            named = max((s for _, s in scored), default=0.0) >= 1.5  # the noun names some object outright
            matching = [(o, s) for o, s in scored if set(colors) <= colors_of(o) and (s >= 1.5 or not named)]
            pool = [(o, s) for o, s in scored if s >= 1.5] if named else scored
            if not any(colors_of(o) for o, _ in pool):
                if not named and not located:
                    raise InputError(f"the scene does not say which object is {colors[0]}: {', '.join(describe(o) for o, _ in scored)}; "
                                     "name it another way")
                # the noun names it and no candidate's colour is recorded: the colour word cannot tell them
                # apart, so it is not checked ("the red brick" with one brick whose texture is missing)
                matching = pool
            scored = matching or (neighbour_colour_pick(pool, colors) if named else [])
            if not scored:
                raise InputError(f"no {' '.join(colors)} object matches {phrase.strip()!r}; {self.listing()}")
        if not scored:
            raise InputError(f"no object matches {phrase.strip()!r}; {self.listing()}")
        best = max(s for _, s in scored)
        cap = 1.7 + (0.3 if want else 0.0)  # the wanted use's bonus lifts every candidate having it alike
        floor = min(best, cap) - 1e-9 if (plural or loose or order or ordinal is not None or sizes or colors) else best - 1e-9
        found = [o for o, s in scored if s >= floor]
        exact = [o for o in found if norm(o.label) == " ".join(words)]
        if len(found) > 1 and not plural and len(exact) == 1 and order is None and not sizes:
            found = exact  # the scene's own name for it, word for word ("the red object" beside a red box)
        # size and position
        if sizes and len(found) > 1:
            found = size_pick(found, sizes[-1], quantity or 1)
        if order is not None and len(found) > 1:
            found = ordered(found, order, ordinal, phrase, self.robot_xy, self._distinguish, radial=self.radial)
        elif ordinal is not None and ordinal not in (1, -1) and len(found) <= 1:
            raise InputError(f"there is no {phrase.strip()!r}: only {len(found)} such object(s)")
        if plural:
            if quantity is not None and len(found) != quantity:
                raise InputError(f"{phrase.strip()!r}: the scene has {len(found)}, not {quantity}: "
                                 f"{', '.join(describe(o) for o in found)}")
            return found
        if len(found) > 1 and not colors:  # "the cracker box" between a white and a red box: a cracker box is red
            found = usual_colour_pick(nouns, found)
        if len(found) > 1:  # "the cardboard one": the box (a material the scene's own names say was read as a name)
            found = usual_material_pick([w for w in words if w not in self._said], found)
        if len(found) > 1:
            found = footprint_shape_pick(words, found)
        if len(found) > 1 and not loose and core is not None:  # talk around a name that names no one thing: no name at all
            raise InputError(f"no object matches {phrase.strip()!r}; {self.listing()}")
        if len(found) > 1 and re.match(r"(?:that|this|the same) ", text):  # "... in front of the red can, so between that can and you": the one just named
            named = [o for o in (*ctx.last, *([ctx.place] if ctx.place else []), *reversed(ctx.seen)) if o in found]
            found = named[:1] or found
        if len(found) > 1 and not loose:
            raise InputError(f"{phrase.strip()!r} is ambiguous: {', '.join(self._distinguish(found))}; "
                             "say which one (colour, size, left/right, or the body name)")
        return found

    def _all(self, phrase: str) -> list[ObjectInfo]:
        """Every object ``phrase`` may mean."""
        return self.resolve(phrase, Context(), allow_plural=True, loose=True)

    def _distinguish(self, objs: list[ObjectInfo]) -> list[str]:
        """Each candidate with its colour, size and position word among the others."""
        ranked = sorted(objs, key=lambda o: -self.robot_xy(o)[1])
        out = []
        for i, o in enumerate(ranked):
            where = left_order(i, len(ranked))
            out.append(f"{o.name} ({' '.join(w for w in (self.color_of(o), o.label) if w)}, {where})")
        return out


def _generic_as_object(text: str) -> str:
    """A name with its generic noun said one way ("the big white thing" or "item": object; "one" may stand for any noun)."""
    return re.sub(r"\b(?:thing|item)$", "object", text)
