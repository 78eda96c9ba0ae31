"""Planner with Claude: a versioned system prompt, the live scene, one repair round.

The system prompt (``prompts/planner_system.md``, its primitive list filled in from
:mod:`realsim.planner.primitives`) documents every primitive with units and frames; the scene's objects are appended to the user message at call time. The reply's
```python block is validated with :func:`realsim.planner.sandbox.check`; when that fails, the
errors go back to Claude once (``prompts/planner_repair.md``). Goals come from the rule parser
when it reads the command, else there are none ("goal unknown").
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from realsim import llm
from realsim.errors import InputError, RealsimError
from realsim.planner import primitives, rules, sandbox
from realsim.planner.attributes import left_order
from realsim.planner.goals import Goal
from realsim.planner.reference import Resolver
from realsim.planner.types import ObjectInfo, Plan
from realsim.resources import load_prompt

SYSTEM_PROMPT = "planner_system.md"
REPAIR_PROMPT = "planner_repair.md"


def system_prompt() -> tuple[str, str]:
    """(version, text) of the planner's system prompt with the registry's primitive list filled in."""
    version, text = load_prompt(SYSTEM_PROMPT)
    return version, text.replace(primitives.PLACEHOLDER, primitives.prompt_block())


class PlanningError(RealsimError):
    """Claude's program could not be made valid: the task fails (exit code 1)."""

    exit_code = 1


def scene_text(objects: list[ObjectInfo], robot_yaw: float = 0.0) -> str:
    """The scene in the rule planner's vocabulary (colours, kinds, left/right order, sizes)."""
    if not objects:
        return "The scene has no movable objects."
    return ("Objects in the scene (live positions via object_pose; left/right/forward as seen from the robot):\n"
            + "\n".join(f"- {line}" for line in scene_vocabulary(objects, robot_yaw)))


_FENCE = re.compile(r"```(?:python|py)?[ \t]*\n(.*?)```", re.DOTALL | re.IGNORECASE)


def extract_code(reply: str) -> str:
    """The first fenced code block of ``reply`` (preferring ```python), else the whole reply."""
    blocks = _FENCE.findall(reply)
    if blocks:
        return blocks[0].strip() + "\n"
    unterminated = re.search(r"```(?:python|py)?[ \t]*\n(.*)$", reply, re.DOTALL | re.IGNORECASE)
    if unterminated:
        return unterminated.group(1).strip() + "\n"
    return reply.strip() + "\n"


@dataclass
class ClaudePlanner:
    """Plans with Claude through :mod:`realsim.llm`; ``repair_rounds`` re-asks after a rejection."""

    settings: llm.LLMSettings = field(default_factory=llm.LLMSettings)
    repair_rounds: int = 1
    name: str = "claude"

    def plan(self, command: str, scene_objects: list[ObjectInfo], robot_yaw: float = 0.0,
             robot_base: tuple[float, float] | None = None) -> Plan:
        if not command.strip():
            raise InputError("the command is empty; say what the robot should do")
        version, system = system_prompt()
        usage = llm.Usage()
        messages: list[dict[str, str]] = [
            {"role": "user", "content": f"{scene_text(scene_objects, robot_yaw)}\n\nCommand: {command.strip()}"}
        ]
        notes = [f"prompt {version}, model {self.settings.model}"]
        for attempt in range(self.repair_rounds + 1):
            reply = llm.complete_text(system, messages, settings=self.settings, usage=usage)
            code = extract_code(reply)
            try:
                sandbox.check(code)
            except sandbox.SandboxViolation as exc:
                notes.append(f"attempt {attempt + 1} rejected: {'; '.join(exc.violations[:5])}")
                if attempt == self.repair_rounds:
                    raise PlanningError(
                        f"Claude's program was rejected {attempt + 1} time(s): {'; '.join(exc.violations[:3])}"
                    ) from None
                _, repair = load_prompt(REPAIR_PROMPT)
                messages += [
                    {"role": "assistant", "content": reply},
                    {"role": "user", "content": repair.replace("{errors}", "\n".join(f"- {v}" for v in exc.violations))},
                ]
                continue
            return Plan(program=code, goals=derive_goals(command, scene_objects, notes, robot_yaw, robot_base), planner=self.name, usage=usage, notes=notes)
        raise AssertionError("unreachable")  # pragma: no cover


def derive_goals(command: str, objects: list[ObjectInfo], notes: list[str] | None = None, robot_yaw: float = 0.0,
                 robot_base: tuple[float, float] | None = None) -> list[Goal]:
    """Goals from the rule parser when it reads ``command``; otherwise none ("goal unknown")."""
    try:
        return rules.parse_calls(command, objects, robot_yaw, robot_base)[1]
    except InputError as exc:
        if notes is not None:
            notes.append(f"goal unknown (rule parser: {exc})")
        return []


def scene_vocabulary(objects: Sequence[ObjectInfo], robot_yaw: float = 0.0) -> list[str]:
    """One line per object in the words the rule planner reads: body name, colour, label, other
    names, kinds, and its place among objects of the same label (leftmost, larger...), then its
    box in the world frame and its affordances."""
    res = Resolver(objects, robot_yaw)
    lines = []
    for o in objects:
        same = [x for x in objects if x.label == o.label]
        words = []
        if len(same) > 1:
            ranked = sorted(same, key=lambda x: -res.robot_xy(x)[1])
            i = ranked.index(o)
            words.append(left_order(i, len(ranked)))
            words.append(f"{'largest' if o is max(same, key=lambda x: float(np.prod(x.size))) else 'smallest' if o is min(same, key=lambda x: float(np.prod(x.size))) else 'middle-sized'}"
                         f" of {len(same)} {o.label}s")
        f, l = res.robot_xy(o)
        kinds = sorted(res.kinds_of(o) - {"container"})
        x, y, z = o.position
        sx, sy, sz = o.size
        line = f"{o.name}: {' '.join(w for w in (res.color_of(o), o.label) if w)}"
        if o.aliases:
            line += f" (also: {', '.join(o.aliases)})"
        if kinds:
            line += f" [kind: {', '.join(kinds)}]"
        if words:
            line += f" [{'; '.join(words)}]"
        line += (f" at ({x:.3f}, {y:.3f}, {z:.3f}) m, size {sx:.3f} x {sy:.3f} x {sz:.3f} m; "
                 f"robot frame (turned with the robot, world origin): forward {f:+.2f} m, left {l:+.2f} m")
        if o.affordances:
            line += f" [{', '.join(o.affordances)}]"
        lines.append(line)
    return lines
