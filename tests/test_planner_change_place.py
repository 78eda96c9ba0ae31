""""Change (the) place(s) of A with/and B" is a swap; "each one goes where the other is" only
says so again. Sentences written for this test, not taken from a bench set."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER

from realsim.planner import RulePlanner


@pytest.mark.parametrize(("sentence", "pair"), [
    ("change place of the bowl with the banana, each one go where is the other", {"obj6_bowl", "obj7_banana"}),
    ("please change the positions of the strawberry and the bowl", {"obj8_strawberry", "obj6_bowl"}),
    ("change spots of the banana with the strawberry so each goes where the other is", {"obj7_banana", "obj8_strawberry"}),
])
def test_change_place_is_a_swap(sentence: str, pair: set[str]) -> None:
    plan = RulePlanner().plan(sentence, CLUTTER)
    assert set(plan.calls.acted_on()) == pair
    assert [c.text().split("(")[0] for c in plan.calls][-2:] == ["place", "place"]
