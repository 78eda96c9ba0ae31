"""``write``: the scene folder written atomically where :func:`realsim.convert` was told
(:mod:`realsim.output`, :mod:`realsim.destination`)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from realsim.errors import InputError
from realsim.output import write_scene
from realsim.scene import Scene
from realsim.stages.base import Stage


@dataclass(frozen=True)
class WriteParams:
    """Where the write stage puts the scene folder (set by :func:`realsim.convert`)."""

    dest: Path | None = None
    force: bool = False  # replace earlier realsim output at ``dest``


def write(scene: Scene, params: WriteParams) -> Scene:
    """Write the scene folder atomically (:func:`realsim.output.write_scene`)."""
    if params.dest is None:
        raise InputError("the write stage needs a destination: use realsim.convert(source, dest) or --output")
    write_scene(scene, params.dest, force=params.force)
    return scene


STAGE = Stage("write", write, WriteParams, needs=("spec",))
