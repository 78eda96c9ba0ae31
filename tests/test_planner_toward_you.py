"""Ways said relative to the robot in learner's or loose English: "towards yourself", "in your
direction", "more near of you" are toward the robot; "more far from you" is away from it; "make it
go ..." moves it. Sentences written for this test, not taken from a bench set."""

from __future__ import annotations

import pytest
from test_planner_rules import call_lines


@pytest.mark.parametrize(("sentence", "line"), [
    ("nudge the banana towards yourself 4 cm", "push('obj7_banana', 'back', 0.04)"),
    ("could you slide the blue cube in your direction by 3 cm", "push('obj4_cube', 'back', 0.03)"),
    ("push the green cube to your direction, 6 cm", "push('obj5_cube', 'back', 0.06)"),
    ("move the banana more near of you, 5 cm", "push('obj7_banana', 'back', 0.05)"),
    ("slide the red cube more close to you by 2 cm", "push('obj3_cube', 'back', 0.02)"),
    ("push the bowl more far from you 7 cm", "push('obj6_bowl', 'forward', 0.07)"),
    ("the green cube, make it go more far of you, 30 millimeter", "push('obj5_cube', 'forward', 0.03)"),
    ("the banana, make it slide to the left 2 cm", "push('obj7_banana', 'left', 0.02)"),
])
def test_way_relative_to_the_robot(sentence: str, line: str) -> None:
    assert call_lines(sentence) == [line]


def test_place_still_read_with_the_way() -> None:
    """"more near of you" after a place says which side of it: in front."""
    assert call_lines("put the strawberry in front from the bowl, more near of you") == ["place_beside('obj8_strawberry', 'obj6_bowl', 'front')"]
