"""The words of a noun phrase that name the thing (realsim.planner.core_noun)."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER, call_lines

from realsim.errors import InputError
from realsim.planner import RulePlanner
from realsim.planner.core_noun import core_words
from realsim.planner.types import ObjectInfo

SCENE_WORDS = {"soda", "can", "cube", "bowl", "banana", "strawberry", "cereal", "box"}


@pytest.mark.parametrize(("words", "core"), [
    (["omg", "cereal", "box", "is"], ["cereal", "box"]),
    (["rn"], []),  # chat shorthand alone: the colour and size words say which
    (["banana", "aloft", "mine", "eyes", "may", "behold", "it"], ["banana"]),
    (["yellow", "lemon"], None),  # a lemon is a thing of its own: never "the yellow" one
    (["lemon", "bowl"], None),
    (["banana", "by", "strawberry"], None),  # two runs: no single core
    (["banana"], None),  # the whole phrase: nothing to drop
    (["teapot"], None),
])
def test_the_core_is_the_one_run_the_scene_names(words: list[str], core: list[str] | None) -> None:
    assert core_words(words, SCENE_WORDS) == core


def test_talk_around_a_name_is_dropped_and_an_absent_thing_is_still_refused() -> None:
    assert call_lines("omg that banana is in the way of everything, move it outta the way") == call_lines("move the banana out of the way")
    assert call_lines("can u stack the red cube on the blue one rn") == call_lines("put the red cube on the blue cube")
    for absent in ("put the yellow lemon in the bowl", "lift the teapot rn"):
        with pytest.raises(InputError):
            RulePlanner().plan(absent, CLUTTER)


def test_colours_of_two_tones_and_of_a_products_usual_packaging() -> None:
    tins = [ObjectInfo("obj1_tomato_soup_can", "tomato soup can", ("can",), (0.4, 0.1, 0.05), (0.066, 0.066, 0.1)),
            ObjectInfo("obj2_potted_meat_can", "potted meat can", ("can",), (0.4, -0.1, 0.04), (0.1, 0.06, 0.08)),
            ObjectInfo("obj3_bowl", "bowl", (), (0.5, 0.0, 0.03), (0.16, 0.16, 0.06), None, ("graspable", "container"))]
    assert call_lines("put the blue tin in the bowl", tins) == ["place_in('obj2_potted_meat_can', 'obj3_bowl')"]
    assert call_lines("put the red and white can in the bowl", tins) == ["place_in('obj1_tomato_soup_can', 'obj3_bowl')"]
    assert call_lines("put the red-and-white can in the bowl", tins) == ["place_in('obj1_tomato_soup_can', 'obj3_bowl')"]
    with pytest.raises(InputError):
        RulePlanner().plan("put the green tin in the bowl", tins)


def test_a_clause_after_the_name_is_never_dropped_as_talk() -> None:
    assert core_words(["bowl", "until", "it", "sits"], SCENE_WORDS) is None
    assert core_words(["banana", "not", "strawberry"], SCENE_WORDS) is None
    assert core_words(["banana", "40", "cm"], SCENE_WORDS) is None
    assert core_words(["banana", "two", "inches"], SCENE_WORDS) is None
    assert core_words(["balance", "banana", "upside"], SCENE_WORDS) is None  # an unknown verb before the name


@pytest.mark.parametrize(("said", "plain"), [
    ("put the fake plastic strawberry in the empty bowl", "put the strawberry in the bowl"),  # what the scene cannot check
    ("put le cube rouge in the bowl s'il te plait", "put the red cube in the bowl"),  # mixed-in articles and colours
    ("put the cube verde in the bowl", "put the green cube in the bowl"),
])
def test_words_the_scene_cannot_check_and_mixed_in_languages(said: str, plain: str) -> None:
    assert call_lines(said) == call_lines(plain)
