"""The one thing a speaker singles out before acting on it: "not the white box, the white bowl:
push that ...", "leave the mug alone, it's the bowl I'm after: push it ...", "only the green one:
set it ...", "nothing else moves apart from the soup can: put it ...", and a ban on lifting what
is then pushed ("don't lift the mustard bottle; slide it 3 cm right instead").

Rule: the singled-out noun phrase takes the place of the first "it", "that" or "that one" after
it, and the words that singled it out go; so does a thing named as a sentence of its own before a
command about "it" ("... anyway. The mug. Can you put it in the bowl"), or a thing only looked for
("Step 1: Locate the mug. Step 2: Place it ..."). A thing that must stay where it is is not to be
touched ("Caution: the blue cube must remain in its current position"). What was set against it ("not the white box") stays as
a thing not to touch, as is each of several things to leave be. A ban on lifting is dropped only when the text also pushes or slides, and
the thing it named is then what "it" means. A text with none of these frames is unchanged.
"""

from __future__ import annotations

import re

from realsim.planner.lexicon import STATEMENT_VERB

__all__ = ["singled_out"]

_NP = r"(?:the|that|this|my|your) (?:(?!(?:and|then|but|so|is|it|i)\b)[a-z' ]+?)"
_START = r"(?:^|(?<=[.;:!?] )|(?<=[.;:!?]))"
_SEP = r"\s*(?:[.;:!?,]\s*|\s+and\s+|$)(?:and\s+)?"
_CONTRAST = re.compile(rf"{_START}(?:no,?\s+)?not ({_NP}),\s*(?:but |rather |i mean |it(?:'s| s| is) )?({_NP}|the other(?: one)?)(?=\s*[.;:!?,]|$)[.;:!?,]?\s*")
_CLEFT = re.compile(rf",?\s*\bit(?:'s| s| is) ({_NP}) (?:(?:that )?i(?:'m| m| am|m) (?:after|talking about|on about|meaning)|(?:that )?(?:i|we) (?:mean|want|need)t?){_SEP}")
_ONLY = re.compile(rf"{_START}\s*(?:just |but )?only ({_NP}){_SEP}")
_EXCEPT = re.compile(rf"{_START}\s*(?:nothing(?: else)?|no other (?:thing|object|item)s?|everything(?: else)? (?:stays|remains)(?: put| still| where it is)?)"
                     rf"(?: (?:moves|should move|gets? moved|is moved|is touched|gets? touched|changes|is to move))?"
                     rf" (?:apart from|except(?: for)?|but|besides|other than|save(?: for)?) ({_NP}){_SEP}")
_NO_LIFT = re.compile(rf"(?:(?<=[,;.:]\s)|^|\s)(?:but )?(?:don't|dont|don t|do not|never|no need to) (?:lift|pick up|pick|grasp|grab|raise|carry)(?: up)?"
                      rf"(?: (it|them|{_NP}))?(?: up)?(?=\s*(?:[,;.:]|$|\s(?:just|only|instead|but)\b))[,;.:]?")
_PUSHED = re.compile(r"\b(?:push|pushing|slide|sliding|shove|shoving|nudge|nudging|drag|dragging|scoot|scooting|slid)\b")
_PRONOUN = re.compile(r"\b(?:it|that one|this one|that)\b(?! (?:is|s|was|way|i)\b)(?!')")
_MODIFIERS = re.compile(r"^(?:(?:left|right|front|back|rear|far|near|first|second|third|last|big|bigger|small|smaller|tall|short|little|large"
                        r"|red|blue|green|yellow|white|black|orange|purple|pink|grey|gray|brown)\s+)+")
_LEAVE_MANY = re.compile(rf"\bleave ((?:{_NP})(?:,? (?:and|or) (?:{_NP}))+) (?:be|alone|where they are|in place|untouched)\b")
# a thing named as a sentence of its own, then acted on as "it": "... anyway. the mug. can you put it in the bowl"
_NAMED_ALONE = re.compile(r"(?:^|(?<=[.;!?] ))((?:the|that|this|my|your) (?:[a-z']+ ){0,3}[a-z']+)\s*[.;!?]+\s+(?=[^.;!?]*\b(?:it|them|that one)\b)")
_SAYS_SOMETHING = re.compile(rf"\b(?:{STATEMENT_VERB}|been|had|do|does|did|will|would|could|should|may|might|must|(?!thing\b|ring\b)\w{2,}ing)\b")
# a thing only looked for before it is acted on: "Step 1: Locate the mug. Step 2: Place it in the bowl."
_LOOKED_FOR = re.compile(rf"(?:^|(?<=[.;:!?] ))(?:step \w+\s*[:.)-]?\s*)?(?:locate|identify|find|spot|look at|observe|notice|look for) ({_NP})\s*[.;!?]+\s*")
_LABEL = re.compile(r"(?:^|(?<=[.;!?] ))(?:note|caution|warning|important|nb|n\.b\.|tip|reminder)\s*:\s*")
_STAYS = re.compile(r"\b((?:the|that|this) [a-z' ]+?) (?:must |should |has to |needs to |is to |will |shall )?(?:remain|stay)s? (?:in (?:its|their) (?:current |present |original )?(?:position|place|spot|location)s?|where (?:it|they) (?:is|are)|put|in place|still|untouched)")
_NOTHING_MORE = re.compile(r",?\s*\bnothing (?:more|else)(?=\s*[.!;]|$)")


def _resumed(rest: str, phrase: str) -> str:
    """``rest`` with its first "it" / "that (one)" made ``phrase`` (unchanged when it has none)."""
    return _PRONOUN.sub(phrase, rest, count=1)


def _other(excluded: str, said: str) -> str:
    """"the other one" said against ``excluded``: the other thing of its kind."""
    if not said.startswith("the other"):
        return said
    head = _MODIFIERS.sub("", re.sub(r"^(?:the|that|this|my|your) ", "", excluded))
    return f"the other {head}"


def singled_out(text: str) -> str:
    """``text`` (lower case, punctuation kept) with a singled-out thing put where it is acted on."""
    text = _LEAVE_MANY.sub(lambda m: " and ".join(f"dont touch {t}" for t in re.split(r",? (?:and|or) ", m.group(1))), _NOTHING_MORE.sub("", text))
    text = _STAYS.sub(r"dont touch \1", _LABEL.sub("", text))
    if (m := _LOOKED_FOR.search(text)) is not None:  # the thing is what "it" means next, else said again by name
        text = f"{text[: m.start()]}{_resumed(text[m.end():], m.group(1))}"
    if (m := _NAMED_ALONE.search(text)) is not None and not _SAYS_SOMETHING.search(m.group(1)):
        text = f"{text[: m.start()]}{_resumed(text[m.end():], m.group(1))}"
    if (m := _CONTRAST.search(text)) is not None:
        phrase = _other(m.group(1), m.group(2))
        text = f"{text[: m.start()]}dont touch {m.group(1)}. {_resumed(text[m.end():], phrase)}"
    for frame in (_CLEFT, _ONLY, _EXCEPT):
        if (m := frame.search(text)) is not None:
            before = text[: m.start()].rstrip(" ,")
            text = f"{before}{'. ' if before and not before.endswith(('.', ';', ':')) else ' ' if before else ''}{_resumed(text[m.end():], m.group(1))}"
    if _PUSHED.search(text) and (m := _NO_LIFT.search(text)) is not None:
        named = m.group(1)
        rest = text[m.end():]
        if named and named not in ("it", "them"):
            rest = _resumed(rest, named)
        text = f"{text[: m.start()].rstrip(' ,')} {rest.lstrip(' ,')}".strip()  # "push it, don't lift it, 5 cm right"
    return " ".join(text.split())
