"""The offline scene-description parser: counts, colours, sizes, supports, unknown nouns."""

from __future__ import annotations

import pytest

from realsim.physics.size_table import lookup
from realsim.text.parser import parse_description


def _objs(text: str) -> dict[str, tuple[int, str, str]]:
    return {o.label: (o.count, o.color, o.size) for o in parse_description(text).objects}


def test_issue_example() -> None:
    req = parse_description("a kitchen table with a mug, a bowl, two soda cans and a cereal box")
    assert req.support == "table" and req.support_height == pytest.approx(0.75)
    assert _objs(req.text) == {"mug": (1, "", ""), "bowl": (1, "", ""), "soda can": (2, "", ""), "cereal box": (1, "", "")}
    assert lookup("cereal box").category.name == "cracker_box"


@pytest.mark.parametrize("text,support,height", [
    ("3 red mugs on the counter", "counter", 0.9),
    ("a bowl on the floor", "floor", 0.0),
    ("a mug and a plate", "table", 0.75),
    ("a desk with a book", "table", 0.75),
])
def test_supports(text: str, support: str, height: float) -> None:
    req = parse_description(text)
    assert (req.support, req.support_height) == (support, height)


def test_counts_colours_sizes() -> None:
    assert _objs("3 red mugs on the counter") == {"mug": (3, "red", "")}
    assert _objs("a large bowl and a small blue cup") == {"bowl": (1, "", "large"), "cup": (1, "blue", "small")}
    assert _objs("two plates, a pair of cans and four books") == {"plate": (2, "", ""), "can": (2, "", ""), "book": (4, "", "")}
    assert _objs("a mug and another mug")["mug"][0] == 2


def test_unknown_noun_kept_with_note() -> None:
    req = parse_description("a toy dinosaur on the table")
    assert [o.label for o in req.objects] == ["toy dinosaur"]
    assert req.notes


def test_nothing_to_build() -> None:
    assert parse_description("a table").objects == []
