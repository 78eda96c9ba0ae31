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
"""

from __future__ import annotations

import ast
import sys
import time
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from types import FrameType, TracebackType
from typing import Any

from realsim.errors import InputError

FILENAME = "<realsim-program>"

PRIMITIVES: tuple[str, ...] = (
    "go_home",
    "move_ee_to",
    "open_gripper",
    "close_gripper",
    "grasp",
    "place",
    "place_on",
    "place_in",
    "place_beside",
    "place_between",
    "place_down",
    "push",
    "open_drawer",
    "close_drawer",
    "object_pose",
    "object_names",
)
ALLOWED_ATTRIBUTES = frozenset({"success", "reason", "append"})
FORBIDDEN_NAMES = frozenset(
    {
        "exec", "eval", "compile", "open", "input", "getattr", "setattr", "delattr", "hasattr",
        "globals", "locals", "vars", "dir", "type", "super", "object", "classmethod",
        "staticmethod", "property", "breakpoint", "help", "exit", "quit", "memoryview",
        "bytearray", "bytes", "format", "iter", "next", "map", "filter", "id", "hash",
        "isinstance", "issubclass", "callable", "chr", "ord", "repr", "ascii", "print_function",
        "os", "sys", "subprocess", "socket", "builtins", "importlib", "pickle", "shutil",
    }
)

_NODE_PHRASES: dict[type, str] = {
    ast.Import: "import is not allowed",
    ast.ImportFrom: "import is not allowed",
    ast.FunctionDef: "defining functions (def) is not allowed",
    ast.AsyncFunctionDef: "defining functions (async def) is not allowed",
    ast.ClassDef: "defining classes is not allowed",
    ast.Lambda: "lambda is not allowed",
    ast.With: "'with' is not allowed",
    ast.AsyncWith: "'async with' is not allowed",
    ast.Try: "try/except is not allowed",
    ast.Raise: "raise is not allowed",
    ast.Global: "global is not allowed",
    ast.Nonlocal: "nonlocal is not allowed",
    ast.Delete: "del is not allowed",
    ast.NamedExpr: "the walrus operator ':=' is not allowed",
    ast.Await: "await is not allowed",
    ast.Yield: "yield is not allowed",
    ast.YieldFrom: "yield is not allowed",
    ast.GeneratorExp: "generator expressions are not allowed (use a list comprehension)",
    ast.DictComp: "dict comprehensions are not allowed",
    ast.SetComp: "set comprehensions are not allowed",
    ast.Dict: "dict literals are not allowed",
    ast.Set: "set literals are not allowed",
    ast.Starred: "'*' unpacking is not allowed",
    ast.Match: "match statements are not allowed",
    ast.AsyncFor: "'async for' is not allowed",
    ast.AnnAssign: "annotated assignments are not allowed",
}
if sys.version_info >= (3, 11):
    _NODE_PHRASES[ast.TryStar] = "try/except is not allowed"

_ALLOWED_NODES: tuple[type, ...] = (
    ast.Module, ast.Expr, ast.Assign, ast.AugAssign, ast.If, ast.For, ast.While, ast.Break,
    ast.Continue, ast.Pass, ast.Assert, ast.BoolOp, ast.BinOp, ast.UnaryOp, ast.Compare, ast.Call,
    ast.keyword, ast.IfExp, ast.Constant, ast.Name, ast.Load, ast.Store, ast.Tuple, ast.List,
    ast.Subscript, ast.Slice, ast.Attribute, ast.ListComp, ast.comprehension, ast.JoinedStr,
    ast.FormattedValue, ast.And, ast.Or, ast.Add, ast.Sub, ast.Mult, ast.Div, ast.FloorDiv,
    ast.Mod, ast.Pow, ast.USub, ast.UAdd, ast.Not, ast.Eq, ast.NotEq, ast.Lt, ast.LtE, ast.Gt,
    ast.GtE, ast.In, ast.NotIn, ast.Is, ast.IsNot,
)
_OP_SYMBOLS = {
    ast.LShift: "<<", ast.RShift: ">>", ast.BitOr: "|", ast.BitAnd: "&", ast.BitXor: "^",
    ast.MatMult: "@", ast.Invert: "~",
}


@dataclass(frozen=True)
class Limits:
    """Budgets for one program run; sizes bound every value the program can build."""

    max_calls: int = 64  # primitive calls
    max_steps: int = 100_000  # executed lines, loop iterations included
    max_seconds: float = 2.0  # time in the program itself (time inside primitives excluded)
    max_wall_seconds: float | None = None  # everything included; None: no bound
    max_while_iterations: int = 1_000  # per while loop
    max_len: int = 10_000  # elements of a list/tuple/str
    max_alloc: int = 2_000_000  # elements/characters of all lists/strings built by the program
    max_int_bits: int = 256
    max_range: int = 10_000
    max_exponent: int = 64
    max_source_chars: int = 20_000
    max_output_lines: int = 1_000
    stop_on_failure: bool = True  # a primitive returning success=False stops the program


class SandboxViolation(InputError):
    """The program is not allowed to run; ``violations`` holds one ``line N: ...`` per problem."""

    def __init__(self, violations: list[str]):
        self.violations = violations
        shown = "; ".join(violations[:5]) + (f"; ... ({len(violations) - 5} more)" if len(violations) > 5 else "")
        super().__init__(f"program rejected: {shown}")


# ---------------------------------------------------------------------------------------------
# static check


class _Checker(ast.NodeVisitor):
    def __init__(self, callables: frozenset[str], limits: Limits) -> None:
        self.callables = callables
        self.limits = limits
        self.problems: list[str] = []
        self.assigned: set[str] = set()

    def bad(self, node: ast.AST, msg: str) -> None:
        self.problems.append(f"line {getattr(node, 'lineno', 1)}: {msg}")

    def generic_visit(self, node: ast.AST) -> None:
        kind = type(node)
        if kind in _NODE_PHRASES:
            for decorator in getattr(node, "decorator_list", None) or ():
                self.bad(decorator, "decorators are not allowed")
            self.bad(node, _NODE_PHRASES[kind])
            return
        if kind in _OP_SYMBOLS:
            return  # reported by the BinOp/UnaryOp visitor that holds a line number
        if not isinstance(node, _ALLOWED_NODES):
            self.bad(node, f"{kind.__name__} is not allowed")
            return
        super().generic_visit(node)

    # names and attributes ----------------------------------------------------------------
    def visit_Name(self, node: ast.Name) -> None:
        name = node.id
        if name.startswith("_") and name != "_":
            self.bad(node, f"name {name!r} is not allowed (names starting with '_' are reserved)")
        elif isinstance(node.ctx, ast.Store):
            if name in self.callables or name in FORBIDDEN_NAMES:
                self.bad(node, f"assigning to {name!r} is not allowed (it names a function)")
        elif name in FORBIDDEN_NAMES:
            self.bad(node, f"{name!r} is not allowed")
        elif name not in self.callables and name not in self.assigned:
            self.bad(node, f"unknown name {name!r} (not a primitive, an allowed builtin or an assigned variable)")

    def visit_Attribute(self, node: ast.Attribute) -> None:
        if node.attr.startswith("_"):
            self.bad(node, f"attribute {node.attr!r} is not allowed (names starting with '_' are reserved)")
        elif node.attr not in ALLOWED_ATTRIBUTES:
            allowed = ", ".join(f".{a}" for a in sorted(ALLOWED_ATTRIBUTES))
            self.bad(node, f"attribute .{node.attr} is not allowed (only {allowed})")
        if isinstance(node.ctx, ast.Store):
            self.bad(node, "assigning to attributes is not allowed")
        self.visit(node.value)

    # calls -------------------------------------------------------------------------------
    def visit_Call(self, node: ast.Call) -> None:
        func = node.func
        if isinstance(func, ast.Name):
            if func.id in FORBIDDEN_NAMES or func.id.startswith("_"):
                self.visit(func)
            elif func.id not in self.callables:
                self.bad(node, f"calling {func.id!r} is not allowed (only the primitives and {', '.join(sorted(SAFE_BUILTIN_NAMES))})")
        elif isinstance(func, ast.Attribute) and func.attr == "append" and len(node.args) == 1 and not node.keywords:
            self.visit(func.value)
        elif isinstance(func, ast.Attribute):
            self.visit(func)  # reports the attribute
            if func.attr in ALLOWED_ATTRIBUTES:
                self.bad(node, f"calling .{func.attr} is not allowed")
        else:
            self.bad(node, "only named functions may be called")
            self.visit(func)
        for kw in node.keywords:
            if kw.arg is None:
                self.bad(node, "'**' unpacking is not allowed")
            elif kw.arg.startswith("_"):
                self.bad(node, f"keyword {kw.arg!r} is not allowed")
            self.visit(kw.value)
        for arg in node.args:
            self.visit(arg)
        if isinstance(func, ast.Name) and func.id == "range":
            self._check_range(node)

    def _check_range(self, node: ast.Call) -> None:
        values = [_const_int(a) for a in node.args]
        if node.args and all(v is not None for v in values):
            try:
                n = len(range(*values))  # type: ignore[arg-type]
            except (TypeError, ValueError, OverflowError):
                self.bad(node, "range(...) arguments are invalid")
                return
            if n > self.limits.max_range:
                self.bad(node, f"range(...) of {n} items is too long (at most {self.limits.max_range})")

    # values and operators ----------------------------------------------------------------
    def visit_Constant(self, node: ast.Constant) -> None:
        v = node.value
        if isinstance(v, bool) or v is None:
            return
        if isinstance(v, int) and v.bit_length() > 64:
            self.bad(node, "integer constant is too large")
        elif isinstance(v, str) and len(v) > 1_000:
            self.bad(node, "string constant is too long (at most 1000 characters)")
        elif isinstance(v, (bytes, complex)) or v is Ellipsis:
            self.bad(node, f"{type(v).__name__} constants are not allowed")

    def visit_BinOp(self, node: ast.BinOp) -> None:
        op = type(node.op)
        if op in _OP_SYMBOLS:
            self.bad(node, f"operator {_OP_SYMBOLS[op]!r} is not allowed")
        elif op is ast.Pow:
            exponent = _const_number(node.right)
            if exponent is None:
                self.bad(node, "'**' needs a constant exponent")
            elif abs(exponent) > self.limits.max_exponent:
                self.bad(node, f"exponent {exponent:g} is too large (at most {self.limits.max_exponent})")
            if any(isinstance(n, ast.BinOp) and isinstance(n.op, ast.Pow) for n in ast.walk(node.left)):
                self.bad(node, "nested '**' is not allowed")
        elif op is ast.Mod and isinstance(node.left, (ast.Constant, ast.JoinedStr)) and isinstance(getattr(node.left, "value", ""), str):
            self.bad(node, "'%' string formatting is not allowed (use an f-string)")
        elif op is ast.Mult:
            for seq, count in ((node.left, node.right), (node.right, node.left)):
                n = _const_int(count)
                if isinstance(seq, (ast.List, ast.Tuple, ast.Constant)) and n is not None and n > self.limits.max_len:
                    self.bad(node, f"repetition by {n} is too large (at most {self.limits.max_len} elements)")
        self.generic_visit(node)

    def visit_UnaryOp(self, node: ast.UnaryOp) -> None:
        if type(node.op) in _OP_SYMBOLS:
            self.bad(node, f"operator {_OP_SYMBOLS[type(node.op)]!r} is not allowed")
        self.generic_visit(node)

    def visit_AugAssign(self, node: ast.AugAssign) -> None:
        if not isinstance(node.target, ast.Name):
            self.bad(node, "augmented assignment (+= ...) only to a plain variable")
        self.visit_BinOp(ast.BinOp(left=node.target, op=node.op, right=node.value, lineno=node.lineno, col_offset=0))

    def visit_Assign(self, node: ast.Assign) -> None:
        for target in node.targets:
            for sub in ast.walk(target):
                if isinstance(sub, ast.Attribute):
                    self.bad(node, "assigning to attributes is not allowed")
                    break
        self.generic_visit(node)

    def visit_JoinedStr(self, node: ast.JoinedStr) -> None:
        for part in node.values:
            if isinstance(part, ast.FormattedValue):
                if part.format_spec is not None:
                    self.bad(node, "format specs in f-strings (f'{x:...}') are not allowed; use round()")
                self.visit(part.value)

    def visit_comprehension(self, node: ast.comprehension) -> None:
        if node.is_async:
            self.bad(node.iter, "async comprehensions are not allowed")
        self.generic_visit(node)


SAFE_BUILTIN_NAMES = frozenset(
    {"range", "len", "min", "max", "abs", "round", "print", "sum", "enumerate", "zip", "sorted", "list", "float", "int", "str", "bool"}
)


def _const_number(node: ast.AST) -> float | None:
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        v = _const_number(node.operand)
        return None if v is None else (-v if isinstance(node.op, ast.USub) else v)
    if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) and not isinstance(node.value, bool):
        return node.value
    return None


def _const_int(node: ast.AST) -> int | None:
    v = _fold(node)
    return v if isinstance(v, int) else None


def _fold(node: ast.AST) -> float | None:
    """The value of a constant arithmetic expression (``10**10``, ``2*3``), computed only when
    small enough to be harmless; None when not constant or too big to compute."""
    v = _const_number(node)
    if v is not None or not isinstance(node, ast.BinOp):
        return v
    a, b = _fold(node.left), _fold(node.right)
    if a is None or b is None:
        return None
    try:
        if isinstance(node.op, ast.Pow):
            if abs(b) > 64 or (isinstance(a, int) and isinstance(b, int) and abs(a).bit_length() * abs(b) > 4096):
                return None
            return a**b
        if isinstance(node.op, ast.Mult):
            return a * b if abs(a) < 2**64 and abs(b) < 2**64 else None
        if isinstance(node.op, ast.Add):
            return a + b
        if isinstance(node.op, ast.Sub):
            return a - b
    except (OverflowError, ZeroDivisionError, ValueError, TypeError):
        return None
    return None


def _assigned_names(tree: ast.AST) -> set[str]:
    return {n.id for n in ast.walk(tree) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Store)}


def check(source: str, *, primitives: Iterable[str] = PRIMITIVES, limits: Limits = Limits()) -> ast.Module:
    """Parse and validate ``source``; returns the AST or raises :class:`SandboxViolation`."""
    if not source.strip():
        raise SandboxViolation(["line 1: the program is empty"])
    if len(source) > limits.max_source_chars:
        raise SandboxViolation([f"line 1: the program is too long ({len(source)} characters, at most {limits.max_source_chars})"])
    try:
        tree = ast.parse(source, filename=FILENAME, mode="exec")
    except SyntaxError as exc:
        raise SandboxViolation([f"line {exc.lineno or 1}: syntax error: {exc.msg}"]) from None
    except (RecursionError, MemoryError, ValueError) as exc:
        raise SandboxViolation([f"line 1: the program cannot be parsed ({type(exc).__name__})"]) from None
    checker = _Checker(frozenset(primitives) | SAFE_BUILTIN_NAMES, limits)
    checker.assigned = _assigned_names(tree)
    try:
        checker.visit(tree)
    except RecursionError:
        checker.problems.append("line 1: the program is nested too deeply")
    if checker.problems:
        raise SandboxViolation(list(dict.fromkeys(checker.problems)))
    return tree


# ---------------------------------------------------------------------------------------------
# execution


@dataclass
class PrimitiveCall:
    """One primitive call made by the program."""

    name: str
    args: tuple[Any, ...]
    kwargs: dict[str, Any]
    result: Any
    line: int

    @property
    def success(self) -> bool:
        return bool(getattr(self.result, "success", True))

    @property
    def reason(self) -> str:
        return str(getattr(self.result, "reason", "") or "")

    def call_text(self) -> str:
        parts = [_short(a) for a in self.args] + [f"{k}={_short(v)}" for k, v in self.kwargs.items()]
        return f"{self.name}({', '.join(parts)})"

    def __str__(self) -> str:
        if hasattr(self.result, "success"):
            outcome = "ok" if self.success else "FAILED"
            if self.reason:
                outcome += f" ({self.reason})"
        else:
            outcome = _short(self.result)
        return f"line {self.line}: {self.call_text()} -> {outcome}"


@dataclass
class ExecutionReport:
    """What a program run did: primitive calls in order, printed lines, and the first error."""

    calls: list[PrimitiveCall] = field(default_factory=list)
    output: list[str] = field(default_factory=list)
    error: str | None = None
    steps: int = 0
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        return self.error is None

    def summary(self) -> str:
        lines = [str(c) for c in self.calls] + [f"print: {o}" for o in self.output]
        lines.append(f"stopped: {self.error}" if self.error else f"finished ({len(self.calls)} primitive calls)")
        return "\n".join(lines)


class _Stop(Exception):
    """Raised inside the program to end it; the message is the report's error."""


def _short(value: Any, limit: int = 60) -> str:
    try:
        import numpy as np

        if isinstance(value, np.ndarray):
            value = [round(float(x), 3) for x in value.ravel()[:8]]
    except ImportError:  # pragma: no cover
        pass
    if isinstance(value, float):
        value = round(value, 4)
    if isinstance(value, (list, tuple)):
        value = type(value)(round(v, 4) if isinstance(v, float) else v for v in value)
    text = repr(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."


class _Runner:
    def __init__(self, funcs: Mapping[str, Callable[..., Any]], limits: Limits) -> None:
        self.funcs = funcs
        self.limits = limits
        self.report = ExecutionReport()
        self.start = 0.0
        self.primitive_time = 0.0
        self.while_counts: dict[int, int] = {}
        self.allocated = 0

    # helpers injected into the program's globals -----------------------------------------
    def _line(self) -> int:
        frame: FrameType | None = sys._getframe(1)
        while frame is not None and frame.f_code.co_filename != FILENAME:
            frame = frame.f_back
        return frame.f_lineno if frame is not None else 0

    def wrap(self, name: str, fn: Callable[..., Any]) -> Callable[..., Any]:
        def primitive(*args: Any, **kwargs: Any) -> Any:
            line = self._line()
            if len(self.report.calls) >= self.limits.max_calls:
                raise _Stop(f"line {line}: more than {self.limits.max_calls} primitive calls (budget exhausted)")
            t0 = time.monotonic()
            try:
                result = fn(*args, **kwargs)
            except _Stop:
                raise
            except Exception as exc:  # a primitive's own failure ends the program
                call = PrimitiveCall(name, args, kwargs, None, line)
                raise _Stop(f"line {line}: {call.call_text()} raised {type(exc).__name__}: {_one_line(exc)}") from None
            finally:
                self.primitive_time += time.monotonic() - t0
            call = PrimitiveCall(name, args, kwargs, result, line)
            self.report.calls.append(call)
            if self.limits.stop_on_failure and not call.success:
                raise _Stop(f"line {line}: {call.call_text()} failed: {call.reason or 'no reason given'}")
            return result

        primitive.__name__ = name
        return primitive

    def alloc(self, value: Any) -> Any:
        """Count a freshly built string/list/tuple against the size and total budgets."""
        if isinstance(value, (str, list, tuple)):
            n = len(value)
            if n > self.limits.max_len:
                raise _Stop(f"line {self._line()}: a value of {n} elements is too large (at most {self.limits.max_len})")
            self.allocated += n
            if self.allocated > self.limits.max_alloc:
                raise _Stop(f"line {self._line()}: the program built more than {self.limits.max_alloc} elements in total")
        return value

    def builtin(self, fn: Callable[..., Any]) -> Callable[..., Any]:
        def counted(*args: Any, **kwargs: Any) -> Any:
            return self.alloc(fn(*args, **kwargs))

        counted.__name__ = fn.__name__
        return counted

    def safe_sum(self, values: Iterable[Any]) -> Any:
        total: Any = 0
        for v in values:
            if not isinstance(v, (int, float)) and type(v).__module__ != "numpy":
                raise _Stop(f"line {self._line()}: sum() only adds numbers")
            total = total + v
        return total

    def binop(self, op: str, a: Any, b: Any) -> Any:
        return self.alloc(self._binop(op, a, b))

    def _binop(self, op: str, a: Any, b: Any) -> Any:
        lim = self.limits
        seqs = (str, list, tuple)
        if op == "Mult":
            for seq, n in ((a, b), (b, a)):
                if isinstance(seq, seqs) and isinstance(n, int) and len(seq) * max(n, 0) > lim.max_len:
                    raise _Stop(f"line {self._line()}: repetition would make {len(seq) * n} elements (at most {lim.max_len})")
            if isinstance(a, int) and isinstance(b, int) and a.bit_length() + b.bit_length() > lim.max_int_bits:
                raise _Stop(f"line {self._line()}: integer result too large (at most {lim.max_int_bits} bits)")
            return a * b
        if op == "Add":
            if isinstance(a, seqs) and isinstance(b, seqs) and len(a) + len(b) > lim.max_len:
                raise _Stop(f"line {self._line()}: concatenation would make {len(a) + len(b)} elements (at most {lim.max_len})")
            return a + b
        if op == "Pow":
            if isinstance(a, int) and isinstance(b, int) and b > 0 and a.bit_length() * b > lim.max_int_bits:
                raise _Stop(f"line {self._line()}: integer power too large (at most {lim.max_int_bits} bits)")
            return a**b
        if op == "Mod" and isinstance(a, str):
            raise _Stop(f"line {self._line()}: '%' string formatting is not allowed")
        if op == "Sub":
            return a - b
        if op == "Div":
            return a / b
        if op == "FloorDiv":
            return a // b
        if op == "Mod":
            return a % b
        raise _Stop(f"line {self._line()}: operator {op} is not allowed")

    def tick(self, loop_id: int) -> bool:
        n = self.while_counts.get(loop_id, 0) + 1
        self.while_counts[loop_id] = n
        if n > self.limits.max_while_iterations:
            raise _Stop(f"line {self._line()}: while loop ran more than {self.limits.max_while_iterations} iterations")
        return True

    def safe_range(self, *args: int) -> range:
        r = range(*args)
        if len(r) > self.limits.max_range:
            raise _Stop(f"line {self._line()}: range(...) of {len(r)} items is too long (at most {self.limits.max_range})")
        return r

    def safe_print(self, *args: Any, **_: Any) -> None:
        if len(self.report.output) < self.limits.max_output_lines:
            self.report.output.append(" ".join(str(a) for a in args)[:1_000])

    # tracing -----------------------------------------------------------------------------
    def tracer(self, frame: FrameType, event: str, arg: Any) -> Callable[..., Any] | None:
        if frame.f_code.co_filename != FILENAME:
            return None
        if event == "line":
            self._on_line(frame)
        return self.tracer

    def _on_line(self, frame: FrameType) -> None:
        lim = self.limits
        self.report.steps += 1
        line = frame.f_lineno
        if self.report.steps > lim.max_steps:
            raise _Stop(f"line {line}: more than {lim.max_steps} steps executed (runaway loop?)")
        now = time.monotonic()
        if now - self.start - self.primitive_time > lim.max_seconds:
            raise _Stop(f"line {line}: the program ran longer than {lim.max_seconds:g} s (runaway loop?)")
        if lim.max_wall_seconds is not None and now - self.start > lim.max_wall_seconds:
            raise _Stop(f"line {line}: the run took longer than {lim.max_wall_seconds:g} s")
        for name, value in frame.f_locals.items():
            if isinstance(value, (str, list, tuple)) and len(value) > lim.max_len:
                raise _Stop(f"line {line}: {name!r} holds {len(value)} elements (at most {lim.max_len})")
            if isinstance(value, int) and value.bit_length() > lim.max_int_bits:
                raise _Stop(f"line {line}: {name!r} is too large an integer (at most {lim.max_int_bits} bits)")

    def run(self, code: Any) -> ExecutionReport:
        builtins_ns: dict[str, Any] = {
            "len": len, "min": min, "max": max, "abs": abs, "round": round, "sum": self.safe_sum,
            "enumerate": enumerate, "zip": zip, "sorted": self.builtin(sorted), "list": self.builtin(list),
            "float": float, "int": int, "str": self.builtin(str), "bool": bool, "range": self.safe_range,
            "print": self.safe_print,
            "True": True, "False": False, "None": None,
        }
        env: dict[str, Any] = {"__builtins__": builtins_ns, "__name__": "program"}
        env.update({name: self.wrap(name, fn) for name, fn in self.funcs.items()})
        env["__rs_binop"] = self.binop
        env["__rs_tick"] = self.tick
        env["__rs_alloc"] = self.alloc
        previous = sys.gettrace()
        self.start = time.monotonic()
        sys.settrace(self.tracer)
        try:
            exec(code, env)  # noqa: S102 - the AST was checked and rewritten; builtins replaced
        except _Stop as stop:
            self.report.error = str(stop)
        except RecursionError:
            self.report.error = f"line {self._tb_line(sys.exc_info()[2])}: recursion too deep"
        except MemoryError:
            self.report.error = f"line {self._tb_line(sys.exc_info()[2])}: out of memory"
        except Exception as exc:
            self.report.error = f"line {self._tb_line(exc.__traceback__)}: {type(exc).__name__}: {_one_line(exc)}"
        finally:
            sys.settrace(previous)
            self.report.seconds = time.monotonic() - self.start
        return self.report

    @staticmethod
    def _tb_line(tb: TracebackType | None) -> int:
        line = 0
        while tb is not None:
            if tb.tb_frame.f_code.co_filename == FILENAME:
                line = tb.tb_lineno
            tb = tb.tb_next
        return line


def _one_line(exc: object, limit: int = 200) -> str:
    s = " ".join(str(exc).split())
    return s if len(s) <= limit else s[: limit - 3] + "..."


class _Rewriter(ast.NodeTransformer):
    """Route arithmetic through the size-checking helper; cap every while loop."""

    def __init__(self) -> None:
        self.loops = 0

    def visit_BinOp(self, node: ast.BinOp) -> ast.AST:
        self.generic_visit(node)
        call = ast.Call(
            func=ast.Name("__rs_binop", ast.Load()),
            args=[ast.Constant(type(node.op).__name__), node.left, node.right],
            keywords=[],
        )
        return ast.copy_location(call, node)

    def _alloc(self, node: ast.expr) -> ast.AST:
        call = ast.Call(func=ast.Name("__rs_alloc", ast.Load()), args=[node], keywords=[])
        return ast.copy_location(call, node)

    def visit_Subscript(self, node: ast.Subscript) -> ast.AST:
        self.generic_visit(node)
        if isinstance(node.slice, ast.Slice) and isinstance(node.ctx, ast.Load):
            return self._alloc(node)
        return node

    def visit_JoinedStr(self, node: ast.JoinedStr) -> ast.AST:
        self.generic_visit(node)
        return self._alloc(node)

    def visit_ListComp(self, node: ast.ListComp) -> ast.AST:
        self.generic_visit(node)
        return self._alloc(node)

    def visit_AugAssign(self, node: ast.AugAssign) -> ast.AST:
        assert isinstance(node.target, ast.Name)
        value = self.visit_BinOp(ast.copy_location(ast.BinOp(ast.Name(node.target.id, ast.Load()), node.op, node.value), node))
        return ast.copy_location(ast.Assign(targets=[ast.Name(node.target.id, ast.Store())], value=value), node)

    def visit_While(self, node: ast.While) -> ast.AST:
        self.generic_visit(node)
        self.loops += 1
        tick = ast.Call(func=ast.Name("__rs_tick", ast.Load()), args=[ast.Constant(self.loops)], keywords=[])
        node.test = ast.copy_location(ast.BoolOp(op=ast.And(), values=[tick, node.test]), node.test)
        return node


def primitives_of(robot: Any, names: Iterable[str] = PRIMITIVES) -> dict[str, Callable[..., Any]]:
    """The primitive functions a robot-like object provides (a mapping is returned as is)."""
    if isinstance(robot, Mapping):
        return {k: v for k, v in robot.items() if k in set(names)}
    return {n: getattr(robot, n) for n in names if callable(getattr(robot, n, None))}


def run(source: str, robot: Any, *, limits: Limits = Limits()) -> ExecutionReport:
    """Check ``source`` (raises :class:`SandboxViolation`) and run it against ``robot``'s
    primitives (an object with primitive methods, or a name -> function mapping)."""
    funcs = primitives_of(robot)
    tree = check(source, limits=limits)
    missing = sorted(
        {n.func.id for n in ast.walk(tree) if isinstance(n, ast.Call) and isinstance(n.func, ast.Name) and n.func.id in PRIMITIVES}
        - set(funcs)
    )
    if missing:
        raise SandboxViolation([f"line {_first_use(tree, name)}: primitive {name}() is not provided by this robot" for name in missing])
    tree = ast.fix_missing_locations(_Rewriter().visit(tree))
    code = compile(tree, FILENAME, "exec")
    return _Runner(funcs, limits).run(code)


def _first_use(tree: ast.AST, name: str) -> int:
    lines = [n.lineno for n in ast.walk(tree) if isinstance(n, ast.Name) and n.id == name]
    return min(lines) if lines else 1
