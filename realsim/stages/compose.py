"""``compose``: one MjSpec of arena, objects, the captured look and the capture camera
(:mod:`realsim.compose`)."""

from realsim.compose import ComposeParams, compose_scene
from realsim.stages.base import Stage

STAGE = Stage("compose", compose_scene, ComposeParams, needs=("planes",))
