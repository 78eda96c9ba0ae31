"""Talk around a command (greetings, thanks, hedges, exhortations), numbered step lists, things
named by where they are ("way over on the left", "right up front", a fronted topic taken up by
"it"), and a choice among named things ("whichever is closer, A or B"). Sentences written for
this test on the generated clutter scene, not taken from a bench set."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER, call_lines

from realsim.errors import InputError
from realsim.planner import RulePlanner
from realsim.planner.discourse import drop_talk, steps_as_clauses
from realsim.planner.types import ObjectInfo


def calls(sentence: str) -> list[str]:
    return [c.text() for c in RulePlanner().plan(sentence, CLUTTER).calls]


@pytest.mark.parametrize(("sentence", "lines"), [
    # talk: whole sentences and comma pieces of greetings, thanks, politeness and hedges
    ("Good morning, robot. Put the banana in the bowl, if you please. Much obliged.", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("hiya mate, put the red cube on the blue cube. cheers, you're a star", ["place_on('obj3_cube', 'obj4_cube')"]),
    ("Put the strawberry in the bowl. If not, no worries.", ["place_in('obj8_strawberry', 'obj6_bowl')"]),
    ("Banana in the bowl. Now. Go!", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("put the banana in the bowl, come on!", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("Might I trouble you to lift the banana? And afterwards do go back home. Thank you kindly.", ["grasp('obj7_banana')", "go_home()"]),
    ("yo grab the strawberry ez", ["grasp('obj8_strawberry')"]),
    # numbered steps
    ("1) pick up the banana 2) put it in the bowl 3) go home", ["grasp('obj7_banana')", "place_in('obj7_banana', 'obj6_bowl')", "go_home()"]),
    ("Step 1: push the banana 10 cm left. Step 2: go home.", ["push('obj7_banana', 'left', 0.1)", "go_home()"]),
    ("Step one, lift the strawberry. Step two, put it next to the bowl.",
     ["grasp('obj8_strawberry')", "place_beside('obj8_strawberry', 'obj6_bowl', 'next')"]),
    # objects named by place, and a fronted topic that "it" takes up
    ("the thing way over on the left, push it 5 cm forward", ["push('obj8_strawberry', 'forward', 0.05)"]),
    ("the can way over on the right, put it in the bowl", ["place_in('obj2_soda_can', 'obj6_bowl')"]),
    ("the thing closest to you, put it next to the banana", ["place_beside('obj8_strawberry', 'obj7_banana', 'next')"]),
    ("the cube right behind the bowl, push it 5 cm left", ["push('obj4_cube', 'left', 0.05)"]),
    # a choice among named things
    ("pick up whichever is further from you, the banana or the strawberry", ["grasp('obj7_banana')"]),
    ("of the bowl and the banana, lift the one closer to you", ["grasp('obj6_bowl')"]),
    ("the banana or the strawberry, whichever is closer, put it in the bowl", ["place_in('obj8_strawberry', 'obj6_bowl')"]),
])
def test_read_right(sentence: str, lines: list[str]) -> None:
    assert calls(sentence) == lines


@pytest.mark.parametrize("sentence", [
    "Put the strawberry in the bowl. If not, put it next to the bowl.",  # a condition is never dropped
    "Hello there. Thank you so much.",  # talk alone
    "the can at the very front, lift it",  # the two cans are level
    "lift the can right up front on the left",  # not first both ways
])
def test_refused(sentence: str) -> None:
    with pytest.raises(InputError):
        calls(sentence)


def test_talk_never_takes_a_word_that_names_something() -> None:
    assert drop_talk("thanks, the mug. cheers.") == "the mug."
    assert drop_talk("thank you, to the left.") == "to the left."
    assert drop_talk("okay, 10 cm.") == "10 cm."
    assert drop_talk("hello. thanks!") == "hello. thanks!"  # nothing else: left for the planner to refuse


def test_a_step_list_counts_up_from_one() -> None:
    assert steps_as_clauses("1. lift the mug 2. go home") == "lift the mug, then go home"
    assert steps_as_clauses("push the mug 10. then go home") == "push the mug 10. then go home"  # a distance, not a step
    assert steps_as_clauses("push it 2. then 3. home") == "push it 2. then 3. home"


@pytest.mark.parametrize(("sentence", "lines"), [
    # "not X, Y": Y replaces what the command named, or only confirms it
    ("put the green cube behind the bowl? not the blue one, the green", ["place_beside('obj5_cube', 'obj6_bowl', 'behind')"]),
    ("put the blue cube on the bowl, no, not the blue one, the red one", ["place_on('obj3_cube', 'obj6_bowl')"]),
    ("put the banana next to the bowl. not in it, just beside it", ["place_beside('obj7_banana', 'obj6_bowl', 'next')"]),
    ("put the banana in the bowl, not in it, behind it", ["place_beside('obj7_banana', 'obj6_bowl', 'behind')"]),
    # remarks and times after a command that has its place; holding on; "while you're at it"; "after"
    ("put the strawberry next to the bowl, they go together", ["place_beside('obj8_strawberry', 'obj6_bowl', 'next')"]),
    ("put the banana behind the bowl before it falls off, thanks", ["place_beside('obj7_banana', 'obj6_bowl', 'behind')"]),
    ("put the banana in the bowl, I'm making a smoothie later", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("lift the banana and keep holding it until I say so", ["grasp('obj7_banana')"]),
    ("put the banana in the bowl while you're at it", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("lift the banana. Oh, and go home after.", ["grasp('obj7_banana')", "go_home()"]),
])
def test_clarifications_and_remarks(sentence: str, lines: list[str]) -> None:
    assert calls(sentence) == lines


@pytest.mark.parametrize("sentence", [
    "put the red cube on the blue cube, not the green one, the yellow one",  # neither named nor agreeing: asked
    "push the banana toward the bowl until it sits next to the strawberry",  # a time that names a place is never dropped
])
def test_unclear_clarifications_refused(sentence: str) -> None:
    with pytest.raises(InputError):
        calls(sentence)


def test_the_scenes_own_name_with_another_generic_noun() -> None:
    """"the big white thing" is the scene's "big white object", not the biggest white thing."""
    objs = [ObjectInfo("obj1_big_white_object", "big white object", (), (0.4, 0.0, 0.03), (0.05, 0.05, 0.05)),
            ObjectInfo("obj2_white_box", "white box", (), (0.4, 0.2, 0.05), (0.2, 0.1, 0.1))]
    assert [c.text() for c in RulePlanner().plan("pick up the big white thing", objs).calls] == ["grasp('obj1_big_white_object')"]


@pytest.mark.parametrize(("sentence", "lines"), [
    # word enumerators and bracketed numbers are step marks, never an ordinal naming an object
    ("Two steps: first, lift the banana; second, put it next to the bowl.", ["grasp('obj7_banana')", "place_beside('obj7_banana', 'obj6_bowl', 'next')"]),
    ("(1) push the banana 5 cm left (2) go home", ["push('obj7_banana', 'left', 0.05)", "go_home()"]),
    # a thing and its place as two pieces; a terse lift, said twice, is one lift
    ("Red cube, on the blue cube. Green one, next to it.", ["place_on('obj3_cube', 'obj4_cube')", "place_beside('obj5_cube', 'obj3_cube', 'next')"]),
    ("Banana. Up. Lift it.", ["grasp('obj7_banana')"]),
    # a remark after a take; a reason never swallows the clause after it
    ("grab the strawberry, my daughter wants it", ["grasp('obj8_strawberry')"]),
    ("put the banana in the bowl because it is ripe, then go home", ["place_in('obj7_banana', 'obj6_bowl')", "go_home()"]),
])
def test_terse_pieces_and_enumerators(sentence: str, lines: list[str]) -> None:
    assert calls(sentence) == lines


@pytest.mark.parametrize(("sentence", "lines"), [
    # a position said as a comparative in a topic or a choice is the extreme it picks, never a push
    ("the can further left, put it in the bowl", ["place_in('obj1_soda_can', 'obj6_bowl')"]),
    ("the one further forward, the bowl or the banana, lift it", ["grasp('obj6_bowl')"]),
    ("whatever is closest to the banana, pick it up", ["grasp('obj4_cube')"]),
    ("which ever is further away, the banana or the strawberry, put it in the bowl", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("of the bowl and the banana, grab whichever is closer to you", ["grasp('obj6_bowl')"]),
    # the pick among the things named, its way said after it ("the one closer to me" is never the one nearest of all)
    ("of the bowl and the banana, push the one closer to me 3 cm left", ["push('obj6_bowl', 'left', 0.03)"]),
    ("whichever of the banana and the strawberry is further from me, push that one forward 4 cm", ["push('obj7_banana', 'forward', 0.04)"]),
    ("Between the bowl and the banana, the one that's closer to me should get pushed 5 cm to the right.", ["push('obj6_bowl', 'right', 0.05)"]),
    ("Whichever is closer to you, the bowl or the banana, that one goes behind the green cube.", ["place_beside('obj6_bowl', 'obj5_cube', 'behind')"]),
    # "there's X ... it", "there are two Xs ... the one ..."
    ("there's a banana on the table. put it in the bowl", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("There are two soda cans. Put the one further right in the bowl.", ["place_in('obj2_soda_can', 'obj6_bowl')"]),
    # more talk: closings, praise, "oh"
    ("Hi! So, um, could you lift the banana for me? That'd be great, thanks! Have a nice day!", ["grasp('obj7_banana')"]),
    ("lift the strawberry. oh also, go home after that. Cheers, legend!", ["grasp('obj8_strawberry')", "go_home()"]),
])
def test_comparatives_existentials_and_closings(sentence: str, lines: list[str]) -> None:
    assert calls(sentence) == lines


def test_the_big_one_in_a_locator_is_of_the_kind_just_named() -> None:
    """"take the small box off the big one": the big box it stands on, never the biggest thing of all."""
    stacked = [ObjectInfo("obj1_box", "box", (), (0.5, 0.0, 0.10), (0.06, 0.06, 0.04), "white"),
               ObjectInfo("obj2_box", "box", (), (0.5, 0.0, 0.04), (0.2, 0.2, 0.08), "white", ("graspable", "support")),
               ObjectInfo("obj3_crate", "crate", (), (0.5, 0.35, 0.1), (0.3, 0.3, 0.2), "red", ("graspable", "support"))]
    assert [c.text() for c in RulePlanner().plan("take the small box off the big one", stacked).calls] == ["grasp('obj1_box')"]


def test_two_things_wished_swapped_are_swapped() -> None:
    assert calls("I'd like the banana and the strawberry to have traded places.") == calls("swap the banana and the strawberry")


def test_an_existential_of_several_is_asked() -> None:
    with pytest.raises(InputError):
        calls("there's a soda can on the table. put it in the bowl")  # two soda cans: which?


@pytest.mark.parametrize(("sentence", "lines"), [
    # a question before a command is talk; the one thing it names is what "it" means next
    ("why is the banana over there? put it in the bowl", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("honestly who leaves cubes everywhere. put the green one behind the bowl", ["place_beside('obj5_cube', 'obj6_bowl', 'behind')"]),
    # a wish, then "give it to me": one lift
    ("i want the strawberry. give it to me", ["grasp('obj8_strawberry')"]),
])
def test_questions_and_wishes_before_a_command(sentence: str, lines: list[str]) -> None:
    assert calls(sentence) == lines


def test_a_question_alone_is_refused() -> None:
    with pytest.raises(InputError, match="question"):
        calls("why is the banana over there?")


@pytest.mark.parametrize(("sentence", "lines"), [
    ("heyyy can u put the banana in the bowl?? thx bestie", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("right, first thing: lift the banana. second thing: go home.", ["grasp('obj7_banana')", "go_home()"]),
    ("a) push the bowl 5 cm left b) go home", ["push('obj6_bowl', 'left', 0.05)", "go_home()"]),
    ("To do: 1) banana in the bowl 2) home", ["place_in('obj7_banana', 'obj6_bowl')", "go_home()"]),
    ("put the banana in the bowl. and then, um, go home i guess", ["place_in('obj7_banana', 'obj6_bowl')", "go_home()"]),
    ("could you put the strawberry in the bowl? if it's too hard, no worries", ["place_in('obj8_strawberry', 'obj6_bowl')"]),
    ("Red cube on the blue cube. Done.", ["place_on('obj3_cube', 'obj4_cube')"]),
    # "not X" alone or across a full stop
    ("put the green cube next to the bowl, not on top of it", ["place_beside('obj5_cube', 'obj6_bowl', 'next')"]),
    ("lift the banana. not the strawberry! the banana.", ["grasp('obj7_banana')"]),
])
def test_more_talk_lists_and_clarifications(sentence: str, lines: list[str]) -> None:
    assert calls(sentence) == lines


@pytest.mark.parametrize("sentence", [
    "put the green cube on the bowl, not on top of it",  # the place it says not: asked
    "put the banana in the bowl. if it's full, put it next to the bowl",  # a condition with a command is kept, and unread
])
def test_contradictions_refused(sentence: str) -> None:
    with pytest.raises(InputError):
        calls(sentence)


@pytest.mark.parametrize(("sentence", "lines"), [
    # "further/more" before a way says more of that way (it had pushed away from the robot)
    ("move the strawberry further left", ["push('obj8_strawberry', 'left', 0.1)"]),
    ("slide the banana a bit further to the right", ["push('obj7_banana', 'right', 0.05)"]),
    # a comparative position before a place says which one; a comparison of a listed pair
    ("put the can further left on the bowl", ["place_on('obj1_soda_can', 'obj6_bowl')"]),
    ("of the red and green cubes, put the one further right in the bowl", ["place_in('obj5_cube', 'obj6_bowl')"]),
    ("pick up the bigger of the bowl and the strawberry", ["grasp('obj6_bowl')"]),
])
def test_comparatives_of_position_and_pairs(sentence: str, lines: list[str]) -> None:
    assert calls(sentence) == lines


@pytest.mark.parametrize(("sentence", "lines"), [
    # "after" before a bare verb is "then" (it had run the home move first); "after picking ..." still orders
    ("put the strawberry in the bowl, after go home", ["place_in('obj8_strawberry', 'obj6_bowl')", "go_home()"]),
    ("go home after you put the banana in the bowl", ["place_in('obj7_banana', 'obj6_bowl')", "go_home()"]),
    # chat words that had made a clause an aside, silently dropped
    ("alright listen up first grab the strawberry then drop it in the bowl then go home thats it",
     ["grasp('obj8_strawberry')", "place_in('obj8_strawberry', 'obj6_bowl')", "go_home()"]),
    ("basically put the banana in the bowl and then like go home or whatever", ["place_in('obj7_banana', 'obj6_bowl')", "go_home()"]),
    # a corrected amount replaces the one said
    ("Move the bowl 10 cm to the left. Oh wait, make it 5 cm.", ["push('obj6_bowl', 'left', 0.05)"]),
])
def test_order_chat_and_corrected_amounts(sentence: str, lines: list[str]) -> None:
    assert calls(sentence) == lines


def test_an_amount_correcting_nothing_is_asked() -> None:
    with pytest.raises(InputError):
        calls("put the banana in the bowl. oh wait, make it 5 cm")


@pytest.mark.parametrize("sentence", [
    "Step 1: lift the teapot. Step 2: go home.",  # a command about a thing the scene lacks was skipped as talk: go home alone
    "lift the teapot then go home",
])
def test_a_command_on_a_missing_thing_is_refused_not_skipped(sentence: str) -> None:
    with pytest.raises(InputError, match="teapot"):
        calls(sentence)


def test_a_vague_amount_after_a_command_stays_talk() -> None:
    assert calls("put the banana in front of the bowl, a little closer to you") == ["place_beside('obj7_banana', 'obj6_bowl', 'front')"]
    assert calls("there's a banana on the table. put it in the bowl, would ya") == ["place_in('obj7_banana', 'obj6_bowl')"]


def test_the_same_place_said_again() -> None:
    assert calls("Green cube in the bowl! Blue one too, same bowl!") == ["place_in('obj5_cube', 'obj6_bowl')", "place_in('obj4_cube', 'obj6_bowl')"]
    assert calls("put the banana in the bowl, then the strawberry, same place") == [
        "place_in('obj7_banana', 'obj6_bowl')", "place_in('obj8_strawberry', 'obj6_bowl')"]


def test_a_contracted_is_makes_a_statement() -> None:
    """"the banana's in the way, move it ...": a statement naming what "it" means, not a thing called "banana in the way"."""
    assert calls("the banana's in the way, move it next to the strawberry") == ["place_beside('obj7_banana', 'obj8_strawberry', 'next')"]
    assert calls("the bowl's dirty. push it 5 cm left") == ["push('obj6_bowl', 'left', 0.05)"]


@pytest.mark.parametrize(("said", "plain"), [
    ("Three things: red cube in the bowl, blue cube next to the bowl, then go home.",
     "put the red cube in the bowl, put the blue cube next to the bowl, go home"),
    ("Stack the red cube on the blue one, edges lined up, no overhang.", "put the red cube on the blue cube"),
    ("Set the strawberry next to the bowl, nice and square.", "put the strawberry next to the bowl"),
    ("Kick the banana over 2 cm to the left.", "push the banana 2 cm to the left"),
    ("Sink the strawberry in the bowl.", "put the strawberry in the bowl"),
])
def test_how_neatly_and_a_count_of_steps_are_talk(said: str, plain: str) -> None:
    assert call_lines(said) == call_lines(plain)
