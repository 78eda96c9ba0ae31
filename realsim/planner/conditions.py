"""A command with a condition on the scene: "if the mug is in the bowl, take it out"; "if the
mug fits in the bowl, put it in there; if not, set it next to the bowl"; "if there's a can
behind the box, push it left, otherwise go home".

The condition is checked on the scene as captured, before anything moves: a relation ("is in /
on / next to / left of / behind / in front of", negated with "not"), whether a thing fits in a
container (its footprint narrower than the container's), or whether a thing exists ("there is a
..."). The branch that holds is the command; "it" in it is the condition's subject and "there"
the condition's place. Only a condition about a thing ("the ...", "there is ...") is one: "if
you would be so kind", "if it isn't too much bother" are politeness. A condition that cannot be read or checked is refused, and a false one
with no "otherwise" does nothing and says so: a conditional is never carried out unchecked.
"""

from __future__ import annotations

import re

from realsim.errors import InputError
from realsim.planner.attributes import relation_holds
from realsim.planner.lexicon import RELATIONS, VERB_START
from realsim.planner.reference import Context, Resolver
from realsim.planner.types import ObjectInfo

__all__ = ["branch"]

_ELSE = r"(?:if not|if it (?:is not|isn t|isnt|does not|doesn t|doesnt)\b[^,.;]*|otherwise|else|or else)"
_IF = re.compile(rf"^(?:(?:ok|okay|so|and|now|well|oh)[\s,]+)*(?:if|in case|assuming) (?P<cond>[^,;.:]+?)(?:,|;|:|\s+then\b|(?=\s(?:{VERB_START.pattern})))\s*(?:then\s+)?"
                 rf"(?P<then>.+?)(?:\s*(?:[,;.]\s*|\s+)(?:and )?{_ELSE}\s*[,;:]?\s*(?P<other>.+?))?[.!]?$")
_BE = r"(?:is|are|s|sits|sit|is sitting|are sitting|stands|is standing|lies|is lying)"
_POSTURE = r"(?:(?:sitting|standing|lying|resting|perched|placed|sat|stood|balanced) )?"  # "is still sitting on top of"
_KINDS = {kind for _, kind in RELATIONS}


def branch(command: str, resolver: Resolver) -> str | None:
    """The command to carry out for a conditional ``command`` (see the module), or None when the
    command has no leading condition."""
    text = " ".join(command.lower().replace("’", "'").replace("'", " ").split())
    text = re.sub(r"\b(is|are|does|do|was|were)n ?t\b", r"\1 not", text)  # "isn't", "doesn't"
    m = _IF.match(text)
    if not m:
        return None
    cond, then, other = m.group("cond"), m.group("then"), m.group("other")
    if not re.match(r"(?:there|the|a|an|any|my|your|both|either|all)\s", cond):  # "if you would be so kind": politeness, no condition
        return None
    holds, subject, place = _check(cond, resolver)
    chosen = then if holds else other
    if not chosen:
        raise InputError(f"nothing to do: the condition '{cond}' does not hold in the scene")
    if subject and re.search(r"\b(?:it|them)\b", chosen) and not re.match(r"(?:[a-z]+ )*?(?:the|a|an|this|that|these|those|my|your)\s(?:[a-z]+ )*?(?:it|them)\b", chosen):
        chosen = f"{subject}, {chosen}"  # "it": the condition's subject (a fronted topic), unless the branch names its own first
    if place:  # "put it in there": the condition's place; "put the banana in it": so is "it" after a thing of its own
        chosen = re.sub(r"\b(in|into|on|onto|next to|beside|behind) there\b", rf"\1 {place}", chosen)
        rel = r"(in|into|on|onto|next to|beside|behind|in front of|left of|right of)"
        if re.match(rf"(?:[a-z]+ )*?(?:the|a|an|this|that|my|your)\s(?:[a-z]+ )*?{rel} (?:it|them)\b", chosen):
            chosen = re.sub(rf"\b{rel} (?:it|them)\b", rf"\1 {place}", chosen, count=1)
    return chosen


def _check(cond: str, r: Resolver) -> tuple[bool, str, str]:
    """Whether the condition holds, its subject's phrase and its place's phrase."""
    cond = re.sub(r"^(?:the )?(?:robot sees|you see|you can see)\s+", "there is ", cond)
    m = re.fullmatch(r"there (?:is|are|s) (?:a|an|any|some|the) (.+)", cond)
    if m:  # "if there's a can behind the box"
        found = r.resolve(m.group(1), Context(), loose=True) if _quiet(m.group(1), r) else []
        return bool(found), (f"the {m.group(1)}" if len(found) == 1 else ""), ""
    m = re.fullmatch(r"(.+?) (?:(does not|doesn t|doesnt|will not|won t|wont|can t|cant|cannot) )?(?:fits?|will fit|can fit|would fit) (?:in|into|inside) (.+)", cond)
    if m:
        obj, box = _one(m.group(1), r), _one(m.group(3), r)
        fits = "container" in box.affordances and max(obj.size[:2]) < 0.95 * min(box.size[:2])
        return fits != bool(m.group(2)), m.group(1), m.group(3)
    m = re.fullmatch(rf"(.+?) {_BE}( not| nt)? (?:already |still |currently )?empty", cond)
    if m:  # "if the bowl is empty": nothing in it
        box = _one(m.group(1), r)
        empty = not any(relation_holds("in", o, box, r.forward, r.left) for o in r.objects if o.name != box.name)
        return empty != bool(m.group(2)), m.group(1), m.group(1)
    m = re.fullmatch(rf"(.+?) {_BE}( not| nt)? (?:already |still |currently |now )?{_POSTURE}(.+)", cond)
    kind, ref = _relation(m.group(3)) if m else (None, "")
    if not m or kind not in _KINDS - {"to", "between", "sides", "other"}:
        raise InputError(f"cannot check the condition '{cond}': say it as 'if X is in / on / next to / left of / behind Y' or do it step by step")
    obj, target = _one(m.group(1), r), _one(ref, r)
    holds = relation_holds(kind, obj, target, r.forward, r.left)
    return holds != bool(m.group(2)), m.group(1), ref


def _relation(predicate: str) -> tuple[str | None, str]:
    for words, kind in sorted(RELATIONS, key=lambda t: -len(t[0])):
        if predicate.startswith(words + " "):
            return kind, predicate[len(words) + 1:]
    return None, ""


def _one(phrase: str, r: Resolver) -> ObjectInfo:
    return r.resolve(phrase, Context(), allow_plural=False)[0]


def _quiet(phrase: str, r: Resolver) -> bool:
    try:
        return bool(r.resolve(phrase, Context(), loose=True))
    except InputError:
        return False
