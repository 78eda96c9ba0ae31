"""``settle``: simulate to rest and write the keyframe in which everything already rests
(:mod:`realsim.composition.settle`), on the model the robot stage compiled."""

from realsim.composition.compiled import handed_model
from realsim.composition.settle import SettleParams, settle_scene
from realsim.scene import Scene
from realsim.stages.base import Stage


def settle(scene: Scene, params: SettleParams) -> Scene:
    """:func:`settle_scene` on the model the stage before compiled (if it did)."""
    return settle_scene(scene, params, handed_model(scene))


STAGE = Stage("settle", settle, SettleParams, needs=("spec",))
