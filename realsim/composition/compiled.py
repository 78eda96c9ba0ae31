"""A spec's compiled model handed from the stage that compiled it to the next (``Scene.compiled``).

Producers (compose, the robot stage) leave ``(spec, model)`` in ``scene.compiled``; the pipeline
keeps it for the next stage only, whose adapter passes it on (:func:`handed_model`). A direct
caller gets nothing handed and compiles: it may have edited the spec in between.
"""

from __future__ import annotations

from typing import Any

from realsim.scene import Scene


def handed_model(scene: Scene) -> Any:
    """The mujoco.MjModel the stage before compiled from this very ``scene.spec`` (taken once), or None."""
    held, scene.compiled = scene.compiled, None
    return held[1] if held is not None and held[0] is scene.spec else None
