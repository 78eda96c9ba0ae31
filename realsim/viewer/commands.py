"""The viewer's natural-language command hook.

``on_command(sim, text)`` plans and runs ``text`` with :func:`realsim.runtime.run_command` on
the viewer's own model and data, so the browser shows the robot acting while poses stream.
Like ``realsim run``, every command starts from keyframe ``initial``.
"""

from __future__ import annotations

import importlib
from typing import Any

NEEDS_RUNTIME = "commands need realsim run"


def command_runner():
    """``realsim.runtime.run_command`` if the runtime is installed, else None."""
    try:
        runtime = importlib.import_module("realsim.runtime")
    except ModuleNotFoundError as exc:
        if exc.name in ("realsim.runtime", "realsim"):
            return None
        raise
    runner = getattr(runtime, "run_command", None)
    return runner if callable(runner) else None


def runtime_sim(sim: Any) -> Any:
    """A :class:`realsim.runtime.Sim` over the viewer's model and data (made once, then reused).

    Objects without ``model``/``data``/``folder`` (other front ends) are passed through as is.
    """
    if not all(hasattr(sim, a) for a in ("model", "data", "folder")):
        return sim
    cached = getattr(sim, "runtime_sim", None)
    if cached is None:
        from realsim.runtime import Sim

        cached = Sim(sim.folder, sim.model, getattr(sim, "scene_json", {}) or {})
        cached.data = sim.data  # one state: the browser sees what the command does
        sim.runtime_sim = cached
    return cached


def _describe(result: Any) -> str:
    """One reply line per goal for a RunRecord, or the result as text."""
    if not hasattr(result, "verdict"):
        return str(result) if result is not None else "done"
    lines = [f"{result.verdict}: {result.command or 'program'}"]
    lines += [f"- {g.get('goal')}: {'met' if g.get('ok') else 'NOT met'} ({g.get('measured')})" for g in result.goals]
    if result.error:
        lines.append(f"stopped: {result.error}")
    return "\n".join(lines)


def on_command(sim: Any, text: str) -> str:
    """Run one command on the live simulation and return the message to show."""
    text = text.strip()
    if not text:
        return "type a command, e.g. 'put the mug on the plate'"
    runner = command_runner()
    if runner is None:
        return NEEDS_RUNTIME
    try:
        result = runner(runtime_sim(sim), text)
    except Exception as exc:  # a failed command is reported in the GUI, never kills the server
        return f"command failed: {type(exc).__name__}: {exc}"
    return _describe(result)
