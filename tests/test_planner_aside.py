"""Out of the way, where another object was, a place refined after a comma, away from, line up."""

from __future__ import annotations

import numpy as np
import pytest
from test_planner_rules import CLUTTER

from realsim.errors import InputError
from realsim.planner import ObjectInfo, Placed, RulePlanner, SideOf
from realsim.planner.aside import CLEAR, aside_spot
from realsim.planner.goals import Aside


def _layout(seed: int, n: int = 6) -> list[ObjectInfo]:
    """``n`` boxes that do not overlap on a 60 x 80 cm patch in front of the robot."""
    rng = np.random.default_rng(seed)
    objs: list[ObjectInfo] = []
    while len(objs) < n:
        size = (*rng.uniform(0.04, 0.18, 2), 0.08)
        xy = rng.uniform((0.3, -0.4), (0.9, 0.4))
        if all(np.any(np.abs(xy - o.position[:2]) > (np.asarray(size[:2]) + o.size[:2]) / 2 + 0.01) for o in objs):
            objs.append(ObjectInfo(f"obj{len(objs) + 1}_box", "box", (), (*xy, 0.04), size))
    return objs


def _gap(a: ObjectInfo, xy: tuple[float, float], b: ObjectInfo) -> float:
    d = np.maximum(0.0, np.abs(np.asarray(xy) - b.position[:2]) - (np.asarray(a.size[:2]) + b.size[:2]) / 2)
    return float(np.hypot(*d))


@pytest.mark.parametrize("seed", range(401, 411))
def test_an_aside_spot_is_clear_of_the_others_and_frees_the_objects_own_spot(seed: int) -> None:
    objs = _layout(seed)
    lo = np.min([np.asarray(b.position[:2]) - np.asarray(b.size[:2]) / 2 for b in objs], axis=0) - 0.10
    hi = np.max([np.asarray(b.position[:2]) + np.asarray(b.size[:2]) / 2 for b in objs], axis=0) + 0.10
    spots = {o.name: aside_spot(o, objs) for o in objs}
    assert sum(xy is not None for xy in spots.values()) >= len(objs) - 1  # a crowded layout may leave one big box no room
    for o in objs:
        xy = spots[o.name]
        if xy is None:
            continue
        assert all(_gap(o, xy, b) >= CLEAR - 1e-9 for b in objs)  # the others and its own start footprint
        half = np.asarray(o.size[:2]) / 2
        assert np.all(np.asarray(xy) - half >= lo - 1e-9) and np.all(np.asarray(xy) + half <= hi + 1e-9)  # on the objects' area


def test_no_free_spot_is_refused() -> None:
    packed = [ObjectInfo(f"obj{i}_box", "box", (), (0.5 + 0.1 * (i % 3), -0.1 + 0.1 * (i // 3), 0.04), (0.09, 0.09, 0.08)) for i in range(9)]
    assert aside_spot(packed[4], packed) is None
    with pytest.raises(InputError, match="no free spot"):
        RulePlanner().plan("move the middle box out of the way", packed)


@pytest.mark.parametrize("sentence", ["move the banana out of the way", "get the banana out of the way", "clear the banana away",
                                      "could you put the banana to one side", "push the banana aside", "clear away the banana",
                                      "tuck the banana away", "put the banana away", "I need the banana out of the way",
                                      "the banana is in the way, move it", "get the banana out of the way of the bowl",
                                      "could you possibly shift the banana out of my way"])
def test_out_of_the_way_places_the_object_at_a_free_spot(sentence: str) -> None:
    plan = RulePlanner().plan(sentence, CLUTTER)
    (call,) = plan.calls.calls
    assert call.name == "place" and call.args[0] == "obj7_banana"
    banana = CLUTTER[6]
    assert all(_gap(banana, call.args[1][:2], b) >= CLEAR - 1e-9 for b in CLUTTER)
    assert [type(g) for g in plan.goals] == [Aside]


def test_out_of_the_way_then_moved_anyway_is_only_taken_up() -> None:
    lines = [c.text() for c in RulePlanner().plan("get the banana out of the way, put it behind the bowl", CLUTTER).calls]
    assert lines == ["grasp('obj7_banana')", "place_beside('obj7_banana', 'obj6_bowl', 'behind')"]


def test_where_another_was_once_it_moved_away() -> None:
    plan = RulePlanner().plan("move the banana out of the way, then put the strawberry where the banana was", CLUTTER)
    place = plan.calls.calls[-1]
    assert place.name == "place" and place.args[0] == "obj8_strawberry" and place.args[1][:2] == [0.65, 0.0]
    assert Placed("obj8_strawberry", (0.65, 0.0)) in plan.goals
    plan = RulePlanner().plan("move the blue cube out of the way, then put the red cube where it was", CLUTTER)
    assert plan.calls.calls[-1].args[:2] == ("obj3_cube", [0.55, 0.05, 0.03])
    plan = RulePlanner().plan("move the left can out of the way, then put the strawberry where the can was", CLUTTER)
    assert plan.calls.calls[-1].args[:2] == ("obj8_strawberry", [0.4, 0.2, 0.06])  # of the two cans, the one moved


def test_where_another_still_is_is_refused_and_where_it_was_is_back() -> None:
    with pytest.raises(InputError, match="still where it is"):
        RulePlanner().plan("put the strawberry where the banana is", CLUTTER)
    lines = [c.text() for c in RulePlanner().plan("pick up the banana, then put it back exactly where it was", CLUTTER).calls]
    assert lines[-1].startswith("place('obj7_banana', [0.65, 0.0")


@pytest.mark.parametrize(("sentence", "side", "extra"), [
    ("put the strawberry next to the bowl, on the left", "left", None),
    ("put the strawberry by the bowl, a bit closer to me", "front", None),
    ("park the strawberry beside the bowl, further away", "behind", None),
    ("put the strawberry in front of the bowl, slightly to the left", "front", ("left", 0.03)),
    ("put the strawberry behind the bowl, 2 cm further to the right", "behind", ("right", 0.02)),
])
def test_a_comma_refines_the_side(sentence: str, side: str, extra: tuple[str, float] | None) -> None:
    plan = RulePlanner().plan(sentence, CLUTTER)
    calls = plan.calls.calls
    assert calls[0].name == "place_beside" and calls[0].args == ("obj8_strawberry", "obj6_bowl", side)
    assert plan.goals == [SideOf("obj8_strawberry", "obj6_bowl", side)]
    assert (tuple(calls[1].args[1:]) if len(calls) > 1 else None) == extra


def test_take_away_from_and_line_up_and_nearest_you() -> None:
    assert [c.text() for c in RulePlanner().plan("take the banana away from the bowl", CLUTTER).calls] == ["push('obj7_banana', 'forward', 0.1)"]
    assert [c.text() for c in RulePlanner().plan("line the strawberry up with the bowl", CLUTTER).calls] == [
        "place_beside('obj8_strawberry', 'obj6_bowl', 'next')"]
    assert [c.text() for c in RulePlanner().plan("pick up the thing nearest you", CLUTTER).calls] == ["grasp('obj8_strawberry')"]


class _Boxes:
    """A world of axis-aligned boxes (no contacts)."""

    def __init__(self, objs: list[ObjectInfo]):
        self.pos = {o.name: o.position for o in objs}
        self.size = {o.name: o.size for o in objs}

    def object_pose(self, name: str):
        return self.pos[name], (1.0, 0.0, 0.0, 0.0)

    def object_size(self, name: str):
        return self.size[name]


def test_the_aside_goal_needs_the_spot_freed_and_a_gap_to_the_others() -> None:
    world = _Boxes(CLUTTER)
    goal = Aside("obj7_banana", tuple(o.name for o in CLUTTER[:6]))
    goal.prepare(world)
    assert not goal.evaluate(world).ok  # still on its spot
    world.pos["obj7_banana"] = (0.65, -0.35, 0.02)
    assert goal.evaluate(world).ok
    world.pos["obj7_banana"] = (0.65, -0.19, 0.02)  # against the green cube
    assert not goal.evaluate(world).ok


@pytest.mark.parametrize(("sentence", "dist"), [
    ("slide the banana a couple inches to the left", 0.0508), ("push the banana a few inches forward", 0.0762),
    ("scoot the banana a hair to the left", 0.01), ("move the banana a smidge to the left", 0.02),
    ("nudge the banana a tad to the left", 0.03),
])
def test_amounts_people_say(sentence: str, dist: float) -> None:
    (call,) = RulePlanner().plan(sentence, CLUTTER).calls.calls
    assert call.name == "push" and call.args[0] == "obj7_banana" and call.args[2] == pytest.approx(dist, abs=1e-3)
