"""The static check: a program's AST against the allowlist, before anything runs."""

from __future__ import annotations

import ast
import sys
from collections.abc import Iterable

from realsim.planner.primitives import BY_NAME, NAMES, value_problem
from realsim.planner.sandbox.limits import ALLOWED_ATTRIBUTES, FILENAME, FORBIDDEN_NAMES, SAFE_BUILTIN_NAMES, Limits, SandboxViolation

__all__ = ["check"]

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
        if isinstance(func, ast.Name) and func.id in BY_NAME and func.id in self.callables:
            self._check_signature(node, func.id)

    def _check_signature(self, node: ast.Call, name: str) -> None:
        """A primitive call against the registry's signature; literal arguments against their kinds."""
        prim = BY_NAME[name]
        if any(isinstance(a, ast.Starred) for a in node.args) or any(kw.arg is None for kw in node.keywords):
            return  # reported as unpacking
        problem = prim.arity_problem(len(node.args), [kw.arg for kw in node.keywords if kw.arg is not None])
        if problem is not None:
            self.bad(node, problem)
            return
        by_name = {p.name: p for p in prim.params}
        given = [(p, a) for p, a in zip(prim.params, node.args)] + [(by_name[kw.arg], kw.value) for kw in node.keywords if kw.arg]
        for param, arg in given:
            if isinstance(arg, (ast.Constant, ast.List, ast.Tuple, ast.UnaryOp)):
                try:
                    value = ast.literal_eval(arg)
                except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
                    continue
                problem = value_problem(param.kind, value)
                if problem is not None:
                    self.bad(node, f"{name}() {param.name}: {problem}")

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


def check(source: str, *, primitives: Iterable[str] = NAMES, limits: Limits = Limits()) -> ast.Module:
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

