"""Commands half-written as code (realsim.planner.code_calls)."""

from __future__ import annotations

import pytest
from test_planner_rules import call_lines

from realsim.planner.code_calls import as_words


@pytest.mark.parametrize(("code", "words"), [
    ("robot.push(banana, direction='left', dist_cm=3)", "push banana left 3 cm"),
    ("arm.put(obj='strawberry', rel='in', ref='bowl')", "put strawberry in bowl"),
    ("place(strawberry, between=[bowl, banana])", "place strawberry between bowl and banana"),
    ("put(strawberry, in_front_of=bowl)", "put strawberry in front of bowl"),
    ("banana.move_aside()", "move aside banana"),
    ("swap(cubes['red'], cubes['green'])  # trade them", "swap red cube and green cube. trade them"),
    ("can you run lift('strawberry') for me", "can you lift strawberry for me"),
    ("put the mug in the bowl (the white one)", "put the mug in the bowl (the white one)"),  # no code: unchanged
])
def test_a_call_is_said_in_words(code: str, words: str) -> None:
    assert as_words(code) == words


@pytest.mark.parametrize(("code", "plain"), [
    ("robot.push(banana, direction='left', dist_cm=3)", "push the banana 3 cm to the left"),
    ("place(strawberry, between=[bowl, banana])", "put the strawberry between the bowl and the banana"),
    ("swap(cubes['red'], cubes['green'])", "swap the red cube and the green cube"),
    ("pick('strawberry'); place_next_to('banana')", "pick up the strawberry and put it next to the banana"),
])
def test_code_plans_as_its_words_do(code: str, plain: str) -> None:
    assert call_lines(code) == call_lines(plain)
