"""The rule planner's typed program: primitive calls with their arguments, in order.

The offline planner emits a :class:`Program`, never source text: quantities ("all the cans") are
already expanded into one call per object, and every argument is a plain value (an object name,
a number, a side or direction word, a list of numbers). :func:`realsim.planner.sandbox.check_calls`
checks it against the primitive registry's signatures and the scene's objects, and
:func:`realsim.planner.sandbox.run` executes it through the registry's bindings with the same
runner, budgets and report as a checked source program. :meth:`Program.source` renders it as
the equivalent program text, for display and run logs only.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import TypeAlias

from realsim.planner.primitives import BY_NAME

__all__ = ["Call", "Program", "Value", "candidates"]

Value: TypeAlias = str | float | int | None | tuple[float, ...] | list[float]
"""An argument of a typed call: what a primitive's parameter kinds take."""


@dataclass(frozen=True)
class Call:
    """One primitive call: its registry name and positional arguments."""

    name: str
    args: tuple[Value, ...] = ()

    def text(self) -> str:
        """The call as program text: ``place_in('obj1_mug', 'obj2_bowl')``."""
        return f"{self.name}({', '.join(_literal(a) for a in self.args)})"

    def objects(self) -> tuple[str, ...]:
        """The object names among its arguments (the registry's ``object`` parameters)."""
        prim = BY_NAME.get(self.name)
        if prim is None:
            return ()
        return tuple(a for p, a in zip(prim.params, self.args) if p.kind == "object" and isinstance(a, str))


def _literal(value: Value) -> str:
    if isinstance(value, float):
        return repr(round(value, 4))
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_literal(v) for v in value) + "]"
    return repr(value)


@dataclass(frozen=True)
class Program:
    """Calls made in order; ``comment`` (the sentence) heads the rendered source."""

    calls: tuple[Call, ...] = ()
    comment: str = ""

    def __iter__(self) -> Iterator[Call]:
        return iter(self.calls)

    def __len__(self) -> int:
        return len(self.calls)

    def line_of(self, index: int) -> int:
        """The line of call ``index`` in :meth:`source` (the comment is line 1)."""
        return index + 1 + (1 if self.comment.strip() else 0)

    def source(self) -> str:
        """The equivalent program text (for display and logs; the typed calls are what runs)."""
        head = [f"# {' '.join(self.comment.split())}"] if self.comment.strip() else []
        return "\n".join(head + [c.text() for c in self.calls]) + "\n"

    def acted_on(self) -> list[str]:
        """The object each action call moves (its first object argument), in call order."""
        out: list[str] = []
        for call in self.calls:
            prim = BY_NAME.get(call.name)
            objs = call.objects()
            if prim is not None and not prim.query and objs:
                out.append(objs[0])
        return out

    def carried(self) -> list[str]:
        """The objects the hand holds (first object of each carrying call), each once, in call order."""
        out: list[str] = []
        for call in self.calls:
            prim, objs = BY_NAME.get(call.name), call.objects()
            if prim is not None and prim.carries and objs and objs[0] not in out:
                out.append(objs[0])
        return out


def candidates(word: str, names: Sequence[str], limit: int = 8) -> str:
    """``candidates: a, b, ...``: the closest names to ``word`` first, then the rest."""
    close = difflib.get_close_matches(word, list(names), n=limit, cutoff=0.4)
    ordered = close + [n for n in names if n not in close]
    shown = ordered[:limit]
    more = f" (and {len(ordered) - limit} more)" if len(ordered) > limit else ""
    return f"candidates: {', '.join(shown)}{more}" if shown else "there are no candidates"
