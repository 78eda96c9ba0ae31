"""Names given for one message, compass bearings set up by the speaker, office jargon, complaints
about a thing, and a plate said as a container (realsim.planner.aliases, compass, formal, phrasing;
blind set heldout37's classes, tested here on sentences of their own)."""

from __future__ import annotations

import pytest
from test_planner_rules import call_lines

from realsim.errors import InputError
from realsim.planner.aliases import named
from realsim.planner.compass import bearings
from realsim.planner.types import ObjectInfo

PLATE = ObjectInfo("obj9_plate", "plate", ("dish",), (0.45, -0.30, 0.01), (0.24, 0.24, 0.02), "white", ("graspable", "support", "pushable"))


@pytest.mark.parametrize(("message", "said"), [
    ("Bravo is the banana. Put Bravo in the bowl.", "Put the banana in the bowl."),
    ("The bowl is Home Base, the strawberry is Rover: Rover goes to Home Base.", "the strawberry goes to the bowl."),
    ("codename Ruby is the red cube, move Ruby left 5 cm", "move the red cube left 5 cm"),
    ("Grab the banana, we'll call it the Boomerang. Boomerang into the bowl.", "Grab the banana, the banana into the bowl."),
    ("Landing zone: the space between the red cube and the blue cube. Strawberry to the landing zone.",
     "Strawberry between the red cube and the blue cube."),
    ("Do you see the green cube near the banana? That's the pebble. Lift the pebble.", "Do you see the green cube near the banana? Lift the green cube."),
])
def test_a_name_given_is_said_as_what_it_stands_for(message: str, said: str) -> None:
    assert named(message) == said


@pytest.mark.parametrize("message", [
    "the can is the problem, move it aside",  # a statement: "the problem" is never used as a name
    "The mug is in the bowl. Move it left.",
    "The bowl is the white one.",  # both sides describe a thing
    "Banana: in the bowl please",  # a thing's own word is no name
    "the red cube is heavy, lift it",
    "the mug goes on the LEFT of the bowl. Your left! it's the same left, just do it.",  # a side is never a name
])
def test_statements_are_no_names(message: str) -> None:
    assert named(message) == message


NAMED_AND_BEARINGS: list[tuple[str, list[str]]] = [
    ("Bravo is the banana, Charlie is the bowl. Bravo goes in Charlie.", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("The green cube is the Scout. Push the Scout back 4 cm, then return to base.", ["push('obj5_cube', 'back', 0.04)", "go_home()"]),
    ("North is away from you. Push the banana two inches south.", ["push('obj7_banana', 'back', 0.05"]),
    ("Let's say north is your left. Push the strawberry 3 cm north, then put the green cube east of the bowl.",
     ["push('obj8_strawberry', 'left', 0.03)", "place_beside('obj5_cube', 'obj6_bowl', 'behind')"]),  # east: a quarter turn clockwise from north
    ("With west to your left and north straight ahead, lift the most westerly cube.", ["grasp('obj3_cube')"]),
    # office jargon; a complaint about a thing names what "it" means next; the side said after "on its six"
    ("Quick win first: the strawberry goes in the bowl, then circle back to your home position. Can we get that actioned?",
     ["place_in('obj8_strawberry', 'obj6_bowl')", "go_home()"]),
    ("The banana is crowding the bowl, two inches to the left, then stay right there.", ["push('obj7_banana', 'left', 0.05"]),
    ("The two of them, the red cube and the blue cube: put the two of them next to each other.", ["place_beside("]),
    ("Put the strawberry on the bowl's six, that is, behind it.", ["place_beside('obj8_strawberry', 'obj6_bowl', 'behind')"]),
    ("lift the soda can furthest to your right", ["grasp('obj2_soda_can')"]),
    ("let the strawberry down onto the table for a breather", ["place_down('obj8_strawberry')"]),
]
TOLD_AND_BARGAINED: list[tuple[str, list[str]]] = [
    # the robot's actions told to an audience
    ("Folks, gather round: in our next trick the robot is going to lift the strawberry and drop it into the bowl. Watch closely.",
     ["place_in('obj8_strawberry', 'obj6_bowl')"]),
    ("What you'll see now is our trusty arm nudging the banana about three centimetres to the left.", ["push('obj7_banana', 'left', 0.03)"]),
    ("And for the finale, the gripper sets the green cube on the red cube and then returns to its resting position.",
     ["place_on('obj5_cube', 'obj3_cube')", "go_home()"]),
    # an auction's and a bargain's talk around the request
    ("Lot number seven, a fine red strawberry! The buyer wants it next to the banana. Going, going, gone!", ["place_beside('obj8_strawberry', 'obj7_banana', 'next')"]),
    ("Here's the deal: the green cube goes in the bowl and we'll call it even. Take it or leave it.", ["place_in('obj5_cube', 'obj6_bowl')"]),
    # a unit made up for the message; a game's and a garden's verbs
    ("Slide the banana two squares to the right, where a square is three centimetres.", ["push('obj7_banana', 'right', 0.06)"]),
    ("Castle the banana and the strawberry.", ["place('obj7_banana'", "place('obj8_strawberry'"]),
    ("Green cube, retreat.", ["push('obj5_cube', 'back'"]),
    ("Transplant the strawberry into the gap between the red cube and the blue cube.", ["place_between('obj8_strawberry', 'obj3_cube', 'obj4_cube')"]),
    ("The green cube gets planted on the blue cube.", ["place_on('obj5_cube', 'obj4_cube')"]),
    ("Three centimetres forward for the strawberry, please.", ["push('obj8_strawberry', 'forward', 0.03)"]),
    ("The strawberry hops off the red cube and lands right beside the bowl.", ["place_beside('obj8_strawberry', 'obj6_bowl', 'next')"]),
    # a magician's, a station announcer's and a furniture mover's words; a thing spoken of as a person
    ("For my last trick, my lovely assistant will make the strawberry vanish... into the bowl! Hey presto!", ["place_in('obj8_strawberry', 'obj6_bowl')"]),
    ("The banana simply disappears. Whisk it out of the way, assistant.", ["place('obj7_banana'"]),
    ("The green cube is requested on the blue cube. Green cube, please take your seat on the blue cube.", ["place_on('obj5_cube', 'obj4_cube')"]),
    ("Would the strawberry, currently by the bowl, please disembark onto the red cube.", ["place_on('obj8_strawberry', 'obj3_cube')"]),
    ("Don't lift the bowl, just walk it along the table, five centimetres to the right.", ["push('obj6_bowl', 'right', 0.05)"]),
    ("The strawberry is the guest of honour, so she sits between the red cube and the blue cube.", ["place_between('obj8_strawberry', 'obj3_cube', 'obj4_cube')"]),
    # "that can": the one just named
    ("Put the banana in front of the left can, so between that can and yourself.", ["place_beside('obj7_banana', 'obj1_soda_can', 'front')"]),
]


@pytest.mark.parametrize(("sentence", "lines"), NAMED_AND_BEARINGS + TOLD_AND_BARGAINED)
def test_named_bearing_told_and_bargained_requests(sentence: str, lines: list[str]) -> None:
    got = call_lines(sentence)
    for line in lines:
        assert any(g.startswith(line) for g in got), (sentence, got)


def test_a_thing_the_robot_is_pointed_at_is_no_narration() -> None:
    got = call_lines("push the banana toward the robot then lift the strawberry")
    assert got[0].startswith("push('obj7_banana', 'back'") and got[1:] == ["grasp('obj8_strawberry')"]
    assert call_lines("The thing closest to the robot goes into the thing farther away.") == ["place_in('obj8_strawberry', 'obj6_bowl')"]


def test_that_one_never_means_several() -> None:
    with pytest.raises(InputError, match="ambiguous"):  # "that one" is one of the two, never both
        call_lines("take the two soda cans, then put that one in the bowl")


def test_compass_words_without_a_set_up_are_not_guessed() -> None:
    assert bearings("push the banana 5 cm north") == "push the banana 5 cm north"
    with pytest.raises(InputError):
        call_lines("push the banana 5 cm north")


def test_into_a_flat_support_is_onto_it_but_a_cube_holds_nothing() -> None:
    assert call_lines("drop the strawberry into the plate", [*call_objects(), PLATE]) == ["place_on('obj8_strawberry', 'obj9_plate')"]
    with pytest.raises(InputError, match="not an open container"):
        call_lines("drop the strawberry into the blue cube")


def call_objects() -> list[ObjectInfo]:
    from test_planner_rules import CLUTTER
    return list(CLUTTER)
