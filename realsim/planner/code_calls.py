"""Commands half-written as code: "robot.push(cracker_box, direction='left', dist_cm=5)",
"place(cube, between=[bowl, can])", "cereal_box.clear_away()", "swap(cubes['blue'], cubes['green'])".

A call ``f(args)`` reads as the words of ``f`` followed by its arguments: names with underscores
become words, quotes and brackets go, a keyword that only names a role (obj, ref, rel, direction)
is dropped, one that names a place (left_of, in_front_of, between) is said, one with a unit
(dist_cm=5) becomes the amount ("5 cm"), and a list is joined with "and". A method on an object
("cereal_box.clear_away()") acts on that object; one on the robot ("robot.put(...)") on its arguments.
"""

from __future__ import annotations

import re

from realsim.planner.vocab import singular

__all__ = ["as_words"]

_ROBOT = r"(?:robot|arm|franka|panda|self|bot|r|gripper|hand)"
_CALL = re.compile(r"(?:([a-z_][a-z0-9_]*)\.)?([a-z_][a-z0-9_]*)\(([^()]*)\)")
_ROLE = {"obj", "object", "item", "target", "thing", "what", "ref", "reference", "anchor", "rel", "relation", "where", "direction", "dir",
         "side", "to", "dest", "destination", "name", "which", "goal", "place", "location"}
_UNIT = re.compile(r"(?:dist(?:ance)?|by|amount|offset|delta|d)?_?(cm|mm|m|in|inch|inches)$")
_PAIRED = {"swap", "switch", "exchange", "trade", "swap_places", "swap_positions"}
_CODE_HINT = re.compile(r"[a-z_]+\([^()]*\)|\w+=\w|\w+\[['\"]")


def _argument(arg: str) -> str:
    key, sep, value = arg.partition("=")
    if not sep:
        key, value = "", arg
    value = re.sub(r"[\[\]]", " ", value).replace(",", " and ")
    value = " ".join(re.sub(r"['\"`]", "", value).replace("_", " ").split())
    key = key.strip()
    if not key or key in _ROLE:
        return value
    if m := _UNIT.fullmatch(key):
        return f"{value} {m.group(1)}"
    return f"{key.replace('_', ' ')} {value}"


def _call(m: re.Match[str]) -> str:
    receiver, name, args = m.group(1), m.group(2), m.group(3)
    words = [name.replace("_", " ")]
    if receiver and not re.fullmatch(_ROBOT, receiver):
        words.append(receiver.replace("_", " "))  # "cereal_box.clear_away()": the object acted on
    said = [_argument(a) for a in _split_args(args) if a.strip()]
    joiner = " and " if name in _PAIRED else " "  # "swap(a, b)": a and b
    return " ".join(w for w in [*words, joiner.join(said)] if w)


def _split_args(args: str) -> list[str]:
    """Arguments at top-level commas (a list's commas stay inside it)."""
    out, depth, start = [], 0, 0
    for i, ch in enumerate(args):
        depth += (ch == "[") - (ch == "]")
        if ch == "," and depth == 0:
            out.append(args[start:i])
            start = i + 1
    return [*out, args[start:]]


def as_words(text: str) -> str:
    """``text`` (lower case) with every code-like call and indexing said in words; text without code is
    returned unchanged."""
    if not _CODE_HINT.search(text):
        return text
    text = re.sub(r"([a-z_]+)\[\s*['\"]([a-z_ ]+)['\"]\s*\]", lambda m: f"{m.group(2)} {singular(m.group(1))}", text)  # cubes['blue']: the blue cube
    text = re.sub(r"\b(?:run|call|execute|exec|invoke|do)\s+(?=[a-z_.]+\()", "", text)  # "can you run put(...)"
    text = re.sub(r"\s*(?://|#)\s", ". ", text)  # a comment after the code
    return _CALL.sub(_call, text)
