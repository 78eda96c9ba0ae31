"""Asides: what people say around a command that is not a command ("ugh my desk is a mess, ...",
"good afternoon", "the spam is in the way of everything, could you move it ...").

An aside is only skipped when another clause of the same sentence is a command, so a sentence
of asides alone is still refused. A statement about one object ("the white box looks messy
there") makes that object what a later "it" means.
"""

from __future__ import annotations

import re

from realsim.errors import InputError
from realsim.planner.lexicon import STATEMENT_VERB, VERB_START, has_relation
from realsim.planner.phrasing import WHICH_ONE
from realsim.planner.steps import Parser
from realsim.planner.vocab import COLOR_WORDS, GENERIC, name_words, singular

__all__ = ["is_aside", "talk_only", "without_talk"]

_OPENER = r"(?:(?:ok|okay|so|ugh|hey|oh|well|um|hmm|haha|lol|alright|right|seriously|honestly|wow|man|like)\s+)*"
# a question is never a command: "why is the marker over there?", "who leaves cubes all over the place"
_WH = re.compile(rf"{_OPENER}(?:why|who|how come|how on earth|what s with|whats with|what is with)\b")
_STATEMENT = re.compile(rf"{_OPENER}(.+?) {STATEMENT_VERB}\b")


def _scene_words(p: Parser) -> set[str]:
    words = {w for o in p.objects for t in (o.label, o.name, *o.aliases) for w in name_words(t)}
    return words - set(GENERIC) - set(COLOR_WORDS)


def is_aside(clause: str, p: Parser) -> bool:
    """Whether a clause the planner could not read is talk around the command: a statement whose
    subject is one scene object (that object becomes "it"), or words naming no scene object. An
    instruction broken off before its place ("put it in the, um"), or naming a place, is never talk."""
    if VERB_START.match(clause) and re.search(r"\b(?:the|a|an|my|that|this|these|those|both|all)\s+(?!(?:little|bit|tad|few|couple|lot|touch|smidge|way)\b)[a-z]", clause):
        return False  # "lift the teapot" with no teapot: a command about a thing the scene lacks is refused, never skipped
    if VERB_START.match(clause) and (re.search(r"\b(?:the|a|an|in|into|on|onto|to|of|next to|behind|beside)$", clause)
                                     or re.search(r"\b(?:in|into|on|onto|inside|next to|behind|beside|in front of|left of|right of) the\b", clause)):
        return False  # "drop it in the white bowl": a place the planner could not find is no aside either
    if (has_relation(clause) and re.match(r"(?:the|a|an|that|this|my|your)\s+[a-z]", clause)
            and not re.search(rf"\b{STATEMENT_VERB}\b", clause)):
        return False  # "and the blue one in the bowl": a placing without its verb, never talk
    if re.match(rf"{_OPENER}(?:there|here|we have|i have|we got|i got|you see|you can see|look|(?:see|watch|notice|look at) (?:how|what|if|whether)"
                rf"|let s see|lets see|has|have|had|does|did)\b", clause):
        return True  # "so there's a bowl and a mug here": what the speaker sees
    if _WH.match(clause):  # the one thing it names, if any, is what "it" means next
        named = [o for a, b in re.findall(r"\bthe ([a-z]+)(?: ([a-z]+))?", clause) for o in (_quiet(p, f"the {a} {b}") if b else []) or _quiet(p, f"the {a}")]
        if len({o.name for o in named}) == 1:
            p.ctx.set(named[:1])
        return True
    m = WHICH_ONE.fullmatch(clause)
    if m:  # "which one is farthest from you?": the answer is what "that one" means next
        try:
            p.ctx.set(p.resolver.resolve(f"the {m.group(1)} {m.group(2)}", p.ctx, allow_plural=False))
        except InputError:
            return False
        return True
    m = _STATEMENT.match(clause)
    if m:
        try:
            subject = p.resolver.resolve(m.group(1), p.ctx, allow_plural=False)
        except InputError:
            subject = []
        if subject:
            p.ctx.set(subject)
            return True
    if re.search(r"\d", clause):
        return False  # an amount ("make it 5 cm") is never talk
    return not any(singular(w) in _scene_words(p) for w in clause.split())


def _quiet(p: Parser, phrase: str) -> list:
    """The one object ``phrase`` names, or none (no error)."""
    try:
        return p.resolver.resolve(phrase, p.ctx, allow_plural=False)
    except InputError:
        return []


def talk_only(piece: str, p: Parser) -> bool:
    """Whether ``piece`` names nothing the robot could act on: no scene object's word, no noun
    phrase at all (a thing the scene lacks is still named: "and the apple"), no place, no amount
    ("let's go", "prove them wrong", "hype moment")."""
    return (bool(piece.strip()) and not re.search(r"\d", piece) and not has_relation(piece)
            and not re.search(r"\b(?:the|a|an|that|these|those|my|your|his|her|their|every|all|both)\s+[a-z]", piece)  # "and the apple": a thing named
            and not any(singular(w) in _scene_words(p) for w in piece.split()))


def without_talk(clause: str, p: Parser) -> list[str]:
    """The clause with "and ..." pieces at its ends dropped while each names nothing to act on, the
    fewest dropped first ("hype moment and put the cube on the plate and let's go": "put the cube on
    the plate"); [] when no end piece is talk."""
    pieces = clause.split(" and ")
    lead = next((i for i, piece in enumerate(pieces) if not talk_only(piece, p)), len(pieces))
    trail = next((i for i, piece in enumerate(reversed(pieces)) if not talk_only(piece, p)), len(pieces))
    cuts = sorted(((i, j) for i in range(lead + 1) for j in range(trail + 1) if (i or j) and i + j < len(pieces)), key=sum)
    return [" and ".join(pieces[i: len(pieces) - j]) for i, j in cuts]
