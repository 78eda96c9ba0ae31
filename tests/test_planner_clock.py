"""Clock-face directions (realsim.planner.clock): places, ways and sides as pilots give them."""

from __future__ import annotations

import math

import pytest
from test_planner_rules import call_lines

from realsim.errors import InputError
from realsim.planner import RulePlanner
from realsim.planner.clock import bearing_gap, clock, nautical
from realsim.planner.types import ObjectInfo


@pytest.mark.parametrize(("said", "plain"), [
    ("slide it two inches toward your nine", "slide it two inches to the left"),
    ("push it 3 cm towards three o'clock", "push it 3 cm to the right"),
    ("nudge it toward twelve", "nudge it forward"),
    ("put it on the bowl's six o'clock side", "put it in front of the bowl"),
    ("put it on the nine o'clock side of the plate", "put it to the left of the plate"),
    ("the can over at your ten o'clock", "the can at clock 10"),
    ("the can, roughly your two", "the can, at clock 2"),
    ("move it to two", "move it to two"),  # no clock word: not a clock
    ("put the mug at the back", "put the mug at the back"),
])
def test_clock_words_become_the_planners_words(said: str, plain: str) -> None:
    assert clock(said) == plain


def test_the_bearing_gap_is_measured_clockwise_from_straight_ahead() -> None:
    assert bearing_gap(1.0, 0.0, 12) == pytest.approx(0.0)
    assert bearing_gap(0.0, -1.0, 3) == pytest.approx(0.0)  # the robot's right
    assert bearing_gap(0.0, 1.0, 9) == pytest.approx(0.0)
    assert bearing_gap(1.0, 1.0, 11) == pytest.approx(math.radians(15))


def test_a_thing_at_an_hour_is_the_one_whose_bearing_is_nearest() -> None:
    """CLUTTER's soda cans stand at y = +0.20 (left, about 11 o'clock) and -0.10 (right, about 1)."""
    assert call_lines("pick up the soda can at your eleven o'clock") == call_lines("pick up the left soda can")
    assert call_lines("the soda can at one o'clock. lift it.") == call_lines("pick up the right soda can")
    assert call_lines("push the banana 2 cm toward your nine") == call_lines("push the banana 2 cm to the left")


def test_two_things_near_the_same_hour_are_not_told_apart() -> None:
    assert call_lines("pick up the cube at twelve o'clock") == call_lines("pick up the blue cube")  # 5 deg off; the others 15 and 24
    twins = [ObjectInfo("obj1_cube", "cube", (), (0.5, 0.1, 0.03), (0.05, 0.05, 0.05), "red"),
             ObjectInfo("obj2_cube", "cube", (), (0.5, -0.08, 0.03), (0.05, 0.05, 0.05), "green")]  # 11 and 9 deg either side
    with pytest.raises(InputError, match="ambiguous"):
        RulePlanner().plan("pick up the cube at twelve o'clock", twins)


@pytest.mark.parametrize(("said", "plain"), [
    ("shove the banana two centimetres to port", "push the banana 2 cm to the left"),
    ("haul the strawberry round to starboard o' the bowl", "put the strawberry to the right of the bowl"),
    ("drag the banana fore 3 cm", "push the banana forward 3 cm"),
    ("nudge the strawberry 2 cm aft", "push the strawberry back 2 cm"),
])
def test_a_ships_sides_and_ways_are_the_robots(said: str, plain: str) -> None:
    assert call_lines(said) == call_lines(plain)


def test_a_word_holding_port_is_no_side() -> None:
    assert nautical("the airport is far") == "the airport is far"
