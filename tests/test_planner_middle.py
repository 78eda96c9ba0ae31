""""The X in the middle of the three": the middle one, when the count said is the count that
matches; another count is refused. Sentences written for this test, not taken from a bench set."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER, call_lines

from realsim.errors import InputError
from realsim.planner import RulePlanner

CUBES = [o for o in CLUTTER if o.label == "cube" or o.label == "bowl"]


@pytest.mark.parametrize("sentence", [
    "lift the cube in the middle of the three",
    "put the cube at the center of the three into the bowl",
    "grab the block in the middle of them",
])
def test_middle_of_the_three(sentence: str) -> None:
    assert call_lines(sentence, CUBES)[0] == "grasp('obj4_cube')" or call_lines(sentence, CUBES)[0] == "place_in('obj4_cube', 'obj6_bowl')"


@pytest.mark.parametrize("sentence", [
    "lift the cube in the middle of the five",
    "pick up the cube in the middle of the two",
])
def test_a_count_that_does_not_match_is_refused(sentence: str) -> None:
    with pytest.raises(InputError, match="said, but 3 match"):
        RulePlanner().plan(sentence, CUBES)
