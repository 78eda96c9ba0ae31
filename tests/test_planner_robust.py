"""Phrasings no bench sentence was tuned for: restarts after "scratch that", an engineer's
units and tolerances, and misspelled colours and names (each class with sentences of its own)."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER, call_lines

from realsim.errors import InputError
from realsim.planner import RulePlanner
from realsim.planner.types import ObjectInfo
from realsim.planner.typos import correct, distance


@pytest.mark.parametrize(("sentence", "lines"), [
    # a restart after a cancellation: only the new command
    ("lift the green cube, no wait, scratch that, lift the strawberry and hold it", ["grasp('obj8_strawberry')"]),
    ("put the banana on the red cube. forget that, put the banana in the bowl", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("slide the red cube -- sorry, the blue cube -- slide the blue cube to the left by 4 cm", ["push('obj4_cube', 'left', 0.04)"]),
    ("put the strawberry, no, the banana, i mean the banana, put it behind the bowl", ["place_beside('obj7_banana', 'obj6_bowl', 'behind')"]),
    ("pick up the red cube, or rather, the green cube", ["grasp('obj5_cube')"]),
    # a new request said to be in the old one's place: the old one is not done ("take it out again" would undo it)
    ("pick up the strawberry, actually no, just push it 3 cm left", ["push('obj8_strawberry', 'left', 0.03)"]),
    ("lift the banana. no wait, slide it left 3 cm instead", ["push('obj7_banana', 'left', 0.03)"]),
])
def test_restarted_commands(sentence: str, lines: list[str]) -> None:
    assert call_lines(sentence) == lines


@pytest.mark.parametrize(("sentence", "lines"), [
    ("Displace the strawberry 3 in toward the robot base.", ["push('obj8_strawberry', 'back', 0.076)"]),
    ("Reposition the green cube ~60 mm in -y, no rotation.", ["push('obj5_cube', 'right', 0.06)"]),
    ("translate the banana 2 in (approx. 5 cm) forward w.r.t. the robot frame", ["push('obj7_banana', 'forward', 0.051)"]),
    ("Place the strawberry directly left of the bowl, ca. 90 mm centre to centre.", ["place_beside('obj8_strawberry', 'obj6_bowl', 'left')"]),
    ("set the banana at the midpoint of the red cube and the green cube, ± 5 mm", ["place_between('obj7_banana', 'obj3_cube', 'obj5_cube')"]),
    ("put the banana 2 in the bowl", ["place_in('obj7_banana', 'obj6_bowl')"]),  # "in" followed by a thing: no inches
    ("move the blue cube 5 cm left, then send the arm back to its rest configuration", ["push('obj4_cube', 'left', 0.05)", "go_home()"]),
])
def test_engineering_phrasing(sentence: str, lines: list[str]) -> None:
    assert call_lines(sentence) == lines


@pytest.mark.parametrize(("sentence", "lines"), [
    ("lift the bleu cube", ["grasp('obj4_cube')"]),
    ("put the geen cube in the bowl", ["place_in('obj5_cube', 'obj6_bowl')"]),
    ("drop the strawbery next to the banan", ["place_beside('obj8_strawberry', 'obj7_banana', 'next')"]),
    ("put the bananas in the bwol", ["place_in('obj7_banana', 'obj6_bowl')"]),
])
def test_misspellings(sentence: str, lines: list[str]) -> None:
    assert call_lines(sentence) == lines


@pytest.mark.parametrize("sentence", [
    "lift the gren cube",  # green or grey: one letter from each, so asked
    "lift the fat cube",  # three letters: never changed (fat, far)
])
def test_unsure_spellings_are_asked(sentence: str) -> None:
    with pytest.raises(InputError, match="ambiguous|no .*object"):
        RulePlanner().plan(sentence, CLUTTER)


def test_distance_and_bound() -> None:
    assert distance("bule", "blue") == 1 and distance("read", "red") == 1 and distance("bowl", "bowl") == 0
    assert correct("yelow", ["yellow", "blue"]) == "yellow"
    assert correct("gren", ["green", "grey"]) is None  # two as near
    assert correct("cans", ["can"]) is None  # a plural is no typo
    assert correct("grab", ["gray"], known=["grab"]) is None  # a known word stays
    assert correct("lfet", ["left", "let"]) == "left"  # as near as "let", but with the word's own letters
    assert correct("lfet", ["lift", "loft"]) is None


@pytest.mark.parametrize(("sentence", "lines"), [
    ("if the strawberry is not in the bowl, put it in the bowl", ["place_in('obj8_strawberry', 'obj6_bowl')"]),
    ("if the strawberry fits in the bowl put it in there otherwise set it beside the bowl", ["place_in('obj8_strawberry', 'obj6_bowl')"]),
    ("If the banana fits into the bowl, drop it in there; if it doesn't, put it behind the bowl.", ["place_beside('obj7_banana', 'obj6_bowl', 'behind')"]),
    ("if the blue cube is behind the bowl then pick up the bowl", ["grasp('obj6_bowl')"]),
    ("if the blue cube is still sitting behind the bowl, pick up the bowl", ["grasp('obj6_bowl')"]),  # a posture said in the condition
    ("if the blue cube is behind the bowl, lift the banana and put it on the green cube",
     ["grasp('obj7_banana')", "place_on('obj7_banana', 'obj5_cube')"]),
    ("if there's a cube behind the strawberry, push it left", ["push('obj3_cube', 'left', 0.1)"]),  # the branch names its own "it"
    ("if you don't mind, put the banana in the bowl", ["place_in('obj7_banana', 'obj6_bowl')"]),  # politeness, no condition
])
def test_conditions_are_checked_on_the_scene(sentence: str, lines: list[str]) -> None:
    assert call_lines(sentence) == lines


@pytest.mark.parametrize(("sentence", "reason"), [
    ("if the banana is in the bowl, take it out", "does not hold"),  # false, no otherwise: nothing is done
    ("if there's a cube in front of the strawberry, push it left", "does not hold"),
    ("if the banana is ripe, put it in the bowl", "cannot check"),  # a condition it cannot check is refused
])
def test_false_or_unreadable_conditions_do_nothing(sentence: str, reason: str) -> None:
    with pytest.raises(InputError, match=reason):
        RulePlanner().plan(sentence, CLUTTER)


@pytest.mark.parametrize(("sentence", "lines"), [
    ("Put the strawberry by the bowl. My husband keeps knocking it over.", ["place_beside('obj8_strawberry', 'obj6_bowl', 'next')"]),
    ("lift the banana, the kids think it's a phone", ["grasp('obj7_banana')"]),
    ("Push the green cube 3 cm left. They're tidying up later.", ["push('obj5_cube', 'left', 0.03)"]),
    ("Watch this, the robot can pick up the strawberry. Can you pick it up for us?", ["grasp('obj8_strawberry')"]),
    ("my boss wants you to put the banana on the blue cube", ["place_on('obj7_banana', 'obj4_cube')"]),  # a request through her
    # a person's sentence that names a place by a thing is a request, kept
    ("put the strawberry in the bowl. we need the banana behind the bowl too",
     ["place_in('obj8_strawberry', 'obj6_bowl')", "place_beside('obj7_banana', 'obj6_bowl', 'behind')"]),
])
def test_remarks_about_people_are_talk(sentence: str, lines: list[str]) -> None:
    assert call_lines(sentence) == lines


def test_a_remark_alone_is_no_command() -> None:
    with pytest.raises(InputError):
        RulePlanner().plan("my daughter likes the banana", CLUTTER)


@pytest.mark.parametrize(("sentence", "lines"), [
    ("whichever cube is closer to the bowl, put it on the banana", ["place_on('obj4_cube', 'obj7_banana')"]),
    ("whichever can is further from the bowl, lift that one", ["grasp('obj1_soda_can')"]),
    ("Banana. 10 cm right.", ["push('obj7_banana', 'right', 0.1)"]),
    ("Blue cube. Left, 5 cm.", ["push('obj4_cube', 'left', 0.05)"]),
])
def test_relation_picks_and_terse_ways(sentence: str, lines: list[str]) -> None:
    assert call_lines(sentence) == lines


def test_a_way_after_a_placing_is_not_taken_as_the_same_place() -> None:
    """"..., then strawberry, left 3 cm": never "put the strawberry in the bowl" with the way dropped."""
    with pytest.raises(InputError):
        RulePlanner().plan("put the banana in the bowl, then strawberry, left 3 cm", CLUTTER)


_HELD = [o if o.name != "obj8_strawberry" else type(o)(o.name, o.label, o.aliases, (0.30, 0.0, 0.03), o.size, o.color) for o in CLUTTER]


def test_the_container_with_a_thing_is_the_one_holding_it() -> None:
    plan = RulePlanner().plan("put the banana in the bowl with the strawberry", _HELD)
    assert [c.text() for c in plan.calls] == ["place_in('obj7_banana', 'obj6_bowl')"]


@pytest.mark.parametrize("sentence", ["put the banana in the bowl with the strawberry", "put banana in bowl w/ strawberry"])
def test_a_thing_with_what_it_does_not_hold_is_asked_about(sentence: str) -> None:
    """Never the strawberry as the target (it was before: 'the bowl with the strawberry' named it)."""
    with pytest.raises(InputError, match="holds"):
        RulePlanner().plan(sentence, CLUTTER)


@pytest.mark.parametrize(("sentence", "lines"), [
    ("pls set the strawberry nxt 2 the banana", ["place_beside('obj8_strawberry', 'obj7_banana', 'next')"]),
    ("cn u put the green cube b4 the bowl thx", ["place_beside('obj5_cube', 'obj6_bowl', 'front')"]),
    ("Place the red cube before the strawberry.", ["place_beside('obj3_cube', 'obj8_strawberry', 'front')"]),
    ("lift the banana before you go home", ["grasp('obj7_banana')", "go_home()"]),  # a time, not a place
    ("It'd be lovely if the strawberry were in the bowl.", ["place_in('obj8_strawberry', 'obj6_bowl')"]),
    ("the green cube needs the banana on it", ["place_on('obj7_banana', 'obj5_cube')"]),
    ("would be perfect if the strawberry sat behind the bowl", ["place_beside('obj8_strawberry', 'obj6_bowl', 'behind')"]),
])
def test_texting_and_indirect_requests(sentence: str, lines: list[str]) -> None:
    assert call_lines(sentence) == lines


@pytest.mark.parametrize(("sentence", "lines"), [
    ("pikc up the strawberry", ["grasp('obj8_strawberry')"]),
    ("set the banana besdie the bowl", ["place_beside('obj7_banana', 'obj6_bowl', 'next')"]),
    ("put the strawberry ontop of the blue cube", ["place_on('obj8_strawberry', 'obj4_cube')"]),
    ("shvoe the green cube rihgt 2 cm", ["push('obj5_cube', 'right', 0.02)"]),
    ("shove the strawberry to the lfet 3 cm", ["push('obj8_strawberry', 'left', 0.03)"]),  # "left", not "let": its own letters swapped
    ("put the banana on the rigth side of the bowl", ["place_beside('obj7_banana', 'obj6_bowl', 'right')"]),  # a side's slot: beside, not on
    ("grab the blue thign and put it in the bowl", ["grasp('obj4_cube')", "place_in('obj4_cube', 'obj6_bowl')"]),
])
def test_misspelled_command_words(sentence: str, lines: list[str]) -> None:
    assert call_lines(sentence) == lines


def test_a_misspelled_swap_is_read() -> None:
    assert call_lines("swpa the banana and the strawberry")[-2:] == call_lines("swap the banana and the strawberry")[-2:]


def test_a_scene_word_is_never_respelled_into_a_command_word() -> None:
    """"plate" is one letter from "place": with no plate in the scene it is refused, not read as a verb."""
    with pytest.raises(InputError, match="plate"):
        RulePlanner().plan("put the banana on the plate", CLUTTER)


@pytest.mark.parametrize(("sentence", "lines"), [
    ("put the strawberry on the -- actually, behind the bowl", ["place_beside('obj8_strawberry', 'obj6_bowl', 'behind')"]),
    ("Blue cube into the bowl... no wait, next to the bowl, not in it.", ["place_beside('obj4_cube', 'obj6_bowl', 'next')"]),
    ("put the banana in the bowl, not on it", ["place_in('obj7_banana', 'obj6_bowl')"]),
])
def test_interrupted_places(sentence: str, lines: list[str]) -> None:
    assert call_lines(sentence) == lines


def test_in_it_is_never_a_thing_that_holds_nothing() -> None:
    """"..., we want the strawberry in it too": the bowl just placed by, never the banana."""
    assert call_lines("put the banana next to the bowl, we want the strawberry in it too") == [
        "place_beside('obj7_banana', 'obj6_bowl', 'next')", "place_in('obj8_strawberry', 'obj6_bowl')"]
    with pytest.raises(InputError, match="holds nothing"):
        RulePlanner().plan("lift the banana and put the strawberry in it", CLUTTER)


@pytest.mark.parametrize(("sentence", "lines"), [
    ("if the bowl is empty, lift it; otherwise put the banana in it", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("if the bowl isn't empty, drop the banana next to it", ["place_beside('obj7_banana', 'obj6_bowl', 'next')"]),
])
def test_empty_conditions(sentence: str, lines: list[str]) -> None:
    assert [c.text() for c in RulePlanner().plan(sentence, _HELD).calls] == lines


TWO_CANS = [
    ObjectInfo("obj1_can", "can", (), (0.40, 0.10, 0.06), (0.05, 0.05, 0.12), "white"),
    ObjectInfo("obj2_can", "can", (), (0.40, -0.10, 0.06), (0.08, 0.08, 0.12), "white"),
    ObjectInfo("obj3_box", "box", (), (0.55, 0.0, 0.03), (0.12, 0.2, 0.06), "red"),
]


@pytest.mark.parametrize(("sentence", "lines"), [
    ("lift the skinny can", ["grasp('obj1_can')"]),  # the narrower footprint
    ("lift the fatter can", ["grasp('obj2_can')"]),
    ("lift the thinnest white thing", ["grasp('obj1_can')"]),
    ("lift the pale slim can", ["grasp('obj1_can')"]),  # "pale" alone: whitish
])
def test_width_and_pale_words(sentence: str, lines: list[str]) -> None:
    assert call_lines(sentence, TWO_CANS) == lines


def test_a_shade_only_qualifies_its_colour() -> None:
    assert call_lines("lift the pale yellow banana") == call_lines("lift the yellow banana")
    assert call_lines("lift the dark-red cube") == ["grasp('obj3_cube')"]
