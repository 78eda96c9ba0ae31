"""Natural-language commands to programs over the robot primitives, run in a sandbox.

``make_planner()`` picks Claude when ``ANTHROPIC_API_KEY`` is set, else the offline rule
planner; both return a :class:`Plan` that runs through :func:`sandbox.run` (the rule planner's
typed :class:`Program` of calls, Claude's checked source), and whose goals are checked
afterwards (:mod:`realsim.planner.goals`).
"""

from __future__ import annotations

from realsim import llm
from realsim.planner.claude import ClaudePlanner, PlanningError
from realsim.planner.goals import (
    AtHome,
    Between,
    DrawerClosed,
    DrawerOpen,
    Goal,
    GoalResult,
    Inside,
    Lifted,
    Moved,
    NextTo,
    On,
    OnTable,
    Placed,
    SideOf,
    WorldView,
    evaluate_all,
    prepare_all,
    verdict,
)
from realsim.planner.rules import RulePlanner
from realsim.planner.sandbox import ExecutionReport, Limits, PrimitiveCall, SandboxViolation, check, check_calls, run
from realsim.planner.types import Call, ObjectInfo, Plan, Planner, Program

__all__ = [
    "AtHome", "Between", "Call", "ClaudePlanner", "DrawerClosed", "DrawerOpen", "ExecutionReport", "Goal", "GoalResult",
    "Inside", "Lifted", "Limits", "Moved", "NextTo", "ObjectInfo", "On", "OnTable", "Placed", "Plan", "Planner",
    "PlanningError", "PrimitiveCall", "Program", "RulePlanner", "SandboxViolation", "SideOf", "WorldView", "check", "check_calls",
    "evaluate_all", "make_planner", "prepare_all", "run", "verdict",
]


def make_planner(kind: str = "auto", settings: llm.LLMSettings | None = None) -> Planner:
    """``"rules"``, ``"claude"``, or ``"auto"`` (Claude when a key is set, else rules)."""
    from realsim.errors import InputError

    if kind == "rules" or (kind == "auto" and not llm.available(settings)):
        return RulePlanner()
    if kind in ("claude", "auto"):
        if not llm.available(settings):
            raise InputError("the Claude planner needs ANTHROPIC_API_KEY; set it or use the rule planner")
        return ClaudePlanner(settings=settings or llm.LLMSettings())
    raise InputError(f"unknown planner {kind!r}; use auto, rules or claude")
