"""A message as sentences: where one ends, and whether it asks the robot to do something.

A message that does not read as a whole is read one sentence at a time (see
:func:`realsim.planner.rules.parse_calls`): talk around the command is skipped, but a request the
planner cannot carry out is never skipped, so "Pour the soup. Thanks!" is still refused.
"""

from __future__ import annotations

import re
from collections.abc import Collection

from realsim.errors import InputError
from realsim.planner.code_calls import as_words
from realsim.planner.lexicon import STATEMENT_VERB, VERB_START, relation_start
from realsim.planner.phrasing import QUESTION, clean
from realsim.planner.vocab import singular

__all__ = ["cleaned", "is_question", "is_request", "split_pieces", "split_sentences"]

_END = re.compile(r"(?<=[.!?;:…])\s+|(?<=\.\.\.)(?=\S)")
# first words that never begin a request: articles, pronouns, prepositions, question words, replies
_NOT_A_VERB = frozenset(
    "the a an this that these those it its i we you they he she my our your their his her there here which what where who whom whose why how "
    "when whenever for in on at to of by with from into onto about and but or so if no not yes yeah yep yup ok okay good great right "
    "correct exactly well now then oh ah ugh hmm seriously damn wow nice cool sure fine perfect excellent".split())
_UNKNOWN_VERB = re.compile(r"([a-z]+) (?:the|it|that|this|those|these|my|your|all|both|every|each)\b")


def split_sentences(command: str) -> list[str]:
    """The sentences of ``command`` in lower case (at full stops, question and exclamation marks,
    semicolons, colons, ellipses and code comments; a decimal point is no end)."""
    return [s.strip() for s in _END.split(as_words(command.strip().lower())) if s.strip(" .!?;:…")]


def split_pieces(command: str) -> list[str]:
    """The phrases of ``command``: its sentences cut again at commas, dashes and a clause-opening
    "but" ("Gosh, this is a silly thing to ask, but could you nudge the brick left?")."""
    return [p.strip() for s in split_sentences(command) for p in re.split(r"\s*(?:,|\s[-–—]+\s|\bbut\b)\s*", s) if p.strip(" .!?;:,")]


def cleaned(text: str) -> str:
    """``text`` without polite and filler words (:func:`clean`), "" when it is only a correction of
    nothing ("not two, not twenty") that cannot be read at all."""
    try:
        said = _CONNECTIVE.sub("", clean(text).strip(" .,;"))
        return "" if said in _REMNANTS else said
    except InputError:
        return ""


_LABEL = re.compile(r"\b(?:level|stage|round|step|part|phase|task|mission|quest|challenge|chapter|episode|lesson|exercise|question|number|no)\.? ?#?\d+\b")
_REMNANTS = {"only", "but", "if", "just", "so", "and", "then", "too", "also", "or", "of course"}  # what is left of a hedge once its words are gone
_STAND_INS = {"one", "ones", "it", "them"}  # words standing for a thing named before ("the last one", "it")
# words that join a step to the one before ("then put ..."), not part of the step itself
_CONNECTIVE = re.compile(r"^(?:(?:and|then|next|after that|afterwards|finally|lastly|also|now|so|plus|and then|once done|after)\s+)+(?=[a-z])")


def is_request(sentence: str, scene_words: Collection[str] = ()) -> bool:
    """Whether ``sentence`` asks the robot to act: it, or a clause of it, begins with a verb once polite words are gone,
    one the planner knows ("put ...") or another one acting on a thing of the scene ("pour the soup
    ...", where "smash that like button" is talk)."""
    text = cleaned(sentence)
    if any(VERB_START.match(piece.strip()) for piece in re.split(r"[,;]", text)):  # "if not, put it next to the bowl"
        return True
    if re.search(r"\d", _LABEL.sub("", text)):  # an amount ("make it 5 cm") is never talk; a label ("level 3") is
        return True
    words = text.split()
    if any(relation_start(" ".join(words[i:])) and any(singular(w) in scene_words or w in _STAND_INS for w in words[:i]) for i in range(1, len(words))) and not re.search(
            rf"\b{STATEMENT_VERB}\b", text):  # "the last one next to the plate": a placing without its verb
        return True
    m = _UNKNOWN_VERB.match(text)
    return bool(m) and m.group(1) not in _NOT_A_VERB and any(singular(w) in scene_words for w in text[m.end():].split())


def is_question(command: str) -> bool:
    """Whether the whole message is one question ("where is the mug?"); "when I come back I'd like
    the can behind the box" is a time clause, not a question."""
    text = command.strip().lower()
    if re.search(r"[?.!]\s+\S", command.strip()):
        return False
    if re.match(r"(?:when|what) (?:i|you|we|they|he|she)\b", text) and "?" not in text:
        return False  # "what I'm picturing is ...": a wish
    return bool(QUESTION.match(text))
