"""What a program may use and how much: names, attributes, budgets, and the rejection error."""

from __future__ import annotations

from dataclasses import dataclass

from realsim.errors import InputError

__all__ = ["ALLOWED_ATTRIBUTES", "FILENAME", "FORBIDDEN_NAMES", "SAFE_BUILTIN_NAMES", "Limits", "SandboxViolation"]

FILENAME = "<realsim-program>"

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


SAFE_BUILTIN_NAMES = frozenset(
    {"range", "len", "min", "max", "abs", "round", "print", "sum", "enumerate", "zip", "sorted", "list", "float", "int", "str", "bool"}
)



@dataclass(frozen=True)
class Limits:
    """Budgets for one program run; sizes bound every value the program can build."""

    max_calls: int = 64  # primitive calls
    max_steps: int = 100_000  # executed lines, loop iterations included
    max_seconds: float = 2.0  # CPU time of the program itself (time inside primitives excluded; a loaded machine does not spend it)
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

