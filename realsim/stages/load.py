"""``load``: read the capture the unread record names into points, colours and a world frame
(:mod:`realsim.perception.capture`: units, up axis, the typed capture.yaml)."""

from __future__ import annotations

from realsim.perception.capture import LoadParams, load_capture
from realsim.scene import Scene
from realsim.stages.base import Stage


def load(scene: Scene, params: LoadParams) -> Scene:
    """Read ``scene.capture.source`` (None: a description in ``params.text``)."""
    return load_capture(scene.capture.source, params, seed=scene.seed)


STAGE = Stage("load", load, LoadParams)
