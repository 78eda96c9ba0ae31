"""Goal predicates against a fake WorldView, and a rule plan run end to end on recorded primitives."""

from __future__ import annotations

import math

from test_planner_rules import OBJECTS
from test_sandbox import Recorder

from realsim.planner import (
    AtHome,
    DrawerClosed,
    DrawerOpen,
    Inside,
    Lifted,
    Moved,
    NextTo,
    On,
    RulePlanner,
    evaluate_all,
    prepare_all,
    run,
    verdict,
)


class FakeWorld:
    def __init__(self) -> None:
        self.pos = {o.name: list(o.position) for o in OBJECTS}
        self.size = {o.name: list(o.size) for o in OBJECTS}
        self.joints = {"obj5_drawer": 0.0}
        self.home = True
        self.yaw = 0.0

    def object_pose(self, name):
        return self.pos[name], (1.0, 0.0, 0.0, 0.0)

    def object_size(self, name):
        return self.size[name]

    def ee_pos(self):
        return (0.3, 0.0, 0.5)

    def at_home(self):
        return self.home

    def joint_position(self, name):
        return self.joints[name]

    def robot_yaw(self):
        return self.yaw


def test_inside_and_on() -> None:
    w = FakeWorld()
    assert not Inside("obj1_mug", "obj2_bowl").evaluate(w).ok
    w.pos["obj1_mug"] = [0.51, -0.21, 0.0 + 0.05]  # bottom at 0.0 = bowl bottom, below rim 0.06
    res = Inside("obj1_mug", "obj2_bowl").evaluate(w)
    assert res.ok and "100% of its base over the container" in str(res)
    w.pos["obj4_block"] = [0.3, 0.3, 0.205 + 0.025]  # on top of the box (top at 0.205)
    assert On("obj4_block", "obj6_cracker_box").evaluate(w).ok
    w.pos["obj4_block"][2] += 0.1
    assert not On("obj4_block", "obj6_cracker_box").evaluate(w).ok


def test_moved_lifted_next_to() -> None:
    w = FakeWorld()
    moved, lifted = Moved("obj3_soup_can", (0.0, 1.0), 0.05), Lifted("obj1_mug")
    prepare_all([moved, lifted], w)
    w.pos["obj3_soup_can"][1] += 0.047
    w.pos["obj1_mug"][2] += 0.10
    results = evaluate_all([moved, lifted], w)
    assert all(r.ok for r in results) and verdict(results) == "met"
    assert "moved 0.047 m along" in results[0].measured
    w.pos["obj3_soup_can"][0] += 0.1
    assert not moved.evaluate(w).ok
    assert not Moved("obj1_mug", (1.0, 0.0), 0.1).evaluate(w).ok  # prepare() was not called
    w.pos["obj1_mug"] = [0.5, -0.2 + 0.14, 0.05]
    w.pos["obj1_mug"][2] = 0.05
    w.pos["obj2_bowl"] = [0.5, -0.2, 0.03]
    assert NextTo("obj1_mug", "obj2_bowl").evaluate(w).ok


def test_drawer_and_home() -> None:
    w = FakeWorld()
    assert DrawerClosed("obj5_drawer").evaluate(w).ok and not DrawerOpen("obj5_drawer").evaluate(w).ok
    w.joints["obj5_drawer"] = 0.2
    assert DrawerOpen("obj5_drawer").evaluate(w).ok
    w.home = False
    assert str(AtHome().evaluate(w)).startswith("[NOT met] robot at home")


def test_no_goals_is_unknown_not_success() -> None:
    assert verdict([]) == "goal unknown"


def test_rule_plan_runs_in_the_sandbox() -> None:
    plan = RulePlanner().plan("pick up the mug, put it next to the bowl, then push the block left 5 cm and go home", OBJECTS)
    rec = Recorder()
    rec.poses["obj2_bowl"] = (0.5, -0.2, 0.03)
    report = run(plan.program, rec)
    assert report.ok, report.error
    assert [c[0] for c in rec.calls] == ["grasp", "place_beside", "push", "go_home"]
    assert rec.calls[1] == ("place_beside", "obj1_mug", "obj2_bowl", "next")
    assert [g.describe() for g in plan.goals] == ["obj1_mug next to obj2_bowl", "obj4_block moved 5 cm toward (+0.00, +1.00)", "robot at home"]


def test_direction_words_follow_the_robot_heading() -> None:
    """'left' is the robot's left: for a robot facing +y (yaw pi/2) that is world -x."""
    from realsim.planner.goals import DIRECTIONS, Moved

    world = FakeWorld()
    world.yaw = math.pi / 2
    name = OBJECTS[0].name
    goal = Moved(name, DIRECTIONS["left"], 0.1)
    goal.prepare(world)
    world.pos[name][0] -= 0.1
    assert goal.evaluate(world).ok
    world.pos[name][0] += 0.2  # the world's +y-left would be wrong: this is robot-right
    assert not goal.evaluate(world).ok
