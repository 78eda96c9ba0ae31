"""The offline rule planner: sentences to programs and goals for a fixed scene."""

from __future__ import annotations

import pytest

from realsim.errors import InputError
from realsim.planner import (
    AtHome,
    Between,
    DrawerClosed,
    DrawerOpen,
    Inside,
    Lifted,
    Moved,
    NextTo,
    ObjectInfo,
    On,
    RulePlanner,
    SideOf,
    check,
)
from realsim.planner.rules import split_command

OBJECTS = [
    ObjectInfo("obj1_mug", "mug", ("cup", "coffee mug"), (0.5, 0.1, 0.05), (0.08, 0.08, 0.1), "red"),
    ObjectInfo("obj2_bowl", "bowl", (), (0.5, -0.2, 0.03), (0.16, 0.16, 0.06), "white", ("graspable", "container")),
    ObjectInfo("obj3_soup_can", "tomato soup can", ("can", "soup can"), (0.4, 0.0, 0.05), (0.066, 0.066, 0.1), "red"),
    ObjectInfo("obj4_block", "wood block", ("block", "cube"), (0.6, 0.2, 0.02), (0.05, 0.05, 0.05), "blue", ("graspable", "support")),
    ObjectInfo("obj5_drawer", "drawer", (), (0.7, -0.4, 0.2), (0.4, 0.3, 0.15), None, ("drawer",)),
    ObjectInfo("obj6_cracker_box", "cracker box", ("box",), (0.3, 0.3, 0.1), (0.06, 0.16, 0.21), "yellow", ("graspable", "support")),
]

# sentence -> (program lines without the comment, goals)
CASES: list[tuple[str, list[str], list[object]]] = [
    ("put the mug in the bowl", ["place_in('obj1_mug', 'obj2_bowl')"], [Inside("obj1_mug", "obj2_bowl")]),
    ("Put the cup into the bowl.", ["place_in('obj1_mug', 'obj2_bowl')"], [Inside("obj1_mug", "obj2_bowl")]),
    ("place the red can inside the bowl", ["place_in('obj3_soup_can', 'obj2_bowl')"], [Inside("obj3_soup_can", "obj2_bowl")]),
    ("drop the cube into the bowl", ["place_in('obj4_block', 'obj2_bowl')"], [Inside("obj4_block", "obj2_bowl")]),
    ("pick up the mug", ["grasp('obj1_mug')"], [Lifted("obj1_mug")]),
    ("grab the soup can", ["grasp('obj3_soup_can')"], [Lifted("obj3_soup_can")]),
    ("lift the blue block", ["grasp('obj4_block')"], [Lifted("obj4_block")]),
    ("pick the coffee mug up", ["grasp('obj1_mug')"], [Lifted("obj1_mug")]),
    ("take the yellow box", ["grasp('obj6_cracker_box')"], [Lifted("obj6_cracker_box")]),
    ("stack the block on the cracker box", ["place_on('obj4_block', 'obj6_cracker_box')"], [On("obj4_block", "obj6_cracker_box")]),
    ("put the mug on top of the box", ["place_on('obj1_mug', 'obj6_cracker_box')"], [On("obj1_mug", "obj6_cracker_box")]),
    ("set the can onto the block", ["place_on('obj3_soup_can', 'obj4_block')"], [On("obj3_soup_can", "obj4_block")]),
    ("push the soup can 5 cm left", ["push('obj3_soup_can', 'left', 0.05)"], [Moved("obj3_soup_can", (0.0, 1.0), 0.05)]),
    ("slide the block to the right by 10 centimeters", ["push('obj4_block', 'right', 0.1)"], [Moved("obj4_block", (0.0, -1.0), 0.1)]),
    ("push the mug forward", ["push('obj1_mug', 'forward', 0.1)"], [Moved("obj1_mug", (1.0, 0.0), 0.1)]),
    ("move the cube 2 inches back", ["push('obj4_block', 'back', 0.051)"], [Moved("obj4_block", (-1.0, 0.0), 0.051)]),
    ("nudge the mug a bit to the left", ["push('obj1_mug', 'left', 0.05)"], [Moved("obj1_mug", (0.0, 1.0), 0.05)]),
    ("push the can 0.05 m right", ["push('obj3_soup_can', 'right', 0.05)"], [Moved("obj3_soup_can", (0.0, -1.0), 0.05)]),
    ("shove the tomato soup can forward by five cm", ["push('obj3_soup_can', 'forward', 0.05)"], [Moved("obj3_soup_can", (1.0, 0.0), 0.05)]),
    ("slide the box backwards 30 mm", ["push('obj6_cracker_box', 'back', 0.03)"], [Moved("obj6_cracker_box", (-1.0, 0.0), 0.03)]),
    ("open the drawer", ["open_drawer('obj5_drawer')"], [DrawerOpen("obj5_drawer")]),
    ("close the drawer", ["close_drawer('obj5_drawer')"], [DrawerClosed("obj5_drawer")]),
    ("go home", ["go_home()"], [AtHome()]),
    ("return to home position", ["go_home()"], [AtHome()]),
    ("open the gripper", ["open_gripper()"], []),
    ("close the gripper", ["close_gripper()"], []),
    (
        "pick up the cup then put it in the bowl",
        ["grasp('obj1_mug')", "place_in('obj1_mug', 'obj2_bowl')"],
        [Inside("obj1_mug", "obj2_bowl")],
    ),
    (
        "grab the blue block and place it on the can",
        ["grasp('obj4_block')", "place_on('obj4_block', 'obj3_soup_can')"],
        [On("obj4_block", "obj3_soup_can")],
    ),
    (
        "first pick up the mug, next put it in the bowl, finally go home",
        ["grasp('obj1_mug')", "place_in('obj1_mug', 'obj2_bowl')", "go_home()"],
        [Inside("obj1_mug", "obj2_bowl"), AtHome()],
    ),
    (
        "open the drawer, then go home",
        ["open_drawer('obj5_drawer')", "go_home()"],
        [DrawerOpen("obj5_drawer"), AtHome()],
    ),
    (
        "go home and then push the block left 3 cm",
        ["go_home()", "push('obj4_block', 'left', 0.03)"],
        [Moved("obj4_block", (0.0, 1.0), 0.03)],
    ),
    (
        "put the mug in the bowl; put the can on the box",
        ["place_in('obj1_mug', 'obj2_bowl')", "place_on('obj3_soup_can', 'obj6_cracker_box')"],
        [Inside("obj1_mug", "obj2_bowl"), On("obj3_soup_can", "obj6_cracker_box")],
    ),
    ("put the mugg in the bowl", ["place_in('obj1_mug', 'obj2_bowl')"], [Inside("obj1_mug", "obj2_bowl")]),
    ("put obj3_soup_can in obj2_bowl", ["place_in('obj3_soup_can', 'obj2_bowl')"], [Inside("obj3_soup_can", "obj2_bowl")]),
    ("could you put the mug in the bowl please", ["place_in('obj1_mug', 'obj2_bowl')"], [Inside("obj1_mug", "obj2_bowl")]),
]


@pytest.mark.parametrize(("sentence", "lines", "goals"), CASES, ids=[c[0][:40] for c in CASES])
def test_sentence_to_program_and_goals(sentence: str, lines: list[str], goals: list[object]) -> None:
    plan = RulePlanner().plan(sentence, OBJECTS)
    body = [ln for ln in plan.program.splitlines() if ln and not ln.startswith("#")]
    assert body == lines
    assert plan.goals == goals
    assert plan.planner == "rules" and plan.usage.calls == 0
    check(plan.program)  # the rule planner's programs pass the same sandbox as Claude's


def test_at_least_thirty_sentences() -> None:
    assert len(CASES) >= 30


def test_relations_become_calls_decided_at_run_time() -> None:
    """Beside/left of/between are primitives that find a free spot in the live scene."""
    plan = RulePlanner().plan("put the red can next to the bowl", OBJECTS)
    assert [c.text() for c in plan.calls] == ["place_beside('obj3_soup_can', 'obj2_bowl', 'next')"]
    assert plan.goals == [NextTo("obj3_soup_can", "obj2_bowl")]
    left = RulePlanner().plan("put the mug to the left of the box", OBJECTS)
    assert [c.text() for c in left.calls] == ["place_beside('obj1_mug', 'obj6_cracker_box', 'left')"]
    assert left.goals == [SideOf("obj1_mug", "obj6_cracker_box", "left")]
    between = RulePlanner().plan("set the block down between the mug and the can", OBJECTS)
    assert between.goals == [Between("obj4_block", "obj1_mug", "obj3_soup_can")]
    assert plan.program.splitlines()[1:] == [c.text() for c in plan.calls]  # the program is the calls' text


def test_split_keeps_verbless_parts_together() -> None:
    assert split_command("pick up the mug and then go home") == ["pick up the mug", "go home"]
    assert split_command("put the salt and pepper in the bowl") == ["put the salt and pepper in the bowl"]


@pytest.mark.parametrize(
    ("sentence", "needle"),
    [
        ("put the banana in the bowl", "no object matches 'the banana'"),
        ("dance with the mug", "cannot understand"),
        ("put the red thing in the bowl", "ambiguous"),
        ("put it in the bowl", "'it' does not refer"),
        ("", "empty"),
        ("push the mug 5 m left", "out of range"),
    ],
)
def test_unknown_words_and_objects_are_input_errors(sentence: str, needle: str) -> None:
    with pytest.raises(InputError) as info:
        RulePlanner().plan(sentence, OBJECTS)
    assert needle in str(info.value)
    assert info.value.exit_code == 2


def test_unknown_object_lists_the_scene() -> None:
    with pytest.raises(InputError) as info:
        RulePlanner().plan("pick up the spoon", OBJECTS)
    assert "obj1_mug (red mug)" in str(info.value) and "obj2_bowl (white bowl)" in str(info.value)


# A cluttered scene with look-alikes: two cans, three cubes of different colours and sizes.
CLUTTER = [
    ObjectInfo("obj1_soda_can", "soda can", ("can",), (0.40, 0.20, 0.06), (0.066, 0.066, 0.12), "red"),
    ObjectInfo("obj2_soda_can", "soda can", ("can",), (0.40, -0.10, 0.06), (0.066, 0.066, 0.12), "red"),
    ObjectInfo("obj3_cube", "cube", ("block",), (0.55, 0.25, 0.03), (0.06, 0.06, 0.06), "red", ("graspable", "support")),
    ObjectInfo("obj4_cube", "cube", ("block",), (0.55, 0.05, 0.03), (0.07, 0.07, 0.07), "blue", ("graspable", "support")),
    ObjectInfo("obj5_cube", "cube", ("block",), (0.55, -0.15, 0.025), (0.05, 0.05, 0.05), "green", ("graspable", "support")),
    ObjectInfo("obj6_bowl", "bowl", (), (0.30, 0.0, 0.03), (0.16, 0.16, 0.06), "white", ("graspable", "container")),
    ObjectInfo("obj7_banana", "banana", (), (0.65, 0.0, 0.02), (0.2, 0.05, 0.04), "yellow"),
    ObjectInfo("obj8_strawberry", "strawberry", (), (0.25, 0.3, 0.02), (0.04, 0.04, 0.04), "red"),
]

def call_lines(sentence: str, objects: list[ObjectInfo] = CLUTTER) -> list[str]:
    """The rule planner's calls for ``sentence`` on ``objects``, one text line each."""
    return [c.text() for c in RulePlanner().plan(sentence, objects).calls]


PEOPLE: list[tuple[str, list[str]]] = [
    ("pick up the left can and set it down inside the bowl", ["grasp('obj1_soda_can')", "place_in('obj1_soda_can', 'obj6_bowl')"]),
    ("could you please drop the green cube into the bowl for me", ["place_in('obj5_cube', 'obj6_bowl')"]),
    ("would you mind picking up the biggest cube", ["grasp('obj4_cube')"]),
    ("put the second cube from the left on the green one", ["place_on('obj4_cube', 'obj5_cube')"]),
    ("put all the fruit in the bowl", ["place_in('obj7_banana', 'obj6_bowl')", "place_in('obj8_strawberry', 'obj6_bowl')"]),
    ("take both cans and put them next to the banana",
     ["place_beside('obj1_soda_can', 'obj7_banana', 'next')", "place_beside('obj2_soda_can', 'obj7_banana', 'next')"]),
    ("grab the red cube, then put it back", ["grasp('obj3_cube')", "place('obj3_cube', [0.55, 0.25, 0.03])"]),
    ("put the smallest cube between the red cube and the blue cube", ["place_between('obj5_cube', 'obj3_cube', 'obj4_cube')"]),
    ("put the can on the right behind the bowl", ["place_beside('obj2_soda_can', 'obj6_bowl', 'behind')"]),
    ("push the rightmost cube a bit toward the robot", ["push('obj5_cube', 'back', 0.05)"]),
    ("put the left can in the bowl and the banana on the table", ["place_in('obj1_soda_can', 'obj6_bowl')", "place_down('obj7_banana')"]),
    ("push the left can 5 cm forward and then push the other one back 5 cm",
     ["push('obj1_soda_can', 'forward', 0.05)", "push('obj2_soda_can', 'back', 0.05)"]),
    ("move the can on the left next to the banana", ["place_beside('obj1_soda_can', 'obj7_banana', 'next')"]),
    ("the banana: lift it", ["grasp('obj7_banana')"]),
    ("i want the banana in the bowl and the strawberry too",
     ["place_in('obj7_banana', 'obj6_bowl')", "place_in('obj8_strawberry', 'obj6_bowl')"]),
    # locators, negation and comparatives say which object; they are never a place
    ("pick up the can closest to the bowl", ["grasp('obj2_soda_can')"]),
    ("pick up the fruit that is not the banana", ["grasp('obj8_strawberry')"]),
    ("lift the can that isn't on the left", ["grasp('obj2_soda_can')"]),
    ("grab the can more to the right", ["grasp('obj2_soda_can')"]),
    ("put the reddish cube in the bowl", ["place_in('obj3_cube', 'obj6_bowl')"]),
    ("put the cans on either side of the bowl", ["place_beside('obj1_soda_can', 'obj6_bowl', 'left')", "place_beside('obj2_soda_can', 'obj6_bowl', 'right')"]),
    # pushes toward or away from another object, passives, arrows, fractions of a unit
    ("push the strawberry 3 cm toward the bowl", ["push('obj8_strawberry', 'right', 0.03)"]),
    ("nudge the banana away from the bowl", ["push('obj7_banana', 'forward', 0.1)"]),
    ("push the green cube half an inch left", ["push('obj5_cube', 'left', 0.013)"]),
    ("could the banana be moved into the bowl?", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("banana -> bowl", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("do me a favor and pick up the strawberry by its top and hold it", ["grasp('obj8_strawberry')"]),
    # an exception said after the place; objects by the scene's numbering
    ("put all the fruit in the bowl except the banana", ["place_in('obj8_strawberry', 'obj6_bowl')"]),
    ("put every cube in the bowl besides the blue one", ["place_in('obj3_cube', 'obj6_bowl')", "place_in('obj5_cube', 'obj6_bowl')"]),
    ("pick up object 7", ["grasp('obj7_banana')"]),
    # how it sits by the target is not part of the object's name; a bare side is a move
    ("put the banana 10 cm to the left of the bowl", ["place_beside('obj7_banana', 'obj6_bowl', 'left')"]),
    ("set the strawberry down on the table right behind the bowl", ["place_beside('obj8_strawberry', 'obj6_bowl', 'behind')"]),
    ("put the banana to the right a bit", ["push('obj7_banana', 'right', 0.05)"]),
    # talk around the command, texting, a dropped object, a plural swap, superlatives said long
    ("ugh this table is a mess, could you drop the strawberry in the bowl", ["place_in('obj8_strawberry', 'obj6_bowl')"]),
    ("the banana looks lonely over there, can you move it next to the bowl", ["place_beside('obj7_banana', 'obj6_bowl', 'next')"]),
    ("so there's a bowl and a banana here, I'd like the banana in the bowl if that's ok", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("mv grn cube 3cm fwd", ["push('obj5_cube', 'forward', 0.03)"]),
    ("take the strawberry and put next to the banana", ["grasp('obj8_strawberry')", "place_beside('obj8_strawberry', 'obj7_banana', 'next')"]),
    ("swap the soda cans", ["place_beside('obj1_soda_can', 'obj2_soda_can', 'right')", "place('obj2_soda_can', [0.4, 0.2, 0.06])",
                            "place('obj1_soda_can', [0.4, -0.1, 0.06])"]),
    ("push whatever is furthest to the right a bit forward", ["push('obj5_cube', 'forward', 0.05)"]),
]


@pytest.mark.parametrize(("sentence", "lines"), PEOPLE, ids=[p[0][:40] for p in PEOPLE])
def test_language_people_use(sentence: str, lines: list[str]) -> None:
    plan = RulePlanner().plan(sentence, CLUTTER)
    assert [c.text() for c in plan.calls] == lines
    check(plan.program)


@pytest.mark.parametrize(("sentence", "candidates"), [
    ("put the can in the bowl", ["obj1_soda_can", "obj2_soda_can"]),
    ("grab the red thing", ["obj1_soda_can", "obj2_soda_can", "obj3_cube", "obj8_strawberry"]),
    ("stack the cube on the bowl", ["obj3_cube", "obj4_cube", "obj5_cube"]),
    ("pick up the cube in the middle and the can", ["obj1_soda_can", "obj2_soda_can"]),
])
def test_ambiguous_references_name_the_candidates(sentence: str, candidates: list[str]) -> None:
    with pytest.raises(InputError) as info:
        RulePlanner().plan(sentence, CLUTTER)
    assert "ambiguous" in str(info.value)
    for name in candidates:
        assert name in str(info.value)


def test_ordinals_count_the_target_too() -> None:
    """'the second cube from the left' is the blue one even when it is also the target."""
    with pytest.raises(InputError, match="itself"):
        RulePlanner().plan("put the second cube from the left on the blue one", CLUTTER)


def test_unknown_object_is_refused_with_the_scene() -> None:
    with pytest.raises(InputError, match="no object matches 'the hammer'.*obj6_bowl"):
        RulePlanner().plan("put the hammer in the bowl", CLUTTER)


def test_left_and_right_follow_the_robot_heading() -> None:
    """Facing +y (yaw pi/2) the robot's left is world -x: the 'left' can is the one at smaller x."""
    cans = [ObjectInfo("obj1_can", "can", (), (0.2, 0.4, 0.06), (0.066, 0.066, 0.12)),
            ObjectInfo("obj2_can", "can", (), (-0.2, 0.4, 0.06), (0.066, 0.066, 0.12))]
    plan = RulePlanner().plan("grab the left can", cans, robot_yaw=1.5708)
    assert [c.text() for c in plan.calls] == ["grasp('obj2_can')"]
    with pytest.raises(InputError, match="ambiguous.*level"):  # facing +x both are equally far left
        RulePlanner().plan("grab the left can", cans)


def test_a_pushed_container_keeps_what_it_holds_checked() -> None:
    """Pushing the bowl after filling it carries the banana along: "inside" is still checked;
    moving the bowl by hand afterwards is not a state the command promised."""
    pushed = RulePlanner().plan("put the banana in the bowl, then push the bowl 5 cm left", CLUTTER)
    assert any(isinstance(g, Inside) for g in pushed.goals)
    lifted = RulePlanner().plan("put the banana in the bowl, then pick up the bowl", CLUTTER)
    assert not any(isinstance(g, Inside) for g in lifted.goals)


@pytest.mark.parametrize("sentence", [
    "don't put the banana in the bowl",
    "do not pick up the strawberry",
    "is the banana in the bowl?",
    "which can is closer?",
    "what is in the bowl",
    "put the banana 40 cm to the left of the bowl",
    "good afternoon, i'm having a lovely day",
])
def test_prohibitions_questions_and_places_too_far_are_refused(sentence: str) -> None:
    with pytest.raises(InputError):
        RulePlanner().plan(sentence, CLUTTER)


@pytest.mark.parametrize(("sentence", "kept"), [
    ("put the banana in the bowl, not the strawberry", "obj8_strawberry"),
    ("put the banana in the bowl but don't put the strawberry in it", "obj8_strawberry"),
    ("put the banana in the bowl and don't touch the left can", "obj1_soda_can"),
])
def test_what_is_not_to_be_done_keeps_its_object_still(sentence: str, kept: str) -> None:
    plan = RulePlanner().plan(sentence, CLUTTER)
    assert [c.text() for c in plan.calls] == ["place_in('obj7_banana', 'obj6_bowl')"]
    assert kept not in plan.program.split("\n", 1)[-1]


def test_objects_are_listed_by_the_colour_they_answer_to() -> None:
    from realsim.planner.reference import Resolver

    white_box = ObjectInfo("obj2_flat_white_box", "flat white box", (), (0.4, 0.1, 0.02), (0.2, 0.2, 0.05), "red")  # measured red, named white
    box = ObjectInfo("obj4_box", "box", (), (0.4, -0.2, 0.07), (0.13, 0.24, 0.15), "red")
    listing = Resolver([white_box, box]).listing()
    assert listing == "objects in the scene: obj2_flat_white_box (flat white box), obj4_box (red box)"


def test_a_locator_whose_landmark_is_ambiguous_is_decided_by_the_relation() -> None:
    from realsim.planner.rules import parse_calls

    objs = [ObjectInfo("obj2_flat_white_box", "flat white box", (), (0.4, 0.1, 0.025), (0.2, 0.2, 0.05), "white"),
            ObjectInfo("obj3_white_can", "white can", (), (0.4, 0.1, 0.1), (0.08, 0.08, 0.1), "white"),  # stands on the flat box
            ObjectInfo("obj4_red_box", "red box", (), (0.4, -0.25, 0.075), (0.13, 0.24, 0.15), "red"),
            ObjectInfo("obj5_red_can", "red can", (), (0.55, 0.35, 0.05), (0.07, 0.07, 0.1), "red")]
    for text in ("pick up the can that is on the box", "grab the can that's on the box", "lift the can on the box"):
        calls, _ = parse_calls(text, objs)
        assert [(c.name, c.args) for c in calls] == [("grasp", ("obj3_white_can",))], text


@pytest.mark.parametrize(("text", "call"), [
    ("tidy up by putting the mug into the bowl", ("place_in", ("obj1_mug", "obj2_bowl"))),  # the purpose is no object ("tidy" is not "tiny")
    ("could you help by putting the soup can in the bowl", ("place_in", ("obj3_soup_can", "obj2_bowl"))),
    ("hold the mug above the bowl", ("place_on", ("obj1_mug", "obj2_bowl"))),  # the head noun is the mug, never the bowl
])
def test_the_object_a_sentence_acts_on_is_the_one_it_names(text: str, call: tuple) -> None:
    from realsim.planner.rules import parse_calls

    calls, _ = parse_calls(text, OBJECTS)
    assert [(c.name, c.args) for c in calls] == [call]


def test_a_thing_located_above_or_under_another_is_found_by_that_relation() -> None:
    from realsim.planner.rules import parse_calls

    objs = [ObjectInfo("obj1_box", "box", (), (0.4, 0.1, 0.025), (0.2, 0.2, 0.05), "white"),
            ObjectInfo("obj2_can", "can", (), (0.4, 0.1, 0.1), (0.08, 0.08, 0.1), "red"),  # on the box
            ObjectInfo("obj3_can", "can", (), (0.55, 0.35, 0.05), (0.07, 0.07, 0.1), "blue")]
    assert [c.args for c in parse_calls("pick up the can above the box", objs)[0]] == [("obj2_can",)]
    assert [c.args for c in parse_calls("pick up the box under the can", objs)[0]] == [("obj1_box",)]


def test_a_wanted_container_is_the_one_the_noun_names_best() -> None:
    """"the white round dish" with a white mug and a white bowl: a dish is a bowl (a synonym) before
    a mug (a kind of dish); wanting a container lifts both alike, so it does not make them a tie."""
    objects = [ObjectInfo("obj1_mug", "mug", ("coffee mug", "cup with handle"), (0.45, 0.3, 0.05), (0.1, 0.08, 0.09), "white", ("graspable", "container")),
               ObjectInfo("obj2_bowl", "bowl", ("soup bowl",), (0.5, -0.05, 0.03), (0.15, 0.15, 0.06), "white", ("graspable", "container")),
               ObjectInfo("obj3_soda_can", "soda can", ("can",), (0.5, 0.45, 0.06), (0.066, 0.066, 0.12), "red")]
    assert call_lines("put the can in the white round dish", objects) == call_lines("put the can in the bowl", objects)


def test_with_a_part_describes_the_object_and_with_an_object_says_what_it_holds() -> None:
    """"the cup with the handle": a part the cup has (the mug's alias is "cup with handle"), never a
    second object; "the bowl with the banana": the bowl, never the banana."""
    objects = [ObjectInfo("obj1_mug", "mug", ("coffee mug", "cup with handle"), (0.45, 0.3, 0.05), (0.1, 0.08, 0.09), "white", ("graspable", "container")),
               ObjectInfo("obj2_bowl", "bowl", ("soup bowl",), (0.5, -0.05, 0.03), (0.15, 0.15, 0.06), "white", ("graspable", "container")),
               ObjectInfo("obj3_banana", "banana", (), (0.4, 0.0, 0.02), (0.2, 0.05, 0.04), "yellow")]
    assert call_lines("put the cup with the handle behind the bowl", objects) == call_lines("put the mug behind the bowl", objects)
    assert call_lines("pick up the bowl with the banana", objects) == ["grasp('obj2_bowl')"]
