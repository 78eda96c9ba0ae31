"""The primitive registry is the one list: the sandbox, the runtime, the Robot and the planner prompt agree with it."""

from __future__ import annotations

import inspect
import re

from realsim.planner import primitives, sandbox
from realsim.planner.claude import system_prompt
from realsim.robot import Robot
from realsim.runtime.primitives import ProgramAPI


def test_sandbox_allows_exactly_the_registry() -> None:
    assert sandbox.PRIMITIVES == primitives.NAMES
    assert len(set(primitives.NAMES)) == len(primitives.NAMES)
    sample = {"object": "'obj1_mug'", "point": "[0.4, 0.0, 0.3]", "quat": "None", "side": "'left'", "direction": "'left'", "distance": "0.05"}
    for p in primitives.PRIMITIVES:  # a call to any registered primitive with its parameters passes the static check
        sandbox.check(f"{p.name}({', '.join(sample[q.kind] for q in p.params)})")
    rejected = False
    try:
        sandbox.check("teleport()")
    except sandbox.SandboxViolation:
        rejected = True
    assert rejected


def test_runtime_binds_every_primitive_with_its_parameters() -> None:
    api = ProgramAPI.__new__(ProgramAPI)  # no Sim needed to bind
    funcs = api.functions()
    assert list(funcs) == list(primitives.NAMES)
    for p in primitives.PRIMITIVES:
        taken = [q for q in inspect.signature(getattr(ProgramAPI, p.api_method)).parameters if q != "self"]
        named = re.findall(r"(\w+)(?:=[^,)]*)?", p.signature)
        assert taken == named, (p.name, taken, named)


def test_robot_provides_every_primitive() -> None:
    for p in primitives.PRIMITIVES:
        assert callable(getattr(Robot, p.robot_method, None)), p.robot_method


def test_prompt_signature_block_comes_from_the_registry() -> None:
    _, text = system_prompt()
    block = primitives.prompt_block()
    assert block in text and "{primitives}" not in text
    listed = re.findall(r"`([a-z_]+)\(", block)
    assert listed == list(primitives.NAMES)
    for p in primitives.PRIMITIVES:
        assert p.call() in text
