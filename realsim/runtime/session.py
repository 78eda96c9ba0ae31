"""Run a sentence or a program in a loaded scene: plan -> check -> run -> goals -> verdict.

Both planners (rules, Claude) and a user's own program go through one path: a static check
(:func:`realsim.planner.sandbox.check` for source, :func:`~realsim.planner.sandbox.check_calls`
for the rule planner's typed calls, both against the primitive registry), then
:func:`realsim.planner.sandbox.run` with the primitives of :class:`ProgramAPI`, then the plan's
goals evaluated on the simulation. Every run
starts from keyframe "initial" and leaves the scene folder untouched; the :class:`RunRecord`
holds everything that happened and is written as a JSON log.
"""

from __future__ import annotations

import json
import os
import re
import time
from collections.abc import Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from realsim import llm
from realsim.errors import InputError
from realsim.planner import make_planner, sandbox
from realsim.planner.goals import Checkpoint, Goal, GoalResult, evaluate_all, prepare_all, verdict
from realsim.planner.program import Program
from realsim.planner.types import Plan
from realsim.planner.vocab import with_colors
from realsim.runtime.primitives import ProgramAPI, _jsonable
from realsim.runtime.sim import Sim

LOG_FORMAT = "realsim-run/1"


@dataclass
class RunRecord:
    """What one run did and whether its goal holds; ``exit_code`` is the CLI's answer.

    ``verdict`` is "met", "not met" or "goal unknown" (no goals: a user's program, or a sentence
    the rule parser cannot read). ``error`` is the program's stop message (a failed primitive or
    a budget), ``program_error`` says it was the program's own fault (not a failed primitive).
    """

    scene: str
    command: str | None
    planner: str
    program: str
    seed: int = 0
    calls: list[dict[str, Any]] = field(default_factory=list)  # the program's primitive calls
    actions: list[dict[str, Any]] = field(default_factory=list)  # every robot action, with values
    output: list[str] = field(default_factory=list)  # the program's print() lines
    error: str | None = None
    program_error: bool = False
    goals: list[dict[str, Any]] = field(default_factory=list)
    verdict: str = "goal unknown"
    sim_time: float = 0.0
    wall_time: dict[str, float] = field(default_factory=dict)
    usage: dict[str, Any] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    objects_before: dict[str, list[float]] = field(default_factory=dict)
    objects_after: dict[str, list[float]] = field(default_factory=dict)
    video: dict[str, Any] | None = None
    log_path: str | None = None

    @property
    def success(self) -> bool:
        if self.verdict == "met":
            return True
        if self.verdict == "not met":
            return False
        # no goal to check: the program must have finished with every primitive succeeding
        return self.error is None and all(c["success"] for c in self.calls)

    @property
    def exit_code(self) -> int:
        if self.program_error and self.command is None:
            return 2  # a user's program broke a sandbox rule at run time: bad input
        return 0 if self.success else 1

    def to_json(self) -> dict[str, Any]:
        d = asdict(self)
        d = {"format": LOG_FORMAT, **d, "success": self.success, "exit_code": self.exit_code}
        record: dict[str, Any] = _jsonable(d)
        return record

    def summary(self) -> str:
        """Human-readable lines: each call's outcome, the goal check, the verdict."""
        lines = []
        for c in self.calls:
            lines.append(c["text"])
        if self.output:
            lines += [f"print: {o}" for o in self.output]
        if self.error:
            lines.append(f"stopped: {self.error}")
        for g in self.goals:
            lines.append(f"goal [{'met' if g['ok'] else 'NOT met'}] {g['goal']}: {g['measured']}")
        if not self.goals:
            lines.append("goal unknown: judged by the primitives' results" if self.command or self.calls else "no goal")
        wall = self.wall_time.get("total", 0.0)
        lines.append(f"verdict: {self.verdict}{'' if self.goals else (' (program ' + ('ok' if self.success else 'failed') + ')')}; "
                     f"{self.sim_time:.1f} s simulated, {wall:.1f} s wall")
        return "\n".join(lines)


def _call_dict(call: sandbox.PrimitiveCall) -> dict[str, Any]:
    res = call.result
    d: dict[str, Any] = {"line": call.line, "call": call.call_text(), "text": str(call), "success": call.success}
    if hasattr(res, "success"):
        d.update(reason=res.reason, sim_time=round(float(res.sim_time), 4), attempts=int(res.attempts))
    return d


def _execute(sim: Sim, plan: Plan, record: RunRecord, limits: sandbox.Limits, video: str | Path | None,
             on_call: Any = None, video_fps: float = 30.0) -> RunRecord:
    """Reset, check, run the plan (its typed calls, else its source), evaluate ``plan.goals``; fills ``record``."""
    t0 = time.perf_counter()
    program: str | Program = plan.calls if plan.calls is not None else plan.program
    if isinstance(program, Program):  # nothing moves when a check raises
        sandbox.check_calls(program, sim.object_names(), limits=limits)
    else:
        sandbox.check(program, limits=limits)
    sim.reset()
    api = ProgramAPI(sim)
    record.objects_before = sim.state()
    goals: list[Goal] = list(plan.goals)
    prepare_all(goals, sim)
    start_time = float(sim.data.time)
    recorder = None
    if video is not None:
        from realsim.runtime.video import VideoRecorder

        recorder = VideoRecorder(sim, video, fps=video_fps)
        recorder.start()
    funcs = api.functions()
    if on_call is not None:
        funcs = {k: _notify(k, f, on_call) for k, f in funcs.items()}
    checks = _Checkpoints(plan.checkpoints if isinstance(program, Program) else [], sim)
    funcs = {k: checks.counted(f) for k, f in funcs.items()}
    try:
        report = sandbox.run(program, funcs, limits=limits, objects=sim.object_names())
    finally:
        if recorder is not None:
            recorder.close()
    t_run = time.perf_counter() - t0
    results: list[GoalResult] = checks.results() + evaluate_all(goals, sim)
    record.calls = [_call_dict(c) for c in report.calls]
    record.actions = api.actions
    record.output = list(report.output)
    record.error = report.error
    failed_primitive = bool(report.calls) and not report.calls[-1].success
    record.program_error = report.error is not None and not failed_primitive
    record.goals = [{"goal": r.goal, "ok": r.ok, "measured": r.measured} for r in results]
    record.verdict = verdict(results)
    if record.verdict == "met" and report.error is not None:
        # the end state may hold without the command having been carried out ("open, then close"
        # when opening failed): a stopped program is not a success
        record.verdict = "not met"
        record.notes.append("the goals hold in the end state, but the program stopped before it finished")
    record.sim_time = round(float(sim.data.time) - start_time, 4)
    record.objects_after = sim.state()
    record.wall_time["run"] = round(t_run, 3)
    if recorder is not None:
        record.video = {"path": str(recorder.path), "frames": recorder.frames, "fps": round(recorder.fps, 3),
                        "size": [recorder.width, recorder.height]}
    return record


class _Checkpoints:
    """Prepares and checks a plan's checkpoints as the typed program's calls run (counted as they return)."""

    def __init__(self, checkpoints: Sequence[Checkpoint], sim: Sim) -> None:
        self.checkpoints, self.sim, self.done = list(checkpoints), sim, 0
        self.found: dict[int, GoalResult] = {}
        self._prepare()

    def _prepare(self) -> None:
        for c in self.checkpoints:
            if c.start == self.done:
                c.goal.prepare(self.sim)

    def counted(self, fn: Any) -> Any:
        def wrapped(*args: Any, **kwargs: Any) -> Any:
            result = fn(*args, **kwargs)
            self.done += 1
            for i, c in enumerate(self.checkpoints):
                if c.after == self.done:
                    r = c.goal.evaluate(self.sim)
                    self.found[i] = GoalResult(c.describe(), r.ok, r.measured)
            self._prepare()
            return result

        wrapped.__name__ = getattr(fn, "__name__", "primitive")
        return wrapped

    def results(self) -> list[GoalResult]:
        """Each checkpoint's result; one the program never reached is not met."""
        return [self.found.get(i, GoalResult(c.describe(), False, "the program stopped before this step ended"))
                for i, c in enumerate(self.checkpoints)]


def _notify(name: str, fn: Any, on_call: Any) -> Any:
    def wrapped(*args: Any, **kwargs: Any) -> Any:
        result = fn(*args, **kwargs)
        if hasattr(result, "success"):
            on_call(name, args, result)
        return result

    wrapped.__name__ = name
    return wrapped


def run_command(sim: Sim, text: str, planner: str = "auto", seed: int | None = None, *,
                limits: sandbox.Limits = sandbox.Limits(), video: str | Path | None = None,
                settings: llm.LLMSettings | None = None, on_plan: Any = None, on_call: Any = None,
                video_fps: float = 30.0) -> RunRecord:
    """Plan ``text`` with ``planner`` ("auto" | "rules" | "claude") and run it from keyframe
    "initial". Raises :class:`InputError` for a sentence the planner cannot map to the scene (it
    lists the objects) and :class:`SandboxViolation` for a rejected program; a plan that runs
    gives a :class:`RunRecord` (``record.success`` / ``record.exit_code``)."""
    t0 = time.perf_counter()
    if seed is not None and seed != sim.seed:
        sim.seed = seed
    sim.reset()
    p = make_planner(planner, settings)
    usage_before = llm.Usage()
    usage_before.add(llm.SESSION_USAGE)
    # the planner reads colours from the capture and directions from where the robot stands
    plan = p.plan(text, with_colors(sim.object_infos(), sim.meta), robot_yaw=sim.robot_yaw(), robot_base=sim.robot_base())
    if plan.calls is not None:
        sim.check_holdable(plan.calls)
    t_plan = time.perf_counter() - t0
    record = RunRecord(scene=str(sim.folder), command=text, planner=plan.planner, program=plan.program, seed=sim.seed,
                       notes=list(plan.notes))
    record.usage = asdict(plan.usage)
    record.wall_time["plan"] = round(t_plan, 3)
    if on_plan is not None:
        on_plan(plan)
    _execute(sim, plan, record, limits, video, on_call, video_fps)
    record.wall_time["total"] = round(time.perf_counter() - t0, 3)
    return record


def run_program(sim: Sim, source: str | Program, seed: int | None = None, *, limits: sandbox.Limits = sandbox.Limits(),
                video: str | Path | None = None, on_call: Any = None, name: str = "program",
                video_fps: float = 30.0, checkpoints: Sequence[Checkpoint] = ()) -> RunRecord:
    """Run a user's own program (same primitives, same sandbox) from keyframe "initial";
    ``source`` is program text or a typed :class:`Program` of calls (whose ``checkpoints`` are
    checked as its calls run).

    Raises :class:`SandboxViolation` (an :class:`InputError` naming the line) before anything
    moves when the program breaks a rule. There are no goals: the verdict is "goal unknown" and
    success means the program finished with every primitive succeeding."""
    t0 = time.perf_counter()
    if seed is not None:
        sim.seed = seed
    text = source.source() if isinstance(source, Program) else source
    plan = Plan(program=text, goals=[], planner=name, calls=source if isinstance(source, Program) else None, checkpoints=list(checkpoints))
    record = RunRecord(scene=str(sim.folder), command=None, planner=name, program=text, seed=sim.seed)
    _execute(sim, plan, record, limits, video, on_call, video_fps)
    record.wall_time["total"] = round(time.perf_counter() - t0, 3)
    return record


def next_log_path(scene: str | Path) -> Path:
    """``<scene>/runs/run_<n>.json`` with the first free n (no wall-clock names)."""
    runs = Path(scene) / "runs"
    taken = [int(m.group(1)) for p in runs.glob("run_*.json") if (m := re.fullmatch(r"run_(\d+)\.json", p.name))]
    return runs / f"run_{max(taken, default=0) + 1:04d}.json"


def write_log(record: RunRecord, path: str | Path | None = None) -> Path:
    """Write ``record`` as JSON (atomically) to ``path`` or the next ``<scene>/runs/run_<n>.json``."""
    out = Path(path) if path is not None else next_log_path(record.scene)
    try:
        out.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"cannot write the run log to {out}: {exc.strerror}") from None
    record.log_path = str(out)
    tmp = out.with_name(f".{out.name}.tmp")
    tmp.write_text(json.dumps(record.to_json(), indent=1) + "\n", encoding="utf-8")
    os.replace(tmp, out)
    return out
