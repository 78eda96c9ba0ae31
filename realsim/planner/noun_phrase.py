"""A noun phrase put in the one form the resolver reads, before any object is looked up: its
leading determiners and trailing fillers dropped, and a partitive comparative as the superlative
it means ("the taller of the two white cans": the tallest white can).
"""

from __future__ import annotations

import re

from realsim.errors import InputError
from realsim.planner.vocab import BIG, SMALL, singular

__all__ = ["normalize"]

_COMPARATIVE = tuple(w for w in (*BIG, *SMALL) if w.endswith("er")) + ("closer", "nearer", "further", "farther")
_PARTITIVE = re.compile(rf"({'|'.join(_COMPARATIVE)})(?: one)? (?:of|out of|among) (?:the |these |those )?"
                        r"(?:(?:two|2|three|3|four|4|five|5|both)(?: |$))?(.*)")


def normalize(text: str) -> str:
    """``text`` (already :func:`~realsim.planner.vocab.norm`-ed) without leading determiners or a
    trailing "again"/"please", "sitting"/"standing" before a relation ("the can sitting on the box":
    the can on the box), "whatever" as a thing, and "the X-er of the Ys" as "X-est Y"."""
    text = re.sub(r"^(?:(?:the|a|an|my|your|our)(?:\s+|$))+", "", text).strip()  # "put it in the, um": names nothing
    text = re.sub(r"\s+(?:again|too|as well|also|please|there|here|for me|over there)$", "", text).strip()
    text = re.sub(r"^(?:whatever|whichever)(?: is| s)?(?= (?:sitting|standing|lying|resting|on|in|behind|next|near|by|beside|at)\b)",
                  "thing", text)  # "whatever's sitting behind the banana"
    text = re.sub(r"^(?:whatever|whichever)(?: one| thing)?(?: is| s)? (?:the )?(\w+(?:most|est))\b", r"\1 thing", text)  # "whatever's furthest to the right"
    text = re.sub(r"\b(?:currently|presently|now|still)\s+(?=(?:sitting|standing|lying|resting|placed|on|in|behind|next|beside|at)\b)", "", text)  # "the can currently on top of the box"
    text = re.sub(r"\b(?:(?:that|which) (?:is |s )?)?(?:sitting|standing|lying|resting|placed|over)(?: (?:just|right|directly|immediately))? "
                  r"(?=(?:behind|in front of|next to|beside|by|near|on|in|inside|left of|right of|to the (?:left|right) of)\b)", "", text)
    # what it is for, said as a clause about people: "the cube you twist until the sides match", "the dish you d eat
    # cereal from": the thing itself, its own words left to name it (or refused as ambiguous)
    text = re.sub(r"^(?!(?:do|does|did|can|could|would|will|should|shall|may|might|must|is|are|was|were|have|has|had|if|when|what|how|why)\b)((?:[a-z]+ )*?(?!(?:from|to|near|nearest|closest|by|for|with|of|at|than|toward|towards|behind|beside|past|among|between|and|or)\b)[a-z]+)"
                  r" (?:that |which )?(?:you|i|we|people|they)(?: d| would| ll| can| could| usually| normally| always| often| use to)?"
                  r" (?!(?:are|is|were|was|am|have|had|said|mean|meant|see|saw|found|moved|put|placed|left|just|among|and|or)\b)[a-z]+\b.*$", r"\1", text)
    m = _PARTITIVE.fullmatch(text)
    if m and not m.group(2):  # "the taller of the two": which two is for the speaker to say
        raise InputError(f"{text!r}: of which ones? name them ('the taller of the two white cans')")
    if m and re.search(r"\s(?:and|or)\s", m.group(2)):  # "the taller of the mustard and the marker": of those two
        return f"{m.group(1)[:-2]}est one among {m.group(2)}"
    if m:  # "the taller of the two white cans", "the bigger one of those boxes"
        words = m.group(2).split()
        text = " ".join([m.group(1)[:-2] + "est", *words[:-1], singular(words[-1])])
    return text
