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


def test_an_undo_puts_the_thing_back_and_checks_the_step_it_undoes() -> None:
    """"push the banana 5 cm left. actually, undo that": moved, then back where it was (it had been dropped unread)."""
    plan = RulePlanner().plan("Push the banana 5 cm to the left. Hmm, actually, undo that.", CLUTTER)
    assert [c.text() for c in plan.calls][-1] == "place('obj7_banana', [0.65, 0.0, 0.02])"
    assert [g.describe() for g in plan.goals] == ["obj7_banana put down at (0.650, 0.000)"]
    assert _checks("push the banana 5 cm to the left, then undo it") == ["obj7_banana moved 5 cm toward (+0.00, +1.00) (after call 1)"]
