"""The words of a noun phrase that name the thing, when the rest is talk around it.

A frame that cuts a phrase out of a sentence may leave talk on it: "omg that cereal box is"
(from "omg that cereal box is in the way"), "the blue one rn", "the foam brick aloft that mine
eyes may behold it". When no object answers to the whole phrase, its core is the one run of
words the scene's names use ("cereal box"); the rest may be dropped only if none of it names a
thing of its own ("the yellow lemon" never becomes "the yellow" one), opens a clause or says an
amount, and before the name only chat is dropped (an unknown verb is not talk). Chat shorthand
alone ("rn", "lol") drops to nothing, leaving the colour and size words to say which.
"""

from __future__ import annotations

from collections.abc import Iterable
from functools import lru_cache

from realsim.planner.vocab import KINDS, NUMBERS, SYNONYMS, TYPICAL_COLORS, UNITS, name_words, singular

# shorthand and interjections that never name or describe a thing
CHAT = frozenset({
    "rn", "u", "k", "kk", "ok", "okay", "pls", "plz", "please", "omg", "lol", "lmao", "fr", "ngl", "tbh", "bruh", "bro",
    "mate", "matey", "yo", "thx", "ty", "asap", "now", "then", "too", "again", "real", "quick", "quickly", "yeah", "ya",
    "yep", "hey", "oi", "innit", "eh", "huh", "yay", "wow", "aye", "arr", "ahoy", "verily", "lo", "hark", "sirrah",
})
# words that open a clause of its own or turn the phrase around: never dropped as talk
_CLAUSE_WORDS = frozenset({"until", "till", "unless", "if", "when", "whenever", "while", "because", "since", "after", "before", "than",
                           "except", "but", "not", "no", "never", "without", "instead", "or", "nor"})
# everyday things people may name that a scene may lack (besides the size table's categories)
_ABSENT_THINGS = ("lemon", "lime", "pear", "peach", "plum", "grape", "cherry", "tomato", "onion", "egg", "key", "keys",
                  "glasses", "wallet", "coin", "card", "cable", "charger", "bottle", "lid", "cap", "handle", "napkin",
                  "sock", "toy", "doll", "duck", "dinosaur", "teddy", "vase", "pen", "pencil", "paper", "note", "box",
                  "can", "tin", "jar", "cup", "mug", "glass", "plate", "bowl", "brick", "block", "cube", "ball")


@lru_cache(maxsize=1)
def thing_words() -> frozenset[str]:
    """Every word known to name a kind of thing: the size table's categories and aliases, synonyms, kinds."""
    from realsim.physics.size_table import load_objects

    words: set[str] = set(_ABSENT_THINGS) | set(SYNONYMS) | set(KINDS) | set(TYPICAL_COLORS)
    for cat in load_objects().values():
        for name in (cat.name.replace("_", " "), *cat.aliases):
            words.update(name_words(name))
    for group in (*SYNONYMS.values(), *KINDS.values()):
        for name in group:
            words.update(name.split())
    return frozenset(singular(w) for w in words)


def core_words(words: list[str], scene_words: Iterable[str]) -> list[str] | None:
    """The one run of ``words`` the scene's names use, if everything else is talk; ``[]`` if all
    of it is chat shorthand; None when no single core can be told (no run, two runs, or a
    dropped word naming some other thing)."""
    said = {singular(w) for w in scene_words}
    if words and all(w in CHAT for w in words):
        return []
    runs: list[list[int]] = []
    for i, w in enumerate(words):
        if singular(w) in said and w not in CHAT:
            if runs and runs[-1][-1] == i - 1:
                runs[-1].append(i)
            else:
                runs.append([i])
    if len(runs) != 1 or len(runs[0]) == len(words):
        return None
    if any(w not in CHAT for w in words[: runs[0][0]]):
        return None  # words before the name may be an unknown verb ("balance the mug upside"): only chat is dropped there
    kept = set(runs[0])
    things = thing_words()
    if any(singular(w) in things or w in _CLAUSE_WORDS or w in UNITS or w in NUMBERS or any(c.isdigit() for c in w)
           for i, w in enumerate(words) if i not in kept):
        return None  # a thing of its own, a clause or an amount ("the banana 40 cm") is never talk
    return [words[i] for i in runs[0]]
