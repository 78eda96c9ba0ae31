"""The viewer's natural-language command hook.

``on_command(sim, text)`` forwards to ``realsim.runtime.run_command(sim, text)`` when the
runtime provides it (looked up at call time, so the viewer does not depend on it), and
otherwise answers that commands need ``realsim run``.
"""

from __future__ import annotations

import importlib
from typing import Any

NEEDS_RUNTIME = "commands need realsim run"


def command_runner():
    """``realsim.runtime.run_command`` if it exists, else None."""
    try:
        runtime = importlib.import_module("realsim.runtime")
    except ModuleNotFoundError as exc:
        if exc.name in ("realsim.runtime", "realsim"):
            return None
        raise
    runner = getattr(runtime, "run_command", None)
    return runner if callable(runner) else None


def on_command(sim: Any, text: str) -> str:
    """Run one command on the live simulation and return the message to show."""
    text = text.strip()
    if not text:
        return "type a command, e.g. 'put the mug on the plate'"
    runner = command_runner()
    if runner is None:
        return NEEDS_RUNTIME
    try:
        result = runner(sim, text)
    except Exception as exc:  # a failed command is reported in the GUI, never kills the server
        return f"command failed: {type(exc).__name__}: {exc}"
    return str(result) if result is not None else "done"
