"""Requests passed on by someone else, places said after a pause or ruled out, a hoped-for result,
short misspelled verbs, materials and footprint shapes, and "between the other two"
(realsim.planner.remarks, phrasing, purpose, typos, attributes; blind set heldout34's classes)."""

from __future__ import annotations

import pytest
from test_planner_rules import call_lines

from realsim.errors import InputError
from realsim.planner.types import ObjectInfo
from realsim.robot.grasps import footprint_widths, narrowest_width

KITCHEN = [
    ObjectInfo("obj1_soup_can", "tomato soup can", ("can",), (0.45, 0.20, 0.05), (0.068, 0.068, 0.10), "red", footprint=(0.068, 0.067)),
    # a flat tin turned 40 deg: its box is nearly square, its footprint is not
    ObjectInfo("obj2_meat_can", "potted meat can", ("can",), (0.45, -0.10, 0.04), (0.10, 0.091, 0.083), "blue", footprint=(0.10, 0.058)),
    ObjectInfo("obj3_cereal_box", "cereal box", ("box",), (0.60, 0.00, 0.11), (0.17, 0.07, 0.22), "orange", footprint=(0.17, 0.074)),
    ObjectInfo("obj4_mug", "mug", ("cup",), (0.40, 0.35, 0.05), (0.11, 0.08, 0.09), "white", ("graspable", "container")),
]


@pytest.mark.parametrize(("sentence", "lines"), [
    # a request passed on: the relay's opening is not the request
    ("Dana asked me to pass this on: the strawberry should be next to the bowl.", ["place_beside('obj8_strawberry', 'obj6_bowl', 'next')"]),
    ("Coach told me to tell you to put the red cube on the blue cube.", ["place_on('obj3_cube', 'obj4_cube')"]),
    ("My flatmate says the banana keeps rolling around -- she wants it in the bowl.", ["place_in('obj7_banana', 'obj6_bowl')"]),
    # where it goes, said after a pause; a vague way the place makes exact
    ("put the strawberry, in front of the bowl", ["place_beside('obj8_strawberry', 'obj6_bowl', 'front')"]),
    ("the strawberry: down closer to me, in front of the bowl.", ["place_beside('obj8_strawberry', 'obj6_bowl', 'front')"]),
    # a place ruled out beside the place meant; a contrast set off by commas; a hoped-for result
    ("the strawberry should be behind the bowl, not out in the open.", ["place_beside('obj8_strawberry', 'obj6_bowl', 'behind')"]),
    ("the bowl is fine where it is; the strawberry, though, belongs on its left.", ["place_beside('obj8_strawberry', 'obj6_bowl', 'left')"]),
    ("the strawberry is lonely so put it by the banana and then they can be friends", ["place_beside('obj8_strawberry', 'obj7_banana', 'next')"]),
    ("set the strawberry down on the table where it's safe", ["place_down('obj8_strawberry')"]),
    # a short misspelled verb in the verb's slot
    ("pik up the banana", ["grasp('obj7_banana')"]),
    ("mve the banana left 5cm", ["push('obj7_banana'"]),
    ("See the strawberry? Push it 5 cm toward yourself.", ["push('obj8_strawberry', 'back', 0.05)"]),  # "see" is no misspelled "set"
    # brands said for the thing; "leave X" said alone; a caution about how; a dog's "heel"; a stage's "upstage of"
    ("put the Chiquita in the bowl", ["place_in('obj7_banana', 'obj6_bowl')"]),
    ("No, not the bowl, leave the bowl. Get the strawberry, and drop it next to the banana.", ["place_beside('obj8_strawberry', 'obj7_banana', 'next')"]),
    ("pick up the banana -- easy, don't squash it -- and set it down in front of the bowl", ["place_beside('obj7_banana', 'obj6_bowl', 'front')"]),
    ("get the strawberry, drop it right beside the bowl, and then heel.", ["go_home()"]),
    ("put the strawberry upstage of the bowl", ["place_beside('obj8_strawberry', 'obj6_bowl', 'behind')"]),
    ("put the strawberry at the back of the bowl", ["place_beside('obj8_strawberry', 'obj6_bowl', 'behind')"]),  # beside the stage words, kept
    # what people let a thing do; breathing cues; how far, said after a pause
    ("take the strawberry, let it float across, and allow it to settle on the green cube.", ["place_on('obj8_strawberry', 'obj5_cube')"]),
    ("lift the strawberry gently... and let it come to rest inside the bowl.", ["place_in('obj8_strawberry', 'obj6_bowl')"]),
    ("Breathe in... and on the out-breath, ease the banana to the right, five centimetres.", ["push('obj7_banana', 'right', 0.05)"]),
    ("let the banana drift back towards you -- three inches or so", ["push('obj7_banana', 'back', 0.076)"]),
    # a thing addressed and told to leave, to take another's place, where its entrance is; the thing meant after "leave X"
    ("Banana, you're not in this scene. Exit -- clear off somewhere out of the way.", ["place('obj7_banana', [0.65, 0.15"]),
    ("Strawberry, you exit first, off to the side. Then the banana takes the strawberry's old mark.", ["place('obj8_strawberry'", "place('obj7_banana', [0.25, 0.3, "]),
    ("Banana, your entrance is between the bowl and the strawberry. Places, everyone!", ["place_between('obj7_banana', 'obj6_bowl', 'obj8_strawberry')"]),
    ("Leave the bowl. Leave it! Strawberry instead -- get it, and hold it up high.", ["grasp('obj8_strawberry')"]),
    # where a thing addressed goes; the arm sent to standby; the ship's computer addressed; a phone call's asides
    ("Strawberry, strawberry, so red and bright, go sit in the bowl.", ["place_in('obj8_strawberry', 'obj6_bowl')"]),
    ("Computer, take the banana and set it on the table, then return the arm to standby position.", ["place_down('obj7_banana')", "go_home()"]),
    ("Hold on, Mum. Banana, slide it left about three inches. Okay, carry on.", ["push('obj7_banana', 'left', 0.076)"]),
    # "the blocks in a line with X between ...", "between the other two"
    ("I want the blocks in a line with the green one sitting between the red cube and the blue cube.", ["place_between('obj5_cube', 'obj3_cube', 'obj4_cube')"]),
    ("put the red cube between the other two", ["place_between('obj3_cube', 'obj4_cube', 'obj5_cube')"]),
])
def test_relayed_and_padded_requests(sentence: str, lines: list[str]) -> None:
    got = call_lines(sentence)
    for line in lines:
        assert any(g.startswith(line) for g in got), (sentence, got)


def test_no_place_is_lent_on_from_what_the_robot_cannot_do() -> None:
    with pytest.raises(InputError, match="cannot"):  # "be daring" never became a thing put into the bowl
        call_lines("the banana is ripe, or so I've been told; pour it into the bowl, be daring and bold.")


def test_hold_on_is_only_an_aside_to_a_person() -> None:
    with pytest.raises(InputError):  # "hold on, not the banana, the apple": a repair to a thing the scene lacks, never the banana
        call_lines("Drop the banana in the bowl -- hold on, not the banana, the apple.")


def test_where_a_thing_comes_from_is_never_the_thing() -> None:
    with pytest.raises(InputError, match="no object matches"):  # the strawberry is not on the green cube: never the cube put down
        call_lines("The strawberry. Off the green cube, down on the table. Good.")


def test_after_that_keeps_the_order_said() -> None:
    got = call_lines("lift the banana, and after that push the green cube 3 cm forward.")
    assert got.index(next(g for g in got if g.startswith("grasp('obj7_banana')"))) < got.index(next(g for g in got if g.startswith("push('obj5_cube'")))
    got = call_lines("push the green cube 3 cm forward afterwards, first lift the banana")
    assert got[0].startswith("grasp('obj7_banana')")


@pytest.mark.parametrize(("sentence", "name"), [
    ("pick up the cardboard one", "obj3_cereal_box"),  # a material the kind is usually made of
    ("pick up the metal one on the right", "obj2_meat_can"),
    ("pick up the rectangular can", "obj2_meat_can"),  # the footprint, however the tin is turned
    ("pick up the round can", "obj1_soup_can"),
])
def test_materials_and_footprint_shapes_pick_one(sentence: str, name: str) -> None:
    assert call_lines(sentence, KITCHEN)[0] == f"grasp('{name}')"


def test_footprint_is_the_turned_length_and_narrowest_width() -> None:
    rng = __import__("numpy").random.default_rng(0)
    np = __import__("numpy")
    box = rng.uniform([-0.05, -0.029, 0.0], [0.05, 0.029, 0.08], (4000, 3))
    c, s = np.cos(0.7), np.sin(0.7)
    turned = box @ np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]).T
    length, width = footprint_widths(turned)
    assert length == pytest.approx(0.10, abs=0.004) and width == pytest.approx(0.058, abs=0.002)
    assert narrowest_width(turned) == width
