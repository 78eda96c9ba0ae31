"""Checkpoints: a goal a later step undoes is checked when its own step ends."""

from __future__ import annotations

from test_planner_rules import CLUTTER

from realsim.planner import RulePlanner


def _checks(sentence: str) -> list[str]:
    return [c.describe() for c in RulePlanner().plan(sentence, CLUTTER).checkpoints]


def test_a_lift_before_putting_back_is_checked_when_it_ends() -> None:
    plan = RulePlanner().plan("pick up the banana, then put it back where it was", CLUTTER)
    assert [g.describe() for g in plan.goals] == ["obj7_banana put down at (0.650, 0.000)"]
    assert [(c.start, c.after, c.goal.describe()) for c in plan.checkpoints] == [(0, 1, "obj7_banana lifted")]


def test_a_place_a_later_step_changes_is_a_checkpoint() -> None:
    assert _checks("put the strawberry in the bowl, then take it out and put it next to the banana") == [
        "obj8_strawberry inside obj6_bowl (after call 1)"]
    assert _checks("go home, then push the banana 5 cm left") == ["robot at home (after call 1)"]


def test_a_lift_that_a_placing_needs_anyway_is_none() -> None:
    assert _checks("pick up the banana and put it in the bowl") == []
    assert _checks("put the strawberry in the bowl") == []
