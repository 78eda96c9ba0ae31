"""``realsim run``: the console side of a run (what it prints), kept out of cli.py.

Prints the program before it runs, each primitive's result as it finishes, the goal check and
the verdict, and where the JSON log (and video) went. Returns the exit code: 0 goal met, 1 not
met, 2 bad input (raised as :class:`InputError` before anything moves).
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any, TextIO

from realsim.errors import InputError
from realsim.planner.types import Plan
from realsim.runtime.session import RunRecord, run_command, run_program, write_log
from realsim.runtime.sim import Sim


def numbered(program: str) -> str:
    """A program with line numbers, as printed by ``realsim run``."""
    lines = program.rstrip("\n").splitlines()
    width = len(str(len(lines)))
    return "\n".join(f"  {i:>{width}} | {line}" for i, line in enumerate(lines, 1))


def _call_line(name: str, args: tuple[Any, ...], result: Any) -> str:
    shown = ", ".join(repr(a) if isinstance(a, str) else str([round(float(v), 3) for v in a]) if isinstance(a, (list, tuple)) else
                      str(round(a, 3)) if isinstance(a, float) else str(a) for a in args)
    outcome = "ok" if result.success else f"FAILED: {result.reason}"
    extra = f", {result.attempts} attempt(s)" if getattr(result, "attempts", 0) > 1 else ""
    return f"  {name}({shown}) -> {outcome} ({result.sim_time:.1f} s sim{extra})"


def run_cli(scene: str, command: str | None, program_file: str | None, planner: str = "auto", seed: int = 0,
            video: str | None = None, log: str | None = None, out: TextIO | None = None,
            video_fps: float = 30.0) -> int:
    """The whole of ``realsim run``; raises :class:`InputError` for bad input (exit 2)."""
    if (command is None) == (program_file is None):
        raise InputError("give either a command in quotes or --program FILE (not both)")
    if command is not None and not command.strip():
        raise InputError("the command is empty; say what the robot should do, e.g. \"put the mug in the bowl\"")
    if video_fps <= 0 or video_fps > 240:
        raise InputError(f"--video-fps {video_fps}: use a rate between 0 and 240 frames per simulated second")
    sim = Sim.load(scene, seed=seed)

    def say(text: str) -> None:
        print(text, file=out or sys.stdout, flush=True)

    def on_plan(plan: Plan) -> None:
        say(f"planner: {plan.planner}" + (f" ({plan.usage.summary()})" if plan.usage.calls else ""))
        say("program:")
        say(numbered(plan.program))
        say("running:")

    def on_call(name: str, args: tuple[Any, ...], result: Any) -> None:
        say(_call_line(name, args, result))

    record: RunRecord
    if command is not None:
        say(f"scene: {sim.folder} ({len(sim.object_names())} objects); command: {command.strip()}")
        record = run_command(sim, command, planner=planner, video=video, video_fps=video_fps, on_plan=on_plan, on_call=on_call)
    else:
        path = Path(program_file)  # type: ignore[arg-type]
        if not path.is_file():
            raise InputError(f"--program {path}: no such file")
        try:
            source = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            raise InputError(f"--program {path}: not a UTF-8 text file") from None
        say(f"scene: {sim.folder} ({len(sim.object_names())} objects); program: {path}")
        from realsim.planner import sandbox

        sandbox.check(source)  # rejected before anything is printed as running
        say("program:")
        say(numbered(source))
        say("running:")
        record = run_program(sim, source, video=video, video_fps=video_fps, on_call=on_call, name=f"program:{path.name}")
    if record.output:
        for line in record.output:
            say(f"  print: {line}")
    if record.error:
        say(f"stopped: {record.error}")
    for g in record.goals:
        say(f"goal [{'met' if g['ok'] else 'NOT met'}] {g['goal']}: {g['measured']}")
    if not record.goals:
        say("goal: unknown (no goal to check); judged by the primitives' results")
    for note in record.notes:
        say(f"note: {note}")
    log_path = write_log(record, log)
    if record.video:
        say(f"video: {record.video['path']} ({record.video['frames']} frames at {record.video['fps']:.1f} fps of simulated time)")
    say(f"log: {log_path}")
    verdict = record.verdict if record.goals else ("program finished" if record.success else "program failed")
    say(f"result: {verdict}; {record.sim_time:.1f} s simulated, {record.wall_time.get('total', 0.0):.1f} s wall; "
        f"exit {record.exit_code}")
    if record.exit_code:  # the reason also goes to stderr, on one line, for scripts that read only it
        kind = "error" if record.exit_code == 2 else "task failed"
        print(f"realsim: {kind}: {record.error or verdict}", file=sys.stderr, flush=True)
    return record.exit_code
