"""A thing named before the command that acts on it: a fronted topic ("the bowl, push it
forward"; "the thing at the very back, closest to you, push it ..."), a partitive opening ("of
the two sodas, take the one on the left") and a choice among named things ("whichever is closer,
the banana or the mug"; "of the marker and the meat can, the one further away").

A choice among named things becomes "<the one ...> among <A> and <B>", which the resolver reads
as the pick among exactly those things (see :mod:`realsim.planner.reference`), never among all.
"""

from __future__ import annotations

import re

from realsim.errors import InputError
from realsim.planner import casual
from realsim.planner.lexicon import AVOID, MEASURE, RELATION_AT, STATEMENT_VERB, VERB_START, has_relation, relation_start
from realsim.planner.vocab import singular

__all__ = ["TOPIC", "bare", "choice", "compared", "fronted", "joined", "partitive", "whichever_of"]

TOPIC = "topic: "  # a clause that only names what the next clause's "it" means

_VERB = VERB_START
_PRONOUN = re.compile(r"\b(?:it|them|th(?:at|is) one)\b")
# a locator said as a piece of its own after a topic ("..., closest to you, push it ..."): which one, never where to
_LOCATOR = re.compile(r"(?:the one )?(?:(?:that is |thats |that s |which is )?(?:closest|nearest|closer|nearer|furthest|farthest|further|farther)\b"
                      r"|(?:on|at|in) the (?:front|back|middle|centre|center|left|right)\b|the \w+most\b"
                      r"|(?:from|off|off of|out of) (?:the|that|this) [a-z ]+?(?: (?:down|off|away|out))?$)")  # where it is taken from
_STATEMENT = re.compile(rf"(?<!that )(?<!which )(?<!who )\b{STATEMENT_VERB}\b")
_LIST = r"(?:the |that |this )?[a-z ]+?(?:(?:,| or| and)\s+(?:the |that |this )?[a-z ]+?)+"


_EXISTS = re.compile(r"^(?:so |ok |okay |oh |look )?(?:there|here)(?: is| s)? (?:a|an|one|the) ")
_SURFACE = r"(?:table|desk|counter|countertop|worktop|surface|floor)"
_MOST = {"back": "backmost", "backward": "backmost", "backwards": "backmost", "forward": "frontmost", "front": "frontmost",
         "left": "leftmost", "right": "rightmost"}


def compared(phrase: str) -> str:
    """A position said as a comparative inside a noun phrase ("the can further back", "the one more
    to the left") as the extreme it picks ("the can backmost"); a push's "further back" is a way and
    never reaches here (only topics and choices are read with it)."""
    return re.sub(r"\b(?:that is |thats |that s |which is |is )?(?:further|farther|more) (?:to (?:the )?|towards? (?:the )?)?(back|backwards?|forward|front|left|right)\b(?! of)",
                  lambda m: _MOST[m.group(1)], phrase)


def bare(phrase: str) -> str:
    """A noun phrase without what only picks among its kind: a relative clause ("the can that is
    on the left"), a position ("the soda on the right") or a distance from the speaker ("closer to you")."""
    phrase = re.sub(r"\s+(?:that is|that s|thats|which is|that|which)\s.*$", "", phrase)
    phrase = re.sub(r"\s+(?:(?:closest|nearest|closer|nearer) to|(?:furthest|farthest|further|farther)(?: away)? from) (?:you|me|the robot)\b", "", phrase)
    return re.sub(r"\s+(?:on|to|at|in) the (?:far )?(?:left|right|front|back|middle|center|centre)(?: side| end| one)?\b", "", phrase)


def choice(parts: list[str]) -> list[str]:
    """"whichever is closer to you, the banana or the mug, and put it ..." / "the banana or the mug,
    whichever is closer": the pick among the things listed (see the module)."""
    for i in range(len(parts) - 1):
        a, b = parts[i], parts[i + 1]
        m = re.search(r"\b(?:whichever|whatever|which ever)(?: one)? (?:is|s) (.+)$", a)
        if m and re.fullmatch(_LIST, b):
            return [*parts[:i], f"{a[: m.start()]}{compared('the one ' + m.group(1))} among {_and(b)}".strip(), *parts[i + 2:]]
        m = re.fullmatch(r"the one (.+)", a)
        if m and re.fullmatch(_LIST, b) and " or " in b:  # "the one further back, the mug or the banana, ..."
            return [*parts[:i], f"{compared(a)} among {_and(b)}", *parts[i + 2:]]
        m = re.fullmatch(r"(?:whichever|whatever|which ever)(?: one)? (?:is|s) (.+)", b)
        if m and re.search(_LIST + "$", a):
            listed = re.search(rf"(?:^|\b(?=the |that |this )){_LIST}$", a)
            if listed:
                return [*parts[:i], f"{a[: listed.start()]}{compared('the one ' + m.group(1))} among {_and(listed.group(0))}".strip(), *parts[i + 2:]]
    return parts


_WHICHEVER_OF = re.compile(r"\b(?:whichever|which ever)(?: one)? (of|out of|between) ((?:the |that |this )?[a-z ]+? (?:and|or) (?:the |that |this )?[a-z ]+?)"
                           r" (?:is|s) ([a-z ]+?)(?=,)")


def whichever_of(text: str) -> str:
    """"whichever of the banana and the mug is closer to me, push that one ..." as the partitive
    "of the banana and the mug, the one closer to me, push that one ...": the pick among those two."""
    return _WHICHEVER_OF.sub(lambda m: f"{m.group(1)} {_and(m.group(2))}, the one {m.group(3)}", text)


def _and(listed: str) -> str:
    return re.sub(r"\s*,\s*|\s+or\s+", " and ", listed)


def partitive(parts: list[str]) -> list[str]:
    """"of the two sodas, pick up the one on the left", "see the two red cans? take the one closer
    to you": "one" is a soda (a can), and the opening names no object of its own; "of the marker
    and the meat can, the one further away": the one among those two."""
    if len(parts) < 2:
        return parts
    while len(parts) > 2 and re.match(r"(?:of|out of|among|from among|between) ", parts[0]) and re.fullmatch(r"(?:(?:the|that|this) )?[a-z ]+", parts[1]) \
            and not _VERB.match(parts[1]) and not re.match(r"(?:the one|whichever|which ever)\b", parts[1]):  # "of the marker and the meat can": split at "and"
        parts = [f"{parts[0]} and {parts[1]}", *parts[2:]]
    m = re.fullmatch(r"(of|out of|among|from among|between|(?:you )?see|look at|notice|(?:so |ok |okay )?(?:there|here)(?: are| is| s)?|we have|i have|i see) "
                     r"((?:all )?(?:the |these |those )?(?:two |three |four |both )?)([a-z ]+)", parts[0])
    restricts = bool(m) and m.group(1) in ("of", "out of", "among", "from among", "between") and bool(m.group(2))
    if m and restricts:  # "of the marker and the meat can, grab whichever is closer": the one closer
        parts = [parts[0], re.sub(r"\b(?:whichever|which ever)(?: one)? (?:is |s )?", "the one ", parts[1]), *parts[2:]]
    one = re.search(r"\bthe one\b", parts[1])
    if m and restricts and " and " in f" {m.group(3)} " and one:  # "of the marker and the meat can, take the one further away"
        listed = f"{m.group(2)}{m.group(3)}".strip()
        start = one.start()
        cut = next((r.start() for r in RELATION_AT.finditer(parts[1], one.end())  # a place it goes, not one that says which
                    if not re.match(r"(?:closer|nearer) to\b", r.group(0))
                    and not re.match(r"\s*(?:me|you|the robot|(?:the )?(?:far |very )?(?:left|right|front|back|middle|centre|center)\b(?! of))", parts[1][r.end():])),
                   len(parts[1]))
        cut = min(cut, _way_start(parts[1], one.end()))  # "push the one closer to me | forward 4 cm"
        phrase = compared(parts[1][start:cut].strip())  # "the one further left | on the plate"
        return [f"{parts[1][:start]}{phrase} among {listed} {parts[1][cut:].strip()}".strip(), *parts[2:]]
    if m and restricts and (" and " in f" {m.group(3)} " or not re.search(r"\bone\b", parts[1])):
        # "out of the yellow things, take the biggest": never chosen among everything
        raise InputError(f"{parts[0]!r}: cannot read which ones to choose among; name the one you mean ('the biggest yellow object')")
    if not m or not re.search(r"\bone\b", parts[1]):
        return parts
    words = m.group(3).split()
    return [re.sub(r"\bone\b", " ".join([*words[:-1], singular(words[-1])]), parts[1], count=1), *parts[2:]]


_DIRECTION = r"(?:left|right|forward|forwards|back|backward|backwards|away|toward (?:me|you)|towards (?:me|you)|closer)"
_WAY = re.compile(rf"(?:(?:by )?(?:about )?{MEASURE} )?(?:to the )?{_DIRECTION}(?: (?:and |by )?(?:about )?{MEASURE})?")  # "10 cm right", "left 5 cm"


# a way said after the pick: a distance, or a direction that no comparative or article makes part of the pick
_WAY_START = re.compile(rf"\s(?:(?:by )?(?:about )?{MEASURE}\b|(?:forwards?|backwards?|back|away|left|right)\b(?! of))")
_PICK_WORD = ("further", "farther", "more", "most", "the", "far", "very", "to", "on", "at", "in")


def _way_start(text: str, start: int) -> int:
    """Where a way ("forward 4 cm", "5 cm to the left") begins in ``text`` after ``start``, or its end."""
    for m in _WAY_START.finditer(text, start):
        if not text[: m.start()].endswith(_PICK_WORD):  # "the one further back", "the one on the left": which one
            return m.start()
    return len(text)


def joined(parts: list[str], verb_re: re.Pattern[str]) -> list[str]:
    """A thing and its place or way said as two pieces ("Blue one, next to it"; "Marker, up!"; "Red
    can. 10 cm right."): one piece, so the place goes with that thing and not with the command before it."""
    out: list[str] = []
    for part in parts:
        prev = out[-1] if out else ""
        if (prev and not verb_re.match(prev) and not verb_re.match(part) and not has_relation(prev) and not _STATEMENT.search(prev)
                and not prev.startswith(TOPIC) and re.fullmatch(r"[a-z ]+", prev) and (relation_start(part) or part in ("up", "up high") or _WAY.fullmatch(part))):
            out[-1] = f"{prev} {part}"
        else:
            out.append(part)
    return out


def fronted(parts: list[str], verb_re: re.Pattern[str], comma: bool) -> list[str]:
    """A bare noun phrase before a clause that acts on it, put into that clause: "the bowl, push it
    forward" (for "it"), "the banana, put in the bowl" (as the verb's object), "the soup, next to the
    banana" (what goes there). Locator pieces after it ("..., closest to you, push it") say which
    one. ``comma``: the topic ends at a comma (then a topic naming a place, "the thing in front of
    the bowl, slide it ...", is still read as one when a pronoun takes it up)."""
    if len(parts) < 2:
        return parts
    topic, n = re.sub(r"^(?:as for|about) ", "", parts[0]), 1
    while n + 1 < len(parts) and _LOCATOR.match(parts[n]) and not verb_re.match(parts[n]):
        topic, n = f"{topic} {re.sub(r'^the one ', '', parts[n])}", n + 1
    rest = parts[n]
    verb = verb_re.match(rest)
    resumed = bool(verb) and bool(_PRONOUN.search(rest))
    said = _EXISTS.match(topic)  # "there's a mug on the table. put it in the bowl": the mug (the one, else asked)
    topic = re.sub(r"^(?:whatever|whichever|which ever) (?!(?:one|thing|is|s)\b)((?:\w+ )?\w+) (?:is|s|are) ", r"the \1 ", topic)  # "whichever can is closer to the bowl"
    topic = compared(re.sub(r"^(?:whatever|whichever)(?: one| thing)? (?:is |s )?", "the thing ", _EXISTS.sub("the ", topic)))
    topic = re.sub(rf"\s+(?:on|at|upon) (?:the |my |your |our )?{_SURFACE}$", "", topic)
    placed_as_is = bool(verb) and relation_start(rest[verb.end():].strip())  # "..., from the box, put on the table": its object left out
    if n > 1 and not resumed and not placed_as_is or said and not resumed:
        return parts
    if (_STATEMENT.search(topic) or verb_re.match(topic) or AVOID.match(topic) or casual.terse(topic, has_relation(topic))
            or re.match(r"(?:i|we) (?:would |d )?(?:like|want|need|wish)\b", topic)):  # "i want the banana. give it to me": a wish
        return parts
    if has_relation(bare(topic)) and not (resumed and (comma or said)):
        return parts
    if resumed:  # "the bowl, push it forward": a command opening with a noun phrase names what "it" means
        return [f"{TOPIC}{topic}", *parts[n:]]
    if verb and (relation_start(rest[verb.end():].strip())  # "the banana, put in the bowl": the verb's object
                 or re.match(r"(?:\d+|a bit|a little|slightly|left|right|forward|back|up|down)\b", rest[verb.end():].strip())):
        return [f"{verb.group(0)} {topic} {rest[verb.end():].strip()}", *parts[n + 1:]]
    if relation_start(rest):
        return [f"{topic} {rest}", *parts[n + 1:]]  # "the soup, next to the banana": where the named thing goes
    return parts
