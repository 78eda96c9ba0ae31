"""Playful voices said plainly (realsim.planner.voices): mock-archaic English and pirate talk."""

from __future__ import annotations

import pytest
from test_planner_rules import call_lines

from realsim.planner.voices import plain


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
