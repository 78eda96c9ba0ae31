"""What the two blind batches of 2026-11-26 taught the rule planner, on the generated clutter scene:
speech-to-text homophones, repairs that contrast a colour, end states, appositives, the robot's own
axes and sides, corners, partitive comparatives, usual colours of kinds, and what must still be refused."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER

from realsim.errors import InputError
from realsim.planner import RulePlanner
from realsim.planner.types import ObjectInfo


def calls(sentence: str, objects: list[ObjectInfo] = CLUTTER) -> list[str]:
    return [c.text() for c in RulePlanner().plan(sentence, objects).calls]


@pytest.mark.parametrize(("sentence", "lines"), [
    ("move the banana two the left of the bowl", ["place_beside('obj7_banana', 'obj6_bowl', 'left')"]),
    ("push the banana too the right for centimeters than go home", ["push('obj7_banana', 'right', 0.04)", "go_home()"]),
    ("put the blue cube in the bowl. actually no, make that the green one", ["place_in('obj5_cube', 'obj6_bowl')"]),
    ("move the strawberry next to the bowl, sorry, i meant next to the banana", ["place_beside('obj8_strawberry', 'obj7_banana', 'next')"]),
    ("push the banana - no, the bowl, the bowl - left 5 cm", ["push('obj6_bowl', 'left', 0.05)"]),
    ("when you're done the green cube should be sitting on the blue cube", ["place_on('obj5_cube', 'obj4_cube')"]),
    ("pick up the soda can, the one on the right, and put it in the bowl", ["grasp('obj2_soda_can')", "place_in('obj2_soda_can', 'obj6_bowl')"]),
    ("push the banana 5 cm to the robot's left", ["push('obj7_banana', 'left', 0.05)"]),
    ("translate the banana 4 cm along -x, i.e. toward the robot", ["push('obj7_banana', 'back', 0.04)"]),
    ("pick up the thing at the front on the left", ["grasp('obj8_strawberry')"]),
    ("pick up the smaller of the three cubes", ["grasp('obj5_cube')"]),
    ("pick up the banana and hold it. do not put it down", ["grasp('obj7_banana')"]),
    ("grab the green cube put it in the bowl", ["grasp('obj5_cube')", "place_in('obj5_cube', 'obj6_bowl')"]),
    ("put the strawberry to behind of the bowl", ["place_beside('obj8_strawberry', 'obj6_bowl', 'behind')"]),
    ("pick up the thing sitting in front of the banana", ["grasp('obj6_bowl')"]),
    ("ok class, which one is farthest from you? pick that one up", ["grasp('obj7_banana')"]),
    ("see the two cans? put the one on the right in the bowl", ["place_in('obj2_soda_can', 'obj6_bowl')"]),
    ("pick up the cube in between the other two", ["grasp('obj4_cube')"]),
    ("pick up the thing between the bowl and the banana", ["grasp('obj4_cube')"]),
    ("lift the bowl up like a trophy", ["grasp('obj6_bowl')"]),
    ("push the bowl left like a bit", ["push('obj6_bowl', 'left', 0.05)"]),
])
def test_blind_batch_classes(sentence: str, lines: list[str]) -> None:
    assert calls(sentence) == lines


def test_an_end_state_swap() -> None:
    got = calls("in the end the banana and the strawberry should have traded places")
    assert [c.split("(")[0] for c in got] == ["place_beside", "place", "place"]
    assert {"obj7_banana", "obj8_strawberry"} <= {a for c in got for a in ("obj7_banana", "obj8_strawberry") if a in c}


@pytest.mark.parametrize("sentence", [
    "put the banana in the, um...",  # broken off before its place
    "push the bigger of the two toward you",  # of which two?
    "put the red cube on the blue cube no wait the green cube",  # either cube could be replaced
    "grab the orange cube",  # of three cubes none is orange, a neighbouring hue does not stand in
])
def test_still_refused(sentence: str) -> None:
    with pytest.raises(InputError):
        RulePlanner().plan(sentence, CLUTTER)


def test_the_usual_colour_of_a_kind_decides_between_look_alikes() -> None:
    boxes = [ObjectInfo("obj1_white_box", "white box", ("box",), (0.4, 0.2, 0.03), (0.2, 0.2, 0.05), "white"),
             ObjectInfo("obj2_red_box", "red box", ("box",), (0.4, -0.2, 0.08), (0.13, 0.25, 0.15), "red")]
    assert calls("pick up the cracker box", boxes) == ["grasp('obj2_red_box')"]
    with pytest.raises(InputError, match="ambiguous"):
        RulePlanner().plan("pick up the box", boxes)


def test_a_neighbouring_hue_names_the_one_object_its_noun_names() -> None:
    scene = [ObjectInfo("obj1_cereal_box", "cereal box", (), (0.4, 0.2, 0.1), (0.17, 0.07, 0.22), "orange"),
             ObjectInfo("obj2_mug", "mug", (), (0.4, -0.2, 0.04), (0.11, 0.08, 0.09), "white")]
    assert calls("put the yellow cereal box next to the mug", scene) == ["place_beside('obj1_cereal_box', 'obj2_mug', 'next')"]
