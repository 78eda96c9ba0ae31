"""Speech as people say it, before it is read as a command: self-repairs ("the soup can in the
mug no no in the bowl", "the soup can uh the tomato one"), narration ("now the robot will place
..."), the robot addressed without a comma, words said twice, "like" as a filler, and the object
said before its verb ("the red fruit put in front of the banana").

The verb and relation patterns come from :mod:`realsim.planner.phrasing` (which calls this), so
the two never disagree on what a verb or a place is.
"""

from __future__ import annotations

import re

from realsim.errors import InputError
from realsim.planner.lexicon import TAKE
from realsim.planner.vocab import BIG, COLOR_WORDS, SMALL

__all__ = ["instead", "noun_phrases", "object_first", "one_as", "reasons", "repair"]

_MARKERS = (r"no no|no wait|no sorry|(?:scratch|strike|forget|cancel|ignore) that|or rather|let me rephrase|correction|hold on|hang on"
            r"|no|sorry|wait|actually|i meant|i mean|uh+|um+|er+|erm|hmm+")
_MARKER = re.compile(rf"(?:^|(?<=[\s,]))({_MARKERS})(?=[\s,])")
_TRAILING = re.compile(rf"(?:[\s,;.!?-]*\b(?:{_MARKERS}))+[\s,;.!?-]*$")  # "... to the left. hang on," before the repair itself
# the speaker saying the whole last request was turned round, before saying it again
_BACKWARDS = re.compile(r"[,.;\s]*(?:i |i ve |you )?(?:said|got|had|have|put|did) (?:that|it|this) (?:backwards|backward|wrong|the wrong way(?: round| around)?|mixed up|the other way(?: round| around)?)[,.;\s]*$")
# the thing a request acts on: its first noun phrase, up to a place word or the end
_FIRST_THING = re.compile(r"\b((?:the|that|this|my|your) [a-z ]+?)(?=\s+(?:in|into|on|onto|next|behind|beside|to|toward|towards|left|right|from|off|up|down|out)\b|\s*[,.;!?]|$)")
_BY = re.compile(r"(?<![a-z])by(?= (?:the|that|this|my|your|it)\b)")  # "by the mug": a place too, where a relation pattern leaves "by" out
_WEAK = re.compile(r"(?:uh+|um+|er+|erm|hmm+)")
_AUDIENCE = r"(?:class|students|everyone|everybody|kids|children|guys|folks|team|you all|all of you)"
# a teacher's opening before the narration: "now students, ", "class, watch the arm: ", "everyone look here: "
_ATTENTION = re.compile(rf"^(?:(?:now|ok|okay|alright|all right|so|right|and)[\s,]+)*(?:{_AUDIENCE}[\s,:]+)?(?:(?:now|ok|okay|alright)[\s,]+)?"
                        rf"(?:(?:watch|look|see|observe|pay attention|eyes (?:up|here|on me))(?: (?:closely|carefully|here|this|now|up))*(?:[\s,]+{_AUDIENCE})?"
                        r"(?: (?:the (?:robot|arm)|it|this))?\s*[:,.!-]+\s*)?")
_NARRATION = re.compile(r"^(?:(?:now|alright|all right|ok|okay|so|class|everyone|kids|guys|and|then)\s+)*"
                        r"(?:(?:watch|look|see)(?: closely| carefully)?(?: everyone| class| kids)?\s+(?:as |how )?(?:the robot|the arm|it)\s+"
                        r"|(?:the robot|the arm|it|you|we)\s+(?:will|is going to|s going to|are going to|re going to|(?:is |s |are |re )?gonna|shall|is about to|can|is able to"
                        r"|is now going to|s now going to|will now)\s+(?:now\s+)?)")
_ADDRESS = re.compile(r"^(?:hey |ok |okay |alright |yo |hi |hello )?(?:robot|franka|panda|class|everyone)\s+(?=\w)")


def repair(text: str, verb: re.Pattern[str], relation: re.Pattern[str]) -> str:
    """``text`` (lower case, punctuation kept) with what the speaker took back replaced by what
    they said instead; ``verb`` / ``relation`` match a command verb / a place at a text's start."""
    text = re.sub(r"\b(\w+)(?: \1\b)+", r"\1", text)  # "bowl bowl", "no no"
    text = re.sub(r"\b((?:\w+ ){1,3}\w+)(?:\s*[,-]\s*\1\b)+", r"\1", text)  # "the blue box, the blue box"
    text = homophones(text, verb)
    text = re.sub(r"(?<!\bi )(?<!\bd )(?<!would )(?<!\byou )\blike an? (?!(?:bit|little|lot|tad|touch|few|couple)\b)\w+(?=$|[\s,.;!?])(?! (?:on|in|into|next|to|behind)\b)", " ", text)  # "like a trophy": how
    text = re.sub(r"(?<!\bi )(?<!\bd )(?<!would )(?<!\byou )\blike\b(?! (?:to|this|that)\b)", " ", text)  # "put it like right there"
    text = " ".join(text.split())
    text = instead(reasons(text, verb, relation))
    text = _MEANT_AFTER.sub(r", i mean \1,", text)  # "the right can, er, the left one I mean, next to the mug"
    for _ in range(4):
        step = _one_repair(text, verb, relation)
        if step == text:
            break
        text = step
    text = _ADDRESS.sub("", _NARRATION.sub("", _ATTENTION.sub("", text) if _NARRATION.match(_ATTENTION.sub("", text)) else text))
    return _NARRATION.sub("", text)


def _one_repair(text: str, verb: re.Pattern[str], relation: re.Pattern[str]) -> str:
    for m in reversed(list(_MARKER.finditer(text))):
        before, after = _TRAILING.sub("", text[: m.start()]).strip(" ,"), _TRAILING.sub("", text[m.end():]).strip(" ,")
        if not before or not after:
            continue
        weak = bool(_WEAK.fullmatch(m.group(1)))
        said = re.sub(r"^(?:(?:just|rather|instead|actually|make (?:that|it)|i meant?)\s+)+", "", after)
        said = re.sub(r"^not (?:the |that |this |in |into |on |onto |by |next to )*[a-z ]+?,\s*(?=\S)", "", said)  # "not the bowl, onto the green box"
        said = _CONFIRMED.sub("", said)  # "I meant the red box, not the blue one": the contrast only confirms
        if _BACKWARDS.search(before) and (verb.match(said) or relation.search(f" {said}")):
            # "bowl to the left of the mug. er, I said that backwards, I meant the mug to the left of the bowl": said anew
            start = max((m.end() for m in re.finditer(r"[.;!?]\s*", _BACKWARDS.sub("", before).rstrip(" ,.;"))), default=0)
            return f"{before[:start]}{said}".strip()
        if verb.match(said) and not weak:  # "put the mug in the bowl no sorry just pick up the bowl"
            # "..., actually no, take it out again": an undo of what was done, so what was done stays
            # unless the speaker cancelled it ("scratch that"), said the new one is instead ("no, just slide it")
            # or the new command names its own object first
            cancelled = re.match(r"(?:scratch|strike|forget|cancel|ignore) that|let me rephrase|correction", m.group(1))
            undo = re.match(r"[a-z ]*?\b(?:it|them)\b", said) and not re.match(r"[a-z ]*?\b(?:the|a|an|this|that)\s[a-z ]*?\b(?:it|them)\b", said)
            instead = re.match(r"(?:just|rather|instead)\b", after) or re.search(r"\binstead\W*$", said)  # "actually no, just slide it": in its place
            if undo and instead and (thing := _FIRST_THING.search(before[_last_verb(before, verb):])):
                return f"{thing.group(1)}, {said}"  # "pick up the can - no, just slide it": the can, slid instead
            return f"{before}, {said}" if undo and not cancelled and not instead else said
        if relation.match(said):  # "the soup can in the mug no no in the bowl"
            places = sorted([*relation.finditer(before), *_BY.finditer(before)], key=lambda r: r.start())  # "put it by the mug. no, between ..."
            if places:
                old_place = re.match(r"\s*(?:\w+\s+)*?((?:the|that|this|my|your)\s[a-z ]+?)\s*(?:[^a-z ]|$)", before[places[-1].end():])
                if old_place and re.search(r"\b(?:it|that one)\b", said):  # "behind the box, no, make that in front of it": of the box
                    said = re.sub(r"\b(?:it|that one)\b", old_place.group(1), said, count=1)
                elif old_place and not _POSITION.fullmatch(f" {old_place.group(1)}") and (side := _BARE_SIDE.fullmatch(said.strip(" ,.;!?"))):  # "left of the plate. no, to the right": of the plate
                    said = f"{side.group(0)}{'' if side.group(0).endswith(('behind', 'beside', 'next to')) else ' of'} {old_place.group(1)}"
                return f"{before[: places[-1].start()].rstrip(' ,')} {said}"
        places = [r for r in relation.finditer(before) if not _POSITION.match(before, r.end())]  # "on the right" says which
        start = max([m.end() for m in verb.finditer(before)] + [r.end() for r in places], default=0)
        if re.match(r"(?:the|that|this|a|an)\s", said) and re.match(r"\s*(?:the|that|this|a|an)\s", before[start:]):
            if restart := _restarted(said, verb):  # "push the red box -- sorry, the red can -- push it toward you"
                return f"{before[: _last_verb(before, verb)].rstrip(' ,')} {restart}".strip()
            said = _continued(said, verb, relation)
            if re.search(r"(?:^|\s)(?:the|that|this|a|an)\s", before[:start]) and not weak:  # which of two does it replace?
                return _contrast(before, said, text, verb, relation)
            if (said_np := _PHRASE_ONLY.fullmatch(said.strip(" ,.;!?"))) and not any(relation.match(said, w.start()) for w in re.finditer(r"\b\w", said)) and (old_np := _OBJECT_PHRASE.match(before, len(before) - len(before[start:].lstrip()))) and old_np.end() < len(before):
                # "push the blue box 5 cm to the left. hang on, I meant the red box": only the object said anew
                return f"{before[:old_np.start()]}{one_as(said_np.group(0), old_np.group(0))} {before[old_np.end():]}".strip(" ,")
            return f"{before[:start].rstrip()} {one_as(said, before[start:])}".strip()  # "put the soup can uh the tomato one behind the bowl"
        if weak:
            return f"{before} {after}"
    return text


_MEANT_AFTER = re.compile(r"(?:(?<=[,;-])|(?<=\.))\s*(?:(?:er+|um+|uh+|erm)\s*,?\s*)?((?:the|that|this) [a-z ]+?),? i mean(?=\s*[,.;-]|$)")
_CONFIRMED = re.compile(r",?\s*(?:and )?not (?:the|that|this) [a-z ]+?(?=$|[.,;!?])")
# a side said alone as a repair ("no, to the right"): of the thing the replaced place named
_BARE_SIDE = re.compile(r"(?:to the |on the )?(?:left|right)|in front|on top|behind|beside|next to")
# a repair that is only an object phrase, and the object phrase of a command it replaces (up to an amount, place or pause)
_PHRASE_ONLY = re.compile(r"(?:the|that|this|a|an) [a-z ]+")
_OBJECT_PHRASE = re.compile(r"(?:the|that|this|a|an) (?:(?!(?:to|in|into|on|onto|next|behind|beside|by|toward|towards|forward|back|left|right|up|down"
                            r"|one|two|three|four|five|six|seven|eight|nine|ten|a|an|about|around|roughly)\b)[a-z]+ ?)+")
_POSITION = re.compile(r"\s+(?:the )?(?:far |very )?(?:left|right|front|back|middle|center|centre)\b")
_HOMOPHONES = ((r"\b(?:too|two)\b(?= (?:the )?(?:left|right|front|back|side|top)\b)", "to"),  # "move it two the left"
               (r"\b(next|close|closer|near|nearer|back|up|over) (?:too|two)\b(?= (?:the|my|your|it|them|that|this|where)\b)", r"\1 to"),  # "next two the bowl"
               (r"\b(?:too|two)\b(?= (?:the|my|your|where)\b)", "to"),  # "move it two the bowl": a count never precedes "the"
               (r"\bwere (?=(?:it|they) (?:was|were|is|are|came|started|stood|sat|used)\b)", "where "),  # "put it back were it was"
               (r"\bblew\b", "blue"),  # "the blew cube"
               (r"\bfor\b(?= (?:cm|mm|centimet|millimet|inch))", "four"),  # "for centimeters"
               (r"(?<=[a-z] )2(?= (?:the|my|your|it|them|where)\b)", "to"),  # "next 2 the banana": a count never precedes "the"
               (r"\b(next|nxt|close|closer|near|nearer|left|right|up) 2\b(?![.,]\d)(?! ?(?:cm|mm|inch|centimet|millimet|more|of))", r"\1 to"),  # "nxt 2 bowl"
               # "place the bowl before the cup": in front of it (a time is "before you ...", "before that")
               (r"\b((?:put|place|set|move|drop|stand|leave) (?:(?!before\b|b4\b)[a-z' ])+?) (?:before|b4) (?=(?:the|a|an|my|your) )", r"\1 in front of "))


def homophones(text: str, verb: re.Pattern[str]) -> str:
    """Words speech-to-text writes for others that sound the same: "two the left", "for
    centimeters", "than go home" (then, before a command verb)."""
    for pattern, word in _HOMOPHONES:
        text = re.sub(pattern, word, text)
    return re.sub(rf"\bthan (?={verb.pattern})", "then ", text)


def _last_verb(before: str, verb: re.Pattern[str]) -> int:
    """Where the last command verb of ``before`` starts (0 when it has none)."""
    return max((m.start() for m in re.finditer(rf"(?:^|(?<=[\s,;.]))(?:{verb.pattern})", before)), default=0)


def _restarted(said: str, verb: re.Pattern[str]) -> str | None:
    """A repaired object phrase followed, after a pause, by the command said again from its verb
    ("the mug, put it in the bowl"; "the red can -- push the red can toward you"): that command,
    its "it" the repaired object; None when no command follows the phrase."""
    m = re.match(r"([^,;.]+?)\s*[,;-]+\s*(.+)", said)
    if not m or not verb.match(m.group(2)):
        return None
    phrase, command = m.group(1).strip(), m.group(2)
    if re.search(r"\b(?:it|them)\b", command):
        return re.sub(r"\b(?:it|them)\b", phrase, command, count=1)
    return command if phrase in command else None


def _continued(said: str, verb: re.Pattern[str], relation: re.Pattern[str]) -> str:
    """A repaired object phrase and the rest of the command it interrupted, without the pause
    between them ("the red can, behind the box" -> "the red can behind the box")."""
    m = re.match(r"([^,;.]+?)\s*[,;-]+\s*(.+)", said)
    if m and not verb.match(m.group(2)) and not re.match(r"(?:then|and)\b", m.group(2)):
        return f"{m.group(1)} {m.group(2)}"
    return said


def noun_phrases(text: str, verb: re.Pattern[str], relation: re.Pattern[str]) -> list[tuple[int, int]]:
    """(start, end) of each noun phrase opened by a determiner, up to a place word, a verb or a pause."""
    out = []
    for m in re.finditer(r"(?:^|(?<=\s))(?:the|that|this|a|an)\s", text):
        end = m.end()
        while end < len(text) and text[end] not in ",;." and not (text[end - 1] == " " and (relation.match(text, end) or verb.match(text, end))):
            end += 1
        out.append((m.start(), end))
    return out


def _contrast(before: str, said: str, text: str, verb: re.Pattern[str], relation: re.Pattern[str]) -> str:
    """Which earlier phrase a repair such as "make that the green one" replaces: the one phrase
    whose kind of modifier it contrasts (a colour for a colour, a size for a size); else the
    speaker is asked."""
    def classes(phrase: str) -> set[str]:
        words = set(phrase.split())
        return {c for c, vocab in (("colour", COLOR_WORDS), ("size", (*BIG, *SMALL))) if words & set(vocab)}

    said_np = next(iter(noun_phrases(said, verb, relation)), (0, len(said)))
    wanted = classes(said[said_np[0]:said_np[1]])
    hits = [(a, b) for a, b in noun_phrases(before, verb, relation) if wanted and wanted & classes(before[a:b])]
    if len(hits) != 1 or not re.search(r"\bone\b", said):
        raise InputError(f"{text!r}: '{said}' could replace either thing named before it; say the whole command again")
    a, b = hits[0]
    return f"{before[:a]}{one_as(said[said_np[0]:said_np[1]].strip(), before[a:b])} {before[b:].strip()}".strip()


def one_as(said: str, replaced: str) -> str:
    """"the green one" replacing "the blue cube": the green cube (its noun taken from what it replaces)."""
    head = re.sub(r"\s+(?:on|in|at|to) the\b.*$|[^a-z ].*$", "", replaced.strip()).split()
    return re.sub(r"\bone\b", head[-1], said, count=1) if len(head) > 1 and head[-1] != "one" else said


def object_first(clause: str, verb: re.Pattern[str]) -> str | None:
    """"the red fruit put in front of the banana", "bowl slide it back toward me": the verb
    first, or None when no command verb follows the opening words."""
    for m in verb.finditer(clause):
        head = clause[: m.start()].strip()
        if not head or verb.match(clause):
            return None
        tail = re.sub(r"^(?:it|them)\b\s*", "", clause[m.end():].strip())
        head = re.sub(r"^(?:please\s+)?|\s+you$", "", head)
        return f"{m.group(0).strip()} {head} {tail}".strip()
    return None


# a reason or purpose after a command: talk about why, never where ("..., it's in my way when I reach for the banana")
_UNTIL = r"(?:(?!,\s*(?:but|then|and|after|also|finally|next)\b)[^.;!?])*"  # to the end of the sentence or the next clause
_REASON = re.compile(rf"\s*,?\s*\b(?:because|cause|cos|coz|since|so that|so(?= (?:i|we|you|it|they|he|she|everyone|the|there|that|my|your|nothing|no)\b))\b{_UNTIL}"
                     rf"|\s*,\s*(?:it's|it is|its|that's|thats|that is|they're|they are|when (?:i|we|you|it|they))\b{_UNTIL}")
# a remark after a command: a statement of the speaker or about the things ("..., they go together",
# "..., I'm making lunch"), or a time ("before it falls off", "until I say so"); dropped like a
# reason, but only when it names no place ("until it sits next to the bowl" is kept)
_REMARK = re.compile(rf"\s*,\s*(?:(?:clearly|obviously|honestly|basically|apparently|anyway|seriously|well)\s+)?"
                     rf"(?:i'm|im|i am|i've|ive|i have|i need|i'll|we're|we are|we|they|he's|she's|there's|theres|this is|that's|thats|that is"
                     rf"|(?:my|our) [a-z]+(?: [a-z]+)? (?:wants?|likes?|loves?|needs?|left|is|was|has|had|made|keeps?|will|gets?))\b{_UNTIL}"
                     rf"|\s*,?\s*\b(?:before (?:it|they|he|she|someone|somebody|anyone|anybody|things?)|until (?:i|we|you|it|they|someone)|in case)\b{_UNTIL}")


_TAKE = re.compile(rf"(?<![a-z])(?:{'|'.join(re.escape(v) for v in sorted(TAKE, key=len, reverse=True))}) (?:up )?(?:the|that|this|it|them)\b")


def reasons(text: str, verb: re.Pattern[str], relation: re.Pattern[str]) -> str:
    """``text`` without a reason or purpose clause ("because ...", "since ...", "so I can ...",
    ", it's ...", ", when I ...") or a remark that follows, in the same sentence, a command whose
    place is already said, or a take that needs none: what such a clause names is never the place
    or the object."""
    verb_any = re.compile(rf"(?<![a-z]){verb.pattern}")
    place_any = re.compile(rf"(?<![a-z]){relation.pattern}\s*(?:the|a|an|my|your|that|this|these|those|each other|one another|it|them|me|you)\b")
    out, start = [], 0
    for sentence in re.finditer(r"[^.;!?]+[.;!?]*", text):
        body = sentence.group(0)
        remarks = [r for r in _REMARK.finditer(body) if not place_any.search(r.group(0))]
        for m in [*_REASON.finditer(body), *remarks]:
            head = body[: m.start()]
            if verb_any.search(head) and (place_any.search(head) or (m in remarks and _TAKE.search(head))):  # a take needs no place
                body = head + body[m.end():]
                break
        out.append(text[start: sentence.start()] + body)
        start = sentence.end()
    return "".join(out) + text[start:]


_INSTEAD = re.compile(r"(?:^|(?<=[.,;!?]))\s*(?:(?:actually|no|sorry|wait|oh|um|uh|hmm|well|ok|okay)\s*,?\s*)*"
                      r"(?:(?:make|do) (?:that|it)|i meant?|use|take)?\s*((?:the|a|an|that|this) [a-z' -]+?) instead of "
                      r"(?:the |a |an |that |this )?([a-z' -]+?)\s*(?=$|[.!?;,])")


def instead(text: str) -> str:
    """A repair "(make that) X instead of Y" said after the command: Y replaced by X where the
    command named it; when Y was not named exactly once the speaker is asked."""
    m = _INSTEAD.search(text)
    before = text[: m.start()].strip(" ,") if m else ""
    if not m or not before:
        return text
    said, old = m.group(1).strip(), m.group(2).strip()
    hits = list(re.finditer(rf"\b(?:(?:the|a|an|that|this) )?{re.escape(old)}\b", before))
    if len(hits) != 1:
        raise InputError(f"{text!r}: '{said} instead of {old}': the command names '{old}' {len(hits)} times, not once; "
                         "say the whole command again")
    h = hits[0]
    return f"{before[: h.start()]}{said}{before[h.end():]}{text[m.end():]}"
