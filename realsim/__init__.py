"""realsim: turn a captured real scene into a settled MuJoCo simulation a Franka Panda can act in.

The public API (imported lazily, so ``import realsim`` stays fast)::

    import realsim

    scene = realsim.convert("capture/", "out/kitchen", seed=0)        # capture -> scene folder
    sim = realsim.Sim.load("out/kitchen")                              # a converted scene
    record = realsim.run_command(sim, "put the mug in the bowl")       # a sentence, in the sandbox
    print(record.verdict)

Stage parameters are dataclasses (``realsim.SegmentParams``, ``realsim.SettleParams``, ...):
``realsim.convert(src, dst, overrides={"settle": realsim.SettleParams(max_time=5.0)})``.

Errors meant for the user derive from :class:`RealsimError` (:class:`InputError`: bad input,
:class:`TaskFailed`: a goal not met).
"""

from __future__ import annotations

import importlib
import os
from typing import TYPE_CHECKING, Any

# MuJoCo picks its GL backend when first imported: offscreen EGL works on CPU-only machines.
os.environ.setdefault("MUJOCO_GL", "egl")

__version__ = "0.1.0"

_EXPORTS: dict[str, str] = {
    # conversion
    "convert": "realsim.pipeline",
    "run_pipeline": "realsim.pipeline",
    "plan_pipeline": "realsim.pipeline",
    "load_capture": "realsim.perception.capture",
    "LoadParams": "realsim.perception.capture",
    "CaptureConfig": "realsim.perception.capture_config",
    "Scene": "realsim.scene",
    "SceneObject": "realsim.scene",
    "SupportPlane": "realsim.scene",
    "write_scene": "realsim.output",
    # stage parameters (``overrides={"segment": SegmentParams(...)}``; ``realsim params`` lists them)
    "PlaneParams": "realsim.perception.planes",
    "SegmentParams": "realsim.perception.segment_scene",
    "CompletionParams": "realsim.completion",
    "ObjectsParams": "realsim.composition.objects",
    "TextParams": "realsim.text.stage",
    "ComposeParams": "realsim.composition.compose",
    "RobotStageParams": "realsim.composition.robot_mount",
    "SettleParams": "realsim.composition.settle",
    "RobotParams": "realsim.robot.params",
    # the runtime
    "Sim": "realsim.runtime",
    "RunRecord": "realsim.runtime",
    "run_command": "realsim.runtime",
    "run_program": "realsim.runtime",
    "write_log": "realsim.runtime",
    # export and viewing
    "export_mjcf": "realsim.export",
    "export_objects": "realsim.export",
    "export_usd": "realsim.export",
    "render_scene": "realsim.render",
    # errors
    "RealsimError": "realsim.errors",
    "InputError": "realsim.errors",
    "TaskFailed": "realsim.errors",
    "SimulationDiverged": "realsim.errors",
}

__all__ = ["__version__", *_EXPORTS]


def __getattr__(name: str) -> Any:
    """Import a public name from its module on first use."""
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'realsim' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(__all__)


if TYPE_CHECKING:  # for type checkers and IDEs: the same names, eagerly
    from realsim.completion import CompletionParams
    from realsim.composition.compose import ComposeParams
    from realsim.composition.objects import ObjectsParams
    from realsim.composition.robot_mount import RobotStageParams
    from realsim.composition.settle import SettleParams
    from realsim.errors import InputError, RealsimError, SimulationDiverged, TaskFailed
    from realsim.export import export_mjcf, export_objects, export_usd
    from realsim.output import write_scene
    from realsim.perception.capture import LoadParams, load_capture
    from realsim.perception.capture_config import CaptureConfig
    from realsim.perception.planes import PlaneParams
    from realsim.perception.segment_scene import SegmentParams
    from realsim.pipeline import convert, plan_pipeline, run_pipeline
    from realsim.render import render_scene
    from realsim.robot.params import RobotParams
    from realsim.runtime import RunRecord, Sim, run_command, run_program, write_log
    from realsim.scene import Scene, SceneObject, SupportPlane
    from realsim.text.stage import TextParams
