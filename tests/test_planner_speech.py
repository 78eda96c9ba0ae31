"""Speech repairs: what the speaker took back is replaced, narration and fillers go."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER, call_lines

from realsim.errors import InputError
from realsim.planner import RulePlanner


@pytest.mark.parametrize(("sentence", "lines"), [
    ("banana in the mug no no in the bowl", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("put the strawberry in the bowl no sorry just pick up the banana", ["grasp('obj7_banana')"]),
    ("put the left can uh the right can in the bowl", ["place_in('obj2_soda_can', 'obj6_bowl')"]),
    ("now the robot will put the banana in the bowl", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("robot go home please", ["go_home()"]),
    ("bowl bowl push it forward", ["push('obj6_bowl', 'forward', 0.1)"]),
    ("put the banana like right next to the bowl", ["place_beside('obj7_banana', 'obj6_bowl', 'next')"]),
    ("please the red cube put on the blue cube", ["place_on('obj3_cube', 'obj4_cube')"]),
    ("push the banana back toward you uh five centimetres", ["push('obj7_banana', 'back', 0.05)"]),
    ("banana: push 5 cm left", ["push('obj7_banana', 'left', 0.05)"]),
    ("put the strawberry at the side of the bowl", ["place_beside('obj8_strawberry', 'obj6_bowl', 'next')"]),
    ("pick up the left can of soda", ["grasp('obj1_soda_can')"]),
    ("strawberry -> next to the banana", ["place_beside('obj8_strawberry', 'obj7_banana', 'next')"]),
    ("lift the bowl up bro lets gooo", ["grasp('obj6_bowl')"]),
])
def test_spoken_commands(sentence: str, lines: list[str]) -> None:
    assert [c.text() for c in RulePlanner().plan(sentence, CLUTTER).calls] == lines


def test_a_repair_that_could_replace_two_things_is_asked_about() -> None:
    with pytest.raises(InputError, match="either"):
        RulePlanner().plan("put the red cube on the blue cube no wait the green cube", CLUTTER)


def test_an_undo_keeps_what_it_undoes() -> None:
    """"..., actually no, take it out again": "it" is what was just put in, and the last word wins."""
    calls = [c.text() for c in RulePlanner().plan(
        "pick up the banana. put it in the bowl. actually no, take it out again and put it back exactly where it was", CLUTTER).calls]
    assert calls[0] == "grasp('obj7_banana')" and calls[-1] == "place('obj7_banana', [0.65, 0.0, 0.02])"


@pytest.mark.parametrize(("said", "plain"), [
    ("Put the banana behind the bowl, hmm, no, make that in front of it.", "put the banana in front of the bowl"),
    ("Okay, bowl to the left of the banana. Er, I said that backwards, I meant the banana to the left of the bowl.",
     "put the banana to the left of the bowl"),
    ("Could you put the strawberry in the bowl? Oh sorry, not the bowl, onto the blue cube.", "put the strawberry on the blue cube"),
    ("Take the strawberry and put it, uh, by the bowl. No, between the bowl and the banana.", "take the strawberry and put it between the bowl and the banana"),
])
def test_a_place_taken_back_and_said_again(said: str, plain: str) -> None:
    assert call_lines(said) == call_lines(plain)


@pytest.mark.parametrize(("said", "plain"), [
    # the place said again after the marker, its object carried over from the place it replaces
    ("Put the banana behind the bowl -- wait, no, in front of it.", "put the banana in front of the bowl"),
    ("Red cube to the left of the bowl. No, to the right, sorry.", "put the red cube to the right of the bowl"),
    ("Move the red cube 10 cm to the left. Sorry, I meant to the right.", "push the red cube 10 cm to the right"),  # a way, not a thing
    # only the object said anew: the amount and the direction the command said stay
    ("Push the red cube five centimetres to the left. Hang on, I meant the blue cube, not the red one.", "push the blue cube 5 cm to the left"),
    # "X I mean" after the phrase it repairs
    ("Move the right can, er, the left one I mean, over next to the bowl.", "put the left can next to the bowl"),
    # an amount corrected by a bare number keeps its unit; number words are amounts too
    ("Slide the banana forward ten centimetres, sorry, make that fifteen.", "push the banana forward 15 cm"),
])
def test_a_repair_replaces_only_what_it_says_again(said: str, plain: str) -> None:
    assert call_lines(said) == call_lines(plain)


@pytest.mark.parametrize(("said", "plain"), [
    ("put the strawberry next too the bowl", "put the strawberry next to the bowl"),  # dictation homophones
    ("move the strawberry so its next two the bowl", "put the strawberry next to the bowl"),
    ("pick up the blew cube", "pick up the blue cube"),
    ("pick up the banana than put it back were it was", "pick up the banana then put it back where it was"),
])
def test_words_speech_to_text_writes_for_others(said: str, plain: str) -> None:
    assert call_lines(said) == call_lines(plain)
