"""Voices the planner had not heard: radio procedure (realsim.planner.radio), a thing singled out
before it is acted on (realsim.planner.focus), a purpose before the request
(realsim.planner.purpose), an office email (realsim.planner.formal), an engineer's names for the
primitives (realsim.planner.technical), a drill sergeant, an unsure speaker asking, spoken
fractions and trade units, chat shorthand, comparisons among all the scene holds, and mock-archaic
English and pirate talk (realsim.planner.voices)."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER, call_lines

from realsim.errors import InputError
from realsim.planner import RulePlanner
from realsim.planner.focus import singled_out
from realsim.planner.formal import formal
from realsim.planner.purpose import purpose
from realsim.planner.radio import radio
from realsim.planner.types import ObjectInfo
from realsim.planner.voices import plain


def test_radio_procedure_and_call_signs_go_only_in_a_radio_call() -> None:
    assert radio("kitchen to robot, over. put the banana in the bowl. how copy? over.") == "put the banana in the bowl."
    assert radio("this is the bowl, put the banana in it") == "this is the bowl, put the banana in it"  # no procedure word: not a call
    assert radio("this is the bowl, over. put the banana in it") == "this is the bowl, put the banana in it"  # names a thing: kept


@pytest.mark.parametrize(("said", "meant"), [
    ("not the banana, the strawberry: put that in the bowl.", "dont touch the banana. put the strawberry in the bowl."),
    ("leave the bowl alone, it's the banana i'm after: lift it.", "leave the bowl alone. lift the banana."),
    ("only the strawberry, and push it 3 cm left.", "push the strawberry 3 cm left."),
    ("everything else stays put except the banana: slide it forward.", "slide the banana forward."),
    ("don't pick up the bowl; nudge it 2 cm back.", "nudge the bowl 2 cm back."),
    ("leave the bowl and the banana be, lift the strawberry", "dont touch the bowl and dont touch the banana, lift the strawberry"),
])
def test_a_thing_singled_out_is_the_one_acted_on(said: str, meant: str) -> None:
    assert singled_out(said) == meant


def test_a_ban_on_lifting_stays_a_ban_without_a_push() -> None:
    assert singled_out("don't lift the bowl.") == "don't lift the bowl."


@pytest.mark.parametrize(("said", "meant"), [
    ("i'm baking later, so the banana should go next to the bowl.", "the banana should go next to the bowl."),
    ("i want to film the bowl, so the banana has to go somewhere else.", "put the banana aside."),
    ("i'm about to put my cup down where the strawberry is, so move it out of the way", "move the strawberry out of the way"),
    ("we need the space, so the strawberry can't stay where it is.", "put the strawberry aside."),
])
def test_a_purpose_leads_to_its_request(said: str, meant: str) -> None:
    assert purpose(said) == meant


@pytest.mark.parametrize(("said", "meant"), [
    ("please be advised that the banana needs to be moved into the bowl. kind regards, ann", "put the banana into the bowl."),
    ("as agreed on monday, kindly ensure the strawberry is placed next to the bowl. thanks in advance.", "put the strawberry next to the bowl."),
    ("further to our call, we must ask that the green cube be relocated onto the plate.", "put the green cube onto the plate."),
    ("i would be grateful if the banana could be set behind the bowl, after which the arm should return home.", "put the banana behind the bowl, then return home."),
])
def test_an_email_is_its_request(said: str, meant: str) -> None:
    assert formal(said) == meant


@pytest.mark.parametrize("said", ["the banana is in the bowl", "is the banana in the bowl?", "the mug should be in the bowl"])
def test_a_statement_or_question_is_never_made_a_request_by_the_email_rules(said: str) -> None:
    assert formal(said) == said


def test_a_statement_ending_in_so_is_not_a_purpose() -> None:
    assert purpose("put the banana in the bowl so i can see it") == "put the banana in the bowl"


@pytest.mark.parametrize(("sentence", "plain"), [
    ("Station two to robot, come in. Put the banana in the bowl. Over and out.", "put the banana in the bowl"),
    ("Robot, Kim here, over. Lift the strawberry. Copy?", "lift the strawberry"),
    ("Tuck the banana in behind the bowl.", "put the banana behind the bowl"),
    ("Look, see the strawberry? The robot's gonna put it in the bowl.", "put the strawberry in the bowl"),  # told to someone else
    ("Base to arm, stand by for tasking... banana into the bowl, then return to home position. Over and out.", "put the banana in the bowl, then go home"),
    ("Execute a grasp on the banana, place pose inside the bowl, then return to nominal.", "pick up the banana, put it in the bowl, then go home"),
    ("Grasp target is the strawberry. Place pose on the -y side of the bowl.", "pick up the strawberry, put it to the right of the bowl"),
    ("Pick the strawberry; place pose 6 cm in -x from the bowl.", "pick up the strawberry, put it in front of the bowl"),
    ("Of the two soda cans, take the one with the larger y coordinate.", "pick up the left soda can"),
    ("The bowl exceeds the gripper aperture, so no grasp: push it 4 cm along +y.", "push the bowl left 4 cm"),
    ("Not the banana, the strawberry: put it in the bowl.", "put the strawberry in the bowl"),
    ("Don't touch the red or the blue cube; only the green one: lift it.", "lift the green cube"),
    ("I'm making a smoothie later, so I'd like the strawberry next to the banana where I can reach it.", "put the strawberry next to the banana"),
    ("I want to photograph the bowl, so the banana has to go out of the way.", "put the banana aside"),
    ("Fancy popping the strawberry into the bowl? Lovely, cheers.", "put the strawberry in the bowl"),
    ("That banana's a bit of a lump, so just shove it 3 cm to the left.", "push the banana left 3 cm"),
    ("green cube ontop blu 1 thx", "put the green cube on the blue cube"),
    ("strawberry 2 teh left 5cm", "push the strawberry left 5 cm"),
    ("Kindly be advised that the strawberry needs to be relocated into the bowl. Regards, Facilities", "put the strawberry in the bowl"),
    ("Per my last message, please arrange for the banana to be placed behind the bowl. Many thanks.", "put the banana behind the bowl"),
    ("Strawberry! Two and a half centimetres to the left! Hustle! Don't make me repeat myself!", "push the strawberry left 2.5 cm"),
    ("Banana, over by the bowl, on the double! Then back to home position!", "put the banana next to the bowl, then go home"),
    ("Is there any way the strawberry could end up in the bowl?", "put the strawberry in the bowl"),
    ("Could the green cube perhaps go on the blue cube? I think that would look nicer.", "put the green cube on the blue cube"),
    ("The banana needs to come back ten mil, nearer the robot.", "push the banana back 1 cm"),
    ("Scoot the strawberry three quarters of an inch to the right.", "push the strawberry right 0.75 inch"),
    ("Banana, a hand's width forward. Call it ten centimetres.", "push the banana forward 10 cm"),
    ("Put the strawberry in the bowl, then the banana next to the bowl, and finish by going back home.", "put the strawberry in the bowl, put the banana next to the bowl, then go home"),
    ("Step 1: Locate the banana. Step 2: Place it behind the bowl. Step 3: Return the arm to its home position.", "put the banana behind the bowl, then go home"),
    ("Ensure that the strawberry is placed adjacent to the bowl. Caution: the red cube must remain in its current position.", "put the strawberry next to the bowl"),
    ("Step 1: Remove the strawberry. Step 2: Set it down on the table surface, wherever there is clearance.", "pick up the strawberry, put it on the table"),
    ("Put the banana in front of the dish you'd eat your cereal from.", "put the banana in front of the bowl"),
    ("Swap the red cube and the green cube, and once that's done put the strawberry in the bowl.", "swap the red cube and the green cube, then put the strawberry in the bowl"),
])
def test_voices_the_planner_had_not_heard(sentence: str, plain: str) -> None:
    assert call_lines(sentence) == call_lines(plain)


def test_the_smaller_of_the_two_when_the_scene_holds_two() -> None:
    two = [o for o in CLUTTER if o.name in ("obj6_bowl", "obj8_strawberry")]
    assert call_lines("put the smaller of the two into the bigger one", two) == call_lines("put the strawberry in the bowl", two)
    with pytest.raises(InputError):  # eight things: which two is for the speaker to say
        RulePlanner().plan("put the smaller of the two into the bowl", CLUTTER)


def test_one_after_a_thing_named_by_its_place_means_any_thing() -> None:
    """"the second object from the left ... the rightmost one": "one" is any object, not "left"."""
    assert call_lines("put the second object from the left next to the rightmost one") == call_lines(
        "put the second object from the left next to the rightmost object")


def test_everything_is_still_refused_when_the_singled_out_thing_is_missing() -> None:
    with pytest.raises(InputError):
        RulePlanner().plan("not the banana, the apple: put that in the bowl", CLUTTER)




def test_nearest_you_is_the_nearest_to_the_robot_base_when_it_is_known() -> None:
    """A thing just ahead of the base is nearer than one a little less far forward but off to the side."""
    ahead = ObjectInfo("obj1_cube", "cube", ("block",), (0.40, 0.0, 0.03), (0.05, 0.05, 0.05), "red", ("graspable", "support"))
    aside = ObjectInfo("obj2_cube", "cube", ("block",), (0.35, 0.40, 0.03), (0.05, 0.05, 0.05), "blue", ("graspable", "support"))
    plan = RulePlanner().plan("pick up the cube nearest you", [ahead, aside], robot_yaw=0.0, robot_base=(0.0, 0.0))
    assert plan.calls is not None and plan.calls.acted_on() == ["obj1_cube"]
    far = RulePlanner().plan("pick up the cube farthest from you", [ahead, aside], robot_yaw=0.0, robot_base=(0.0, 0.0))
    assert far.calls is not None and far.calls.acted_on() == ["obj2_cube"]
    # without the base, "nearest" is along the robot's forward axis
    plain = RulePlanner().plan("pick up the cube nearest you", [ahead, aside], robot_yaw=0.0)
    assert plain.calls is not None and plain.calls.acted_on() == ["obj2_cube"]


def test_things_as_far_from_the_base_are_told_apart_by_their_depth() -> None:
    """Two cans 71 cm from the base, one 8 cm further ahead: "the one further away" is that one."""
    near = ObjectInfo("obj1_soda_can", "soda can", ("can",), (0.47, 0.53, 0.06), (0.066, 0.066, 0.12), "red")
    ahead = ObjectInfo("obj2_soda_can", "soda can", ("can",), (0.55, 0.45, 0.06), (0.066, 0.066, 0.12), "red")
    plan = RulePlanner().plan("pick up the soda can that is further away", [near, ahead], robot_yaw=0.0, robot_base=(0.0, 0.0))
    assert plan.calls is not None and plan.calls.acted_on() == ["obj2_soda_can"]


def test_a_thing_named_alone_before_a_command_about_it_is_what_it_means() -> None:
    assert singled_out("they have three hearts, did you know that. anyway. the banana. can you put it in the bowl") == (
        "they have three hearts, did you know that. anyway. can you put the banana in the bowl")
    assert call_lines("so I was watching a documentary, octopuses have three hearts... anyway. The strawberry. Can you put it in the bowl please") == (
        call_lines("put the strawberry in the bowl"))


def test_a_direction_alone_after_a_thing_is_no_push() -> None:
    """"the cubes, right, ...": "right" is talk; only a way with how far ("forward ten cm") is a push."""
    with pytest.raises(InputError):
        RulePlanner().plan("okay so the cubes, right, where was I", CLUTTER)


def test_talk_glued_to_a_command_is_dropped_but_a_named_thing_never_is() -> None:
    assert call_lines("chat, watch this. okay robot, lift the banana. LET'S GOOO") == call_lines("lift the banana")
    assert call_lines("chat, watch this: put the strawberry in the bowl. let's gooo") == call_lines("put the strawberry in the bowl")
    assert call_lines("lift the banana, then let go") == call_lines("lift the banana, then open the gripper")  # "let go" is still a command
    assert call_lines("hype moment chat, hype moment. robot: the strawberry goes in the bowl. prove them wrong") == (
        call_lines("put the strawberry in the bowl"))
    with pytest.raises(InputError):  # "and the apple": a thing the scene lacks is refused, never dropped as talk
        RulePlanner().plan("put the strawberry in the bowl and the apple", CLUTTER)


@pytest.mark.parametrize(("said", "expected"), [
    ("prithee, set thou yon mug upon the plate", "please, set that mug on the plate"),
    ("the can standeth too near unto thee", "the can stands too near to you"),
    ("hark! lift the banana", "lift the banana"),
    ("put the green cube betwixt the red cube and the blue cube, an it please thee", "put the green cube between the red cube and the blue cube, please"),
    ("haul the can o' soup to port o' the bowl an' be quick", "haul the can of soup to port of the bowl and be quick"),
    ("them cans be mutinyin', arr!", "them cans be mutinyin'!"),
    ("put the mug beneath the lamp at seven o'clock", "put the mug beneath the lamp at seven o'clock"),  # nothing archaic: unchanged
])
def test_old_and_pirate_word_forms_become_plain(said: str, expected: str) -> None:
    assert plain(said) == expected


@pytest.mark.parametrize(("said", "plain_said"), [
    ("Prithee, good arm, set thou the strawberry within the bowl.", "put the strawberry in the bowl"),
    ("Hearken: thou shalt place the banana betwixt the green cube and the blue cube, an it please thee.",
     "put the banana between the green cube and the blue cube"),
    ("Lo, the strawberry upon the left doth vex me. Remove it from my path.", "move the strawberry out of the way"),
    ("Yo ho, matey, haul the banana round to port o' the bowl an' be quick about it!", "put the banana to the left of the bowl"),
    ("Arr, them two soda cans be mutinyin'! Make 'em trade places, port for starboard!", "swap the two soda cans"),
    ("Verily, the banana standeth too near. Push it forth some four centimetres, I beseech thee.", "push the banana forward 4 cm"),
])
def test_a_playful_voice_asks_what_the_plain_words_ask(said: str, plain_said: str) -> None:
    assert call_lines(said) == call_lines(plain_said)


@pytest.mark.parametrize(("said", "plain_said"), [
    ("Och, gie yon wee green cube a shove tae the left, aboot five centimetres like.", "push the green cube 5 cm to the left"),
    ("Cannae see a thing past that banana, shift it oot the road, would ye?", "move the banana out of the way"),
    ("Well I'll be, that banana's plumb in the way. Carry it on over behind the bowl, would ya?", "put the banana behind the bowl"),
    ("yo toss the strawberry in the bowl no cap", "put the strawberry in the bowl"),
    ("lowkey the strawberry needs to be chillin next to the banana fr fr", "put the strawberry next to the banana"),
    ("Translate the banana 5 cm along the base frame's negative x axis, i.e. toward the robot.", "push the banana back 5 cm"),
    ("Displace the strawberry laterally by 0.04 m in the robot's negative y direction.", "push the strawberry 4 cm to the right"),
    ("Apply a planar displacement of +4 cm along the y axis to the banana.", "push the banana 4 cm to the left"),
    ("Relocate the strawberry to a position posterior to the bowl.", "put the strawberry behind the bowl"),
    ("Elevate the blue cube off the tabletop surface and maintain the grasp.", "lift the blue cube"),
    ("Transpose the positions of the banana and the strawberry.", "swap the banana and the strawberry"),
])
def test_regional_slang_and_technical_voices(said: str, plain_said: str) -> None:
    assert call_lines(said) == call_lines(plain_said)
