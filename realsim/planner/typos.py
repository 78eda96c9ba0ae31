"""Misspelled words ("the read cube", "the gren block", "the yelow bananna"): a word the
planner does not know is read as the one word of a vocabulary (the scene's names, colours, sizes)
it is closest to, when that word is within a distance bound relative to its length and no other
vocabulary word is as close (of two as close, one with the very same letters wins: fast typing swaps
letters far more often than it drops or adds one, "lfet" is "left", not "let"). Short words (three
letters or fewer) are never changed (too many real words lie one letter apart: "fat", "far"), except
a clause's first word, the verb's slot, when it is one verb with a letter missed ("pik up the mug").
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from typing import TypeVar

from realsim.planner.lexicon import ALL_VERBS, BEYOND_VERBS, RELATIONS
from realsim.planner.ordering import EXTREMES
from realsim.planner.vocab import (
    BIG,
    COLOR_WORDS,
    DIRECTION_WORDS,
    FOREIGN_COLOR_WORDS,
    GENERIC,
    KINDS,
    NUMBERS,
    ORDINALS,
    SMALL,
    SYNONYMS,
    TYPICAL_COLORS,
    UNITS,
    is_plural,
    singular,
)

__all__ = ["bound", "correct", "distance", "retry", "sides", "spelled"]

T = TypeVar("T")
# the words a command is built of: its verbs and place words (a misspelled one leaves the clause unread)
_SWAPS = ("swap", "switch", "exchange", "trade")  # verbs of a swap, read by their own rule
_COMMAND_WORDS = frozenset({w for v in ALL_VERBS for w in v.split()} | {w for r, _ in RELATIONS for w in r.split()} | set(DIRECTION_WORDS) | set(_SWAPS))

# words a noun phrase may hold that are no misspelling of a scene's name, a colour or a size
_KNOWN = frozenset({*COLOR_WORDS, *BIG, *SMALL, *EXTREMES, *ORDINALS, *GENERIC, *NUMBERS, *SYNONYMS, *(w for v in SYNONYMS.values() for w in v),
                    *KINDS, *(w for v in KINDS.values() for w in v), *TYPICAL_COLORS, "colored", "coloured", "central", "middle", "center",
                    "centre", "most", "thing", "things", "the", "a", "an", "my", "your", "our", "some", "any", "of", "that", "this", "these", "those",
                    *(w for v in ALL_VERBS for w in v.split()), *(w for r, _ in RELATIONS for w in r.split()), *(w for d in DIRECTION_WORDS for w in d.split()),
                    *UNITS, "like", "just", "please", "and", "then", "it", "them", "with", "from", "away", "other", "else", "same", "only",
                    "tidy", "clean", "help", "sort", "neat", "room", "space", "make", "ready", "done"})  # a purpose ("tidy up by ..."), never a size


def distance(a: str, b: str) -> int:
    """Optimal-string-alignment distance: insertions, deletions, substitutions, adjacent swaps."""
    prev2: list[int] = []
    prev = list(range(len(b) + 1))
    for i in range(1, len(a) + 1):
        cur = [i] + [0] * len(b)
        for j in range(1, len(b) + 1):
            cost = a[i - 1] != b[j - 1]
            cur[j] = min(prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost)
            if i > 1 and j > 1 and a[i - 1] == b[j - 2] and a[i - 2] == b[j - 1]:
                cur[j] = min(cur[j], prev2[j - 2] + 1)
        prev2, prev = prev, cur
    return prev[-1]


def bound(word: str) -> int:
    """Edits allowed for a word of this length: none up to 3 letters, 1 up to 6, else 2."""
    return 0 if len(word) <= 3 else 1 if len(word) <= 6 else 2


def correct(word: str, vocabulary: Iterable[str], known: Iterable[str] = ()) -> str | None:
    """The one vocabulary word ``word`` misspells, or None: ``word`` is neither in the vocabulary
    nor ``known``, and exactly one vocabulary word is nearest, within :func:`bound`."""
    vocab, known = set(vocabulary), set(known)
    if {word, singular(word)} & (vocab | known) or not word.isalpha() or bound(word) == 0:
        return None
    near = sorted((distance(word, v), v) for v in vocab if abs(len(v) - len(word)) <= bound(word) and len(v) > 2)
    near = [(d, v) for d, v in near if d <= bound(word)]
    if near:  # of the nearest, those with the word's own letters (swapped) first
        nearest = [v for d, v in near if d == near[0][0]]
        near = [(0, v) for v in nearest if sorted(v) == sorted(word)] or [(0, v) for v in nearest]
    if not near or len(near) > 1:
        return None
    return near[0][1]


# words near a command word that are words of their own ("plate": place; "bowl": roll)
_OTHER = frozenset({"plate", "please", "plates", "bowl", "ball", "bottle", "table", "cable", "label", "handle", "sides", "side", "top", "bottom",
                    "there", "here", "where", "them", "then", "than", "these", "those", "their", "they", "other", "another", "bit", "little",
                    "want", "wants", "need", "needs", "make", "made", "have", "has", "give", "gave", "hand", "take", "took", "like", "look",
                    *BEYOND_VERBS})


def spelled(word: str, scene_words: set[str]) -> str:
    """``word`` of a noun phrase, or the one scene name, colour or size word it misspells."""
    vocabulary = scene_words | (set(COLOR_WORDS) - set(FOREIGN_COLOR_WORDS)) | set(BIG) | set(SMALL) | set(GENERIC)
    if said := correct(word, vocabulary, _KNOWN):
        return said
    said = correct(singular(word), scene_words, _KNOWN) if is_plural(word) else None  # "strawberies": the plural kept
    return f"{said}s" if said else word


# a slot only a side fills: "on the lefft side of", "to the rigth of", "the left-hand side"
_SIDE_SLOT = re.compile(r"\b((?:to|on|at|off) the )([a-z]+)(?=(?:[ -]hand)?(?: side)? of\b)")


def sides(text: str) -> str:
    """``text`` with a misspelled side in a slot only a side fills read as that side ("put the mug on
    the lefft side of the bowl": a place beside the bowl, not on it)."""
    return _SIDE_SLOT.sub(lambda m: m.group(1) + (correct(m.group(2), DIRECTION_WORDS, _KNOWN | _OTHER) or m.group(2)), text)


_OPENING_VERBS = frozenset(v.split()[0] for v in ALL_VERBS)


def _opening_verb(word: str, known: set[str]) -> str:
    """The clause's first word, or the one verb it misspells: in the verb's own slot even a short word
    is read ("pik up the mug", "mve it left", "pt it in the bowl") when it is that verb with one letter
    missed and no other verb is; longer words as :func:`correct` reads them."""
    if len(word) > 3 or word in known or word in _OPENING_VERBS or not word.isalpha():
        return correct(word, _COMMAND_WORDS, known) or word
    near = [v for v in _OPENING_VERBS if len(v) == len(word) + 1 and distance(word, v) == 1]  # a letter missed, not changed ("see" is no "set")
    return near[0] if len(near) == 1 else word


def retry(clause: str, scene_words: set[str], read: Callable[[str], T]) -> T:
    """``read(clause)``; when that fails, ``read`` of the clause with its misspelled verbs and place
    words corrected ("pcik up the banana", "put it behnid the bowl"), if any; the first error else.
    Scene names, colours and sizes are never corrected into command words."""
    try:
        return read(clause)
    except Exception as exc:
        known = _KNOWN | scene_words
        words = clause.split()
        fixed = " ".join([_opening_verb(words[0], known | _OTHER), *(correct(w, _COMMAND_WORDS - scene_words, known | _OTHER) or w for w in words[1:])] if words else [])
        if fixed == clause:
            raise
        try:
            return read(fixed)
        except Exception:
            raise exc from None
