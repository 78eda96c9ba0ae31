"""What planners take and give: scene objects in, a program with its goals out."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Protocol

from realsim.llm import Usage

if TYPE_CHECKING:
    from realsim.planner.goals import Goal

AFFORDANCES = ("graspable", "container", "support", "pushable", "drawer", "door")


@dataclass(frozen=True)
class ObjectInfo:
    """One object of the scene as a planner sees it.

    ``name`` is the scene body name (``"obj3_mug"``), ``label`` its category (``"mug"``),
    ``aliases`` other words for it (from the size table), ``position`` its centre (world frame,
    m), ``size`` its extents (x, y, z in m), ``color`` a colour name when known, and
    ``affordances`` a subset of :data:`AFFORDANCES`.
    """

    name: str
    label: str
    aliases: tuple[str, ...] = ()
    position: tuple[float, float, float] = (0.0, 0.0, 0.0)
    size: tuple[float, float, float] = (0.05, 0.05, 0.05)
    color: str | None = None
    affordances: tuple[str, ...] = ("graspable",)

    def describe(self) -> str:
        x, y, z = self.position
        sx, sy, sz = self.size
        words = [f"{self.name}: {self.color + ' ' if self.color else ''}{self.label}"]
        if self.aliases:
            words.append(f"(also: {', '.join(self.aliases)})")
        words.append(f"at ({x:.3f}, {y:.3f}, {z:.3f}) m, size {sx:.3f} x {sy:.3f} x {sz:.3f} m")
        if self.affordances:
            words.append(f"[{', '.join(self.affordances)}]")
        return " ".join(words)


@dataclass(frozen=True)
class Call:
    """One primitive call: its name and arguments (strings, numbers, lists of numbers)."""

    name: str
    args: tuple[Any, ...] = ()

    def text(self) -> str:
        return f"{self.name}({', '.join(_literal(a) for a in self.args)})"


def _literal(value: Any) -> str:
    if isinstance(value, float):
        return repr(round(value, 4))
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_literal(v) for v in value) + "]"
    return repr(value)


def program_text(calls: list[Call], comment: str = "") -> str:
    """The program that makes ``calls`` in order (what the sandbox runs)."""
    head = [f"# {' '.join(comment.split())}"] if comment.strip() else []
    return "\n".join(head + [c.text() for c in calls]) + "\n"


@dataclass
class Plan:
    """A program over the primitives, the goals to check afterwards, who planned it, what it cost.

    ``calls`` holds the primitive calls when the planner emits them directly (the rule planner);
    ``program`` is then their text. Claude writes ``program`` itself (``calls`` is None).
    """

    program: str
    goals: list[Goal] = field(default_factory=list)
    planner: str = "rules"
    usage: Usage = field(default_factory=Usage)
    notes: list[str] = field(default_factory=list)
    calls: list[Call] | None = None


class Planner(Protocol):
    """Turns a sentence into a :class:`Plan` for the given scene objects (``robot_yaw``: the
    robot base's heading in the world, rad; "left" is the robot's left)."""

    name: str

    def plan(self, command: str, scene_objects: list[ObjectInfo], robot_yaw: float = 0.0) -> Plan: ...
