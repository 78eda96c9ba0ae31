"""Steps that lean on the one before: "the other side", "the last one", "then ...", "on the table"."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER, call_lines

from realsim.errors import InputError
from realsim.planner import RulePlanner
from realsim.planner.reference import Context, Resolver
from realsim.planner.sentences import is_request
from realsim.planner.types import ObjectInfo


@pytest.mark.parametrize(("said", "plain"), [
    ("Put the banana to the left of the bowl. Now the strawberry, but the other side.",
     "put the banana to the left of the bowl, then put the strawberry to the right of the bowl"),
    ("put the banana behind the bowl and the strawberry on the other side",
     "put the banana behind the bowl, then put the strawberry in front of the bowl"),
])
def test_the_other_side_is_the_opposite_side_of_the_same_thing(said: str, plain: str) -> None:
    assert call_lines(said) == call_lines(plain)


def test_the_last_one_is_the_one_of_its_kind_not_named_yet() -> None:
    assert call_lines("Red cube in the bowl. Then the green one next to the bowl. And the last one behind the bowl.") == call_lines(
        "put the red cube in the bowl, put the green cube next to the bowl, put the blue cube behind the bowl")
    assert call_lines("lift the red cube and the blue cube, then put the remaining cube in the bowl") == call_lines(
        "lift the red cube and the blue cube, then put the green cube in the bowl")


def test_a_step_after_then_is_never_skipped_as_talk() -> None:
    assert is_request("then put the last one next to the plate")
    assert is_request("and the last one next to the plate.", {"plate"})
    assert not is_request("the cube is next to the plate", {"cube", "plate"})
    with pytest.raises(InputError):  # the second step cannot be done: the whole message is refused, not its first step done alone
        RulePlanner().plan("put the red cube in the bowl, then put the teapot next to the bowl", CLUTTER)


def test_on_the_table_says_it_stands_on_no_other_thing() -> None:
    cans = [ObjectInfo("obj1_can", "can", (), (0.5, 0.1, 0.05), (0.066, 0.066, 0.1), "red"),
            ObjectInfo("obj2_box", "box", (), (0.5, -0.1, 0.03), (0.12, 0.12, 0.06), "white", ("graspable", "support")),
            ObjectInfo("obj3_can", "can", (), (0.5, -0.1, 0.11), (0.066, 0.066, 0.1), "red")]
    resolver = Resolver(cans)
    assert [o.name for o in resolver.resolve("the red can on the table", Context())] == ["obj1_can"]
    assert [o.name for o in resolver.resolve("the can sitting on the box", Context())] == ["obj3_can"]
    with pytest.raises(InputError, match="ambiguous"):
        resolver.resolve("the red can", Context())


def test_to_sit_with_a_thing_is_to_be_next_to_it() -> None:
    assert call_lines("bring the strawberry over to sit with the banana") == call_lines("put the strawberry next to the banana")
    assert call_lines("can you bring the strawberry over to sit next to the banana?") == call_lines("put the strawberry next to the banana")


def test_the_right_one_of_those_just_named() -> None:
    assert call_lines("The two soda cans are crammed together. Slide the right-hand one 5 cm further to the right.") == call_lines(
        "push the right soda can 5 cm to the right")
    assert call_lines("slide the right one 5 cm to the right") == call_lines("push the rightmost thing 5 cm to the right")


def test_on_the_table_beside_a_thing_is_both() -> None:
    plan = RulePlanner().plan("put the red cube on the table next to the bowl", CLUTTER)
    assert [g.describe() for g in plan.goals] == ["obj3_cube next to obj6_bowl", "obj3_cube on the table"]


def test_a_placing_without_its_verb_is_never_dropped_as_talk() -> None:
    with pytest.raises(InputError, match="bowl"):  # CLUTTER has no plate: the second placing cannot be done, so nothing is
        RulePlanner().plan("the red cube in the bowl and the blue one on the plate", CLUTTER)
    assert call_lines("It bothers me that the banana is lined up behind the bowl, it looks cluttered. Push it 5 cm to the left.") == call_lines(
        "push the banana 5 cm to the left")
    assert call_lines("Set the strawberry dead centre between the banana and that red cube.") == call_lines(
        "put the strawberry between the banana and the red cube")
    assert call_lines("Butt the strawberry up tight against the right-hand side of the bowl.") == call_lines("put the strawberry to the right of the bowl")
    assert call_lines("Line the strawberry up behind the bowl.") == call_lines("put the strawberry behind the bowl")


@pytest.mark.parametrize(("said", "plain"), [
    ("Put the strawberry on my right side of the bowl.", "put the strawberry to the right of the bowl"),  # the speaker's side is the robot's
    ("Grab the thing that sits between the bowl and the banana.", "pick up the blue cube"),
    ("Lift the cube directly behind the bowl.", "lift the blue cube"),
    ("Slide the dish you'd eat your cereal out of 5 cm to the left.", "push the bowl 5 cm to the left"),
])
def test_places_and_uses_said_by_people(said: str, plain: str) -> None:
    assert call_lines(said) == call_lines(plain)


def test_things_named_alone_then_a_place_for_the_first_in_the_second() -> None:
    assert call_lines("Strawberry. Bowl. In it goes.") == call_lines("put the strawberry in the bowl")
    assert call_lines("Red cube. Bowl. In it. How hard can that possibly be?") == call_lines("put the red cube in the bowl")


def test_a_body_name_said_whole() -> None:
    assert call_lines("put obj8_strawberry in obj6_bowl") == call_lines("put the strawberry in the bowl")
    with pytest.raises(InputError, match="no object 8 bowl"):
        RulePlanner().plan("lift obj8_bowl", CLUTTER)
