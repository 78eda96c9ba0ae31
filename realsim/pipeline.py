"""The pipeline runner: stages over one Scene, with timing, progress and the conversion report.

A pipeline is a YAML file in ``pipelines/`` naming stages in order, each with optional
parameter overrides::

    stages:
      - load
      - planes: {distance_threshold: 0.008}

Every stage is a function ``(Scene, Params) -> Scene`` with its parameter dataclass, one thin
adapter module each in :mod:`realsim.stages` (:data:`STAGES`).
"""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass, field, is_dataclass
from pathlib import Path
from typing import Any, Callable

import yaml
from rich.console import Console

from realsim import rerun
from realsim.alloc import reuse_freed_memory
from realsim.composition import backdrop_ahead, robot_ahead
from realsim.destination import check_destination
from realsim.errors import InputError
from realsim.perception.capture_config import read_capture_config
from realsim.perception.lone_object import is_lone_object
from realsim.perception.rgbd import is_rgbd_sequence
from realsim.resources import data_dir
from realsim.scene import Scene
from realsim.stages import STAGES, Stage, WriteParams  # noqa: F401 (Stage, WriteParams: re-exported)
from realsim.understanding.photo import PHOTO_SUFFIXES, find_photo
from realsim.validation import build_params, check_seed, unknown_names

Overrides = dict[str, Any]
"""Stage name -> ``{parameter: value}`` or that stage's parameter dataclass."""

BEGUN_AFTER: dict[str, tuple[str, Callable[[Scene, Any], None]]] = {
    "load": ("robot", lambda scene, robot: robot_ahead.begin(robot.enabled)),
    "segment": ("compose", lambda scene, compose: backdrop_ahead.begin(scene, compose.appearance, compose.backdrop)),
}
"""Work for a later stage begun beside the stages in between as soon as a stage has made what it
reads: stage -> (the later stage, a function of the Scene and that stage's parameters beginning the
work). The later stage takes the work only when what it read is unchanged; it is begun only when
that stage is still to run."""


def as_mapping(value: Any) -> Any:
    """A parameter dataclass as the mapping of its fields (nested ones too); anything else unchanged."""
    if is_dataclass(value) and not isinstance(value, type):
        return asdict(value)
    return value


@dataclass
class PipelineSpec:
    """Stages in order with their parameter overrides."""

    name: str
    stages: list[tuple[str, dict[str, Any]]] = field(default_factory=list)


def load_pipeline(name_or_path: str | Path) -> PipelineSpec:
    """Read a pipeline by name (``pipelines/<name>.yaml``) or from a YAML file path."""
    path = Path(name_or_path)
    if path.suffix in (".yaml", ".yml") and path.exists():
        text = path.read_text(errors="replace")
    else:
        file = data_dir("pipelines") / f"{name_or_path}.yaml"
        if not file.is_file():
            known = ", ".join(sorted(p.stem for p in data_dir("pipelines").glob("*.yaml")))
            raise InputError(f"unknown pipeline {name_or_path!r}: use one of {known} or a YAML file")
        text = file.read_text()
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        raise InputError(f"pipeline {name_or_path}: invalid YAML ({str(exc).splitlines()[0]})") from None
    if not isinstance(data, dict) or not isinstance(data.get("stages"), list):
        raise InputError(f"pipeline {name_or_path}: expected a mapping with a 'stages' list")
    stages: list[tuple[str, dict[str, Any]]] = []
    for entry in data["stages"]:
        if isinstance(entry, dict) and len(entry) == 1:
            name, params = next(iter(entry.items()))
        else:
            name, params = entry, {}
        if not isinstance(name, str) or not isinstance(params or {}, dict):
            raise InputError(f"pipeline {name_or_path}: a stage is a name or {{name: {{param: value}}}}, got {entry!r}")
        unknown_names([name], STAGES, f"pipeline {data.get('name')}")
        stages.append((name, params or {}))
    names = [name for name, _ in stages]
    if not names or names[0] != "load" or names.count("load") != 1:
        raise InputError(f"pipeline {name_or_path}: the first stage (and only the first) must be 'load'")
    if "write" in names and names.index("write") != len(names) - 1:
        raise InputError(f"pipeline {name_or_path}: 'write' must be the last stage")
    return PipelineSpec(name=data.get("name", str(name_or_path)), stages=stages)


def pipeline_for(source: Path | None, text: str | None = None) -> str:
    """The default pipeline for a capture: ``scan`` for an environment, ``objects`` otherwise,
    ``text`` for a description (``--text``, a ``.txt`` file, or ``text:`` in capture.yaml), ``photo``
    for a photo alone (a JPEG/PNG/WebP file, or a folder holding only ``photo.*``)."""
    if source is None or text or Path(source).suffix.lower() == ".txt":
        return "text"
    source = Path(source)
    if source.is_dir() and not any(source.glob("scene.*")) and not any((source / "objects").glob("*")):
        try:
            meta = yaml.safe_load((source / "capture.yaml").read_text()) if (source / "capture.yaml").is_file() else None
        except yaml.YAMLError:
            meta = None
        if isinstance(meta, dict) and meta.get("text"):
            return "text"
        if find_photo(source) is not None:
            return "photo"  # a folder holding only photo.*
    if source.is_file() and source.suffix.lower() in PHOTO_SUFFIXES:
        return "photo"
    if is_lone_object(source):
        return "objects"  # one object mesh: on a table, as a capture's objects/
    if source.is_dir() and not any(source.glob("scene.*")) and not is_rgbd_sequence(source):
        return "objects"
    return "scan"


def plan_pipeline(
    source: Path | None,
    *,
    pipeline: str | Path | None = None,
    seed: int = 0,
    overrides: Overrides | None = None,
) -> tuple[PipelineSpec, list[tuple[str, Any]]]:
    """Check everything the user gave before any work: the seed, the pipeline, every stage's
    parameters, and that the capture exists with a valid ``capture.yaml``. Returns the pipeline
    and each stage's validated parameters.

    ``overrides`` maps stage names to ``{parameter: value}`` or to the stage's parameter
    dataclass itself (``{"segment": SegmentParams(min_object_size=0.02)}``)."""
    overrides = overrides or {}
    if isinstance(overrides, dict):
        overrides = {k: as_mapping(v) for k, v in overrides.items()}
    check_seed(seed)
    if not isinstance(overrides, dict) or not all(isinstance(v, dict) for v in overrides.values()):
        raise InputError("overrides must map stage names to {parameter: value} mappings")
    if source is not None:
        if not Path(source).exists():
            hint = "; to build a scene from a description use --text" if " " in str(source) and not Path(source).suffix else ""
            raise InputError(f"{source}: no such file or folder{hint}")
        if Path(source).is_dir():
            read_capture_config(Path(source))
    spec = load_pipeline(pipeline or pipeline_for(source, (overrides.get("load") or {}).get("text")))
    unknown_names(overrides, {name for name, _ in spec.stages} | {"load", "write"}, f"stages of pipeline {spec.name}")
    plan = []
    for name, params in spec.stages:
        cls = STAGES[name].params
        plan.append((name, build_params(cls, {**params, **overrides.get(name, {})}, name)))
    return spec, plan


def run_pipeline(
    source: Path | None,
    *,
    pipeline: str | Path | None = None,
    seed: int = 0,
    overrides: Overrides | None = None,
    console: Console | None = None,
    write: bool = False,
) -> Scene:
    """Run the pipeline's stages in order on ``source`` and return the composed, settled Scene.

    ``overrides`` maps stage names to parameter values that win over the pipeline file's
    (the CLI's ``--units``/``--up`` arrive as ``{"load": {"units": ..., "up": ...}}``).
    Everything is validated (:func:`plan_pipeline`) before the first stage runs, and each stage
    checks that the earlier ones gave it what it needs. The ``write`` stage runs only with
    ``write=True`` (its destination in ``overrides["write"]``; :func:`convert` does this);
    otherwise the pipeline ends before it and the returned Scene is what would be written.
    """
    spec, plan = plan_pipeline(source, pipeline=pipeline, seed=seed, overrides=overrides)
    reuse_freed_memory()  # numpy temporaries reuse freed heap instead of fresh page-faulted mmaps
    scene = Scene.unread(source, seed)
    try:
        for i, (name, params) in enumerate(plan):
            if name == "write" and not write:
                break
            stage = STAGES[name]
            stage.check(scene, spec.name)
            started = time.perf_counter()
            if console is not None:
                console.log(f"[bold]{name}[/bold]")
            left = scene.compiled
            scene = stage.run(scene, params)
            if scene.compiled is left:  # a compiled spec is handed to the next stage only: this one may have edited the spec
                scene.compiled = None
            later, begin = BEGUN_AFTER.get(name, ("", None))
            ahead = {n: p for n, p in plan[i + 1:] if n != "write" or write}
            if begin is not None and later in ahead:
                begin(scene, ahead[later])
            scene.timings[name] = round(time.perf_counter() - started, 4)
    finally:  # begun work never outlives the conversion (the Panda's thread may write the disk cache)
        robot_ahead.finish()
    scene.timings["total"] = round(sum(scene.timings.values()), 4)
    return scene


def convert(source: Path | str | None, dest: Path | str, *, text: str | None = None, pipeline: str | Path | None = None,
            seed: int = 0, overrides: Overrides | None = None, force: bool = False, check_only: bool = False,
            console: Console | None = None) -> Scene | None:
    """Convert a capture (a file or folder; None with ``text``) into a scene folder at ``dest``.

    ``text`` describes a scene instead ("a table with a mug and a bowl"). ``dest`` is checked
    before any work (:func:`realsim.destination.check_destination`): a new path, an empty
    folder, or earlier realsim output replaced only with ``force``; the folder is written
    atomically. ``pipeline`` names one (default: chosen from the capture), ``seed`` seeds every
    random choice, ``overrides`` sets stage parameters (see :func:`plan_pipeline`), ``console``
    shows progress. With ``check_only`` everything is validated and nothing is run or written
    (returns None). A rerun with unchanged inputs restores the stored output.
    """
    overrides = {k: as_mapping(v) for k, v in (overrides or {}).items()}
    kwargs: dict[str, Any] = {"pipeline": pipeline, "seed": seed, "overrides": overrides}
    if console is not None:
        kwargs["console"] = console
    if text is not None:
        if not text.strip():
            raise InputError('the description is empty: describe the scene, e.g. "a table with a mug and two soda cans"')
        overrides = dict(kwargs.get("overrides") or {})
        overrides["load"] = {**(overrides.get("load") or {}), "text": text}
        kwargs["overrides"] = overrides
    started = time.perf_counter()
    photo = ((kwargs.get("overrides") or {}).get("objects", {}).get("understanding", {}) or {}).get("photo")
    source = Path(source) if source is not None else None
    dest = check_destination(dest, inputs=[source, Path(photo) if photo else None], force=force)
    if check_only:
        plan_pipeline(source, **{k: v for k, v in kwargs.items() if k != "console"})
        return None
    key = rerun.conversion_key(source, kwargs)  # a warm rerun restores the stored output, byte for byte
    if (reused := rerun.restore(key, dest, force=force)) is not None:
        return reused
    overrides = dict(kwargs.pop("overrides", None) or {})
    overrides["write"] = {"dest": dest, "force": force}
    scene = run_pipeline(source, overrides=overrides, write=True, **kwargs)
    scene.timings["total"] = round(time.perf_counter() - started, 4)
    rerun.remember(key, dest, scene)
    return scene
