"""Language safety: sentences the planner must read right or refuse, never act on wrongly. A
reason after a complete command is talk, not the place; a fronted "out of the X" restricts a
superlative or is refused; a size comparison of near-equal things is refused; "make that X
instead of Y" replaces Y. Sentences written for this test, not taken from a bench set."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER

from realsim.errors import InputError
from realsim.planner import RulePlanner
from realsim.planner.types import ObjectInfo


def calls(sentence: str, objects: list[ObjectInfo] = CLUTTER) -> list[str]:
    return [c.text() for c in RulePlanner().plan(sentence, objects).calls]


@pytest.mark.parametrize(("sentence", "lines"), [
    # 1: a reason or purpose after a command that has its place
    ("put the banana behind the bowl, it's always in the way when I grab the strawberry", ["place_beside('obj7_banana', 'obj6_bowl', 'behind')"]),
    ("set the strawberry left of the bowl because the banana keeps squashing it", ["place_beside('obj8_strawberry', 'obj6_bowl', 'left')"]),
    ("put the green cube on the blue cube so I can take a photo of the red cube", ["place_on('obj5_cube', 'obj4_cube')"]),
    ("place the banana in front of the bowl so the strawberry is not hidden", ["place_beside('obj7_banana', 'obj6_bowl', 'front')"]),
    ("place the banana in front of the bowl since the strawberry is hidden", ["place_beside('obj7_banana', 'obj6_bowl', 'front')"]),
    ("put the red cube next to the bowl, when I come back I'll need the banana", ["place_beside('obj3_cube', 'obj6_bowl', 'next')"]),
    ("move the banana so that it's behind the bowl", ["place_beside('obj7_banana', 'obj6_bowl', 'behind')"]),  # no place before: kept
    # 2: a fronted restriction of a superlative
    ("out of the cubes, lift the smallest one", ["grasp('obj5_cube')"]),
    ("among all the cubes, pick up the largest one", ["grasp('obj4_cube')"]),
    ("of the banana and the strawberry, lift the one closest to you", ["grasp('obj8_strawberry')"]),  # among those two only
    # 4: "make that X instead of Y"
    ("Put the strawberry in the bowl. Actually, make that the banana instead of the strawberry.", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("put the red cube on the blue cube. no, the green cube instead of the red cube", ["place_on('obj5_cube', 'obj4_cube')"]),
])
def test_read_right(sentence: str, lines: list[str]) -> None:
    assert calls(sentence) == lines


@pytest.mark.parametrize("sentence", [
    # 2: a restriction the planner cannot read is refused, never dropped
    "out of all the red things, grab the biggest",
    "among all the red things, pick up the largest one",  # the two soda cans are the same size
    # 3: a comparison of things of about the same size
    "pick up the bigger soda can",
    "lift the smaller of the two soda cans",
    # 4: a repair of something the command never named
    "put the banana in the bowl. make that the red cube instead of the strawberry",
])
def test_refused(sentence: str) -> None:
    with pytest.raises(InputError):
        calls(sentence)


def test_near_equal_sizes_refused_clear_ones_chosen() -> None:
    """Three boxes within 15 % in volume have no "biggest"; one clearly bigger is chosen."""
    boxes = [ObjectInfo(f"obj{i}_box", "box", (), (0.4, 0.1 * i, 0.03), (s, s, s)) for i, s in enumerate((0.060, 0.061, 0.062), 1)]
    with pytest.raises(InputError, match="about the same size"):
        calls("pick up the biggest box", boxes)
    boxes.append(ObjectInfo("obj4_box", "box", (), (0.4, 0.4, 0.04), (0.08, 0.08, 0.08)))
    assert calls("pick up the biggest box", boxes) == ["grasp('obj4_box')"]
    assert calls("pick up the tall box on the left", boxes)  # a kind, not a comparison: no margin


@pytest.mark.parametrize("sentence", [
    "how about you pour the soup into the bowl, genius?",  # a verb no primitive does, inside a clause
    "I need you to peel the banana and put it in the bowl",  # never skipped as what "it" means
    "could you peel the banana, then put it in the bowl",
])
def test_what_no_primitive_does_is_refused_wherever_it_is_asked(sentence: str) -> None:
    with pytest.raises(InputError, match="cannot (?:pour|peel)"):
        RulePlanner().plan(sentence, CLUTTER)
