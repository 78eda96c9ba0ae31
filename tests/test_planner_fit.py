""""In Y" only for an open container Y the thing passes into; "in/at the <side> side of Y" is the
side relation. Sentences written for this test, not taken from a bench set."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER, call_lines

from realsim.errors import InputError
from realsim.planner import RulePlanner
from realsim.planner.types import ObjectInfo

MUG = ObjectInfo("obj9_mug", "mug", ("cup",), (0.35, -0.3, 0.05), (0.08, 0.08, 0.1), "blue", ("graspable", "container"))
SCENE = [*CLUTTER, MUG]


@pytest.mark.parametrize(("sentence", "line"), [
    ("set the strawberry in left side of the bowl", "place_beside('obj8_strawberry', 'obj6_bowl', 'left')"),
    ("could you put the banana in the right side of the mug", "place_beside('obj7_banana', 'obj9_mug', 'right')"),
    ("place the green cube at the right hand side of the banana", "place_beside('obj5_cube', 'obj7_banana', 'right')"),
    ("put the strawberry into the back side of the blue cube", "place_beside('obj8_strawberry', 'obj4_cube', 'behind')"),
    ("put the red cube on the front side of the bowl", "place_beside('obj3_cube', 'obj6_bowl', 'front')"),
])
def test_side_of_is_a_side(sentence: str, line: str) -> None:
    assert call_lines(sentence, SCENE)[-1] == line


@pytest.mark.parametrize("sentence", [
    "drop the strawberry in the mug",
    "put the green cube inside the bowl",
    "put the banana in the bowl",  # long, but narrow enough to go in
])
def test_fits_in_a_container(sentence: str) -> None:
    assert call_lines(sentence, SCENE)[-1].startswith("place_in(")


@pytest.mark.parametrize(("sentence", "reason"), [
    ("put the strawberry in the banana", "not an open container"),
    ("would you fit the green cube inside the left soda can?", "not an open container"),
    ("drop the banana into the blue cube", "not an open container"),
    ("put the bowl into the mug", "does not fit"),
    ("I'd like the bowl inside the mug please", "does not fit"),
])
def test_in_what_holds_nothing_or_too_small_is_refused(sentence: str, reason: str) -> None:
    with pytest.raises(InputError, match=reason):
        RulePlanner().plan(sentence, SCENE)


def test_a_drawer_holds_things() -> None:
    """A drawer is not an open container, but things go in it."""
    drawer = ObjectInfo("obj9_drawer", "drawer", (), (0.7, -0.4, 0.2), (0.4, 0.3, 0.15), None, ("drawer",))
    assert call_lines("put the strawberry in the drawer", [*CLUTTER, drawer]) == ["place_in('obj8_strawberry', 'obj9_drawer')"]
