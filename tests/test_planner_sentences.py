"""A message read one sentence at a time (realsim.planner.sentences, realsim.planner.mentions):
talk around the command is skipped or says what "it" means; a request that cannot be done is
never skipped. Also end states said as wishes, time frames and adverbs before the verb."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER, call_lines

from realsim.errors import InputError
from realsim.planner import RulePlanner
from realsim.planner.mentions import mentioned
from realsim.planner.sentences import is_question, is_request, split_sentences
from realsim.planner.steps import Parser


def test_sentences_end_at_stops_marks_colons_and_ellipses_but_not_decimals() -> None:
    assert split_sentences("Ugh. Move it 2.5 cm left! Why? Fine: go... now") == ["ugh.", "move it 2.5 cm left!", "why?", "fine:", "go...", "now"]


@pytest.mark.parametrize(("sentence", "asks"), [
    ("Pour the soup into the bowl.", True),  # a verb the planner lacks is still a request on a thing of the scene
    ("Smash that like button.", False),
    ("Put the banana away, thanks.", True),
    ("We're back, chat!", False),
    ("For the last time:", False),
    ("Someone said it can't be done.", False),
    ("Prove them wrong.", False),  # a verb on people, not on a thing
])
def test_a_request_begins_with_a_verb(sentence: str, asks: bool) -> None:
    assert is_request(sentence, {"soup", "bowl", "banana"}) is asks


def test_the_first_thing_named_and_those_joined_to_it_are_mentioned() -> None:
    p = Parser(CLUTTER)
    assert [o.name for o in mentioned("mm, the banana, the yellow one, i keep forgetting it", p)] == ["obj7_banana"]
    assert [o.name for o in mentioned("someone bet the strawberry and the banana can't trade", p)] == ["obj8_strawberry", "obj7_banana"]
    assert [o.name for o in mentioned("look at the strawberry, over there by the bowl", p)] == ["obj8_strawberry"]
    assert mentioned("the cube, you know", p) == []  # three cubes: no one thing named


@pytest.mark.parametrize(("message", "plain"), [
    ("Hi chat, we're live! Put the strawberry in the bowl. Smash that like button.", "put the strawberry in the bowl"),
    ("Okay. The banana. Yeah, the yellow one. Push it 3 cm to the left.", "push the banana left 3 cm"),
    ("Somebody said the strawberry and the banana can't trade spots. Swap 'em.", "swap the strawberry and the banana"),
    ("Third time now. The blue cube goes on the plate... I mean on the green cube. Thanks.", "put the blue cube on the green cube"),
    ("There's a strawberry near you. See it? Lift it.", "lift the strawberry"),
])
def test_talk_between_sentences_is_skipped(message: str, plain: str) -> None:
    assert call_lines(message) == call_lines(plain)


@pytest.mark.parametrize("message", [
    "We're live, chat! Pour the strawberry into the bowl.",  # a request it cannot do
    "Hello there. Lift the teapot. Thanks!",  # a thing the scene lacks
    "We're back. Nice weather today.",  # nothing asked at all
])
def test_a_request_it_cannot_do_is_never_skipped(message: str) -> None:
    with pytest.raises(InputError):
        RulePlanner().plan(message, CLUTTER)


def test_a_sentence_skipped_leaves_nothing_behind() -> None:
    """A sentence that fails half-way does not leave its half-read objects as "it"."""
    assert call_lines("Look at the banana, over by the cans. Lift it.") == call_lines("lift the banana")


@pytest.mark.parametrize(("said", "plain"), [
    ("The strawberry really belongs next to the bowl.", "put the strawberry next to the bowl"),
    ("When I get back I'd like to find the banana sitting behind the bowl.", "put the banana behind the bowl"),
    ("By the end of this, the strawberry should be standing in front of the bowl.", "put the strawberry in front of the bowl"),
    ("Ideally the banana would have been pushed about five centimetres to the left.", "push the banana left 5 cm"),
    ("It'd be great if the strawberry and the banana had traded places by now.", "swap the strawberry and the banana"),
    ("The strawberry shouldn't be sitting there; it belongs down on the table.", "put the strawberry on the table"),
])
def test_an_end_state_said_as_a_wish_is_its_request(said: str, plain: str) -> None:
    assert call_lines(said) == call_lines(plain)


def test_a_time_clause_is_not_a_question() -> None:
    assert not is_question("When you're done I'd like the mug in the bowl")
    assert is_question("when is the mug going in the bowl?")
    assert is_question("where is the mug")


@pytest.mark.parametrize(("command", "why"), [
    ("pour the strawberry into the bowl", "cannot pour"),  # never read as the nearest known verb
    ("please peel the banana", "cannot peel"),
    ("open the bowl", "does not open"),  # only drawers and doors open
])
def test_what_no_primitive_does_is_refused_by_name(command: str, why: str) -> None:
    with pytest.raises(InputError, match=why):
        RulePlanner().plan(command, CLUTTER)


@pytest.mark.parametrize(("said", "plain"), [
    ("Slide the banana left a bit, three-ish centimetres should do it.", "push the banana left 3 cm"),
    ("The banana wants to go a little more to the right, say a couple of centimetres.", "push the banana right 2 cm"),
    ("The strawberry, could it come toward me by roughly two centimetres?", "push the strawberry back 2 cm"),
    ("Por favor, la banana... put it next to the bowl, gracias!", "put the banana next to the bowl"),
    ("S'il vous plaît, lift the strawberry. Merci beaucoup!", "lift the strawberry"),
    ("strawberry <-> banana", "swap the strawberry and the banana"),
    ("1) strawberry in bowl 2) arm home", "put the strawberry in the bowl, then go home"),
    ("The banana is in the way, move it somewhere else.", "move the banana out of the way"),
    ("clear away banana", "move the banana out of the way"),
    ("strawberry left side of bowl", "put the strawberry to the left of the bowl"),
])
def test_amounts_asides_and_other_tongues(said: str, plain: str) -> None:
    assert call_lines(said) == call_lines(plain)


@pytest.mark.parametrize(("message", "plain"), [
    ("Ugh. Strawberry. In the bowl. IN it. Come on.", "put the strawberry in the bowl"),
    ("Tell me which cube is green. Right! Park that one to the right of the bowl.", "put the green cube to the right of the bowl"),
    ("Banana's in the way. It's in the way, move it somewhere else.", "move the banana out of the way"),
    ("I'd like the banana an inch further away from me.", "push the banana forward 1 inch"),
    ("A couple of centimetres closer to me with the strawberry, please.", "push the strawberry back 2 cm"),
])
def test_a_place_alone_a_quiz_and_an_amount_said_around_the_thing(message: str, plain: str) -> None:
    assert call_lines(message) == call_lines(plain)


def test_a_thing_named_by_its_nearness_before_a_command_is_a_topic_not_a_push() -> None:
    two = [o for o in CLUTTER if o.name in ("obj6_bowl", "obj7_banana")]
    assert call_lines("the thing closer to you, put it in front of the other one", two) == call_lines(
        "put the bowl in front of the banana", two)


def test_talk_between_commas_is_skipped_when_the_sentence_does_not_read() -> None:
    assert call_lines("Gosh, this is probably silly to ask, but could you nudge the banana 2 cm to the left? Totally fine if not.") == call_lines(
        "push the banana 2 cm to the left")
    with pytest.raises(InputError):  # a phrase asking for what cannot be done is still never skipped
        RulePlanner().plan("Gosh, sorry to ask, but could you pour the strawberry into the bowl?", CLUTTER)


@pytest.mark.parametrize(("message", "plain"), [
    ("Gosh, this is a silly thing to ask, but would it be at all possible to nudge the banana 2 cm to the left? Totally fine if not.",
     "push the banana 2 cm to the left"),
    ("Sorry, sorry, last thing: would it be terribly inconvenient to lift the strawberry?", "lift the strawberry"),
    ("I hate to be a pain, honestly I do, but I was hoping you might put the strawberry in the bowl.", "put the strawberry in the bowl"),
])
def test_the_request_a_hedge_leads_up_to(message: str, plain: str) -> None:
    assert call_lines(message) == call_lines(plain)


@pytest.mark.parametrize(("said", "plain"), [
    ("The strawberry and the banana have quarrelled. Let them trade places.", "swap the strawberry and the banana"),
    ("have the strawberry go in the bowl", "put the strawberry in the bowl"),
    ("get the banana to sit behind the bowl", "put the banana behind the bowl"),
    ("lift the strawberry, then let the arm return to its resting place", "lift the strawberry, then go home"),
])
def test_what_people_have_a_thing_do_is_the_request(said: str, plain: str) -> None:
    assert call_lines(said) == call_lines(plain)


@pytest.mark.parametrize(("said", "plain"), [
    ("I'm so sorry to bother you, I really am, but I don't suppose the strawberry could end up somewhere to the left of the bowl? "
     "Only if it's no trouble at all.", "put the strawberry to the left of the bowl"),
    ("Totally your call, of course, and I don't want to be difficult, but I'd sort of love it if the banana were sitting behind the bowl?",
     "put the banana behind the bowl"),
    ("If it's not too much of an imposition, and do feel free to say no, might the banana perhaps be moved so it sits right beside the bowl?",
     "put the banana next to the bowl"),
    ("You probably have more important things to do, but I'd be ever so grateful if the bowl found its way in front of the banana.",
     "put the bowl in front of the banana"),
    ("It bugs me that the banana is stuck out at the back and the strawberry is off on the left; they'd look better the other way round. Swap them.",
     "swap the banana and the strawberry"),
    ("The two soda cans are crammed together. Swap them.", "swap the two soda cans"),
])
def test_politeness_and_complaints_around_a_request(said: str, plain: str) -> None:
    assert call_lines(said) == call_lines(plain)
