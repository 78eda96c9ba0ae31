"""A plain size word ("the tall can") only picks an object it tells apart: between look-alikes it
picks nothing and the planner asks, unless the scene's own name of one of them carries the word.
Sentences written for this test, not taken from a bench set."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER, call_lines

from realsim.errors import InputError
from realsim.planner import ObjectInfo, RulePlanner


@pytest.mark.parametrize("sentence", ["lift the tall can", "pick up the big soda can", "put the small can in the bowl"])
def test_equal_cans_are_not_told_apart_by_a_size_word(sentence: str) -> None:
    with pytest.raises(InputError, match="ambiguous"):
        RulePlanner().plan(sentence, CLUTTER)


def test_a_size_word_with_another_locator_still_picks() -> None:
    assert call_lines("grab the tall can on the left", CLUTTER)[0] == "grasp('obj1_soda_can')"


def test_a_clearly_bigger_one_is_picked() -> None:
    cans = [*CLUTTER[2:], ObjectInfo("obj9_can", "can", (), (0.4, -0.3, 0.09), (0.07, 0.07, 0.18), "red"),
            ObjectInfo("obj10_can", "can", (), (0.4, 0.35, 0.05), (0.07, 0.07, 0.10), "red")]
    assert call_lines("pick up the tall can", cans)[0] == "grasp('obj9_can')"


def test_the_scenes_own_name_decides_between_near_equals() -> None:
    cans = [*CLUTTER[2:], ObjectInfo("obj9_tall_white_can", "tall white can", ("can",), (0.4, -0.3, 0.07), (0.07, 0.07, 0.14), "white"),
            ObjectInfo("obj10_red_can", "red can", ("can",), (0.4, 0.35, 0.065), (0.1, 0.1, 0.13), "red")]
    assert call_lines("lift the tall can", cans)[0] == "grasp('obj9_tall_white_can')"
