"""What planners take and give: scene objects in, a program with its goals out."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Protocol

from realsim.llm import Usage
from realsim.planner.program import Call, Program

__all__ = ["AFFORDANCES", "Call", "ObjectInfo", "Plan", "Planner", "Program"]

if TYPE_CHECKING:
    from realsim.planner.goals import Checkpoint, Goal

AFFORDANCES = ("graspable", "container", "support", "pushable", "drawer", "door")


@dataclass(frozen=True)
class ObjectInfo:
    """One object of the scene as a planner sees it.

    ``name`` is the scene body name (``"obj3_mug"``), ``label`` its category (``"mug"``),
    ``aliases`` other words for it (from the size table), ``position`` its centre (world frame,
    m), ``size`` its extents (x, y, z in m), ``color`` a colour name when known, ``affordances`` a subset of :data:`AFFORDANCES`, and
    ``footprint`` its horizontal length and narrowest width however it is turned (m), when known.
    """

    name: str
    label: str
    aliases: tuple[str, ...] = ()
    position: tuple[float, float, float] = (0.0, 0.0, 0.0)
    size: tuple[float, float, float] = (0.05, 0.05, 0.05)
    color: str | None = None
    affordances: tuple[str, ...] = ("graspable",)
    footprint: tuple[float, float] | None = None

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


@dataclass
class Plan:
    """A program over the primitives, the goals to check afterwards, who planned it, what it cost.

    ``calls`` is the typed program when the planner emits calls (the rule planner): that is what
    runs, and ``program`` is only its rendered text for display and logs. Claude writes source
    (``program``, run in the sandbox; ``calls`` is None).
    """

    program: str
    goals: list[Goal] = field(default_factory=list)
    planner: str = "rules"
    usage: Usage = field(default_factory=Usage)
    notes: list[str] = field(default_factory=list)
    calls: Program | None = None
    checkpoints: list[Checkpoint] = field(default_factory=list)  # goals checked between the typed calls


class Planner(Protocol):
    """Turns a sentence into a :class:`Plan` for the given scene objects (``robot_yaw``: the
    robot base's heading in the world, rad; "left" is the robot's left; ``robot_base``: its world
    xy, when known, so "the one nearest you" is the nearest to it)."""

    name: str

    def plan(self, command: str, scene_objects: list[ObjectInfo], robot_yaw: float = 0.0,
             robot_base: tuple[float, float] | None = None) -> Plan: ...
