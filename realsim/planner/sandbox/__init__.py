"""Check and run a command program: plain Python over the robot primitives, nothing else.

:func:`check` validates the program's AST against an allowlist before anything runs: calls only
to the primitives and a few safe builtins, arithmetic, comparisons, ``if``/``for``/``while``,
assignments, lists/tuples/subscripts, f-strings without format specs, and attribute access only
to result fields (``.success``, ``.reason``) and ``list.append``. No imports, no ``def``/
``class``/``lambda``, no ``with``/``try``/``global``, no names starting with ``_``, no
``eval``/``getattr``/``open``... Constants are bounded (no ``10**10**10``). Every rejection
names its line.

:func:`run` executes a checked program with builtins replaced by the allowlist, under budgets:
primitive calls, executed lines, seconds spent in the program itself (primitive time excluded),
an iteration cap per ``while`` loop, and size caps on integers, strings and lists (every
arithmetic operation is routed through a size-checking helper, so ``[0] * 10**9`` never
allocates). The :class:`ExecutionReport` lists each primitive call with its arguments, result
and line, and stops at the first error with a one-line message.

A typed program (:class:`realsim.planner.program.Program`, what the rule planner emits) is
checked by :func:`check_calls` against the registry's signatures and the scene's objects, and
:func:`run` makes its calls through the same runner, budgets and report, without source text.
"""

from __future__ import annotations

import ast
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import Any

from realsim.planner.primitives import NAMES as PRIMITIVES
from realsim.planner.program import Program
from realsim.planner.sandbox.calls import check_calls
from realsim.planner.sandbox.checker import check
from realsim.planner.sandbox.limits import ALLOWED_ATTRIBUTES, FILENAME, FORBIDDEN_NAMES, SAFE_BUILTIN_NAMES, Limits, SandboxViolation
from realsim.planner.sandbox.runner import ExecutionReport, PrimitiveCall, Rewriter, Runner

__all__ = [
    "ALLOWED_ATTRIBUTES", "FILENAME", "FORBIDDEN_NAMES", "PRIMITIVES", "SAFE_BUILTIN_NAMES", "ExecutionReport", "Limits",
    "PrimitiveCall", "SandboxViolation", "check", "check_calls", "primitives_of", "run",
]


def primitives_of(robot: Any, names: Iterable[str] = PRIMITIVES) -> dict[str, Callable[..., Any]]:
    """The primitive functions a robot-like object provides (a mapping is returned as is)."""
    if isinstance(robot, Mapping):
        return {k: v for k, v in robot.items() if k in set(names)}
    return {n: getattr(robot, n) for n in names if callable(getattr(robot, n, None))}


def run(program: str | Program, robot: Any, *, limits: Limits = Limits(), objects: Sequence[str] | None = None) -> ExecutionReport:
    """Check ``program`` (raises :class:`SandboxViolation`) and run it against ``robot``'s
    primitives (an object with primitive methods, or a name -> function mapping). ``program`` is
    source text (Claude's, a user's) or a typed :class:`Program` (the rule planner's); ``objects``
    (the scene's names) lets a typed program's object arguments be checked before anything runs."""
    funcs = primitives_of(robot)
    if isinstance(program, Program):
        check_calls(program, objects, limits=limits)
        missing = [f"line {program.line_of(i)}: primitive {c.name}() is not provided by this robot"
                   for i, c in enumerate(program) if c.name not in funcs]
        if missing:
            raise SandboxViolation(missing)
        return Runner(funcs, limits).run_calls((program.line_of(i), c.name, c.args) for i, c in enumerate(program))
    tree = check(program, limits=limits)
    missing_names = sorted(
        {n.func.id for n in ast.walk(tree) if isinstance(n, ast.Call) and isinstance(n.func, ast.Name) and n.func.id in PRIMITIVES}
        - set(funcs)
    )
    if missing_names:
        raise SandboxViolation([f"line {_first_use(tree, name)}: primitive {name}() is not provided by this robot" for name in missing_names])
    tree = ast.fix_missing_locations(Rewriter().visit(tree))
    code = compile(tree, FILENAME, "exec")
    return Runner(funcs, limits).run(code)


def _first_use(tree: ast.AST, name: str) -> int:
    lines = [n.lineno for n in ast.walk(tree) if isinstance(n, ast.Name) and n.id == name]
    return min(lines) if lines else 1
