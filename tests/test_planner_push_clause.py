"""Push clauses: a way relative to another object, and the refusal when there is no room."""

from __future__ import annotations

import pytest
from test_planner_rules import CLUTTER

from realsim.errors import InputError
from realsim.planner import Moved, ObjectInfo, RulePlanner


@pytest.mark.parametrize(("sentence", "push"), [
    ("push the strawberry toward the bowl", ("obj8_strawberry", "right")),  # the bowl is to its right
    ("shove the banana towards the bowl", ("obj7_banana", "back")),  # the bowl is nearer the robot
    ("nudge the banana away from the bowl", ("obj7_banana", "forward")),
    ("push the left can further from the right can", ("obj1_soda_can", "left")),
    ("push the strawberry next to the bowl", ("obj8_strawberry", "right")),  # a push verb goes there by pushing
    ("shove the strawberry up against the bowl", ("obj8_strawberry", "right")),
    ("move the banana 3 cm closer to the bowl", ("obj7_banana", "back")),
])
def test_a_way_toward_or_away_from_another_object(sentence: str, push: tuple[str, str]) -> None:
    (call,) = RulePlanner().plan(sentence, CLUTTER).calls.calls
    assert (call.name, call.args[:2]) == ("push", push)


def test_toward_without_a_distance_stops_short_of_the_other_object() -> None:
    plan = RulePlanner().plan("push the strawberry toward the bowl", CLUTTER)
    (goal,) = plan.goals
    assert isinstance(goal, Moved)
    gap = 0.30 - 0.0 - 0.5 * (0.04 + 0.16)  # centres 30 cm apart sideways, half footprints
    assert 0.0 < goal.distance <= gap


def test_toward_an_object_it_already_touches_is_refused() -> None:
    touching = [ObjectInfo("obj1_cube", "cube", (), (0.5, 0.0, 0.03), (0.06, 0.06, 0.06)),
                ObjectInfo("obj2_box", "box", (), (0.5, -0.065, 0.05), (0.06, 0.06, 0.1))]
    with pytest.raises(InputError, match="no room"):
        RulePlanner().plan("push the cube toward the box", touching)


def test_a_verb_that_also_carries_puts_it_next_to_the_other_object() -> None:
    (call,) = RulePlanner().plan("move the strawberry next to the bowl", CLUTTER).calls.calls
    assert call.name == "place_beside"
