"""Execution of a checked program: budgets, size-checked arithmetic, the report of its calls."""

from __future__ import annotations

import ast
import sys
import time
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from types import FrameType, TracebackType
from typing import Any

from realsim.planner.sandbox.limits import FILENAME, Limits

__all__ = ["ExecutionReport", "PrimitiveCall", "Rewriter", "Runner"]


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


class Runner:
    """Runs a checked program's statements or typed calls against the bound primitives within the step and time limits."""

    def __init__(self, funcs: Mapping[str, Callable[..., Any]], limits: Limits) -> None:
        self.funcs = funcs
        self.limits = limits
        self.report = ExecutionReport()
        self.start = 0.0  # wall clock (time.monotonic) at the run's start
        self.cpu_start = 0.0  # this thread's CPU time at the run's start: the program's budget is CPU, so load cannot spend it
        self.primitive_cpu = 0.0  # CPU time spent inside primitives (not the program's)
        self.while_counts: dict[int, int] = {}
        self.allocated = 0
        self.line: int | None = None  # the current call's line when running a typed program

    # helpers injected into the program's globals -----------------------------------------
    def _line(self) -> int:
        if self.line is not None:
            return self.line
        frame: FrameType | None = sys._getframe(1)
        while frame is not None and frame.f_code.co_filename != FILENAME:
            frame = frame.f_back
        return frame.f_lineno if frame is not None else 0

    def wrap(self, name: str, fn: Callable[..., Any]) -> Callable[..., Any]:
        def primitive(*args: Any, **kwargs: Any) -> Any:
            line = self._line()
            if len(self.report.calls) >= self.limits.max_calls:
                raise _Stop(f"line {line}: more than {self.limits.max_calls} primitive calls (budget exhausted)")
            t0 = time.thread_time()
            try:
                result = fn(*args, **kwargs)
            except _Stop:
                raise
            except Exception as exc:  # a primitive's own failure ends the program
                call = PrimitiveCall(name, args, kwargs, None, line)
                raise _Stop(f"line {line}: {call.call_text()} raised {type(exc).__name__}: {_one_line(exc)}") from None
            finally:
                self.primitive_cpu += time.thread_time() - t0
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
        line = frame.f_lineno
        self._step(line)
        for name, value in frame.f_locals.items():
            if isinstance(value, (str, list, tuple)) and len(value) > lim.max_len:
                raise _Stop(f"line {line}: {name!r} holds {len(value)} elements (at most {lim.max_len})")
            if isinstance(value, int) and value.bit_length() > lim.max_int_bits:
                raise _Stop(f"line {line}: {name!r} is too large an integer (at most {lim.max_int_bits} bits)")

    def _step(self, line: int) -> None:
        """Count one executed line against the step and time budgets."""
        lim = self.limits
        self.report.steps += 1
        if self.report.steps > lim.max_steps:
            raise _Stop(f"line {line}: more than {lim.max_steps} steps executed (runaway loop?)")
        if time.thread_time() - self.cpu_start - self.primitive_cpu > lim.max_seconds:
            raise _Stop(f"line {line}: the program ran longer than {lim.max_seconds:g} s (runaway loop?)")
        if lim.max_wall_seconds is not None and time.monotonic() - self.start > lim.max_wall_seconds:
            raise _Stop(f"line {line}: the run took longer than {lim.max_wall_seconds:g} s")

    def run_calls(self, calls: Iterable[tuple[int, str, tuple[Any, ...]]]) -> ExecutionReport:
        """Make ``(line, name, args)`` calls in order through the same wrapped primitives, budgets
        and report as a source program (a typed program has no loops or arithmetic to trace)."""
        self.start, self.cpu_start = time.monotonic(), time.thread_time()
        try:
            for line, name, args in calls:
                self.line = line
                self._step(line)
                self.wrap(name, self.funcs[name])(*args)
        except _Stop as stop:
            self.report.error = str(stop)
        finally:
            self.line = None
            self.report.seconds = time.monotonic() - self.start
        return self.report

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
        self.start, self.cpu_start = time.monotonic(), time.thread_time()
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


class Rewriter(ast.NodeTransformer):
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

