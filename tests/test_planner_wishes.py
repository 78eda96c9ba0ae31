"""Requests said as wishes, chat spelling, lift heights, the object said before "you", and
courtesy around a command (realsim.planner.wishes and realsim.planner.phrasing)."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER, call_lines

from realsim.errors import InputError
from realsim.planner import RulePlanner
from realsim.planner.wishes import as_request


@pytest.mark.parametrize(("said", "meant"), [
    ("it would be nice if the banana were sitting next to the bowl", "put the banana next to the bowl"),
    ("it'd be lovely if the red cube was on the blue cube", "put the red cube on the blue cube"),
    ("i'd like the green cube stacked neatly on top of the blue cube", "put the green cube on top of the blue cube"),
    ("i was kind of hoping the strawberry could end up in the bowl", "put the strawberry in the bowl"),
    ("i should very much like the banana to be set beside the bowl", "put the banana beside the bowl"),
])
def test_a_wish_for_a_place_is_a_request_to_put_it_there(said: str, meant: str) -> None:
    assert as_request(said) == meant


def test_a_wish_without_a_place_is_left_alone() -> None:
    assert as_request("i'd like the banana please") == "i'd like the banana please"


@pytest.mark.parametrize(("sentence", "plain"), [
    ("It would be great if the strawberry were in the bowl, if that's not too much trouble.", "put the strawberry in the bowl"),
    ("I'd love the red cube placed on the green cube, if you could manage it. Thank you, young robot!", "put the red cube on the green cube"),
    ("pls mov teh banana 2in fwd thx", "push the banana forward 2 inches"),
    ("cn u swp teh banana n teh strawberry", "swap the banana and the strawberry"),
    ("grab the banana and hold it up really high!!", "lift the banana"),
    ("take the strawberry and make it go up in the air, and hold.", "lift the strawberry"),
    ("Would you mind terribly lifting the banana up off the table for a moment?", "lift the banana"),
    ("The strawberry, you must to put him at beside of the bowl.", "put the strawberry beside the bowl"),
    ("Green cube, you are sliding it to left side 4 centimetre.", "push the green cube left 4 cm"),
    ("the banana you are pushing 30 millimetre to forward", "push the banana forward 3 cm"),
    ("put the strawberry in the bowl, then park the arm", "put the strawberry in the bowl, then go home"),
    ("Class, watch the arm: it is going to pick up the banana.", "pick up the banana"),
    ("Now students, the robot will put the strawberry in the bowl.", "put the strawberry in the bowl"),
    ("Everyone look here: the arm is now going to push the banana 5 cm to the left.", "push the banana left 5 cm"),
    ("Alright class, the robot will push the bowl 4 cm farther away from itself.", "push the bowl forward 4 cm"),
    ("When it's finished, the strawberry should be sitting in the bowl.", "put the strawberry in the bowl"),
    ("The way I'd like it: the strawberry sitting in the bowl.", "put the strawberry in the bowl"),
    ("What I'm after is the banana lying next to the bowl.", "put the banana next to the bowl"),
    ("I'd like the red cube resting on the table instead of on top of the blue cube.", "put the red cube on the table"),
])
def test_sentences_as_people_type_them(sentence: str, plain: str) -> None:
    assert call_lines(sentence) == call_lines(plain)


@pytest.mark.parametrize("sentence", [
    "it would be nice if the can were in the bowl",  # two cans: which?
    "i'd like the apple on the blue cube",  # no apple
    "pls mov teh can 2in fwd",
])
def test_a_wish_or_chat_spelling_never_guesses_an_object(sentence: str) -> None:
    with pytest.raises(InputError):
        RulePlanner().plan(sentence, CLUTTER)


@pytest.mark.parametrize(("sentence", "plain"), [
    ("I'd rather the banana were behind the bowl.", "put the banana behind the bowl"),
    ("The banana is about to fall. I'd feel better with it over to the left of the bowl.", "put the banana to the left of the bowl"),
    ("I'd be ever so grateful if the strawberry found its way into the bowl.", "put the strawberry in the bowl"),
])
def test_wishes_said_as_feelings(sentence: str, plain: str) -> None:
    assert call_lines(sentence) == call_lines(plain)
