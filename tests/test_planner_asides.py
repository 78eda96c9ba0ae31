"""Asides: talk around a command is skipped only beside a command, and can say what "it" is."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER

from realsim.errors import InputError
from realsim.planner.asides import is_aside
from realsim.planner.steps import Parser


def test_a_statement_about_one_object_makes_it_what_it_means() -> None:
    p = Parser(CLUTTER)
    assert is_aside("the banana is in the way", p)
    assert [o.name for o in p.ctx.last] == ["obj7_banana"]


@pytest.mark.parametrize(("clause", "aside"), [
    ("im tidying up before guests come", True),
    ("there a bowl and a banana here", True),
    ("put the banana on the moon", False),  # names a scene object: a command gone wrong, not talk
])
def test_talk_names_no_scene_object(clause: str, aside: bool) -> None:
    assert is_aside(clause, Parser(CLUTTER)) is aside


def test_asides_alone_are_refused() -> None:
    from realsim.planner import RulePlanner

    with pytest.raises(InputError):
        RulePlanner().plan("ugh my desk is a mess", CLUTTER)
