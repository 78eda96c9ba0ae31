"""Casual speech the blind batch of 13:20 taught the rule planner, on the generated clutter scene:
closings and fillers, light verbs ("give X a shove"), split particles ("pick X up"), verbless
terse commands ("bowl left 6cm"), "swap ... around", things to keep still, "that one" after a
topic, and home said another way. Sentences written for this test, not taken from a bench set."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER

from realsim.errors import InputError
from realsim.planner import RulePlanner
from realsim.planner.types import ObjectInfo


def calls(sentence: str) -> list[str]:
    return [c.text() for c in RulePlanner().plan(sentence, CLUTTER).calls]


@pytest.mark.parametrize(("sentence", "lines"), [
    ("set the banana next to the bowl, cheers mate", ["place_beside('obj7_banana', 'obj6_bowl', 'next')"]),
    ("pop the strawberry in the bowl for now, ill sort the rest out later", ["place_in('obj8_strawberry', 'obj6_bowl')"]),
    ("put the green cube behind the bowl, there's a good girl", ["place_beside('obj5_cube', 'obj6_bowl', 'behind')"]),
    ("give the banana a little push to the right", ["push('obj7_banana', 'right', 0.05)"]),
    ("give the bowl a nudge 4 cm forward", ["push('obj6_bowl', 'forward', 0.04)"]),
    ("lift the banana up and take a look at it", ["grasp('obj7_banana')"]),
    ("pick the strawberry up then go back to your usual spot", ["grasp('obj8_strawberry')", "go_home()"]),
    ("bowl left 6cm", ["push('obj6_bowl', 'left', 0.06)"]),
    ("the banana 3 cm forward", ["push('obj7_banana', 'forward', 0.03)"]),
    ("strawberry by the bowl", ["place_beside('obj8_strawberry', 'obj6_bowl', 'next')"]),
    ("the soda can furthest to the right, put that one in the bowl", ["place_in('obj2_soda_can', 'obj6_bowl')"]),
    ("put the green cube in the bowl and leave the red cube where it is", ["place_in('obj5_cube', 'obj6_bowl')"]),
    ("move the banana next to the bowl but keep clear of the strawberry", ["place_beside('obj7_banana', 'obj6_bowl', 'next')"]),
    ("put the banana in the bowl and leave it there", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("put the banana in the bowl, thanks heaps mate", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("put the banana in the bowl. thank you ever so much", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("lift the banana but leave the bowl alone", ["grasp('obj7_banana')"]),
    ("stack the blue cube on the green one, there's a good robot", ["place_on('obj4_cube', 'obj5_cube')"]),
])
def test_casual_classes(sentence: str, lines: list[str]) -> None:
    assert calls(sentence) == lines


def test_swap_around() -> None:
    got = calls("could you be able to swap the banana and the strawberry around")
    assert got[1:] == ["place('obj8_strawberry', [0.65, 0.0, 0.02])", "place('obj7_banana', [0.25, 0.3, 0.02])"]
    assert calls("swap the two cans round")[1:] == ["place('obj2_soda_can', [0.4, 0.2, 0.06])", "place('obj1_soda_can', [0.4, -0.1, 0.06])"]


@pytest.mark.parametrize("sentence", [
    "put the green cube in the bowl and leave the green cube where it is",  # moves what it says to keep still
    "give the banana a shove, cheers, and leave the banana alone",
    "put the strawberry in the bowl but leave the strawberry where it is",
    "the banana on the left",  # a place, no command
    "cheers mate",  # a closing alone
])
def test_still_refused(sentence: str) -> None:
    with pytest.raises(InputError):
        RulePlanner().plan(sentence, CLUTTER)


MUG_BOWL_PUCK = [
    ObjectInfo("obj1_bowl", "bowl", (), (0.5, -0.2, 0.03), (0.16, 0.16, 0.06), "white", ("graspable", "container")),
    ObjectInfo("obj2_mug", "mug", ("cup",), (0.5, 0.1, 0.05), (0.08, 0.08, 0.1), "white", ("graspable", "container")),
    ObjectInfo("obj3_puck", "orange cylinder", (), (0.4, 0.3, 0.01), (0.09, 0.09, 0.02), "orange"),
]


@pytest.mark.parametrize(("sentence", "lines"), [
    # by use; the target of two round containers is the one that is not moved
    ("take the thing you sip from and set it behind the round container",
     ["grasp('obj2_mug')", "place_beside('obj2_mug', 'obj1_bowl', 'behind')"]),
    ("put the bowl next to the round container", ["place_beside('obj1_bowl', 'obj2_mug', 'next')"]),
    ("put the bowl-shaped thing left of the orange disc", ["place_beside('obj1_bowl', 'obj3_puck', 'left')"]),  # by look; a disc
])
def test_named_by_use_or_look(sentence: str, lines: list[str]) -> None:
    assert [c.text() for c in RulePlanner().plan(sentence, MUG_BOWL_PUCK).calls] == lines


@pytest.mark.parametrize("sentence", [
    "put the round container next to the round container",  # which one moves is not said
    "put the mug next to the round thing",  # the bowl or the puck
])
def test_named_by_look_still_ambiguous(sentence: str) -> None:
    with pytest.raises(InputError):
        RulePlanner().plan(sentence, MUG_BOWL_PUCK)
