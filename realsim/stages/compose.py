"""``compose``: one MjSpec of arena, objects, the captured look and the capture camera
(:mod:`realsim.composition.compose`)."""

from realsim.composition.compose import ComposeParams, compose_scene
from realsim.stages.base import Stage

STAGE = Stage("compose", compose_scene, ComposeParams, needs=("planes",))
