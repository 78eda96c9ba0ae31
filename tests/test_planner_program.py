"""The rule planner's typed program: calls checked against the registry and the scene, run without source text."""

from __future__ import annotations

import pytest
from test_planner_rules import OBJECTS
from test_sandbox import Recorder

from realsim.errors import InputError
from realsim.planner import RulePlanner, sandbox
from realsim.planner.program import Call, Program

NAMES = [o.name for o in OBJECTS]


def test_a_plan_is_its_calls_with_quantities_expanded() -> None:
    plan = RulePlanner().plan("please put the mug and the soup can in the bowl, then go home", OBJECTS)
    assert isinstance(plan.calls, Program)
    assert list(plan.calls) == [
        Call("place_in", ("obj1_mug", "obj2_bowl")),
        Call("place_in", ("obj3_soup_can", "obj2_bowl")),
        Call("go_home"),
    ]
    assert plan.calls.acted_on() == ["obj1_mug", "obj3_soup_can"]
    assert plan.program == plan.calls.source()  # the text is only a rendering of the calls
    assert sandbox.check_calls(plan.calls, NAMES) is plan.calls


def test_typed_calls_run_in_order_with_their_source_lines() -> None:
    plan = RulePlanner().plan("push the block 4 cm to the left and put the mug next to the bowl", OBJECTS)
    assert plan.calls is not None
    rec = Recorder()
    report = sandbox.run(plan.calls, rec, objects=NAMES)
    assert report.ok
    assert rec.calls == [("push", "obj4_block", "left", 0.04), ("place_beside", "obj1_mug", "obj2_bowl", "next")]
    source_lines = plan.program.splitlines()
    assert [source_lines[c.line - 1] for c in report.calls] == [c.text() for c in plan.calls]


def test_a_failed_call_stops_the_typed_program_naming_its_line() -> None:
    program = Program((Call("grasp", ("obj1_mug",)), Call("place_in", ("obj1_mug", "obj2_bowl")), Call("go_home")), "mug in bowl")
    rec = Recorder(fail={"place_in"})
    report = sandbox.run(program, rec)
    assert [c[0] for c in rec.calls] == ["grasp", "place_in"]
    assert report.error is not None and report.error.startswith("line 3: place_in('obj1_mug', 'obj2_bowl') failed")


def test_an_unknown_reference_is_refused_with_candidates_before_anything_runs() -> None:
    rec = Recorder()
    program = Program((Call("grasp", ("obj1_mug",)), Call("place_in", ("obj1_mug", "obj9_bowl"))))
    with pytest.raises(sandbox.SandboxViolation) as err:
        sandbox.run(program, rec, objects=NAMES)
    assert rec.calls == []
    (problem,) = err.value.violations
    assert problem.startswith("line 2: place_in() container: no object named 'obj9_bowl'")
    assert "candidates: obj2_bowl," in problem  # the closest name first, then the rest of the scene


def test_calls_are_checked_against_the_registry_signatures() -> None:
    bad = Program((
        Call("teleport", ("obj1_mug",)),
        Call("grasp"),
        Call("place_beside", ("obj1_mug", "obj2_bowl", "above")),
        Call("push", ("obj4_block", "left", 5.0)),
        Call("place", ("obj1_mug", (0.4, 0.1))),
    ))
    with pytest.raises(sandbox.SandboxViolation) as err:
        sandbox.check_calls(bad, NAMES)
    v = err.value.violations
    assert v[0].startswith("line 1: unknown primitive 'teleport'; candidates:")
    assert v[1] == "line 2: grasp(obj) is missing obj"
    assert v[2].startswith("line 3: place_beside() side: side 'above'")
    assert v[3].startswith("line 4: push() distance: distance 5.0 m is out of range")
    assert v[4].startswith("line 5: place() pos: a position is [x, y, z]")


def test_source_programs_meet_the_same_signatures() -> None:
    sandbox.check("place_beside('obj1_mug', 'obj2_bowl')\nmove_ee_to(pos=[0.4, 0.0, 0.3])")  # defaults may be left out
    with pytest.raises(sandbox.SandboxViolation) as err:
        sandbox.check("grasp('obj1_mug', 'obj2_bowl')\npush('obj4_block', 'up', 0.1)\nplace_in(obj='obj1_mug', bowl='obj2_bowl')")
    assert err.value.violations == [
        "line 1: grasp(obj) takes 1 argument(s), got 2",
        "line 2: push() direction: direction 'up': use left, right, forward, back or [dx, dy]",
        "line 3: place_in(obj, container) has no parameter 'bowl'",
    ]


def test_the_rule_planner_refuses_an_unknown_object_naming_the_scene() -> None:
    with pytest.raises(InputError) as err:
        RulePlanner().plan("put the teapot in the bowl", OBJECTS)
    assert "obj1_mug" in str(err.value) and "obj2_bowl" in str(err.value)


def test_a_typed_program_keeps_the_same_budgets() -> None:
    import time

    from realsim.planner.sandbox import Limits

    def slow(obj: str) -> bool:
        time.sleep(0.05)
        return True

    program = Program(tuple(Call("grasp", (n,)) for n in NAMES[:4]))
    report = sandbox.run(program, {"grasp": slow}, limits=Limits(max_wall_seconds=0.12))
    assert report.error is not None and "the run took longer than 0.12 s" in report.error
    assert 2 <= len(report.calls) < 4
    with pytest.raises(sandbox.SandboxViolation, match="more than 2 primitive calls"):
        sandbox.run(program, {"grasp": slow}, limits=Limits(max_calls=2))
