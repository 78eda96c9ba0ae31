"""The static check of a typed program: each call against the registry's signature and the scene."""

from __future__ import annotations

from collections.abc import Sequence

from realsim.planner.primitives import BY_NAME, NAMES, value_problem
from realsim.planner.program import Program, candidates
from realsim.planner.sandbox.limits import Limits, SandboxViolation

__all__ = ["check_calls"]


def check_calls(program: Program, objects: Sequence[str] | None = None, *, limits: Limits = Limits()) -> Program:
    """``program`` when every call names a registered primitive with arguments its parameters
    take and (given the scene's ``objects``) every object exists; else :class:`SandboxViolation`
    with one ``line N: ...`` per problem, an unknown name answered with the closest candidates."""
    problems: list[str] = []
    if not program.calls:
        problems.append("line 1: the program is empty")
    if len(program) > limits.max_calls:
        problems.append(f"line {program.line_of(limits.max_calls)}: more than {limits.max_calls} primitive calls")
    for i, call in enumerate(program):
        where = f"line {program.line_of(i)}"
        prim = BY_NAME.get(call.name)
        if prim is None:
            problems.append(f"{where}: unknown primitive {call.name!r}; {candidates(call.name, NAMES)}")
            continue
        arity = prim.arity_problem(len(call.args))
        if arity is not None:
            problems.append(f"{where}: {arity}")
            continue
        for param, value in zip(prim.params, call.args):
            problem = value_problem(param.kind, value)
            if problem is None and param.kind == "object" and objects is not None and value not in objects:
                problem = f"no object named {value!r} in the scene; {candidates(str(value), objects)}"
            if problem is not None:
                problems.append(f"{where}: {call.name}() {param.name}: {problem}")
    if problems:
        raise SandboxViolation(problems)
    return program
